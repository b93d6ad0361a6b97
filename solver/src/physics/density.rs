//! Density: number-density summation, and the re-initialisation filters of the continuity
//! density (docs/model.md §2).

use crate::kernel::Kernel;
use crate::neighbours::{NeighbourLists, ACTIVE_BITS};
use crate::state::Vec3;
use nalgebra::Vector4;
use rayon::prelude::*;

/// Summation density of fluid particles:
/// `ρ_i = ρ0_i (W(0) + Σ_j W_ij) / Σ_lattice W` (Eq. 6 of Natsui 2021 in number-density form,
/// calibrated so that the undisturbed lattice has exactly `ρ0`, docs/model.md §1–2). Every
/// neighbour counts, whatever its phase (walls complete the support), so density jumps between
/// phases are not smeared.
///
/// On the way it writes each particle's mask of interacting near entries into `active` (see
/// [`crate::neighbours::NeighbourSearch::active`]): those closer than `active_radius_m` [m]
/// (the larger of the kernel support and `r_e`).
#[allow(clippy::too_many_arguments)]
pub fn summation<K: Kernel>(
    kernel: &K,
    pos: &[Vec3],
    phase: &[u8],
    rho0: &[f64],
    lists: &NeighbourLists,
    lattice_sum: f64,
    active_radius_m: f64,
    rho_out: &mut [f64],
    active: &mut [u64],
) {
    let support2 = kernel.support_m() * kernel.support_m();
    let active2 = active_radius_m * active_radius_m;
    let w0 = kernel.w(0.0);
    const CHUNK: usize = 16;
    rho_out
        .par_iter_mut()
        .zip(active.par_iter_mut())
        .enumerate()
        .for_each_init(Vec::new, |near, (i, (rho, mask))| {
            lists.near(i).decode_into(near);
            let pi = pos[i];
            let mut s = w0;
            let mut bits = 0u64;
            // gather, evaluate W branch-free over the chunk (vectorisable), then add in list
            // order: the same sum, bit for bit, as a scalar loop
            for (c, chunk) in near.chunks(CHUNK).enumerate() {
                let mut r2 = [f64::INFINITY; CHUNK];
                if lists.periodic.is_periodic() {
                    for (k, &j) in chunk.iter().enumerate() {
                        r2[k] = lists.delta(pi, pos[j as usize]).norm_squared();
                    }
                } else {
                    for (k, &j) in chunk.iter().enumerate() {
                        r2[k] = (pi - pos[j as usize]).norm_squared();
                    }
                }
                let mut w = [0.0; CHUNK];
                for k in 0..CHUNK {
                    let v = kernel.w_inside(r2[k].min(support2).sqrt());
                    w[k] = if r2[k] < support2 { v } else { 0.0 };
                }
                for wk in &w[..chunk.len()] {
                    s += wk;
                }
                if c * CHUNK < ACTIVE_BITS {
                    let mut m = 0u64;
                    for (k, &d2) in r2.iter().enumerate() {
                        m |= u64::from(d2 < active2) << k;
                    }
                    bits |= m << (c * CHUNK);
                }
            }
            *rho = rho0[phase[i] as usize] * s / lattice_sum; // Eq. (6), Natsui 2021 (number density)
            *mask = bits;
        });
}

/// Same-phase fluid neighbours of `i` within the kernel support, self excluded:
/// `(x_i − x_j [m], W_ij [1/m³], j)`.
fn same_phase<'a, K: Kernel>(
    kernel: &'a K,
    pos: &'a [Vec3],
    phase: &'a [u8],
    lists: &'a NeighbourLists,
    n_fluid: usize,
    i: usize,
) -> impl Iterator<Item = (Vec3, f64, usize)> + 'a {
    let support2 = kernel.support_m() * kernel.support_m();
    let (pi, ph) = (pos[i], phase[i]);
    lists.near(i).filter_map(move |j| {
        if j >= n_fluid || phase[j] != ph {
            return None;
        }
        let d = lists.delta(pi, pos[j]);
        let r2 = d.norm_squared();
        (r2 < support2).then(|| (d, kernel.w(r2.sqrt()), j))
    })
}

/// Shepard filter (zeroth order, Colagrossi & Landrini 2003) over same-phase fluid neighbours:
/// `ρ_i = Σ_j m_j W_ij / Σ_j V_j W_ij`, self included.
pub fn shepard<K: Kernel>(
    kernel: &K,
    pos: &[Vec3],
    phase: &[u8],
    mass: &[f64],
    rho: &[f64],
    lists: &NeighbourLists,
    n_fluid: usize,
) -> Vec<f64> {
    let w0 = kernel.w(0.0);
    (0..n_fluid)
        .into_par_iter()
        .map(|i| {
            let m = mass[phase[i] as usize];
            let (mut num, mut den) = (m * w0, m / rho[i] * w0);
            for (_, w, j) in same_phase(kernel, pos, phase, lists, n_fluid, i) {
                num += m * w;
                den += m / rho[j] * w;
            }
            num / den
        })
        .collect()
}

/// First-order moving-least-squares filter (Colagrossi & Landrini 2003 §3.2) over same-phase
/// fluid neighbours: `ρ_i = Σ_j m_j W_ij (β0 + β·(x_i − x_j))` with `β = A⁻¹ e_1`,
/// `A = Σ_j V_j W_ij [1, x_ij][1, x_ij]ᵀ`. Where `A` is near-singular (a particle with few
/// neighbours, e.g. at a free surface) it falls back to the Shepard value.
#[allow(clippy::too_many_arguments)]
pub fn mls<K: Kernel>(
    kernel: &K,
    pos: &[Vec3],
    phase: &[u8],
    mass: &[f64],
    rho: &[f64],
    lists: &NeighbourLists,
    n_fluid: usize,
    l0: f64,
) -> Vec<f64> {
    let w0 = kernel.w(0.0);
    // coordinates scaled by l0 keep A well conditioned
    let basis = |d: Vec3| Vector4::new(1.0, d.x / l0, d.y / l0, d.z / l0);
    (0..n_fluid)
        .into_par_iter()
        .map(|i| {
            let m = mass[phase[i] as usize];
            let mut a = basis(Vec3::zeros()) * basis(Vec3::zeros()).transpose() * (m / rho[i] * w0);
            let mut shep = (m * w0, m / rho[i] * w0);
            for (d, w, j) in same_phase(kernel, pos, phase, lists, n_fluid, i) {
                let b = basis(d);
                a += b * b.transpose() * (m / rho[j] * w);
                shep.0 += m * w;
                shep.1 += m / rho[j] * w;
            }
            // relative determinant test: a free-surface particle's moment matrix is nearly
            // singular in the normal direction; 1e-3 of the bulk-lattice scale is a safe floor
            let scale = a[(0, 0)].powi(4);
            let inv = if a.determinant().abs() > 1e-3 * scale {
                a.try_inverse()
            } else {
                None
            };
            match inv {
                Some(inv) => {
                    let beta: Vector4<f64> = inv.column(0).into_owned();
                    let mut num = m * w0 * beta[0];
                    for (d, w, _) in same_phase(kernel, pos, phase, lists, n_fluid, i) {
                        num += m * w * beta.dot(&basis(d));
                    }
                    num
                }
                None => shep.0 / shep.1,
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    //! Re-initialisation filters: Shepard reproduces a constant field and MLS a linear one,
    //! also at a free surface where the plain summation falls short.
    use super::*;
    use crate::kernel::WendlandC2;
    use crate::neighbours::NeighbourSearch;

    /// A 9³ lattice block (spacing 1e-4 m), sorted and with lists built.
    fn block() -> (Vec<Vec3>, NeighbourLists, WendlandC2) {
        let l0 = 1e-4;
        let k = WendlandC2::new(1.3 * l0);
        let mut pos = Vec::new();
        for z in 0..9 {
            for y in 0..9 {
                for x in 0..9 {
                    pos.push(Vec3::new(x as f64, y as f64, z as f64) * l0);
                }
            }
        }
        let mut s = NeighbourSearch::new(k.support_m(), k.support_m(), 0.0);
        let perm = s.sort_order(&pos).unwrap();
        let pos: Vec<Vec3> = perm.iter().map(|&i| pos[i as usize]).collect();
        s.build(&pos, pos.len()).unwrap();
        (pos, s.lists, k)
    }

    #[test]
    fn shepard_keeps_a_uniform_density_everywhere() {
        let (pos, lists, k) = block();
        let n = pos.len();
        let phase = vec![0u8; n];
        let rho = vec![1000.0; n];
        let mass = [1000.0 * 1e-12];
        let out = shepard(&k, &pos, &phase, &mass, &rho, &lists, n);
        // a weighted mean of equal values: exact up to the rounding of the sums (1e-13)
        assert!(out.iter().all(|r| (r / 1000.0 - 1.0).abs() < 1e-13));
        // while the plain summation is 30 % short at a corner of the block
        let mut summ = vec![0.0; n];
        // the calibration: Σ W at the block's centre, a bulk site (4 l0 from every face)
        let centre = Vec3::repeat(4e-4);
        let lattice: f64 = pos.iter().map(|p| k.w((p - centre).norm())).sum();
        let mut active = vec![0; n];
        let support = k.support_m();
        summation(
            &k,
            &pos,
            &phase,
            &[1000.0],
            &lists,
            lattice,
            support,
            &mut summ,
            &mut active,
        );
        assert!(summ.iter().fold(f64::INFINITY, |a, &b| a.min(b)) < 800.0);
    }

    #[test]
    fn mls_reproduces_a_linear_density_field_up_to_the_free_surface() {
        // ρ_MLS,i = Σ_j m_j W^MLS_ij = Σ_j V_j ρ_j W^MLS_ij with V_j = m_j/ρ_j, the volumes the
        // moment matrix is built with; first-order MLS reproduces linear fields exactly, so a
        // linear ρ comes back to round-off (1e-13 relative), at the block's faces too — where
        // the plain summation is short. Only where A is singular (edges, corners) may it fall
        // back to Shepard.
        let (pos, lists, k) = block();
        let n = pos.len();
        let phase = vec![0u8; n];
        let rho: Vec<f64> = pos
            .iter()
            .map(|p| 1000.0 * (1.0 + 0.05 * p.x / 8e-4))
            .collect();
        let mass = [1000.0 * 1e-12];
        let out = mls(&k, &pos, &phase, &mass, &rho, &lists, n, 1e-4);
        let on_edge = |p: &Vec3| (0..3).filter(|&a| p[a] < 0.5e-4 || p[a] > 7.5e-4).count() >= 2;
        let mut worst: f64 = 0.0;
        for (i, p) in pos.iter().enumerate() {
            if !on_edge(p) {
                worst = worst.max((out[i] / rho[i] - 1.0).abs());
            }
        }
        assert!(worst < 1e-13, "MLS error {worst}");
    }
}
