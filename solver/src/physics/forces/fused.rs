//! The fused pair loop: one gather loop per fluid particle over its neighbours, evaluating a
//! list of force terms ([`PairTerm`]) together.
//!
//! Each pair's geometry (distance, kernel gradient, `v_ij · x_ij`) is computed once for all
//! terms; the pair force is `a_ij x_ij + b_ij v_ij` with the central coefficient `a_ij` and
//! the shear coefficient `b_ij` summed over the terms in list order. All parallel work gathers
//! per particle in the fixed order of its neighbour list, so the result is bitwise identical
//! for any thread count.

use super::term::{
    Lanes, Neighbour, Neighbourhood, PairKinematics, PairSums, PairTerm, Particle, CHUNK,
};
use crate::kernel::Kernel;
use crate::neighbours::{NeighbourLists, ACTIVE_BITS};
use crate::state::Vec3;
use rayon::prelude::*;

/// What the loop reads besides the terms.
#[derive(Clone, Copy, Debug)]
pub struct LoopInput<'a, K: Kernel> {
    /// The kernel.
    pub kernel: K,
    /// The particles.
    pub state: Neighbourhood<'a>,
    /// Gravity [m/s²] (zero without the effect; a body force, added outside the pair sums).
    pub gravity: Vec3,
    /// Neighbour lists.
    pub lists: &'a NeighbourLists,
    /// Per fluid particle: which of its first near entries interact
    /// ([`crate::neighbours::NeighbourSearch::active`]).
    pub active: &'a [u64],
}

/// `x_i − x_j` [m] and `v_i − v_j` [m/s] of one chunk of neighbours.
struct Relative {
    dx: [f64; CHUNK],
    dy: [f64; CHUNK],
    dz: [f64; CHUNK],
    vx: [f64; CHUNK],
    vy: [f64; CHUNK],
    vz: [f64; CHUNK],
}

impl Relative {
    fn new() -> Self {
        Relative {
            dx: [0.0; CHUNK],
            dy: [0.0; CHUNK],
            dz: [0.0; CHUNK],
            vx: [0.0; CHUNK],
            vy: [0.0; CHUNK],
            vz: [0.0; CHUNK],
        }
    }
}

/// Scratch of one rayon job (allocated once per job, not per chunk or particle: zeroing the
/// gather buffers per chunk cost 4 % of a step).
struct Scratch<L> {
    rel: Relative,
    lanes: L,
    visit: [u32; ACTIVE_BITS],
}

/// Evaluates the accelerations [m/s²] of all fluid particles under the force terms `terms`,
/// and, if a term contributes to the density rate, `dρ/dt` [kg/(m³ s)] into `drho`.
pub fn fluid_forces<K: Kernel, T: PairTerm>(
    inp: &LoopInput<K>,
    terms: &T,
    acc: &mut [Vec3],
    drho: &mut [f64],
) {
    let scratch = || Scratch {
        rel: Relative::new(),
        lanes: T::Lanes::new(),
        visit: [0u32; ACTIVE_BITS],
    };
    if T::RATE {
        assert_eq!(drho.len(), acc.len(), "a density rate per fluid particle");
        acc.par_iter_mut()
            .zip(drho.par_iter_mut())
            .enumerate()
            .for_each_init(scratch, |s, (i, (a, d))| {
                let (ai, di) = particle(inp, terms, s, i);
                *a = ai;
                *d = di;
            });
    } else {
        acc.par_iter_mut()
            .enumerate()
            .for_each_init(scratch, |s, (i, a)| *a = particle(inp, terms, s, i).0);
    }
}

/// The acceleration [m/s²] and density rate [kg/(m³ s)] of fluid particle `i`.
#[inline(always)]
fn particle<K: Kernel, T: PairTerm>(
    inp: &LoopInput<K>,
    terms: &T,
    s: &mut Scratch<T::Lanes>,
    i: usize,
) -> (Vec3, f64) {
    let st = &inp.state;
    let k = inp.kernel;
    let support = k.support_m();
    let support2 = support * support;
    let pi = st.pos[i];
    let vi = st.vel[i];
    let me = Particle {
        i,
        phase: st.phase[i] as usize,
    };
    let own = terms.own(me);
    let mut f = Vec3::zeros();
    let mut dr = 0.0;
    for chunk in near_entries(inp.lists, inp.active[i], i, &mut s.visit) {
        let rel = &mut s.rel;
        for (n, &j) in chunk.iter().enumerate() {
            let j = j as usize;
            let d = inp.lists.delta(pi, st.pos[j]);
            rel.dx[n] = d.x;
            rel.dy[n] = d.y;
            rel.dz[n] = d.z;
            if T::USES_VELOCITY {
                let v = vi - st.vel[j];
                rel.vx[n] = v.x;
                rel.vy[n] = v.y;
                rel.vz[n] = v.z;
            }
            let nb = Neighbour {
                j,
                phase: st.phase[j] as usize,
                is_wall: j >= st.n_fluid,
            };
            terms.gather(&own, &mut s.lanes, n, nb);
        }
        // every pair term of the chunk, branch-free (the compiler vectorises this loop); lanes
        // past the chunk's end hold a previous chunk's values: computed, never added
        let (mut ca, mut cb, mut cd) = ([0.0; CHUNK], [0.0; CHUNK], [0.0; CHUNK]);
        for n in 0..CHUNK {
            let r2 = rel.dx[n] * rel.dx[n] + rel.dy[n] * rel.dy[n] + rel.dz[n] * rel.dz[n];
            let r = r2.sqrt();
            let ir = 1.0 / r;
            let apart = r2 > 0.0;
            let kin = PairKinematics {
                r2,
                r,
                ir,
                apart,
                inside: apart && r2 < support2,
                dw_r: k.dw_dr_inside(r.min(support)) * ir, // dW/dr / r [1/m⁵]
                vr: rel.vx[n] * rel.dx[n] + rel.vy[n] * rel.dy[n] + rel.vz[n] * rel.dz[n],
            };
            let mut sums = PairSums::default();
            terms.pair(&mut sums, &own, &s.lanes, n, &kin);
            ca[n] = sums.central;
            cb[n] = sums.shear;
            if T::RATE {
                cd[n] = sums.rate;
            }
        }
        for n in 0..chunk.len() {
            f.x += rel.dx[n] * ca[n] + rel.vx[n] * cb[n];
            f.y += rel.dy[n] * ca[n] + rel.vy[n] * cb[n];
            f.z += rel.dz[n] * ca[n] + rel.vz[n] * cb[n];
            if T::RATE {
                dr += cd[n];
            }
        }
    }
    if T::FAR {
        terms.far(&own, &mut f, pi, inp.lists.far(i));
    }
    (f / st.mass[me.phase] + inp.gravity, st.rho[i] * dr)
}

/// The near entries of `i` that interact, in list order, as chunks: among the first
/// `ACTIVE_BITS` entries those marked in `active` (copied into `visit`), then the rest;
/// when all marked entries interact (r_e beyond the support), the list itself.
#[inline(always)]
fn near_entries<'v>(
    lists: &'v NeighbourLists,
    active: u64,
    i: usize,
    visit: &'v mut [u32; ACTIVE_BITS],
) -> impl Iterator<Item = &'v [u32]> {
    let near = lists.near(i);
    let (masked, rest) = near.split_at(near.len().min(ACTIVE_BITS));
    let all = low_bits(masked.len());
    let mut bits = active & all;
    let first: &[u32] = if bits == all {
        masked
    } else {
        let mut n = 0;
        while bits != 0 {
            visit[n] = masked[bits.trailing_zeros() as usize];
            n += 1;
            bits &= bits - 1;
        }
        &visit[..n]
    };
    first.chunks(CHUNK).chain(rest.chunks(CHUNK))
}

/// The mask of the lowest `n` bits (`n ≤ 64`).
#[inline(always)]
fn low_bits(n: usize) -> u64 {
    if n >= 64 {
        u64::MAX
    } else {
        (1u64 << n) - 1
    }
}
