//! Fixed wall particles (Adami, Hu & Adams 2012): pressure extrapolated from the fluid, density
//! from the EOS, and for no-slip walls a ghost velocity.

use super::eos::TaitEos;
use crate::kernel::Kernel;
use crate::neighbours::NeighbourLists;
use crate::state::{Particles, Vec3};
use rayon::prelude::*;

/// Updates pressure, density, volume and (no-slip) ghost velocity of every wall particle from
/// its fluid neighbours:
/// `p_w = (Σ_f p_f W_wf + g·Σ_f ρ_f r_wf W_wf) / Σ_f W_wf` (Adami et al. 2012, Eq. 27, fixed
/// wall), `ρ_w` from the EOS with the kernel-averaged reference density of the neighbours, and
/// `V_w = V0 ρ0_w/ρ_w`. No-slip walls get `v_w = −Σ_f v_f W_wf / Σ_f W_wf` (their own velocity
/// being zero). Walls without fluid neighbours are left at rest, `p = 0`.
#[allow(clippy::too_many_arguments)]
pub fn update<K: Kernel>(
    kernel: &K,
    eos: &TaitEos,
    p: &mut Particles,
    lists: &NeighbourLists,
    rho0: &[f64],
    rest_volume_m3: f64,
    gravity: Option<Vec3>,
    no_slip: &[bool],
) {
    let n_fluid = p.n_fluid;
    let (fluid_pos, wall_pos) = p.pos.split_at(n_fluid);
    let (fluid_vel, wall_vel) = p.vel.split_at_mut(n_fluid);
    let (fluid_p, wall_p) = p.pressure.split_at_mut(n_fluid);
    let (fluid_rho, wall_rho) = p.rho.split_at_mut(n_fluid);
    let wall_vol = &mut p.vol[n_fluid..];
    let phase = &p.phase;
    let g = gravity.unwrap_or_else(Vec3::zeros);
    let support2 = kernel.support_m() * kernel.support_m();
    wall_p
        .par_iter_mut()
        .zip(wall_rho.par_iter_mut())
        .zip(wall_vol.par_iter_mut())
        .zip(wall_vel.par_iter_mut())
        .enumerate()
        .for_each(|(k, (((pw, rw), vw), velw))| {
            let xw = wall_pos[k];
            let (mut sw, mut sp, mut srho0) = (0.0, 0.0, 0.0);
            let mut srx = Vec3::zeros();
            let mut sv = Vec3::zeros();
            for f in lists.near(n_fluid + k) {
                let r = lists.delta(xw, fluid_pos[f]);
                let r2 = r.norm_squared();
                if r2 >= support2 {
                    continue;
                }
                let w = kernel.w(r2.sqrt());
                sw += w;
                sp += fluid_p[f] * w;
                srx += r * (fluid_rho[f] * w);
                srho0 += rho0[phase[f] as usize] * w;
                sv += fluid_vel[f] * w;
            }
            if sw > 0.0 {
                *pw = (sp + g.dot(&srx)) / sw; // Adami et al. 2012, Eq. 27
                let rho0_w = srho0 / sw;
                *rw = eos.density(*pw, rho0_w);
                *vw = rest_volume_m3 * rho0_w / *rw;
                *velw = if no_slip[k] { -sv / sw } else { Vec3::zeros() };
            } else {
                *pw = 0.0;
                *vw = rest_volume_m3;
                *velw = Vec3::zeros();
            }
        });
}
