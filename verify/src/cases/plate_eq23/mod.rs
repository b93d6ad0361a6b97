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
use crate::suite::{Case, DeclaredEffects, Fidelity, Metric, RunData, RunSpec};
use solver::scene::{BodyShape, Cut, WallBoundary, WallShape};
use std::path::Path;

/// The case.
pub struct PlateEq23;

const R_M: f64 = 1.0e-3;
const PLATE_RADIUS_M: f64 = 6.0e-3;
const SIGMA12: f64 = 0.1;
const THETA31_DEG: f64 = 90.0;
const END_S: f64 = 0.032;

/// The two systems of §4: identical liquids, and matte/slag.
fn systems(f: Fidelity) -> Vec<(&'static str, LiquidProps, LiquidProps, Vec<f64>)> {
    let identical = (
        "identical",
        MATTE.named("matte1"),
        MATTE.named("matte2"),
        if f == Fidelity::Smoke {
            vec![90.0]
        } else {
            vec![30.0, 60.0, 90.0, 120.0, 150.0]
        },
    );
    let matte_slag = ("matte_slag", MATTE, SLAG, vec![60.0, 90.0, 120.0]);
    if f == Fidelity::Smoke {
        vec![identical]
    } else {
        vec![identical, matte_slag]
    }
}

fn l0(f: Fidelity) -> f64 {
    match f {
        Fidelity::Smoke => 2.0e-4,
        Fidelity::Standard => 1.25e-4,
        Fidelity::Paper => 6.0e-5,
    }
}

fn scene(f: Fidelity, a: LiquidProps, b: LiquidProps, theta23: f64) -> solver::Scene {
    let end = if f == Fidelity::Smoke { 0.012 } else { END_S };
    SceneBuilder::new(l0(f), 150f64.sqrt())
        .time(end, 2.0e-4)
        .fixed_dt((f == Fidelity::Paper).then_some(1.0e-6))
        .paper_effects()
        .gravity(GRAVITY_M_S2)
        .liquid(&a)
        .liquid(&b)
        .interface(a.name, b.name, SIGMA12)
        .solid("plate", &[(a.name, THETA31_DEG), (b.name, theta23)])
        .cut_body(
            "drop",
            BodyShape::Sphere {
                center: [0.0, 0.0, R_M],
                radius: R_M,
            },
            Cut {
                point: [0.0; 3],
                normal: [1.0, 0.0, 0.0],
                liquids: [a.name.into(), b.name.into()],
            },
        )
        .wall(
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

/// What Eq. 23 predicts for a run.
struct Prediction {
    /// Which liquids touch the plate, and θ12 where both do.
    contact: SolidContact,
    /// cos θ12 of Eq. 23 (beyond ±1: one liquid spreads under the other).
    cos_theta12: f64,
}

impl Prediction {
    /// Eq. 23 for liquids of surface tensions `(σ1, σ2)` [N/m], liquid 2 at `theta23_deg` [deg]
    /// on the plate.
    fn of((s1, s2): (f64, f64), theta23_deg: f64) -> anyhow::Result<Self> {
        Ok(Prediction {
            contact: eq23::solid_contact(s1, s2, SIGMA12, THETA31_DEG, theta23_deg)
                .map_err(anyhow::Error::msg)?,
            cos_theta12: eq23::cos_theta12(s1, s2, SIGMA12, THETA31_DEG, theta23_deg),
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
    fn resolution(&self, f: Fidelity) -> String {
        let l0 = l0(f);
        let n = 4.0 / 3.0 * std::f64::consts::PI * (R_M / l0).powi(3);
        let why = match f {
            Fidelity::Smoke => "R/l0 = 5, 12 ms, θ23 = 90° only",
            Fidelity::Standard => {
                "R/l0 = 8: the 1–2 interface spans 16 spacings; 32 ms as the paper's Fig. 18"
            }
            Fidelity::Paper => "the paper's l0 = 0.06 mm, dt = 1e-6 s",
        };
        format!(
            "l0 = {:.3} mm, about {n:.0} liquid particles; plate 6 mm radius, 5 layers; {why}.",
            l0 * 1e3
        )
    }
    fn runs(&self, f: Fidelity) -> Vec<RunSpec> {
        let mut v = Vec::new();
        for (sys, a, b, thetas) in systems(f) {
            for th in thetas {
                v.push(RunSpec {
                    id: format!("{sys}_theta23_{th:.0}"),
                    scene: scene(f, a, b, th),
                    snapshot_times_s: vec![],
                });
            }
        }
        v
    }
    fn analyse(&self, f: Fidelity, runs: &[RunData], dir: &Path) -> anyhow::Result<Vec<Metric>> {
        analysis::analyse(self, f, runs, dir)
    }
}

impl Analysis for PlateEq23 {
    type Measured<'r> = Vec<measure::PlateRun<'r>>;

    fn measure<'r>(&self, f: Fidelity, runs: &'r [RunData]) -> anyhow::Result<Self::Measured<'r>> {
        runs.iter()
            .map(|run| measure::plate_run(run, l0(f)))
            .collect()
    }

    fn judge(&self, _: Fidelity, measured: &Self::Measured<'_>) -> anyhow::Result<Vec<Metric>> {
        let mut out = Vec::new();
        for m in measured {
            out.extend(judge::run_metrics(self.name(), m)?);
        }
        Ok(out)
    }

    fn draw(&self, f: Fidelity, measured: &Self::Measured<'_>, dir: &Path) -> anyhow::Result<()> {
        draw::plots(measured, l0(f), dir)
    }
}
