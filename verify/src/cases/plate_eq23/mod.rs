//! A binary droplet on a plate and Eq. 23 (Natsui 2021 §4, Fig. 3, Figs. 16–19).
//!
//! A 2 mm sphere whose halves are liquids 1 and 2 rests on a 6 mm-radius plate under gravity,
//! θ31 = 90° (liquid 1 on the solid), σ12 = 0.1 N/m, free-slip wall. Eq. 23,
//! `cos θ12 = (σ1 cos θ31 − σ2 cos θ23)/σ12`, predicts whether a solid/liquid/liquid line exists
//! and its angle θ12 (inside liquid 1); if `|cos θ12| > 1` one liquid spreads under the other.
//! Measured on the state at t = 32 ms (the paper's Fig. 18 instant): which liquids touch the
//! plate, and θ12 where a line exists. The analytic θ12 maps of Fig. 3(a)/(b) are drawn with the
//! simulated points on them.

mod draw;
mod judge;
mod measure;

pub(super) use judge::triple_line_tolerance;

use super::analysis::{self, Analysis};
use super::scene::{LiquidProps, SceneBuilder, GRAVITY_M_S2, MATTE, SLAG};
use crate::analytic::eq23::{self, SolidContact};
use crate::suite::{
    smoke_is_coarse, Case, Check, DeclaredEffects, Fidelity, Metric, RunData, RunSpec,
};
use solver::scene::{BodyShape, Cut, WallBoundary, WallShape};
use std::path::Path;

/// The case.
pub struct PlateEq23;

const R_M: f64 = 1.0e-3;
const PLATE_RADIUS_M: f64 = 6.0e-3;
const SIGMA12: f64 = 0.1;
const END_S: f64 = 0.032;

/// One binary drop on the plate: its system, liquids and the two Young angles.
#[derive(Clone, Copy)]
struct Point {
    system: &'static str,
    a: LiquidProps,
    b: LiquidProps,
    theta31_deg: f64,
    theta23_deg: f64,
}

impl Point {
    fn id(&self) -> String {
        let (sys, t31, t23) = (self.system, self.theta31_deg, self.theta23_deg);
        if t31 == 90.0 {
            format!("{sys}_theta23_{t23:.0}")
        } else {
            format!("{sys}_theta31_{t31:.0}_theta23_{t23:.0}")
        }
    }
}

/// The binary drops of the two systems of §4, identical liquids and matte/slag: the paper's
/// θ31 = 90° sweeps (lines at 90°, or one liquid spreading under the other), and points where
/// Eq. 23 gives a line with θ12 well away from 90° (|θ12 − 90°| ≥ 28°, both sides).
fn points(f: Fidelity) -> Vec<Point> {
    let identical = |t31, t23| Point {
        system: "identical",
        a: MATTE.named("matte1"),
        b: MATTE.named("matte2"),
        theta31_deg: t31,
        theta23_deg: t23,
    };
    let matte_slag = |t31, t23| Point {
        system: "matte_slag",
        a: MATTE,
        b: SLAG,
        theta31_deg: t31,
        theta23_deg: t23,
    };
    if f == Fidelity::Smoke {
        return vec![identical(90.0, 90.0)];
    }
    let mut v: Vec<Point> = [30.0, 60.0, 90.0, 120.0, 150.0]
        .map(|t| identical(90.0, t))
        .into();
    v.extend([60.0, 90.0, 120.0].map(|t| matte_slag(90.0, t)));
    // Eq. 23's θ12: 134.0°, 46.0°, 117.6°, 59.9° (identical); 121.2°, 58.8°, 135.6°, 54.1°
    v.extend([
        identical(90.0, 80.0),
        identical(90.0, 100.0),
        identical(60.0, 52.0),
        identical(60.0, 68.0),
        matte_slag(90.0, 75.0),
        matte_slag(90.0, 105.0),
        matte_slag(120.0, 130.0),
        matte_slag(60.0, 45.0),
    ]);
    v
}

/// The single drops that measure the ingredients of Eq. 23 in the same setting: each liquid
/// at each Young angle a point with a line uses (identical liquids are one liquid), in order.
fn singles(f: Fidelity) -> Vec<(LiquidProps, f64)> {
    let mut v: Vec<(LiquidProps, f64)> = Vec::new();
    for p in points(f) {
        let Ok(pred) = Prediction::of(p.sigma(), p.theta31_deg, p.theta23_deg) else {
            continue;
        };
        if pred.line_to_measure().is_none() {
            continue;
        }
        for (liquid, theta) in [(p.a, p.theta31_deg), (p.b, p.theta23_deg)] {
            let base = base_liquid(liquid);
            if !v.iter().any(|(l, t)| l.name == base.name && *t == theta) {
                v.push((base, theta));
            }
        }
    }
    v
}

impl Point {
    fn sigma(&self) -> (f64, f64) {
        (self.a.surface_tension_n_m, self.b.surface_tension_n_m)
    }
}

/// The liquid a renamed copy stands for (identical liquids are matte under two names).
fn base_liquid(l: LiquidProps) -> LiquidProps {
    if l.surface_tension_n_m == MATTE.surface_tension_n_m && l.density_kg_m3 == MATTE.density_kg_m3
    {
        MATTE
    } else {
        l
    }
}

fn single_id(liquid: &LiquidProps, theta_deg: f64) -> String {
    format!("single_{}_theta_{theta_deg:.0}", liquid.name)
}

fn l0(f: Fidelity) -> f64 {
    match f {
        Fidelity::Smoke => 2.0e-4,
        Fidelity::Standard => 1.25e-4,
        Fidelity::Paper => 6.0e-5,
    }
}

/// The setting every run shares: resolution, time, gravity, the free-slip plate.
fn setting(f: Fidelity) -> SceneBuilder {
    let end = if f == Fidelity::Smoke { 0.012 } else { END_S };
    SceneBuilder::new(l0(f), 150f64.sqrt())
        .time(end, 2.0e-4)
        .fixed_dt((f == Fidelity::Paper).then_some(1.0e-6))
        .paper_effects()
        .gravity(GRAVITY_M_S2)
}

fn plate(b: SceneBuilder) -> solver::Scene {
    b.wall(
        "plate",
        "plate",
        WallShape::Disk {
            center: [0.0; 3],
            radius: PLATE_RADIUS_M,
        },
        WallBoundary::FreeSlip,
    )
    .build()
}

fn drop_shape() -> BodyShape {
    BodyShape::Sphere {
        center: [0.0, 0.0, R_M],
        radius: R_M,
    }
}

fn scene(f: Fidelity, p: &Point) -> solver::Scene {
    let (a, b) = (p.a, p.b);
    plate(
        setting(f)
            .liquid(&a)
            .liquid(&b)
            .interface(a.name, b.name, SIGMA12)
            .solid("plate", &[(a.name, p.theta31_deg), (b.name, p.theta23_deg)])
            .cut_body(
                "drop",
                drop_shape(),
                Cut {
                    point: [0.0; 3],
                    normal: [1.0, 0.0, 0.0],
                    liquids: [a.name.into(), b.name.into()],
                },
            ),
    )
}

/// One liquid's drop (the binary drop's volume) on the plate at Young angle `theta_deg`.
fn single_scene(f: Fidelity, liquid: &LiquidProps, theta_deg: f64) -> solver::Scene {
    plate(
        setting(f)
            .liquid(liquid)
            .solid("plate", &[(liquid.name, theta_deg)])
            .body("drop", liquid.name, drop_shape()),
    )
}

/// What Eq. 23 predicts for a run.
struct Prediction {
    /// Which liquids touch the plate, and θ12 where both do.
    contact: SolidContact,
    /// cos θ12 of Eq. 23 (beyond ±1: one liquid spreads under the other).
    cos_theta12: f64,
}

impl Prediction {
    /// Eq. 23 for liquids of surface tensions `(σ1, σ2)` [N/m], liquid 1 at `theta31_deg` and
    /// liquid 2 at `theta23_deg` [deg] on the plate.
    fn of((s1, s2): (f64, f64), theta31_deg: f64, theta23_deg: f64) -> anyhow::Result<Self> {
        Ok(Prediction {
            contact: eq23::solid_contact(s1, s2, SIGMA12, theta31_deg, theta23_deg)
                .map_err(anyhow::Error::msg)?,
            cos_theta12: eq23::cos_theta12(s1, s2, SIGMA12, theta31_deg, theta23_deg),
        })
    }

    /// At |cos θ12| = 1 exactly the line is on the edge of existing.
    fn on_boundary(&self) -> bool {
        (self.cos_theta12.abs() - 1.0).abs() < 1e-9
    }

    /// θ12 [deg] where a line exists off the boundary: the angle to measure.
    fn line_to_measure(&self) -> Option<f64> {
        match self.contact {
            SolidContact::TripleLine { theta12_deg } if !self.on_boundary() => Some(theta12_deg),
            _ => None,
        }
    }

    /// What touches the plate, in words.
    fn words(&self) -> &'static str {
        match self.contact {
            SolidContact::TripleLine { .. } => {
                "both liquids touch the plate (solid/liquid/liquid line)"
            }
            SolidContact::Liquid1SpreadsUnder2 => "liquid 2 rides on liquid 1",
            SolidContact::Liquid2SpreadsUnder1 => "liquid 1 rides on liquid 2",
        }
    }
}

impl Case for PlateEq23 {
    fn name(&self) -> &'static str {
        "plate_eq23"
    }
    fn title(&self) -> &'static str {
        "Binary droplet on a plate: Eq. 23 maps, which liquid rides on which, θ12"
    }
    fn source(&self) -> &'static str {
        "Natsui et al. 2021 §4, Eq. 23, Fig. 3(a)/(b), Figs. 16–19"
    }
    fn effects(&self) -> Option<DeclaredEffects> {
        Some(DeclaredEffects::ON_A_PLATE)
    }
    fn accepted_findings(&self, f: Fidelity) -> Vec<(Check, String)> {
        let mut out = smoke_is_coarse(f);
        if f == Fidelity::Paper {
            out.push((
                Check::CohesiveSoundSpeed,
                "paper fidelity keeps the paper's c² = 150 m²/s² (§2.3) at its finer spacing"
                    .into(),
            ));
        }
        out
    }
    fn resolution(&self, f: Fidelity) -> String {
        let l0 = l0(f);
        let n = 4.0 / 3.0 * std::f64::consts::PI * (R_M / l0).powi(3);
        let why = match f {
            Fidelity::Smoke => "R/l0 = 5, 12 ms, θ23 = 90° only",
            Fidelity::Standard => {
                "R/l0 = 8: the 1–2 interface spans 16 spacings; 32 ms as the paper's Fig. 18; \
                 each liquid alone at each Young angle a line uses, for Eq. 23's ingredients"
            }
            Fidelity::Paper => "the paper's l0 = 0.06 mm, dt = 1e-6 s",
        };
        format!(
            "l0 = {:.3} mm, about {n:.0} liquid particles; plate 6 mm radius, 5 layers; {why}.",
            l0 * 1e3
        )
    }
    fn runs(&self, f: Fidelity) -> Vec<RunSpec> {
        let binaries = points(f).into_iter().map(|p| RunSpec {
            id: p.id(),
            scene: scene(f, &p),
            snapshot_times_s: vec![],
        });
        let singles = singles(f).into_iter().map(|(l, th)| RunSpec {
            id: single_id(&l, th),
            scene: single_scene(f, &l, th),
            snapshot_times_s: vec![],
        });
        binaries.chain(singles).collect()
    }
    fn analyse(&self, f: Fidelity, runs: &[RunData], dir: &Path) -> anyhow::Result<Vec<Metric>> {
        analysis::analyse(self, f, runs, dir)
    }
}

impl Analysis for PlateEq23 {
    type Measured<'r> = measure::Measured<'r>;

    fn measure<'r>(&self, f: Fidelity, runs: &'r [RunData]) -> anyhow::Result<Self::Measured<'r>> {
        measure::measure(runs, l0(f))
    }

    fn judge(&self, f: Fidelity, measured: &Self::Measured<'_>) -> anyhow::Result<Vec<Metric>> {
        judge::Judge {
            case: self.name(),
            r_over_l0: R_M / l0(f),
        }
        .metrics(measured)
    }

    fn draw(&self, f: Fidelity, measured: &Self::Measured<'_>, dir: &Path) -> anyhow::Result<()> {
        draw::plots(measured, l0(f), dir)
    }
}
