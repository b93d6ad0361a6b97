//! The surface tension the relaxed particle liquid really has, against the one typed in: a
//! periodic slab of each liquid of a scene, relaxed under the scene's own forces, its tension
//! from the pair-force virial ([`solver::simulation::calibration::slab_tension`]). `verify slab-tension`
//! prints it for any kernel, `h`, `r_e` and potential order.

use solver::kernel::KernelKind;
use solver::simulation::calibration::{slab_tension, SlabDesign};
use solver::Scene;
use std::fmt::Write;
use std::time::Instant;

/// One setting to measure: the scene's discretisation with these replaced.
#[derive(Clone, Copy, Debug)]
pub struct Setting {
    /// Kernel.
    pub kernel: KernelKind,
    /// `h/l0` [-].
    pub h_over_l0: f64,
    /// `r_e/l0` [-].
    pub re_over_l0: f64,
    /// Order of the potential's zero at `r_e`.
    pub order: u8,
}

/// A markdown table of `σ_KB/σ` for every liquid of `scene` at every setting.
pub fn table(scene: &Scene, settings: &[Setting], design: SlabDesign) -> anyhow::Result<String> {
    let mut out = String::from(
        "| kernel | h/l0 | r_e/l0 | m | liquid | σ typed (N/m) | σ_KB (N/m) | σ_KB/σ | ± (1 s.e.) | ρ_bulk/ρ0 | σ_KB/σ after one scaling by σ/σ_KB | particles | steps | wall s |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    for s in settings {
        let mut sc = scene.clone();
        let d = &mut sc.discretisation;
        d.kernel = s.kernel;
        d.h_over_l0 = s.h_over_l0;
        d.re_over_l0 = s.re_over_l0;
        d.potential_order = s.order;
        for liquid in 0..sc.liquids.len() {
            let t0 = Instant::now();
            let m = slab_tension(&sc, liquid, design, 1.0)?;
            let ratio = m.sigma_measured_n_m / m.sigma_typed_n_m;
            // what one scaling leaves: the response's nonlinearity (a run's calibration takes
            // secant steps until it is within tolerance, `calibrate_liquid`)
            let after = slab_tension(&sc, liquid, design, 1.0 / ratio)?;
            let residual = after.sigma_measured_n_m / after.sigma_typed_n_m;
            writeln!(
                out,
                "| {:?} | {} | {} | {} | {} | {} | {:.5} | {:.4} | {:.4} | {:.5} | {:.4} ± {:.4} | {} | {} | {:.1} |",
                s.kernel,
                s.h_over_l0,
                s.re_over_l0,
                s.order,
                m.liquid,
                m.sigma_typed_n_m,
                m.sigma_measured_n_m,
                ratio,
                m.sigma_standard_error_n_m / m.sigma_typed_n_m,
                m.bulk_density_ratio,
                residual,
                after.sigma_standard_error_n_m / after.sigma_typed_n_m,
                m.particles,
                m.steps,
                t0.elapsed().as_secs_f64()
            )?;
        }
    }
    Ok(out)
}
