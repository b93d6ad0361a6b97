//! The fused loop's side of the energy ledger ([`super::ledger`]): per fluid particle, the
//! force of each booked term summed apart, and its power.
//!
//! Liquid pairs are summed lane by lane over the chunks (vectorised) and the lanes added at
//! the end; the few pairs with wall particles are evaluated once more on their own and summed
//! on the wall side. None of this touches the accelerations.

use super::chunk::Relative;
use super::ledger::{channel, Bookings, Ledger, Part, Power};
use super::term::{PairSums, PairTerm, CHUNK};
use crate::state::Vec3;

// `Coefficients::store` and `Booked::add_liquid` name every ledger
const _: () = assert!(Ledger::COUNT == 3);

/// Whether ledger `l` books pairs with liquid neighbours.
const fn liquid(b: Bookings, l: usize) -> bool {
    matches!(b[l], Some(x) if x.liquid)
}

/// The coefficient ledger `l` books (central if none).
const fn part(b: Bookings, l: usize) -> Part {
    match b[l] {
        Some(x) => x.part,
        None => Part::Central,
    }
}

/// Per ledger booking liquid pairs, the booked coefficient of each lane of a chunk.
pub(super) struct Coefficients([[f64; CHUNK]; Ledger::COUNT]);

impl Coefficients {
    pub fn new() -> Self {
        Coefficients([[0.0; CHUNK]; Ledger::COUNT])
    }

    /// Keeps the booked coefficients of lane `n` (those of ledgers booking liquid pairs).
    #[inline(always)]
    pub fn store<T: PairTerm>(&mut self, n: usize, sums: &PairSums) {
        if const { liquid(T::BOOKINGS, 0) } {
            self.0[0][n] = sums.booked[0];
        }
        if const { liquid(T::BOOKINGS, 1) } {
            self.0[1][n] = sums.booked[1];
        }
        if const { liquid(T::BOOKINGS, 2) } {
            self.0[2][n] = sums.booked[2];
        }
    }
}

/// The booked forces on one particle [N]: liquid side per lane, wall side summed.
pub(super) struct Booked {
    liquid: [[[f64; CHUNK]; 3]; Ledger::COUNT],
    wall: [Vec3; Ledger::COUNT],
}

impl Booked {
    pub fn new() -> Self {
        Booked {
            liquid: [[[0.0; CHUNK]; 3]; Ledger::COUNT],
            wall: [Vec3::zeros(); Ledger::COUNT],
        }
    }

    /// Books the pair with a wall particle in lane `n`, whose booked coefficients are `sums`,
    /// on the wall side of the ledgers that book wall pairs, and takes it out of the liquid
    /// side of every ledger.
    #[inline(always)]
    pub fn add_wall<T: PairTerm>(
        &mut self,
        c: &mut Coefficients,
        rel: &Relative,
        n: usize,
        sums: &PairSums,
    ) {
        for (l, lanes) in c.0.iter_mut().enumerate() {
            let Some(b) = T::BOOKINGS[l] else { continue };
            if b.walls {
                self.wall[l] += rel.along(b.part, n) * sums.booked[l];
            }
            lanes[n] = 0.0;
        }
    }

    /// Adds the liquid side of a chunk of `len` pairs (lanes from `len` on hold stale values:
    /// excluded).
    #[inline(always)]
    pub fn add_liquid<T: PairTerm>(&mut self, rel: &Relative, c: &Coefficients, len: usize) {
        self.add_lanes::<0, T>(rel, c, len);
        self.add_lanes::<1, T>(rel, c, len);
        self.add_lanes::<2, T>(rel, c, len);
    }

    #[inline(always)]
    fn add_lanes<const L: usize, T: PairTerm>(
        &mut self,
        rel: &Relative,
        c: &Coefficients,
        len: usize,
    ) {
        if !const { liquid(T::BOOKINGS, L) } {
            return;
        }
        let [ux, uy, uz] = rel.lanes(const { part(T::BOOKINGS, L) });
        let c = &c.0[L];
        let [ax, ay, az] = &mut self.liquid[L];
        for n in 0..CHUNK {
            let cn = if n < len { c[n] } else { 0.0 };
            ax[n] += ux[n] * cn;
            ay[n] += uy[n] * cn;
            az[n] += uz[n] * cn;
        }
    }

    /// The power of the booked forces at velocity `v` [m/s] and acceleration `a` [m/s²].
    #[inline(always)]
    pub fn power<T: PairTerm>(&self, v: &Vec3, a: &Vec3) -> Power {
        let mut p = Power::default();
        for l in 0..Ledger::COUNT {
            let Some(b) = T::BOOKINGS[l] else { continue };
            if b.liquid {
                let acc = &self.liquid[l];
                let f = Vec3::new(lane_sum(acc[0]), lane_sum(acc[1]), lane_sum(acc[2]));
                let c = channel(l, false);
                p.velocity_w[c] = f.dot(v);
                p.acceleration_w_s[c] = f.dot(a);
            }
            if b.walls {
                let c = channel(l, true);
                p.velocity_w[c] = self.wall[l].dot(v);
                p.acceleration_w_s[c] = self.wall[l].dot(a);
            }
        }
        p
    }
}

/// The sum of a chunk's lanes, halving (vectorised).
#[inline(always)]
fn lane_sum(mut v: [f64; CHUNK]) -> f64 {
    let mut width = CHUNK / 2;
    while width > 0 {
        for n in 0..width {
            v[n] += v[n + width];
        }
        width /= 2;
    }
    v[0]
}
