//! The fused pair loop: one gather loop per fluid particle over its neighbours, evaluating a
//! list of force terms ([`PairTerm`]) together.
//!
//! Each pair's geometry (distance, kernel gradient, `v_ij · x_ij`) is computed once for all
//! terms; the pair force is `a_ij x_ij + b_ij v_ij` with the central coefficient `a_ij` and
//! the shear coefficient `b_ij` summed over the terms in list order. All parallel work gathers
//! per particle in the fixed order of its neighbour list, so the result is bitwise identical
//! for any thread count.
//!
//! Booked terms ([`super::ledger`]) are also summed apart per particle ([`super::booking`]);
//! the loop returns their power, summed in blocks of [`BLOCK`] particles in particle order and
//! then over the blocks in order — a fixed order for any thread count. The accelerations do
//! not depend on it.

use super::booking::{Booked, Coefficients};
use super::chunk::Relative;
use super::ledger::{self, Power};
use super::term::{Lanes, Neighbour, Neighbourhood, PairSums, PairTerm, Particle, CHUNK};
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

/// Particles per block of the power sums (a few blocks per thread even for small scenes).
pub const BLOCK: usize = 256;

/// Scratch of one rayon job (allocated once per job, not per chunk or particle: zeroing the
/// gather buffers per chunk cost 4 % of a step).
struct Scratch<L> {
    rel: Relative,
    lanes: L,
    /// The particle's near entries, decoded.
    near: Vec<u32>,
    visit: [u32; ACTIVE_BITS],
    booked: Booked,
}

/// Evaluates the accelerations [m/s²] of all fluid particles under the force terms `terms`,
/// and, if a term contributes to the density rate, `dρ/dt` [kg/(m³ s)] into `drho`; returns
/// the power of the booked terms ([`super::ledger`]).
pub fn fluid_forces<K: Kernel, T: PairTerm>(
    inp: &LoopInput<K>,
    terms: &T,
    acc: &mut [Vec3],
    drho: &mut [f64],
) -> Power {
    let scratch = || Scratch {
        rel: Relative::new(),
        lanes: T::Lanes::new(),
        near: Vec::new(),
        visit: [0u32; ACTIVE_BITS],
        booked: Booked::new(),
    };
    // the far pairs first, each once, into `acc` (read back by each particle below)
    if T::FAR {
        acc.fill(Vec3::zeros());
        terms.far_forces(inp.lists, acc);
    }
    // a scene without walls skips their bookings (a test per particle)
    let walls = const { ledger::any_walls(T::BOOKINGS) } && inp.state.pos.len() > inp.state.n_fluid;
    let blocks: Vec<Power> = if T::RATE {
        assert_eq!(drho.len(), acc.len(), "a density rate per fluid particle");
        acc.par_chunks_mut(BLOCK)
            .zip(drho.par_chunks_mut(BLOCK))
            .enumerate()
            .map_init(scratch, |s, (b, (ab, db))| {
                let mut sum = Power::default();
                for (k, (a, d)) in ab.iter_mut().zip(db.iter_mut()).enumerate() {
                    let out = particle(inp, terms, s, b * BLOCK + k, walls, *a);
                    (*a, *d) = (out.acc, out.rate);
                    add_booked::<T>(&mut sum, &out.power);
                }
                sum
            })
            .collect()
    } else {
        acc.par_chunks_mut(BLOCK)
            .enumerate()
            .map_init(scratch, |s, (b, ab)| {
                let mut sum = Power::default();
                for (k, a) in ab.iter_mut().enumerate() {
                    let out = particle(inp, terms, s, b * BLOCK + k, walls, *a);
                    *a = out.acc;
                    add_booked::<T>(&mut sum, &out.power);
                }
                sum
            })
            .collect()
    };
    let mut total = Power::default();
    for b in &blocks {
        add_booked::<T>(&mut total, b);
    }
    total
}

/// Adds `p` to `sum` if some term of `T` is booked (nothing to add otherwise).
#[inline(always)]
fn add_booked<T: PairTerm>(sum: &mut Power, p: &Power) {
    if const { ledger::any(T::BOOKINGS) } {
        sum.add(p);
    }
}

/// What the loop computes for one fluid particle.
struct ParticleOut {
    /// Acceleration [m/s²].
    acc: Vec3,
    /// Density rate [kg/(m³ s)].
    rate: f64,
    /// Its share of the booked power.
    power: Power,
}

/// The acceleration [m/s²], density rate [kg/(m³ s)] and booked power of fluid particle `i`;
/// `walls`: some term books wall pairs and the scene has walls; `far`: the force [N] of its
/// far pairs (zero without a far term).
#[inline(always)]
fn particle<K: Kernel, T: PairTerm>(
    inp: &LoopInput<K>,
    terms: &T,
    s: &mut Scratch<T::Lanes>,
    i: usize,
    walls: bool,
    far: Vec3,
) -> ParticleOut {
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
    inp.lists.near(i).decode_into(&mut s.near);
    for chunk in near_entries(&s.near, inp.active[i], &mut s.visit) {
        let rel = &mut s.rel;
        let mut has_wall = false;
        for (n, &j) in chunk.iter().enumerate() {
            let j = j as usize;
            let d = pi - st.pos[j];
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
            if walls {
                rel.wall[n] = nb.is_wall;
                has_wall |= nb.is_wall;
            }
            terms.gather(&own, &mut s.lanes, n, nb);
        }
        let m = chunk.len();
        inp.lists
            .periodic
            .image_lanes(&mut rel.dx[..m], &mut rel.dy[..m], &mut rel.dz[..m]);
        // every pair term of the chunk, branch-free (the compiler vectorises this loop); lanes
        // past the chunk's end hold a previous chunk's values: computed, never added
        let (mut ca, mut cb, mut cd) = ([0.0; CHUNK], [0.0; CHUNK], [0.0; CHUNK]);
        let mut cl = Coefficients::new();
        for n in 0..CHUNK {
            let sums = pair_sums(terms, &own, &s.lanes, rel, &k, n, support2);
            ca[n] = sums.central;
            cb[n] = sums.shear;
            if T::RATE {
                cd[n] = sums.rate;
            }
            cl.store::<T>(n, &sums);
        }
        // pairs with wall particles (few chunks have any): the terms once more for them alone
        if walls && has_wall {
            for n in 0..chunk.len() {
                if rel.wall[n] {
                    let sums = pair_sums(terms, &own, &s.lanes, rel, &k, n, support2);
                    s.booked.add_wall::<T>(&mut cl, rel, n, &sums);
                }
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
        s.booked.add_liquid::<T>(rel, &cl, chunk.len());
    }
    if T::FAR {
        f += far;
    }
    let acc = f / st.mass[me.phase] + inp.gravity;
    ParticleOut {
        acc,
        rate: st.rho[i] * dr,
        power: s.booked.take_power::<T>(&vi, &acc),
    }
}

/// The pair sums of the terms for the pair in lane `n`.
#[inline(always)]
fn pair_sums<K: Kernel, T: PairTerm>(
    terms: &T,
    own: &T::Own,
    lanes: &T::Lanes,
    rel: &Relative,
    k: &K,
    n: usize,
    support2: f64,
) -> PairSums {
    let mut sums = PairSums::default();
    terms.pair(&mut sums, own, lanes, n, &rel.kinematics(k, n, support2));
    sums
}

/// The entries of a near list `near` that interact, in list order, as chunks: among the first
/// `ACTIVE_BITS` entries those marked in `active` (copied into `visit`), then the rest;
/// when all marked entries interact (r_e beyond the support), the list itself.
#[inline(always)]
fn near_entries<'v>(
    near: &'v [u32],
    active: u64,
    visit: &'v mut [u32; ACTIVE_BITS],
) -> impl Iterator<Item = &'v [u32]> {
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
