//! The pairwise-potential force in the fused pair loop: Eq. (15), Natsui 2021,
//! `F_i = Σ_j C_ij P'(r_ij) e_ij` [N] over every neighbour within `r_e`, liquid or wall (a
//! wall pair's `C` sets the wetting).
//!
//! Within the kernel support the pair is one lane of the loop's chunk; beyond it (the lists'
//! far part, when `r_e` exceeds the support) the term runs its own chunked loop
//! ([`PairTerm::far`]): the per-pair factors are computed branch-free over a chunk (the
//! compiler vectorises it; `sqrt` and division are exact IEEE operations), then added one by
//! one in list order — the same operations in the same order as a scalar loop, hence the same
//! bits.

use super::potential::Kondo2007Potential;
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
        s.central += if k.apart && k.r2 < r_e * r_e { v } else { 0.0 };
    }
    #[inline(always)]
    fn far(&self, row: &&'a [f64], f: &mut Vec3, pi: Vec3, far: &[u32]) {
        let r_e = self.potential.r_e_m;
        let re2 = r_e * r_e;
        for chunk in far.chunks(CHUNK) {
            let (mut dx, mut dy, mut dz, mut c) =
                ([0.0; CHUNK], [0.0; CHUNK], [0.0; CHUNK], [0.0; CHUNK]);
            for (k, &j) in chunk.iter().enumerate() {
                let j = j as usize;
                let d = pi - self.pos[j];
                dx[k] = d.x;
                dy[k] = d.y;
                dz[k] = d.z;
                c[k] = row[self.phase[j] as usize];
            }
            let m = chunk.len();
            self.periodic
                .image_lanes(&mut dx[..m], &mut dy[..m], &mut dz[..m]);
            let mut s = [0.0; CHUNK];
            for k in 0..CHUNK {
                let r2 = dx[k] * dx[k] + dy[k] * dy[k] + dz[k] * dz[k];
                let r = r2.sqrt();
                let v = self.potential.pair_force_inside(c[k], r) / r;
                s[k] = if r2 < re2 && r2 > 0.0 { v } else { 0.0 };
            }
            for k in 0..chunk.len() {
                f.x += dx[k] * s[k];
                f.y += dy[k] * s[k];
                f.z += dz[k] * s[k];
            }
        }
    }
}
