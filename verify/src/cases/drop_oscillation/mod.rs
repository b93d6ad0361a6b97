//! Small-amplitude l = 2 oscillation of a free drop across amplitudes: does the particle system
//! respond as a liquid?
//!
//! A drop of matte with the volume of a sphere of radius `R` = 1 mm starts at rest as a
//! spheroid stretched along z by `ε` (semi-axes `R/√(1+ε)`, `R/√(1+ε)`, `R(1+ε)`) and oscillates
//! in the l = 2 mode in zero gravity. Measured from the axial moment Q2 of the particle
//! positions ([`crate::measure::shape::axial_quadrupole_q2`], recorded at every output) by a
//! damped-cosine fit: the period against Rayleigh's (Lamb's frequency at l = 2 for the drop's
//! equal-volume radius), the damping against Lamb's with the physical viscosity plus the
//! artificial viscosity's `α1 h c/10`, and how both change with `ε`. A liquid's period and damping
//! do not depend on the amplitude; an elastic–plastic body's do: a small deformation stays
//! elastic and adds the lattice's shear stiffness to the capillary restoring force, a large one
//! yields. Beside them, the Born shear moduli of the setting's reference lattice
//! ([`crate::diagnostics::lattice_moduli`]).

mod draw;
mod judge;
mod measure;

use super::analysis::{self, Analysis};
use super::scene::{sound_speed_for, SceneBuilder, MATTE};
use crate::analytic::lamb;
use crate::measure::shape::axial_quadrupole_q2;
use crate::suite::{Case, DeclaredEffects, Fidelity, Metric, RunData, RunSpec};
use solver::scene::BodyShape;
use solver::Simulation;
use std::path::Path;

/// The case.
pub struct DropOscillation;

/// Equal-volume radius of the drop [m].
const RADIUS_M: f64 = 1e-3;

/// `R/l0` and the amplitudes `ε` run at a fidelity.
fn design(f: Fidelity) -> (f64, Vec<f64>) {
    match f {
        Fidelity::Smoke => (6.0, vec![0.1]),
        Fidelity::Standard => (10.0, vec![0.05, 0.1, 0.2]),
        Fidelity::Paper => (15.0, vec![0.05, 0.1, 0.2]),
    }
}

/// Rayleigh's l = 2 period of the nominal drop [s] (sets the run length and output interval).
fn nominal_period_s() -> f64 {
    lamb::lamb_period(2, MATTE.surface_tension_n_m, MATTE.density_kg_m3, RADIUS_M)
}

/// Name of the probe column.
const Q2: &str = "q2";

impl Case for DropOscillation {
    fn name(&self) -> &'static str {
        "drop_oscillation"
    }
    fn title(&self) -> &'static str {
        "Free drop, l = 2: period and damping against Rayleigh and Lamb, and their dependence on the amplitude"
    }
    fn source(&self) -> &'static str {
        "Rayleigh (1879); Lamb (1932) §275, §355 — a diagnostic of the model, not a paper check"
    }
    fn effects(&self) -> Option<DeclaredEffects> {
        Some(DeclaredEffects::FREE_DROP)
    }
    fn resolution(&self, f: Fidelity) -> String {
        let (r_over_l0, eps) = design(f);
        let why = match f {
            Fidelity::Smoke => "seconds per run, one amplitude",
            Fidelity::Standard => {
                "R/l0 = 10: where the lattice's elastic l = 2 frequency is expected to be comparable with the capillary one"
            }
            Fidelity::Paper => "R/l0 = 15: the trend with resolution",
        };
        format!(
            "R/l0 = {r_over_l0} (l0 = {:.4} mm), ε = {eps:?}; {why}.",
            RADIUS_M / r_over_l0 * 1e3
        )
    }
    fn runs(&self, f: Fidelity) -> Vec<RunSpec> {
        let (r_over_l0, amplitudes) = design(f);
        let l0 = RADIUS_M / r_over_l0;
        let period = nominal_period_s();
        let periods = if f == Fidelity::Smoke { 1.5 } else { 2.5 };
        amplitudes
            .into_iter()
            .map(|eps| {
                let (a, c) = (RADIUS_M / (1.0 + eps).sqrt(), RADIUS_M * (1.0 + eps));
                let scene = SceneBuilder::new(l0, sound_speed_for(&MATTE, l0, 0.0))
                    .time(periods * period, period / 100.0)
                    .paper_effects()
                    .liquid(&MATTE)
                    .body(
                        "drop",
                        MATTE.name,
                        BodyShape::Ellipsoid {
                            center: [0.0; 3],
                            semi_axes: [a, a, c],
                        },
                    )
                    .build();
                RunSpec {
                    id: format!("eps_{:.0}", eps * 100.0),
                    scene,
                    snapshot_times_s: vec![],
                }
            })
            .collect()
    }
    fn probe(&self, sim: &Simulation) -> Vec<(&'static str, f64)> {
        let p = &sim.particles;
        let points: Vec<[f64; 3]> = p.pos[..p.n_fluid].iter().map(|x| [x.x, x.y, x.z]).collect();
        vec![(Q2, axial_quadrupole_q2(&points))]
    }
    fn analyse(&self, f: Fidelity, runs: &[RunData], dir: &Path) -> anyhow::Result<Vec<Metric>> {
        analysis::analyse(self, f, runs, dir)
    }
}

impl Analysis for DropOscillation {
    type Measured<'r> = Vec<measure::DropRun<'r>>;

    fn measure<'r>(&self, _: Fidelity, runs: &'r [RunData]) -> anyhow::Result<Self::Measured<'r>> {
        Ok(runs.iter().map(measure::drop_run).collect())
    }

    fn judge(&self, _: Fidelity, measured: &Self::Measured<'_>) -> anyhow::Result<Vec<Metric>> {
        Ok(judge::metrics(self.name(), measured))
    }

    fn draw(&self, _: Fidelity, measured: &Self::Measured<'_>, dir: &Path) -> anyhow::Result<()> {
        draw::plots(measured, dir)
    }
}
