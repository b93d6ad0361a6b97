//! The fused loop's side of the energy ledger ([`super::ledger`]): per fluid particle, the
//! force of each booked term summed apart, and its power.
//!
//! Liquid pairs are summed on a few lanes (vectorised), the lanes added at the end; the few pairs with wall particles are evaluated once more on their own and summed
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

/// The booked forces on one particle [N]: liquid side per lane, wall side summed. Kept with
/// the scratch of a rayon job and reset as its power is taken (a fresh one per particle made
/// the booking up to 1.5 times as costly: the ignored test `booking_cost`).
pub(super) struct Booked {
    liquid: [[[f64; WIDTH]; 3]; Ledger::COUNT],
    wall: [Vec3; Ledger::COUNT],
}

impl Booked {
    pub fn new() -> Self {
        Booked {
            liquid: [[[0.0; WIDTH]; 3]; Ledger::COUNT],
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
        for h in (0..CHUNK).step_by(WIDTH) {
            for m in 0..WIDTH {
                let n = h + m;
                let cn = if n < len { c[n] } else { 0.0 };
                ax[m] += ux[n] * cn;
                ay[m] += uy[n] * cn;
                az[m] += uz[n] * cn;
            }
        }
    }

    /// The power of the booked forces at velocity `v` [m/s] and acceleration `a` [m/s²];
    /// the sums are reset for the next particle.
    #[inline(always)]
    pub fn take_power<T: PairTerm>(&mut self, v: &Vec3, a: &Vec3) -> Power {
        let mut p = Power::default();
        for l in 0..Ledger::COUNT {
            let Some(b) = T::BOOKINGS[l] else { continue };
            if b.liquid {
                let acc = &mut self.liquid[l];
                let f = Vec3::new(lane_sum(acc[0]), lane_sum(acc[1]), lane_sum(acc[2]));
                *acc = [[0.0; WIDTH]; 3];
                let c = channel(l, false);
                p.velocity_w[c] = f.dot(v);
                p.acceleration_w_s[c] = f.dot(a);
            }
            if b.walls {
                let f = std::mem::replace(&mut self.wall[l], Vec3::zeros());
                let c = channel(l, true);
                p.velocity_w[c] = f.dot(v);
                p.acceleration_w_s[c] = f.dot(a);
            }
        }
        p
    }
}

/// Lanes of the liquid-side sums: a chunk is folded onto them (one AVX-512 register; 16
/// lanes, a whole chunk, made the booking twice as costly, 4 no cheaper; `booking_cost`).
const WIDTH: usize = 8;

/// The sum of the lanes, halving (vectorised).
#[inline(always)]
fn lane_sum(mut v: [f64; WIDTH]) -> f64 {
    let mut width = WIDTH / 2;
    while width > 0 {
        for n in 0..width {
            v[n] += v[n + width];
        }
        width /= 2;
    }
    v[0]
}
