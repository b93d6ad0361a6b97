//! The shear wave's metrics: per run the effective viscosity against the liquid's, from the
//! first samples and from the whole run, the number of reversals (a liquid's: none), for a
//! ringing run the shear modulus it implies beside the Born modulus of the setting's reference
//! lattice, and for a wave that neither reverses nor decays into the noise the rate left over
//! the last quarter with the modulus it implies.

use super::measure::{Response, WaveRun};
use crate::cases::scene::{artificial_viscosity_m2_s, SLAG};
use crate::diagnostics::lattice_moduli::lattice_elasticity;
use crate::suite::{Metric, Tolerance};

/// The liquid model's target for the shear wave's decay (README, "Targets of the liquid
/// model").
const DECAY_TARGET: f64 = 0.10;

/// The kinematic viscosity the run's liquid should show [m²/s], `μ/ρ`, and the artificial
/// viscosity's estimate `α1 h c/10` (Monaghan 1992) — an estimate for compressive flows: it
/// acts only on approaching pairs, and a shear wave does not compress.
pub fn reference_viscosity_m2_s(m: &WaveRun) -> (f64, f64) {
    let scene = &m.run.info.scene;
    let nu = SLAG.viscosity_pa_s / SLAG.density_kg_m3;
    (nu, artificial_viscosity_m2_s(scene))
}

/// Every metric of the case.
pub fn metrics(case: &str, runs: &[WaveRun]) -> Vec<Metric> {
    runs.iter().flat_map(|m| run_metrics(case, m)).collect()
}

fn run_metrics(case: &str, m: &WaveRun) -> Vec<Metric> {
    let id = &m.run.id;
    let status = m.run.status_note();
    let (nu_ref, nu_av) = reference_viscosity_m2_s(m);
    let k2 = m.k_per_m * m.k_per_m;
    let nu_initial = m.initial_rate_per_s / k2;
    let whole = m.response.viscosity_m2_s(m.k_per_m);
    let response = match &m.response {
        Response::Decay { .. } => format!("whole run: exponential decay, ν = {whole:.3e} m²/s"),
        Response::Ringing(f) => format!(
            "whole run: damped oscillation, period {:.3} ms, Kelvin–Voigt ν = {whole:.3e} m²/s",
            f.period_s * 1e3
        ),
        Response::Unmeasured(e) => format!("whole run not measured: {e}"),
    };
    let mut out = vec![
        Metric::new(case, format!("{id}: ν_eff / ν"), "-", nu_initial / nu_ref)
            .against(
                1.0,
                Tolerance::relative(
                    DECAY_TARGET,
                    1.0,
                    "10 %: the liquid model's target for the shear wave's decay",
                ),
            )
            .run(m.run)
            .note(format!(
                "{status}ν_eff = −A'(0)/(A(0) k²) = {nu_initial:.3e} m²/s (unaffected by elasticity: the strain is 0 at the start) against ν = μ/ρ = {nu_ref:.3e} m²/s (the artificial viscosity's α1 h c/10 = {nu_av:.2e} m²/s is an estimate for compressive flows)"
            )),
        Metric::new(case, format!("{id}: whole-run ν / ν"), "-", whole / nu_ref)
            .against(
                1.0,
                Tolerance::relative(
                    DECAY_TARGET,
                    1.0,
                    "10 %: the liquid model's target for the shear wave's decay, which a liquid keeps for the whole run",
                ),
            )
            .run(m.run)
            .note(format!(
                "{status}{response}, against ν = μ/ρ = {nu_ref:.3e} m²/s: where ν_eff reads the first samples only, this reads the decay of the whole run (a decay: ln A(t) fitted over the samples above 1 % of A(0); a ringing: the damped cosine's rate γ as 2γ/k²)"
            )),
        Metric::new(case, format!("{id}: reversals of A(t)"), "-", m.reversals as f64)
            .against(
                0.0,
                Tolerance::absolute(0.5, "a liquid's shear wave decays without reversing"),
            )
            .run(m.run)
            .note(format!("{status}sign changes of the sin(kz) velocity mode above 0.1 % of its start")),
    ];
    if let (Response::Decay { .. }, Some(late)) = (&m.response, m.late_rate_per_s) {
        out.push(late_rate(case, m, late, m.initial_rate_per_s));
    }
    if let (Response::Ringing(f), Some(w_el)) = (&m.response, m.response.elastic_frequency_rad_s())
    {
        out.push(
            Metric::new(
                case,
                format!("{id}: ringing frequency"),
                "Hz",
                1.0 / f.period_s,
            )
            .run(m.run)
            .note(format!(
                "{status}damped-cosine fit of A(t); a liquid's: none"
            )),
        );
        out.push(shear_modulus(case, m, w_el));
    }
    out
}

/// The decay rate of a wave that stays above 1 % of its start over the run's last quarter
/// (information: a liquid's decays at `ν k²` into the noise), with the Kelvin–Voigt modulus its
/// slow root implies. Such a medium, `A'' + ν k² A' + (G k²/ρ) A = 0` started at zero strain,
/// has the rates `s_f`, `s_s` of its two roots add up to `ν k²` (the initial rate) and multiply
/// to `G k²/ρ`, so the slow one gives `G = ρ s_s (ν k² − s_s)/k²`. A positive `G` makes `A`
/// reverse (a ringing, or an overdamped swing through zero); a wave that neither reverses nor
/// decays into the noise has a growing slow root (`s_s < 0`), a negative `G`: the medium drives
/// the shear on.
fn late_rate(case: &str, m: &WaveRun, late: f64, initial: f64) -> Metric {
    let scene = &m.run.info.scene;
    let unit = SLAG.surface_tension_n_m / scene.discretisation.l0;
    let k2 = m.k_per_m * m.k_per_m;
    let g_pa = SLAG.density_kg_m3 * late * (initial - late) / k2;
    Metric::new(
        case,
        format!("{}: late decay rate of A(t)", m.run.id),
        "1/s",
        late,
    )
    .run(m.run)
    .note(format!(
        "{}ln A(t) over the run's last quarter, where A stays above 1 % of A(0); a liquid's: ν k² = {:.0} 1/s, fallen into the noise by then. As the slow root of a Kelvin–Voigt medium with the initial rate {initial:.0} 1/s: G = ρ s_s (ν k² − s_s)/k² = {g_pa:.3} Pa = {:.2e} σ/l0{}",
        m.run.status_note(),
        reference_viscosity_m2_s(m).0 * k2,
        g_pa / unit,
        if late < 0.0 {
            " (negative: the wave grows back, the medium drives the shear on)"
        } else {
            ""
        }
    ))
}

/// The shear modulus `G = ρ ω_el²/k²` a ringing run implies, in σ/l0, beside the Born `G44`
/// of the setting's reference lattice (information: a liquid has neither). The periodic box
/// holds the lattice at its reference density, where the EOS pressure is zero: only the
/// potential's term applies. A drop's interior is compressed until the EOS carries the
/// cohesive pressure `p_b`, which adds the pressure term (stated beside).
fn shear_modulus(case: &str, m: &WaveRun, w_el: f64) -> Metric {
    let scene = &m.run.info.scene;
    let d = &scene.discretisation;
    let unit = SLAG.surface_tension_n_m / d.l0;
    let g = SLAG.density_kg_m3 * w_el * w_el / (m.k_per_m * m.k_per_m) / unit;
    let e = lattice_elasticity(d.kernel, d.h_over_l0, d.re_over_l0, d.potential_order);
    let born = if scene.density.background_pressure != 0.0 {
        format!(
            "Born G44 of the reference lattice at the box's state (lattice density, the EOS pressure raised by p_b = {:.3} σ/l0 as in a drop's interior): potential {:.3} + pressure term {:+.3} = {:.3} σ/l0",
            scene.density.background_pressure / unit,
            e.potential.g44,
            e.pressure.g44,
            e.total().g44
        )
    } else if scene.effects.interfacial_tension.is_potential() {
        format!(
            "Born G44 of the reference lattice at the box's state (lattice density, zero pressure: the potential's term, r_e = {} l0): {:.3} σ/l0; in a drop's interior, where the EOS carries p_b = {:.3} σ/l0 ({} at h = {} l0), the pressure term adds {:+.3}",
            d.re_over_l0,
            e.potential.g44,
            e.background_pressure,
            d.kernel.name(),
            d.h_over_l0,
            e.pressure.g44
        )
    } else {
        "no potential: the reference lattice carries no stress, its Born moduli are 0".into()
    };
    Metric::new(
        case,
        format!("{}: shear modulus from the ringing", m.run.id),
        "σ/l0",
        g,
    )
    .run(m.run)
    .note(format!(
        "ρ ω_el²/k² with ω_el = √(ω² + γ²) = {w_el:.1} rad/s; {born}"
    ))
}
