//! The continuum surface stress (CSS) between liquid phases: Lafaurie et al. 1994's capillary
//! stress `Π = σ_ab (|∇c| I − ∇c ∇cᵀ/|∇c|)` in the pair form of Hu & Adams 2006
//! (docs/model.md §4a). A liquid by construction: the stress lives only where another phase is
//! within the colour kernel, so a bulk has no pair stiffness at all.
//!
//! Per fluid particle `i` of phase `a` and every other liquid `b` with `σ_ab > 0`:
//! - the colour gradient of `b`, `G_i^b = Σ_{j∈b} V_j ∇_i W_c(r_ij)` [1/m] (pointing into `b`);
//! - the stress `T_i = Σ_b σ_ab (|G_i^b| I − G_i^b G_i^bᵀ/|G_i^b|)` [N/m²];
//! - the force `F_i = Σ_j V_i V_j (T_i + T_j) · ∇_i W_c(r_ij)` [N], so `F_ji = −F_ij`: linear
//!   momentum is conserved exactly (angular momentum is not: the pair force is not central).
//!
//! `W_c` is the run's kernel with its support stretched to the tension's cut-off `r_e` (the
//! colour kernel: the 2D prototypes paired with the pressure's narrow kernel, docs/findings.md).
//! Both sums run over every pair once ([`each_pair_once`]: the near part of the lists with
//! `j > i`, then the far part), so the bits do not depend on the thread count. Walls take no
//! part (the model has no contact angles yet; validation keeps walls out).

use crate::kernel::Kernel;
use crate::neighbours::NeighbourLists;
use crate::physics::forces::pairs_once::{each_pair_once, Reactions, Spills};
use crate::state::Vec3;
use rayon::prelude::*;

/// A symmetric 3×3 tensor `[xx, yy, zz, xy, xz, yz]` [N/m²].
pub type SymTensor = [f64; 6];

/// `s · v` for a symmetric tensor `s`.
#[inline(always)]
fn apply(s: &SymTensor, v: Vec3) -> Vec3 {
    Vec3::new(
        s[0] * v.x + s[3] * v.y + s[4] * v.z,
        s[3] * v.x + s[1] * v.y + s[5] * v.z,
        s[4] * v.x + s[5] * v.y + s[2] * v.z,
    )
}

/// `σ (|g| I − g gᵀ/|g|)` [N/m²] for a colour gradient `g` [1/m] and a tension `σ` [N/m]: the
/// capillary stress of one interface at a particle (zero for `g = 0`).
#[inline]
pub fn capillary_stress(sigma_n_m: f64, g: Vec3) -> SymTensor {
    let a = g.norm();
    if a == 0.0 {
        return [0.0; 6];
    }
    let s = sigma_n_m / a;
    [
        s * (a * a - g.x * g.x), // Lafaurie et al. 1994: σ |∇c| (I − n n)
        s * (a * a - g.y * g.y),
        s * (a * a - g.z * g.z),
        -s * g.x * g.y,
        -s * g.x * g.z,
        -s * g.y * g.z,
    ]
}

/// What the surface stress reads of the particles (fluid first, `n_fluid` of them; walls
/// after, ignored).
#[derive(Clone, Copy, Debug)]
pub struct StressInput<'a, K: Kernel> {
    /// The colour kernel (support `r_e`).
    pub kernel: K,
    /// Positions [m].
    pub pos: &'a [Vec3],
    /// Volumes `m/ρ` [m³].
    pub vol: &'a [f64],
    /// Phase per particle.
    pub phase: &'a [u8],
    /// Number of fluid particles.
    pub n_fluid: usize,
    /// Neighbour lists whose far radius covers the colour kernel's support.
    pub lists: &'a NeighbourLists,
}

impl<K: Kernel> StressInput<'_, K> {
    /// Calls `pair(j, ∇_i W_c(r_ij) [1/m⁴], r_ij [m])` for every fluid `j > i` within the colour
    /// kernel's support for which `wanted(j)`, in list order (the near part's `j > i`, then
    /// the far part); `wanted` is asked first, so that unwanted pairs cost no geometry.
    #[inline(always)]
    pub(super) fn each_later_neighbour(
        &self,
        i: usize,
        wanted: impl Fn(usize) -> bool,
        pair: impl FnMut(usize, Vec3, Vec3),
    ) {
        self.later_neighbours::<false>(i, wanted, pair);
    }

    /// [`StressInput::each_later_neighbour`] with wall particles too (`j ≥ n_fluid`: every wall
    /// neighbour of a fluid particle is later).
    #[inline(always)]
    pub(super) fn each_later_neighbour_or_wall(
        &self,
        i: usize,
        wanted: impl Fn(usize) -> bool,
        pair: impl FnMut(usize, Vec3, Vec3),
    ) {
        self.later_neighbours::<true>(i, wanted, pair);
    }

    /// The two above: walls visited if `WALLS`.
    #[inline(always)]
    fn later_neighbours<const WALLS: bool>(
        &self,
        i: usize,
        wanted: impl Fn(usize) -> bool,
        mut pair: impl FnMut(usize, Vec3, Vec3),
    ) {
        let cut = self.kernel.support_m();
        let cut2 = cut * cut;
        let pi = self.pos[i];
        let later = self.lists.near(i).filter(|&j| j > i);
        for j in later.chain(self.lists.far(i)) {
            if (!WALLS && j >= self.n_fluid) || !wanted(j) {
                continue;
            }
            let d = self.lists.delta(pi, self.pos[j]);
            let r2 = d.norm_squared();
            if r2 >= cut2 || r2 == 0.0 {
                continue;
            }
            let r = r2.sqrt();
            pair(j, d * (self.kernel.dw_dr(r) / r), d);
        }
    }

    /// Calls `pair(j, ∇_w W_c(r_wj) [1/m⁴])` for every fluid neighbour `j` of wall particle `w`
    /// within the colour kernel's support for which `wanted(j)`, in list order (near, then
    /// far: complete only with [`crate::neighbours::NeighbourSearch::walls_reach_far`]).
    #[inline(always)]
    pub(super) fn each_fluid_neighbour_of_wall(
        &self,
        w: usize,
        wanted: impl Fn(usize) -> bool,
        mut pair: impl FnMut(usize, Vec3),
    ) {
        let cut = self.kernel.support_m();
        let cut2 = cut * cut;
        let pw = self.pos[w];
        for j in self.lists.all(w) {
            if !wanted(j) {
                continue;
            }
            let d = self.lists.delta(pw, self.pos[j]);
            let r2 = d.norm_squared();
            if r2 >= cut2 || r2 == 0.0 {
                continue;
            }
            let r = r2.sqrt();
            pair(j, d * (self.kernel.dw_dr(r) / r));
        }
    }

    /// The colour gradient of phase `b` [1/m] at every fluid particle not of phase `b` (zero
    /// for those of `b`), into `out`.
    pub fn colour_gradient(&self, b: u8, spills: &Spills, out: &mut [Vec3]) {
        out.fill(Vec3::zeros());
        each_pair_once(out, spills, |i, reactions: &mut Reactions| {
            let in_b = self.phase[i] == b;
            let mut g = Vec3::zeros();
            // only pairs with one particle in b (the colour differs across them)
            let across = |j: usize| (self.phase[j] == b) != in_b;
            self.each_later_neighbour(i, across, |j, grad_w, _| {
                if in_b {
                    // G_j^b gains V_i ∇_j W_ji = −V_i ∇_i W_ij
                    reactions.subtract(j, grad_w * self.vol[i]);
                } else {
                    g += grad_w * self.vol[j];
                }
            });
            g
        });
    }

    /// The force [N] of the stresses `stress` (one per fluid particle) on every fluid particle,
    /// into `out`: `Σ_j V_i V_j (T_i + T_j) · ∇_i W_c(r_ij)` (Hu & Adams 2006, Eq. 18's form).
    pub fn forces(&self, stress: &[SymTensor], spills: &Spills, out: &mut [Vec3]) {
        out.fill(Vec3::zeros());
        let zero = |t: &SymTensor| t.iter().all(|&x| x == 0.0);
        each_pair_once(out, spills, |i, reactions: &mut Reactions| {
            let ti = &stress[i];
            let ti_zero = zero(ti);
            let mut f = Vec3::zeros();
            // the bulk of a phase has no stress on either side of its pairs
            let stressed = |j: usize| !(ti_zero && zero(&stress[j]));
            self.each_later_neighbour(i, stressed, |j, grad_w, _| {
                let tj = &stress[j];
                let s: SymTensor = std::array::from_fn(|k| ti[k] + tj[k]);
                let fij = apply(&s, grad_w) * (self.vol[i] * self.vol[j]);
                f += fij;
                reactions.subtract(j, fij);
            });
            f
        });
    }
}

/// Scratch of the surface stress, kept between steps.
#[derive(Clone, Debug, Default)]
pub struct StressScratch {
    /// One phase's colour gradient per fluid particle [1/m].
    gradient: Vec<Vec3>,
    /// The stress per fluid particle [N/m²].
    pub stress: Vec<SymTensor>,
    /// The force per fluid particle [N].
    pub force: Vec<Vec3>,
    /// The interfacial energy estimate `Σ_i V_i Σ_b σ_ab |G_i^b|` [J] of the last evaluation
    /// (each side of an interface sums about half of its area: `G^b` of phase `a`'s particles
    /// rises from 0 to ½|∇c| at the interface, where the other side's takes over).
    pub interface_energy_j: f64,
    /// Its share per fluid particle [J].
    energy: Vec<f64>,
    spills: Spills,
}

impl StressScratch {
    /// Evaluates the stresses and forces of the current state: `sigma(a, b)` [N/m] is the
    /// tension of the pair of liquid phases `a ≠ b` (zero: no interface term), `n_liquids`
    /// the number of liquid phases.
    pub fn evaluate<K: Kernel>(
        &mut self,
        inp: &StressInput<K>,
        n_liquids: usize,
        sigma: impl Fn(usize, usize) -> f64 + Sync,
    ) {
        let n = inp.n_fluid;
        self.gradient.resize(n, Vec3::zeros());
        self.stress.clear();
        self.stress.resize(n, [0.0; 6]);
        self.force.resize(n, Vec3::zeros());
        self.energy.clear();
        self.energy.resize(n, 0.0);
        for b in 0..n_liquids {
            if (0..n_liquids).all(|a| a == b || sigma(a, b) == 0.0) {
                continue;
            }
            inp.colour_gradient(b as u8, &self.spills, &mut self.gradient);
            self.stress
                .par_iter_mut()
                .zip(self.energy.par_iter_mut())
                .enumerate()
                .for_each(|(i, (t, e))| {
                    let a = inp.phase[i] as usize;
                    if a == b {
                        return;
                    }
                    let s = sigma(a, b);
                    let g = self.gradient[i];
                    if s == 0.0 || g == Vec3::zeros() {
                        return;
                    }
                    let c = capillary_stress(s, g);
                    for k in 0..6 {
                        t[k] += c[k];
                    }
                    *e += inp.vol[i] * s * g.norm();
                });
        }
        // a fixed-order sum: the same bits for any thread count
        self.interface_energy_j = self.energy.iter().sum();
        inp.forces(&self.stress, &self.spills, &mut self.force);
    }
}

#[cfg(test)]
mod tests;
