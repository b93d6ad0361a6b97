//! The virial of the liquid: the mechanical stress the particle system carries, from which a
//! periodic slab's surface tension follows (Kirkwood & Buff 1949).
//!
//! For central pair forces `F_ij` (on `i` from `j`, along `x_ij = x_i − x_j`) the pressure
//! tensor of a volume `V` is `P V = Σ_i m_i v_i ⊗ v_i + Σ_{i<j} x_ij ⊗ F_ij` (Irving &
//! Kirkwood 1950). The conservative pair forces of the liquid are central: the potential's
//! `C_ij P'(r) e_ij` and the pressure's `−(p_i V_i² + p_j V_j²) ∇_i W_ij`. The dissipative
//! ones vanish at rest and are left out; wall forces are external to the liquid and left out
//! too (the tensor is meant for scenes without walls).

use crate::kernel::Kernel;
use crate::model::Model;
use crate::neighbours::NeighbourLists;
use crate::state::Particles;

/// Each fluid particle's share of the liquid's virial [J] (row-major 3×3): `m_i v_i ⊗ v_i +
/// ½ Σ_j x_ij ⊗ F_ij`, half of each pair to each particle. Their sum is the virial
/// `W_αβ = Σ_i m_i v_iα v_iβ + Σ_{i<j} x_ijα F_ijβ`; divided by a volume, the pressure tensor.
/// Summed in neighbour-list order: the same bits for any thread count.
pub fn particle_virials<K: Kernel>(
    model: &Model,
    p: &Particles,
    lists: &NeighbourLists,
) -> Vec<[f64; 9]> {
    let kernel = K::new(model.h_m);
    let support2 = model.support_m * model.support_m;
    let r_e2 = model.r_e_m * model.r_e_m;
    let tension = model.effects.interfacial_tension;
    let mut out = vec![[0.0; 9]; p.n_fluid];
    for i in 0..p.n_fluid {
        let a = p.phase[i] as usize;
        let m = model.mass[a];
        let v = p.vel[i];
        let pv_i = p.pressure[i] * p.vol[i] * p.vol[i];
        for r in 0..3 {
            for c in 0..3 {
                out[i][3 * r + c] += m * v[r] * v[c];
            }
        }
        let near = lists.near(i).map(|j| (j, false));
        for (j, far) in near.chain(lists.far(i).map(|j| (j, true))) {
            if j >= p.n_fluid {
                continue;
            }
            let d = lists.delta(p.pos[i], p.pos[j]);
            let r2 = d.norm_squared();
            if r2 == 0.0 {
                continue;
            }
            let r = r2.sqrt();
            // the force on i along x_ij per metre of x_ij [N/m]
            let mut f = 0.0;
            if tension && r2 < r_e2 {
                let c = model.pairs.c(a, p.phase[j] as usize);
                f += model.potential.pair_force_inside(c, r) / r; // Eq. (15), Natsui 2021
            }
            if r2 < support2 {
                let pv_j = p.pressure[j] * p.vol[j] * p.vol[j];
                f -= (pv_i + pv_j) * kernel.dw_dr(r) / r; // Eq. (11), Natsui 2021
            }
            // half of the pair to each particle: a near pair is in both lists (its half to i
            // here), a far pair in i's only (a half to each here)
            for r in 0..3 {
                for c in 0..3 {
                    let half = 0.5 * d[r] * d[c] * f;
                    out[i][3 * r + c] += half;
                    if far {
                        out[j][3 * r + c] += half;
                    }
                }
            }
        }
    }
    out
}
