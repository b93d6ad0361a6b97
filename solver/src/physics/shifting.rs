//! Particle shifting: a small displacement of each fluid particle down the gradient of the
//! particle concentration, added to the drift, that keeps the particle distribution uniform
//! as the liquid flows (Lind et al. 2012; the δ⁺-SPH form of Sun et al. 2017 without its
//! anti-clustering term).
//!
//! `δr_i = −A h U dt ∇C_i` with `∇C_i = Σ_j V_j ∇_i W_ij` over every neighbour in the kernel
//! support (fluid of any phase and wall particles: a wall completes the support, so it does
//! not pull a particle in), `U` the largest fluid speed [m/s], `dt` the step [s] and `A` the
//! scene's coefficient. `A = 4` is Sun et al.'s `CFL·Ma·(2h)²` (with `CFL = c dt/h`,
//! `Ma = U/c`). A liquid at rest is not shifted.
//!
//! Near a boundary of its phase (a free surface, another liquid or a wall) a particle's
//! concentration gradient is the boundary's, and moving down it would push the particle out
//! of its phase. So a particle whose own-phase kernel sum `W(0) + Σ_{j same phase} W_ij` is
//! below [`boundary_kernel_sum`] (halfway between the outer plane of a flat free surface of the
//! lattice and the plane below it), and every particle within one kernel support of such a
//! particle, is shifted only along the boundary: `δr ← (I − n n) δr` with `n` the direction
//! of its own-phase gradient `Σ_{j same phase} V_j ∇_i W_ij`.
//!
//! The velocity and density are not corrected for the displacement (a first-order
//! simplification; the summation density is recomputed at the new positions anyway).

use crate::kernel::Kernel;
use crate::lattice;
use crate::neighbours::NeighbourLists;
use crate::state::Vec3;
use rayon::prelude::*;

/// The own-phase kernel sum below which a particle is at a boundary of its phase [1/m³]:
/// halfway between the sums of the outer (001) plane of a flat free surface of the lattice and
/// of the plane below it. Relative to the bulk sum they are 0.72–0.91 and 0.96–1.00 for the
/// four kernels at `h = 1.05…1.3 l0` (the outer plane's in-plane neighbours and `W(0)` hold
/// most of the sum), so no single fraction suits every kernel.
pub fn boundary_kernel_sum<K: Kernel>(kernel: &K, l0_m: f64) -> f64 {
    0.5 * (lattice::half_space_kernel_sum(kernel, l0_m, 0)
        + lattice::half_space_kernel_sum(kernel, l0_m, 1))
}

/// What the first pass finds per fluid particle.
#[derive(Clone, Copy)]
struct Gradients {
    /// `Σ_j V_j ∇_i W_ij` over every neighbour [1/m].
    all: Vec3,
    /// The same over same-phase fluid neighbours [1/m].
    own: Vec3,
    /// Own-phase kernel sum `W(0) + Σ_{j same phase} W_ij` [1/m³].
    fill: f64,
}

/// The shifting displacement of every fluid particle [m], into `out` (length `n_fluid`):
/// `δr_i = −scale_m2 ∇C_i`, tangential near a boundary of the particle's phase (module doc).
/// `scale_m2 = A h U dt` [m²]. `vol` [m³] covers fluid and wall particles; `boundary_sum`
/// [1/m³] is [`boundary_kernel_sum`].
#[allow(clippy::too_many_arguments)]
pub fn displacements<K: Kernel>(
    kernel: &K,
    pos: &[Vec3],
    vol: &[f64],
    phase: &[u8],
    lists: &NeighbourLists,
    boundary_sum: f64,
    scale_m2: f64,
    out: &mut [Vec3],
) {
    let n_fluid = out.len();
    let support2 = kernel.support_m() * kernel.support_m();
    let w0 = kernel.w(0.0);
    let grads: Vec<Gradients> = (0..n_fluid)
        .into_par_iter()
        .map(|i| {
            let (pi, ph) = (pos[i], phase[i]);
            let mut g = Gradients {
                all: Vec3::zeros(),
                own: Vec3::zeros(),
                fill: w0,
            };
            for &j in lists.near(i) {
                let j = j as usize;
                let d = lists.delta(pi, pos[j]);
                let r2 = d.norm_squared();
                if r2 >= support2 || r2 == 0.0 {
                    continue;
                }
                let r = r2.sqrt();
                let grad = d * (vol[j] * kernel.dw_dr_inside(r) / r);
                g.all += grad;
                if j < n_fluid && phase[j] == ph {
                    g.own += grad;
                    g.fill += kernel.w_inside(r);
                }
            }
            g
        })
        .collect();
    out.par_iter_mut().enumerate().for_each(|(i, dr)| {
        let g = &grads[i];
        // the boundary's direction: the own-phase gradients of the particle's same-phase
        // neighbours, kernel-weighted, its own left out (on a free surface the particle's own
        // gradient is the very vector to be projected, and would leave nothing; the
        // neighbours' keep the boundary's direction without the particle's own disorder)
        let mut normal = Vec3::zeros();
        let mut near_boundary = g.fill < boundary_sum;
        for &j in lists.near(i) {
            let j = j as usize;
            if j >= n_fluid || phase[j] != phase[i] {
                continue;
            }
            let r2 = lists.delta(pos[i], pos[j]).norm_squared();
            if r2 < support2 && r2 > 0.0 {
                normal += grads[j].own * kernel.w_inside(r2.sqrt());
                near_boundary |= grads[j].fill < boundary_sum;
            }
        }
        let full = -scale_m2 * g.all;
        *dr = if !near_boundary {
            full
        } else {
            let norm = normal.norm();
            if norm > 0.0 {
                let n = normal / norm;
                full - n * n.dot(&full)
            } else {
                Vec3::zeros() // alone: no boundary direction, no shift
            }
        };
    });
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::{QuinticSpline, WendlandC2};
    use crate::neighbours::NeighbourSearch;

    /// A slab of `n × n × layers` lattice sites of spacing `l0` [m], unit volume fractions.
    fn slab(n: usize, layers: usize, l0: f64) -> Vec<Vec3> {
        let mut pos = Vec::new();
        for z in 0..layers {
            for y in 0..n {
                for x in 0..n {
                    pos.push(Vec3::new(x as f64, y as f64, z as f64) * l0);
                }
            }
        }
        pos
    }

    fn shifts<K: Kernel>(
        h_over_l0: f64,
        pos: &[Vec3],
        perturbed: Option<(usize, Vec3)>,
    ) -> Vec<Vec3> {
        let l0 = 1.0;
        let k = K::new(h_over_l0 * l0);
        let mut pos = pos.to_vec();
        if let Some((i, d)) = perturbed {
            pos[i] += d;
        }
        let boundary = boundary_kernel_sum(&k, l0);
        let vol = vec![l0 * l0 * l0; pos.len()];
        let phase = vec![0u8; pos.len()];
        let mut search = NeighbourSearch::new(k.support_m(), k.support_m(), 0.1 * l0);
        // the search wants positions sorted by cell; the shifts are returned in input order
        let perm = search.sort_order(&pos).unwrap();
        let sorted: Vec<Vec3> = perm.iter().map(|&i| pos[i as usize]).collect();
        search.build(&sorted, sorted.len()).unwrap();
        let mut out = vec![Vec3::zeros(); pos.len()];
        displacements(
            &k,
            &sorted,
            &vol,
            &phase,
            &search.lists,
            boundary,
            1.0,
            &mut out,
        );
        let mut back = vec![Vec3::zeros(); pos.len()];
        for (k, &i) in perm.iter().enumerate() {
            back[i as usize] = out[k];
        }
        back
    }

    #[test]
    fn a_slab_is_shifted_only_along_its_surfaces() {
        let (n, layers) = (9, 9);
        let pos = slab(n, layers, 1.0);
        let idx = |x: usize, y: usize, z: usize| (z * n + y) * n + x;
        // the top surface's centre particle, displaced sideways: pushed back towards its site,
        // along the surface (the normal is the neighbourhood's; 10 % of the shift allows for
        // the tilt the displaced particle gives its neighbours' gradients)
        let top = idx(4, 4, layers - 1);
        let out = shifts::<WendlandC2>(1.05, &pos, Some((top, Vec3::new(0.2, 0.0, 0.0))));
        assert!(out[top].x < 0.0, "{:?}", out[top]);
        assert!(out[top].z.abs() < 0.1 * out[top].x.abs(), "{:?}", out[top]);
        // a displaced interior particle (4 planes deep: beyond one support of any surface
        // particle) is pushed back towards its site in every direction
        let mid = idx(4, 4, 4);
        let out = shifts::<WendlandC2>(1.05, &pos, Some((mid, Vec3::new(0.1, 0.0, 0.1))));
        assert!(out[mid].x < 0.0 && out[mid].z < 0.0, "{:?}", out[mid]);
        // the undisturbed slab away from its side faces (4 sites from them, beyond the
        // quintic spline's support of 3.15): no shift at any depth, to round-off — the
        // surface planes' normal gradients are projected out
        let out = shifts::<QuinticSpline>(1.05, &pos, None);
        for z in 0..layers {
            let d = out[idx(4, 4, z)];
            assert!(d.norm() < 1e-12, "plane {z}: {d:?}");
        }
    }
}
