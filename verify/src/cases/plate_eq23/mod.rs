//! A binary droplet on a plate and Eq. 23 (Natsui 2021 §4, Fig. 3, Figs. 16–19).
//!
//! A 2 mm sphere whose halves are liquids 1 and 2 rests on a 6 mm-radius plate under gravity,
//! θ31 = 90° (liquid 1 on the solid), σ12 = 0.1 N/m, free-slip wall. Eq. 23,
//! `cos θ12 = (σ1 cos θ31 − σ2 cos θ23)/σ12`, predicts whether a solid/liquid/liquid line exists
//! and its angle θ12 (inside liquid 1); if `|cos θ12| > 1` one liquid spreads under the other.
//! Measured on the state at t = 32 ms (the paper's Fig. 18 instant): which liquids touch the
//! plate, and θ12 where a line exists. The analytic θ12 maps of Fig. 3(a)/(b) are drawn with the
//! simulated points on them. Beside the paper's potential, Eq. 23's points away from 90° run
//! under the candidate continuum model (the surface force with the wall normal's walls, in a
//! gas, zero gravity, 40 ms; `csfn_` runs), judged on the same metrics against the typed
//! angles, and, as the potential's, against Eq. 23 at the angles single drops of each liquid
//! measured in the same setting (`csfn_single_` runs).

mod draw;
mod judge;
mod measure;

pub(super) use judge::triple_line_tolerance;

use super::analysis::{self, Analysis};
use super::scene::{laplace_sound_speed, LiquidProps, SceneBuilder, GRAVITY_M_S2, MATTE, SLAG};
use crate::analytic::eq23::{self, SolidContact};
use crate::suite::{
    smoke_is_coarse, Case, Check, DeclaredEffects, Fidelity, Metric, RunData, RunSpec,
};
use solver::kernel::KernelKind;
use solver::scene::{BodyShape, Cut, SurfaceForceWalls, TensionModel, WallBoundary, WallShape};
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

/// The prefix of the runs under the candidate continuum model (the surface force with the wall
/// normal's walls, docs/model.md §4b) and of their metrics' run ids.
const SURFACE_FORCE_PREFIX: &str = "csfn_";

/// Identical liquids (matte under two names) at Young angles θ31, θ23 [deg].
fn identical(theta31_deg: f64, theta23_deg: f64) -> Point {
    Point {
        system: "identical",
        a: MATTE.named("matte1"),
        b: MATTE.named("matte2"),
        theta31_deg,
        theta23_deg,
    }
}

/// Matte (liquid 1) and slag (liquid 2) at Young angles θ31, θ23 [deg].
fn matte_slag(theta31_deg: f64, theta23_deg: f64) -> Point {
    Point {
        system: "matte_slag",
        a: MATTE,
        b: SLAG,
        theta31_deg,
        theta23_deg,
    }
}

/// The binary drops of the two systems of §4, identical liquids and matte/slag: the paper's
/// θ31 = 90° sweeps (lines at 90°, or one liquid spreading under the other), and points where
/// Eq. 23 gives a line with θ12 well away from 90° (|θ12 − 90°| ≥ 28°, both sides).
fn points(f: Fidelity) -> Vec<Point> {
    if f == Fidelity::Smoke {
        return vec![identical(90.0, 90.0)];
    }
    let mut v: Vec<Point> = [30.0, 60.0, 90.0, 120.0, 150.0]
        .map(|t| identical(90.0, t))
        .into();
    v.extend([60.0, 90.0, 120.0].map(|t| matte_slag(90.0, t)));
    v.extend(off_right_angle_points());
    v
}

/// The eight points where Eq. 23 gives a line with θ12 well away from 90° (Eq. 23's θ12:
/// 134.0°, 46.0°, 117.6°, 59.9° for identical liquids; 121.2°, 58.8°, 135.6°, 54.1° for
/// matte/slag).
fn off_right_angle_points() -> [Point; 8] {
    [
        identical(90.0, 80.0),
        identical(90.0, 100.0),
        identical(60.0, 52.0),
        identical(60.0, 68.0),
        matte_slag(90.0, 75.0),
        matte_slag(90.0, 105.0),
        matte_slag(120.0, 130.0),
        matte_slag(60.0, 45.0),
    ]
}

/// The binary drops run under the surface force beside the paper's potential: the smoke
/// fidelity's one point (that the runs are measured), from standard fidelity on the eight
/// points away from 90°.
fn surface_force_points(f: Fidelity) -> Vec<Point> {
    match f {
        Fidelity::Smoke => points(f),
        _ => off_right_angle_points().into(),
    }
}

/// The single drops that measure the ingredients of Eq. 23 for `points` in the same setting:
/// each liquid at each Young angle a point with a line uses (identical liquids are one
/// liquid), in order.
fn singles(points: &[Point]) -> Vec<(LiquidProps, f64)> {
    let mut v: Vec<(LiquidProps, f64)> = Vec::new();
    for p in points {
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

/// The drop's cut into its halves across x = 0: liquid `a` at x < 0, `b` beyond.
fn halves(a: &str, b: &str) -> Cut {
    Cut {
        point: [0.0; 3],
        normal: [1.0, 0.0, 0.0],
        liquids: [a.into(), b.into()],
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
            .cut_body("drop", drop_shape(), halves(a.name, b.name)),
    )
}

/// The liquids' viscosity under the surface force [Pa·s]: as the convergence case's caps, so
/// that the drop settles within the run (Ohnesorge number 0.5 for matte at R = 1 mm, where the
/// liquids' own viscosities leave it ringing for the viscous time `ρR²/μ` ≈ 1.4 s); the angles
/// Eq. 23 relates are static, and the viscosity does not enter them.
const SURFACE_FORCE_VISCOSITY_PA_S: f64 = 0.7;

/// The gas around the drop under the surface force: matte's density at a tenth of the liquids'
/// viscosity, without a surface tension (the gas of Young's relation, as the convergence
/// case's caps).
const SURFACE_FORCE_GAS: LiquidProps = LiquidProps {
    name: "gas",
    viscosity_pa_s: 0.1 * SURFACE_FORCE_VISCOSITY_PA_S,
    ..MATTE
};

/// Half the side of the surface force's periodic box [m]: the flattest binary drop
/// (matte/slag at θ31 = 60°, θ23 = 45°) spreads to a wetted radius of about 1.8 mm, and the
/// flattest single drop (slag at 45°, a spherical cap of the drop's volume) to 1.83 mm, 0.92 mm
/// (7 l0) short of the box's side.
const SURFACE_FORCE_HALF_BOX_M: f64 = 2.75e-3;

/// The binary drop of [`scene`] under the surface force with the wall normal's walls
/// (docs/model.md §4b), in a gas filling a box periodic along x, y and z above the plate (the
/// gas at the top meets the plate's underside), in zero gravity, its liquids at
/// [`SURFACE_FORCE_VISCOSITY_PA_S`]; the continuum models' kernel (h = 1.3 l0, r_e = 4.2 l0),
/// the plate `2 r_e/l0` layers thick, and a sound speed for which the drop's Laplace pressure
/// compresses it by 1 %, as the convergence case's caps. Eq. 23's angles are local: gravity
/// (Bond number ρgR²/σ = 0.11 for matte) is left out, as the gas's weight would otherwise float the
/// lighter slag.
fn surface_force_scene(f: Fidelity, p: &Point) -> solver::Scene {
    let (a, b, gas) = (viscous(p.a), viscous(p.b), SURFACE_FORCE_GAS);
    in_gas(
        f,
        surface_force_setting(f, &a)
            .liquid(&a)
            .liquid(&b)
            .gas(&gas)
            .interface(a.name, b.name, SIGMA12)
            .interface(a.name, gas.name, a.surface_tension_n_m)
            .interface(b.name, gas.name, b.surface_tension_n_m)
            .solid("plate", &[(a.name, p.theta31_deg), (b.name, p.theta23_deg)])
            .cut_body("drop", drop_shape(), halves(a.name, b.name)),
    )
}

/// One liquid's drop (the binary drop's volume) at Young angle `theta_deg` [deg] in the
/// setting of [`surface_force_scene`]: the ingredient of Eq. 23 under the surface force. Its
/// sound speed is set by its own liquid's Laplace pressure, as the binary drop's by its first
/// liquid's.
fn surface_force_single_scene(f: Fidelity, liquid: &LiquidProps, theta_deg: f64) -> solver::Scene {
    let (a, gas) = (viscous(*liquid), SURFACE_FORCE_GAS);
    in_gas(
        f,
        surface_force_setting(f, &a)
            .liquid(&a)
            .gas(&gas)
            .interface(a.name, gas.name, a.surface_tension_n_m)
            .solid("plate", &[(a.name, theta_deg)])
            .body("drop", a.name, drop_shape()),
    )
}

/// A liquid at [`SURFACE_FORCE_VISCOSITY_PA_S`].
fn viscous(l: LiquidProps) -> LiquidProps {
    LiquidProps {
        viscosity_pa_s: SURFACE_FORCE_VISCOSITY_PA_S,
        ..l
    }
}

/// What every run under the surface force shares: spacing, time, the continuum models' kernel,
/// the surface force with the wall normal's walls, and the sound speed at which the Laplace
/// pressure of a drop of liquid `first` compresses it by 1 %.
fn surface_force_setting(f: Fidelity, first: &LiquidProps) -> SceneBuilder {
    let re_over_l0 = solver::scene::Setting::Natsui2021.re_over_l0();
    SceneBuilder::new(l0(f), laplace_sound_speed(first, R_M))
        .time(surface_force_end_s(f), 2.0e-4)
        .kernel(KernelKind::WendlandC2, SURFACE_FORCE_H_OVER_L0, re_over_l0)
        .paper_effects()
        .tension_model(TensionModel::SurfaceForce)
        .surface_force_walls(SurfaceForceWalls::Normal)
}

/// `b`'s drop in the gas filling the periodic box above the plate, built.
fn in_gas(f: Fidelity, b: SceneBuilder) -> solver::Scene {
    let l0 = l0(f);
    let half = (SURFACE_FORCE_HALF_BOX_M / l0).round() * l0;
    let top = (2.5 * R_M / l0).round() * l0;
    let layers = (2.0 * solver::scene::Setting::Natsui2021.re_over_l0()).ceil() as u32;
    b.gas_over_plate(SURFACE_FORCE_GAS.name, half, top, layers)
        .build()
}

/// `h/l0` of the continuum models (the convergence case's).
const SURFACE_FORCE_H_OVER_L0: f64 = 1.3;

/// The end of the runs under the surface force [s]: the convergence case's caps', in which a
/// cap of these liquids' viscosity and gas settles; at smoke fidelity 6 ms, that the run is
/// measured (its 17,000 particles with the plate cost CI about 40 s of one thread).
fn surface_force_end_s(f: Fidelity) -> f64 {
    match f {
        Fidelity::Smoke => 0.006,
        _ => 0.04,
    }
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
        // the potential's drops under gravity, the surface force's in zero gravity
        None
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
                 each liquid alone at each Young angle a line uses, for Eq. 23's ingredients; \
                 and Eq. 23's eight points away from 90° under the surface force with the wall \
                 normal, in a gas (38,720 fluid and 17,424 wall particles, h = 1.3 l0, zero \
                 gravity, the liquids at 0.7 Pa·s, 40 ms), with their ingredients, each liquid \
                 alone at each Young angle they use, in the same setting"
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
        let ingredients = singles(&points(f)).into_iter().map(|(l, th)| RunSpec {
            id: single_id(&l, th),
            scene: single_scene(f, &l, th),
            snapshot_times_s: vec![],
        });
        let surface_force = surface_force_points(f).into_iter().map(|p| RunSpec {
            id: format!("{SURFACE_FORCE_PREFIX}{}", p.id()),
            scene: surface_force_scene(f, &p),
            snapshot_times_s: vec![],
        });
        let surface_force_singles = singles(&surface_force_points(f))
            .into_iter()
            .map(|(l, th)| RunSpec {
                id: format!("{SURFACE_FORCE_PREFIX}{}", single_id(&l, th)),
                scene: surface_force_single_scene(f, &l, th),
                snapshot_times_s: vec![],
            });
        (binaries.chain(ingredients).chain(surface_force))
            .chain(surface_force_singles)
            .collect()
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
