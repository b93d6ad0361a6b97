//! A shear wave in a periodic box: does the particle system flow like a liquid or ring like a
//! solid?
//!
//! A cube of slag fills a box periodic along x, y and z with side `L`; it starts on the
//! undisturbed lattice with the velocity `v_x = U sin(k z)`, `k = 2π/L`, and no pressure,
//! gravity or free surface. A Newtonian liquid's wave decays as `exp(−ν k² t)` without ever
//! reversing. A medium with a shear modulus `G` rings instead: `A'' + ν k² A' + (G/ρ) k² A = 0`
//! for the amplitude `A(t)` of the velocity's `sin(kz)` mode (Kelvin–Voigt), an oscillation of
//! angular frequency `√(G k²/ρ − (ν k²/2)²)` when `G` is large enough.
//!
//! Three runs: with the paper's effects (the pairwise potential and both viscosities); with
//! the viscosities alone — no potential, so no cohesive background pressure and no lattice
//! stress: that isolates the SPH viscous operator from the lattice's elasticity; and with the
//! paper's effects at the pressure a drop's interior carries (`density.background_pressure` =
//! the cohesive pressure `p_b` of the Born sums), whose pair forces add the pressure term of
//! the lattice's modulus. Measured from
//! `A(t)` (recorded at every output): the effective viscosity `ν_eff` against `μ/ρ` (the
//! artificial viscosity's `α1 h c/10`, 4 % of it here, is noted beside), and whether and how
//! fast the wave rings; beside them the shear modulus `G44` that the Born sums of the reference
//! lattice predict ([`crate::diagnostics::lattice_moduli`]) — for this wave, the relevant one.
//! The box keeps the lattice at its reference density, where the EOS pressure is zero, so only
//! the potential's term of the modulus acts here; a drop's interior adds the pressure term.
//!
//! Two more runs put an interface in the wave's way: the box is split at `z = 0` and `L/2`
//! into two slabs of liquids alike but for their names, with an interfacial tension between
//! them, once under the paper's potential and once under the continuum surface force
//! (docs/model.md §4b, at its own `h/l0`). The flow is parallel to the interfaces and its
//! shear is largest on them; flat interfaces stay flat, so a liquid pair's wave is the single
//! liquid's, `exp(−ν k² t)` without a reversal: an interface that resists shear, or
//! a tension model whose forces do not vanish on a flat sheared interface, shows as ringing,
//! as a ν_eff off μ/ρ, or as a wave that does not decay away (the whole run's decay, and the
//! rate left over the last quarter read as a Kelvin–Voigt modulus).

mod draw;
mod judge;
mod measure;

use super::analysis::{self, Analysis};
use super::convergence::HOST_MODELS;
use super::scene::{sound_speed_for, LiquidProps, SceneBuilder, SLAG};
use crate::diagnostics::lattice_moduli::lattice_elasticity;
use crate::suite::{Case, DeclaredEffects, Fidelity, Metric, RunData, RunSpec};
use solver::kernel::KernelKind;
use solver::scene::{BodyShape, SceneAxis, TensionModel, VelocityWave};
use solver::Simulation;
use std::path::Path;

/// The case.
pub struct ShearWave;

/// Side of the periodic box, one wavelength [m].
const BOX_M: f64 = 1.6e-3;
/// Velocity amplitude `U` [m/s]: the strain amplitude `k U/ω` stays below 1e-2 for the
/// ringing measured at the default setting (ω ≈ 670 rad/s) — small enough for the lattice not
/// to yield.
const AMPLITUDE_M_S: f64 = 1e-3;

/// The second liquid of the two-liquid runs: slag but for its name, so that the pair's wave
/// has the single liquid's reference.
const SLAG_B: LiquidProps = LiquidProps {
    name: "slag_b",
    ..SLAG
};
/// The interfacial tension between [`SLAG`] and [`SLAG_B`] [N/m]: slag's own surface tension,
/// so that the interface is as strong as the potential's cohesion in the bulk.
const INTERFACE_TENSION_N_M: f64 = SLAG.surface_tension_n_m;

/// How a run's liquid is made up.
#[derive(Clone, Copy)]
enum Fill {
    /// One liquid; with the potential or not, at the reference lattice's zero pressure or at
    /// a drop interior's `p_b`.
    One { potential: bool, interior: bool },
    /// Two slabs with an interface, under a tension model.
    TwoSlabs(TensionModel),
}

/// The runs: id and fill.
const RUNS: [(&str, Fill); 5] = [
    (
        "potential_and_viscosity",
        Fill::One {
            potential: true,
            interior: false,
        },
    ),
    (
        "viscosity_only",
        Fill::One {
            potential: false,
            interior: false,
        },
    ),
    (
        "potential_viscosity_and_p_b",
        Fill::One {
            potential: true,
            interior: true,
        },
    ),
    (
        "two_liquids_potential",
        Fill::TwoSlabs(TensionModel::Potential),
    ),
    (
        "two_liquids_surface_force",
        Fill::TwoSlabs(TensionModel::SurfaceForce),
    ),
];

/// Spacings per side and the run length [s] at a fidelity.
fn design(f: Fidelity) -> (usize, f64) {
    match f {
        // the smallest box the potential's cut-off allows (2 (r_e + skin) = 8.8 l0)
        Fidelity::Smoke => (10, 1.5e-3),
        // seventeen viscous decay times 1/(ν k²) of slag in this box (2.3 ms), four periods of
        // the ringing at the Born modulus: a liquid's wave is below 1 % of its start from
        // 10.5 ms on, and the last quarter (30–40 ms) reads a slow root if one is there, the
        // fast root's leftover 1.6e-6 of the start (the surface force's slabs, thinner than
        // its colour kernel's reach, held the wave at about 1 % from 18 ms on until a film's
        // opposite faces were left out of the curvature, docs/findings.md)
        Fidelity::Standard => (16, 40e-3),
        Fidelity::Paper => (24, 40e-3),
    }
}

/// Names of the probe columns: `(2/N) Σ v_x sin(k z)` and `(2/N) Σ v_x cos(k z)` [m/s].
const SINE: &str = "vx_sin_kz_m_s";
const COSINE: &str = "vx_cos_kz_m_s";

/// `scene` with the EOS pressure raised by the cohesive pressure `p_b` [Pa] a drop's interior
/// carries at its setting (the Born sums' `p_b`, in σ/l0 times σ/l0).
fn with_interior_pressure(mut scene: solver::Scene) -> solver::Scene {
    let d = &scene.discretisation;
    let e = lattice_elasticity(d.kernel, d.h_over_l0, d.re_over_l0, d.potential_order);
    scene.density.background_pressure = e.background_pressure * SLAG.surface_tension_n_m / d.l0;
    scene
}

/// The wave's velocity field.
fn wave() -> VelocityWave {
    VelocityWave {
        amplitude: [AMPLITUDE_M_S, 0.0, 0.0],
        along: SceneAxis::Z,
        wavelength: BOX_M,
    }
}

/// The periodic box of side [`BOX_M`] at spacing `l0` [m], run for `end` [s], filled as `fill`
/// says and moving with [`wave`].
fn wave_scene(l0: f64, end: f64, fill: Fill) -> solver::Scene {
    let b = SceneBuilder::new(l0, sound_speed_for(&SLAG, l0, 0.0))
        .time(end, 5e-5)
        .paper_effects()
        .liquid(&SLAG);
    let slab = |z0: f64, z1: f64| BodyShape::Box {
        min: [0.0, 0.0, z0],
        max: [BOX_M, BOX_M, z1],
    };
    let b = match fill {
        Fill::One { potential, .. } => {
            b.interfacial_tension(potential)
                .waving_body("box", SLAG.name, slab(0.0, BOX_M), wave())
        }
        Fill::TwoSlabs(model) => {
            let b = if model.is_potential() {
                b
            } else {
                // the continuum model at the kernel its drops and caps run at
                let m = HOST_MODELS
                    .into_iter()
                    .find(|m| m.model == model)
                    .expect("a continuum model of the convergence case");
                let re_over_l0 = b.scene().discretisation.re_over_l0;
                b.kernel(KernelKind::WendlandC2, m.h_over_l0, re_over_l0)
                    .tension_model(model)
            };
            b.liquid(&SLAG_B)
                .interface(SLAG.name, SLAG_B.name, INTERFACE_TENSION_N_M)
                .waving_body("lower", SLAG.name, slab(0.0, 0.5 * BOX_M), wave())
                .waving_body("upper", SLAG_B.name, slab(0.5 * BOX_M, BOX_M), wave())
        }
    };
    let scene = b.periodic_box([0.0; 3], [BOX_M; 3]).build();
    match fill {
        Fill::One { interior: true, .. } => with_interior_pressure(scene),
        _ => scene,
    }
}

impl Case for ShearWave {
    fn name(&self) -> &'static str {
        "shear_wave"
    }
    fn title(&self) -> &'static str {
        "Shear wave in a periodic box: viscous decay against ν k², and any elastic ringing"
    }
    fn source(&self) -> &'static str {
        "Newtonian shear-wave decay exp(−ν k² t) (e.g. Landau & Lifshitz, Fluid Mechanics §24); a diagnostic of the model, not a paper check"
    }
    fn effects(&self) -> Option<DeclaredEffects> {
        None
    }
    fn resolution(&self, f: Fidelity) -> String {
        let (n, end) = design(f);
        format!(
            "{n}³ particles, L = {} mm = {n} l0 (one wavelength), U = {AMPLITUDE_M_S} m/s, {} ms.",
            BOX_M * 1e3,
            end * 1e3
        )
    }
    fn runs(&self, f: Fidelity) -> Vec<RunSpec> {
        let (n, end) = design(f);
        let l0 = BOX_M / n as f64;
        RUNS.into_iter()
            .map(|(id, fill)| RunSpec {
                id: id.into(),
                scene: wave_scene(l0, end, fill),
                snapshot_times_s: vec![],
            })
            .collect()
    }
    fn probe(&self, sim: &Simulation) -> Vec<(&'static str, f64)> {
        let p = &sim.particles;
        let k = std::f64::consts::TAU / BOX_M;
        let (s, c) = measure::mode_amplitudes(
            p.pos[..p.n_fluid]
                .iter()
                .zip(&p.vel[..p.n_fluid])
                .map(|(x, v)| (x.z, v.x)),
            k,
        );
        vec![(SINE, s), (COSINE, c)]
    }
    fn analyse(&self, f: Fidelity, runs: &[RunData], dir: &Path) -> anyhow::Result<Vec<Metric>> {
        analysis::analyse(self, f, runs, dir)
    }
}

impl Analysis for ShearWave {
    type Measured<'r> = Vec<measure::WaveRun<'r>>;

    fn measure<'r>(&self, _: Fidelity, runs: &'r [RunData]) -> anyhow::Result<Self::Measured<'r>> {
        Ok(runs.iter().map(measure::wave_run).collect())
    }

    fn judge(&self, _: Fidelity, measured: &Self::Measured<'_>) -> anyhow::Result<Vec<Metric>> {
        Ok(judge::metrics(self.name(), measured))
    }

    fn draw(&self, _: Fidelity, measured: &Self::Measured<'_>, dir: &Path) -> anyhow::Result<()> {
        draw::plots(measured, dir)
    }
}
