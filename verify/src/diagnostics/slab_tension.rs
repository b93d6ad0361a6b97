//! The surface tension the relaxed particle liquid really has, against the one typed in: a
//! periodic slab of each liquid of a scene, relaxed under the scene's own forces, its tension
//! from the pair-force virial ([`solver::simulation::calibration::slab_tension`]). `verify slab-tension`
//! prints it for any kernel, `h`, `r_e` and potential order.

use solver::kernel::KernelKind;
use solver::simulation::calibration::{pair_slab_tension, slab_tension, SlabDesign};
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

/// A markdown table of `σ_KB/σ` for every liquid of `scene` at every setting, and one of the
/// interfacial tension of every pair of liquids with adhesion (a two-liquid slab at the
/// lattice's coefficients, less the liquids' measured free surfaces).
pub fn table(scene: &Scene, settings: &[Setting], design: SlabDesign) -> anyhow::Result<String> {
    let mut out = String::from(
        "| kernel | h/l0 | r_e/l0 | m | liquid | σ typed (N/m) | σ_KB (N/m) | σ_KB/σ | ± (1 s.e.) | ρ_bulk/ρ0 | σ_KB/σ after one scaling by σ/σ_KB | particles | steps | wall s |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    let mut pairs = String::new();
    for s in settings {
        let mut sc = scene.clone();
        let d = &mut sc.discretisation;
        d.kernel = s.kernel;
        d.h_over_l0 = s.h_over_l0;
        d.re_over_l0 = s.re_over_l0;
        d.potential_order = s.order;
        let mut free = Vec::new();
        for liquid in 0..sc.liquids.len() {
            let t0 = Instant::now();
            let m = slab_tension(&sc, liquid, design, 1.0)?;
            free.push(m.sigma_measured_n_m);
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
        let table = solver::Model::from_scene(&sc)?.pairs;
        for a in 0..sc.liquids.len() {
            for b in a + 1..sc.liquids.len() {
                if table.sigma(a, b) <= 0.0 {
                    continue;
                }
                let t0 = Instant::now();
                let m = pair_slab_tension(&sc, (a, b), design, [1.0; 2], 1.0, [free[a], free[b]])?;
                pairs.push_str(&format!(
                    "| {:?} | {} | {} | {} | {} / {} | {} | {:.5} | {:.4} | {:.5} | {} | {} | {:.1} |\n",
                    s.kernel,
                    s.h_over_l0,
                    s.re_over_l0,
                    s.order,
                    m.liquids[0],
                    m.liquids[1],
                    m.sigma_typed_n_m,
                    m.sigma_measured_n_m,
                    m.sigma_measured_n_m / m.sigma_typed_n_m,
                    m.sigma_standard_error_n_m,
                    m.particles,
                    m.steps,
                    t0.elapsed().as_secs_f64()
                ));
            }
        }
    }
    if !pairs.is_empty() {
        out.push_str("\nPairs of liquids (their slab's total excess less the two liquids' measured surface tensions):\n\n| kernel | h/l0 | r_e/l0 | m | liquids | σ_ab typed (N/m) | σ_ab relaxed (N/m) | ratio | ± (1 s.e., N/m) | particles | steps | wall s |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n");
        out.push_str(&pairs);
    }
    Ok(out)
}
