//! The oscillating drop's metrics: per amplitude the period against Rayleigh's and the damping
//! against Lamb's, across amplitudes their spread, and the Born moduli of the setting's lattice.

use super::measure::DropRun;
use crate::analytic::lamb;
use crate::cases::scene::{artificial_viscosity_m2_s, MATTE};
use crate::diagnostics::lattice_moduli::lattice_elasticity;
use crate::measure::oscillation::spread_percent;
use crate::suite::{Metric, Tolerance};

/// The liquid model's target for the period of a small-amplitude oscillation: a liquid's period
/// is set by σ, ρ and R alone (docs/findings.md, "Targets of the liquid model").
const PERIOD_TARGET: f64 = 0.03;
/// The liquid model's target for the damping (docs/findings.md, "Targets of the liquid model").
const DAMPING_TARGET: f64 = 0.30;

/// Rayleigh's period and Lamb's damping of a run's drop.
pub struct Reference {
    /// Rayleigh's l = 2 period for the equal-volume radius [s].
    pub period_s: f64,
    /// Lamb's l = 2 amplitude decay rate with ν = μ/ρ + α1 h c/10 [1/s].
    pub damping_per_s: f64,
    /// The same with the physical viscosity alone [1/s].
    pub physical_damping_per_s: f64,
    /// The artificial viscosity's kinematic viscosity α1 h c/10 [m²/s].
    pub nu_av_m2_s: f64,
}

/// The references of a run.
pub fn reference(m: &DropRun) -> Reference {
    let scene = &m.run.info.scene;
    let nu = MATTE.viscosity_pa_s / MATTE.density_kg_m3;
    // the artificial viscosity's effective ν ≈ α h c/10 (Monaghan 1992; docs/model.md §3)
    let nu_av = artificial_viscosity_m2_s(scene);
    Reference {
        period_s: lamb::lamb_period(
            2,
            MATTE.surface_tension_n_m,
            MATTE.density_kg_m3,
            m.radius_m,
        ),
        damping_per_s: lamb::lamb_damping_rate(2, nu + nu_av, m.radius_m),
        physical_damping_per_s: lamb::lamb_damping_rate(2, nu, m.radius_m),
        nu_av_m2_s: nu_av,
    }
}

/// Every metric of the case.
pub fn metrics(case: &str, runs: &[DropRun]) -> Vec<Metric> {
    let mut out: Vec<Metric> = runs.iter().flat_map(|m| run_metrics(case, m)).collect();
    out.extend(spread(case, runs));
    if let Some(m) = runs.first() {
        out.extend(lattice(case, m));
    }
    out
}

/// Period and damping of one run.
fn run_metrics(case: &str, m: &DropRun) -> Vec<Metric> {
    let r = reference(m);
    let (period, gamma) = m.oscillation.period_and_damping();
    let eps = m.amplitude;
    let status = m.run.status_note();
    let fit_note = match &m.oscillation.fit {
        Ok(f) => format!(
            "damped-cosine fit of Q2 over the run, amplitude {:.3}, rms residual {:.1e}",
            f.amplitude, f.rms_residual
        ),
        Err(e) => format!("fit failed: {e}"),
    };
    let t_ms = r.period_s * 1e3;
    vec![
        Metric::new(case, format!("period ε={eps:.2}"), "ms", period * 1e3)
            .against(
                t_ms,
                Tolerance::relative(PERIOD_TARGET, t_ms, "3 %: the liquid model's target for a small-amplitude period"),
            )
            .run(m.run)
            .note(format!(
                "{status}{fit_note}; Rayleigh's l = 2 period for R = {:.4} mm (the drop's volume)",
                m.radius_m * 1e3
            )),
        Metric::new(case, format!("damping ε={eps:.2}"), "1/s", gamma)
            .against(
                r.damping_per_s,
                Tolerance::relative(
                    DAMPING_TARGET,
                    r.damping_per_s,
                    "30 %: the liquid model's target for the damping (the artificial viscosity's ν is itself an estimate)",
                ),
            )
            .run(m.run)
            .note(format!(
                "{status}Lamb's 5ν/R² with ν = μ/ρ + α1 h c/10 = {:.2e} + {:.2e} m²/s (physical alone: {:.2} 1/s)",
                MATTE.viscosity_pa_s / MATTE.density_kg_m3,
                r.nu_av_m2_s,
                r.physical_damping_per_s
            )),
    ]
}

/// How much the period and the damping change across the amplitudes: (max − min)/mean [%].
fn spread(case: &str, runs: &[DropRun]) -> Vec<Metric> {
    let fitted: Vec<(f64, f64)> = runs
        .iter()
        .map(|m| m.oscillation.period_and_damping())
        .filter(|(p, g)| p.is_finite() && g.is_finite())
        .collect();
    if fitted.len() < 2 || fitted.len() < runs.len() {
        return Vec::new();
    }
    let amplitudes: Vec<String> = runs.iter().map(|m| format!("{:.2}", m.amplitude)).collect();
    let note = format!(
        "(max − min)/mean over ε = {}; a liquid's is 0",
        amplitudes.join(", ")
    );
    vec![
        Metric::new(
            case,
            "period spread over amplitudes",
            "%",
            spread_percent(&fitted.iter().map(|f| f.0).collect::<Vec<_>>()),
        )
        .against(
            0.0,
            Tolerance::absolute(100.0 * PERIOD_TARGET, "3 %: as the period"),
        )
        .note(note.clone()),
        Metric::new(
            case,
            "damping spread over amplitudes",
            "%",
            spread_percent(&fitted.iter().map(|f| f.1).collect::<Vec<_>>()),
        )
        .against(
            0.0,
            Tolerance::absolute(100.0 * DAMPING_TARGET, "30 %: as the damping"),
        )
        .note(note),
    ]
}

/// The Born shear moduli of the run's setting (information beside the results).
fn lattice(case: &str, m: &DropRun) -> Vec<Metric> {
    let d = &m.run.info.scene.discretisation;
    let e = lattice_elasticity(d.kernel, d.h_over_l0, d.re_over_l0, d.potential_order);
    let t = e.total();
    let note = format!(
        "reference lattice of {} at h = {} l0, r_e = {} l0, potential + pressure term at p_b = {:.3} σ/l0 (a liquid: 0)",
        d.kernel.name(),
        d.h_over_l0,
        d.re_over_l0,
        e.background_pressure
    );
    vec![
        Metric::new(case, "lattice shear modulus G44", "σ/l0", t.g44).note(note.clone()),
        Metric::new(case, "lattice shear modulus C′", "σ/l0", t.c_prime).note(note),
    ]
}
