//! The pairwise-potential force in the fused pair loop: Eq. (15), Natsui 2021,
//! `F_i = Σ_j C_ij P'(r_ij) e_ij` [N] over every neighbour within `r_e`, liquid or wall (a
//! wall pair's `C` sets the wetting).
//!
//! Within the kernel support the pair is one lane of the loop's chunk; beyond it (the lists'
//! far part, when `r_e` exceeds the support) each pair is evaluated once and added to both
//! particles ([`far_pair_forces`]): the per-pair factors are computed branch-free over a chunk
//! of the far list (the compiler vectorises it; `sqrt` and division are exact IEEE operations),
//! then added one by one in list order, `F_ij` to `i` and `−F_ij` to `j`.

use super::potential::Kondo2007Potential;
use crate::neighbours::NeighbourLists;
use crate::physics::forces::pairs_once::{each_pair_once, Spills};
use crate::physics::forces::term::{
    Lane, Lanes, Neighbour, PairKinematics, PairSums, PairTerm, Particle, CHUNK,
};
use crate::state::Vec3;

/// The potential force term.
#[derive(Clone, Copy, Debug)]
pub struct PairwisePotential<'a> {
    /// The potential (spacing `l0`, cut-off `r_e`).
    pub potential: Kondo2007Potential,
    /// Coefficients `C_ab` [N/m²], row-major by phase.
    pub coeff: &'a [f64],
    /// Number of phases (row length of `coeff`).
    pub n_phases: usize,
    /// Positions [m] (all particles; for the far neighbours).
    pub pos: &'a [Vec3],
    /// Phase index per particle (all).
    pub phase: &'a [u8],
    /// The box pair vectors are measured in (the lists' [`crate::neighbours::NeighbourLists::periodic`]).
    pub periodic: crate::periodic::PeriodicBox,
    /// Spill buffers of the far pass, kept between steps.
    pub spills: &'a Spills,
}

/// `C_ij` [N/m²] per neighbour.
pub struct PotentialLanes {
    c: Lane<f64>,
}

impl Lanes for PotentialLanes {
    fn new() -> Self {
        PotentialLanes { c: [0.0; CHUNK] }
    }
}

impl<'a> PairTerm for PairwisePotential<'a> {
    const FAR: bool = true;
    /// Row `C_{phase(i), ·}` [N/m²].
    type Own = &'a [f64];
    type Lanes = PotentialLanes;

    #[inline(always)]
    fn own(&self, i: Particle) -> &'a [f64] {
        &self.coeff[i.phase * self.n_phases..(i.phase + 1) * self.n_phases]
    }
    #[inline(always)]
    fn gather(&self, row: &&'a [f64], l: &mut PotentialLanes, n: usize, nb: Neighbour) {
        l.c[n] = row[nb.phase];
    }
    #[inline(always)]
    fn pair(
        &self,
        s: &mut PairSums,
        _row: &&'a [f64],
        l: &PotentialLanes,
        n: usize,
        k: &PairKinematics,
    ) {
        let r_e = self.potential.r_e_m;
        // C_ij P'(r) e_ij: the force along x_ij per metre of x_ij
        let v = self.potential.pair_force_inside(l.c[n], k.r) * k.ir;
        s.central += if k.apart & (k.r2 < r_e * r_e) { v } else { 0.0 };
    }
    fn far_forces(&self, lists: &NeighbourLists, out: &mut [Vec3]) {
        far_pair_forces(self, lists, out);
    }
}

/// Adds to `out` (one per fluid particle) the potential's forces [N] of the far pairs (beyond
/// the kernel support, within `r_e`), each pair evaluated once: `C_ij P'(r) e_ij` on `i`, its
/// negative on `j` (`C_ij = C_ji`); a wall neighbour takes nothing. Eq. (15), Natsui 2021.
pub fn far_pair_forces(term: &PairwisePotential, lists: &NeighbourLists, out: &mut [Vec3]) {
    let re2 = term.potential.r_e_m * term.potential.r_e_m;
    each_pair_once(out, term.spills, |i, reactions| {
        let pi = term.pos[i];
        let row = term.own(Particle {
            i,
            phase: term.phase[i] as usize,
        });
        let mut f = Vec3::zeros();
        let mut ids = lists.far(i);
        let mut chunk = [0u32; CHUNK];
        loop {
            let m = ids.fill(&mut chunk);
            if m == 0 {
                break;
            }
            let chunk = &chunk[..m];
            let (mut dx, mut dy, mut dz, mut c) =
                ([0.0; CHUNK], [0.0; CHUNK], [0.0; CHUNK], [0.0; CHUNK]);
            for (k, &j) in chunk.iter().enumerate() {
                let j = j as usize;
                let d = pi - term.pos[j];
                dx[k] = d.x;
                dy[k] = d.y;
                dz[k] = d.z;
                c[k] = row[term.phase[j] as usize];
            }
            term.periodic
                .image_lanes(&mut dx[..m], &mut dy[..m], &mut dz[..m]);
            // the pair forces F_ij [N] of the chunk, branch-free over all lanes (vectorised)
            let (mut fx, mut fy, mut fz) = ([0.0; CHUNK], [0.0; CHUNK], [0.0; CHUNK]);
            for k in 0..CHUNK {
                let r2 = dx[k] * dx[k] + dy[k] * dy[k] + dz[k] * dz[k];
                let r = r2.sqrt();
                // C_ij P'(r) / r: the force along x_ij per metre of x_ij [N/m]
                let v = term.potential.pair_force_inside(c[k], r) / r; // Eq. (15), Natsui 2021
                let s = if r2 < re2 && r2 > 0.0 { v } else { 0.0 };
                (fx[k], fy[k], fz[k]) = (dx[k] * s, dy[k] * s, dz[k] * s);
            }
            // on i, in list order (a loop of its own: the sum stays in registers)
            for k in 0..m {
                f += Vec3::new(fx[k], fy[k], fz[k]);
            }
            // on each j (every j once per list, so the order of these is free)
            for (k, &j) in chunk.iter().enumerate() {
                reactions.subtract(j as usize, Vec3::new(fx[k], fy[k], fz[k]));
            }
        }
        f
    });
}
