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
//! below [`crate::lattice::shifting_boundary_sum`] (halfway between the outer plane of a flat free surface of the
//! lattice and the plane below it), and every particle within one kernel support of such a
//! particle, is shifted only along the boundary: `δr ← (I − n n) δr` with `n` the direction
//! of its own-phase gradient `Σ_{j same phase} V_j ∇_i W_ij`.
//!
//! The velocity and density are not corrected for the displacement (a first-order
//! simplification; the summation density is recomputed at the new positions anyway).

use crate::kernel::Kernel;
use crate::neighbours::NeighbourLists;
use crate::state::Vec3;
use rayon::prelude::*;

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
/// [1/m³] is [`crate::lattice::shifting_boundary_sum`].
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
            for j in lists.near(i) {
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
        for j in lists.near(i) {
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
