//! The contract between the fused pair loop and one force term.
//!
//! A term (pressure, a viscosity, the potential, …) is a type implementing [`PairTerm`]. The
//! loop gathers the neighbours of particle `i` in chunks; for each chunk every term first
//! gathers what it needs of each neighbour `j` into its own lanes, then, for every pair, adds
//! its parts to three sums ([`PairSums`]): the coefficient `a_ij` of `x_i − x_j` (central
//! forces), the coefficient `b_ij` of `v_i − v_j` (viscous shear), and the density rate. The pair force is
//! `a_ij (x_i − x_j) + b_ij (v_i − v_j)` with `a_ij = a_ji`, `b_ij = b_ji`, so `F_ji = −F_ij`
//! to the last bit.
//!
//! A term whose work the energy budget books apart ([`super::ledger`]: the viscosities, the
//! walls' own pressure) declares a [`Booking`] and also writes the coefficient of the force
//! it books into [`PairSums::booked`]; the loop sums that force apart. The totals do not
//! depend on it.
//!
//! Terms are combined into a list by nesting pairs, `(A, (B, (C, Off)))`, evaluated in list
//! order; [`Off`] is the empty term: a term a scene does not declare is replaced by `Off`, and
//! every line of it compiles away.

use super::ledger::{self, Booking, Bookings, Ledger};
use crate::neighbours::NeighbourLists;
use crate::state::Vec3;

/// Neighbours processed together by the pair loop (measured, per step of the 20 k cube at
/// r_e = 2.1 and 4.2 l0: 16 is 3–6 % faster than 8, 32 slower than 16).
pub const CHUNK: usize = 16;

/// One lane per neighbour of a chunk.
pub type Lane<T> = [T; CHUNK];

/// The state a term reads, shared by all terms (borrowed from the particles).
#[derive(Clone, Copy, Debug)]
pub struct Neighbourhood<'a> {
    /// Number of fluid particles (indices `0..n_fluid`; walls follow).
    pub n_fluid: usize,
    /// Positions [m] (all particles).
    pub pos: &'a [Vec3],
    /// Velocities [m/s] (all particles; walls: ghost velocity).
    pub vel: &'a [Vec3],
    /// Densities [kg/m³] (all).
    pub rho: &'a [f64],
    /// Volumes `m/ρ` [m³] (all).
    pub vol: &'a [f64],
    /// Phase index per particle (all).
    pub phase: &'a [u8],
    /// Particle mass per phase [kg].
    pub mass: &'a [f64],
}

/// A neighbour `j` as the gather sees it.
#[derive(Clone, Copy, Debug)]
pub struct Neighbour {
    /// Particle index.
    pub j: usize,
    /// Its phase.
    pub phase: usize,
    /// Whether it is a wall particle (`j ≥ n_fluid`).
    pub is_wall: bool,
}

/// The particle `i` whose neighbours are being summed.
#[derive(Clone, Copy, Debug)]
pub struct Particle {
    /// Particle index.
    pub i: usize,
    /// Its phase.
    pub phase: usize,
}

/// The geometry of one pair, computed once per pair for every term.
#[derive(Clone, Copy, Debug)]
pub struct PairKinematics {
    /// `|x_ij|²` [m²].
    pub r2: f64,
    /// `|x_ij|` [m].
    pub r: f64,
    /// `1/|x_ij|` [1/m] (infinite for coincident particles; masked by `apart`).
    pub ir: f64,
    /// The particles do not coincide (coincident particles have no direction: no force).
    pub apart: bool,
    /// Within the kernel support.
    pub inside: bool,
    /// `(dW/dr)/r` [1/m⁵] (at the support for pairs outside it; masked by `inside`).
    pub dw_r: f64,
    /// `v_ij · x_ij` [m²/s] (zero lanes unless some term gathers velocities).
    pub vr: f64,
}

/// The sums one pair contributes to, each added to by the terms in list order.
#[derive(Clone, Copy, Debug, Default)]
pub struct PairSums {
    /// Coefficient `a_ij` [N/m] of `x_i − x_j` in the force on `i` (central forces).
    pub central: f64,
    /// Coefficient `b_ij` [N·s/m] of `v_i − v_j` in the force on `i` (viscous shear).
    pub shear: f64,
    /// The pair's part of `Σ_j (…)` in `dρ_i/dt = ρ_i Σ_j (…)` [1/s].
    pub rate: f64,
    /// Per ledger, the coefficient [N/m or N·s/m, by its [`Booking::part`]] of the force the
    /// term booked to it books, written by that term.
    pub booked: [f64; Ledger::COUNT],
}

/// Gathered per-neighbour data of a term: created once per rayon job, refilled per chunk.
pub trait Lanes: Send {
    /// Buffers whose unused lanes hold harmless values (lanes past a chunk's end are computed
    /// but never added).
    fn new() -> Self;
}

impl Lanes for () {
    fn new() -> Self {}
}

impl<A: Lanes, B: Lanes> Lanes for (A, B) {
    fn new() -> Self {
        (A::new(), B::new())
    }
}

/// A force term of the fused pair loop. Every method has a neutral default, so a term
/// implements only what it contributes to.
pub trait PairTerm: Sync {
    /// Whether the term takes part; [`Off`] sets it false.
    const ON: bool = true;
    /// Whether the term reads the velocity difference `v_i − v_j` (gathered only if some term
    /// does).
    const USES_VELOCITY: bool = false;
    /// Whether the term contributes to the density rate `dρ_i/dt`.
    const RATE: bool = false;
    /// Whether the term reaches beyond the kernel support (the lists' far part).
    const FAR: bool = false;
    /// The ledger of a term whose work is booked apart ([`super::ledger`]); such a term writes
    /// `PairSums::booked[ledger]` in [`PairTerm::pair`].
    const BOOKING: Option<Booking> = None;
    /// Per ledger, the booking of the term of the list booked to it.
    const BOOKINGS: Bookings = ledger::single(Self::BOOKING);
    /// What the term needs of particle `i`, computed once per particle.
    type Own: Copy;
    /// What the term gathers of each neighbour.
    type Lanes: Lanes;

    /// The per-particle values of `i`.
    fn own(&self, i: Particle) -> Self::Own;

    /// Gathers neighbour `nb` into lane `n`.
    #[inline(always)]
    fn gather(&self, _own: &Self::Own, _lanes: &mut Self::Lanes, _n: usize, _nb: Neighbour) {}

    /// Adds the term's parts of the pair sums of lane `n` to `sums`, in the sign convention of
    /// [`PairSums`].
    #[inline(always)]
    fn pair(
        &self,
        _sums: &mut PairSums,
        _own: &Self::Own,
        _lanes: &Self::Lanes,
        _n: usize,
        _k: &PairKinematics,
    ) {
    }

    /// Adds to `out` (one per fluid particle) the forces [N] of the pairs beyond the kernel
    /// support — the lists' far parts, each pair once ([`super::pairs_once`]).
    #[inline(always)]
    fn far_forces(&self, _lists: &NeighbourLists, _out: &mut [Vec3]) {}
}

/// The absent term: contributes nothing and compiles to nothing.
#[derive(Clone, Copy, Debug, Default)]
pub struct Off;

impl PairTerm for Off {
    const ON: bool = false;
    type Own = ();
    type Lanes = ();
    #[inline(always)]
    fn own(&self, _i: Particle) {}
}

/// A list of terms, evaluated head first: `(head, tail)`.
impl<A: PairTerm, B: PairTerm> PairTerm for (A, B) {
    const ON: bool = A::ON || B::ON;
    const USES_VELOCITY: bool = (A::ON && A::USES_VELOCITY) || (B::ON && B::USES_VELOCITY);
    const RATE: bool = (A::ON && A::RATE) || (B::ON && B::RATE);
    const FAR: bool = (A::ON && A::FAR) || (B::ON && B::FAR);
    const BOOKINGS: Bookings = ledger::merge(
        if A::ON {
            A::BOOKINGS
        } else {
            ledger::NO_BOOKINGS
        },
        if B::ON {
            B::BOOKINGS
        } else {
            ledger::NO_BOOKINGS
        },
    );
    type Own = (A::Own, B::Own);
    type Lanes = (A::Lanes, B::Lanes);

    #[inline(always)]
    fn own(&self, i: Particle) -> Self::Own {
        (self.0.own(i), self.1.own(i))
    }
    #[inline(always)]
    fn gather(&self, own: &Self::Own, lanes: &mut Self::Lanes, n: usize, nb: Neighbour) {
        if A::ON {
            self.0.gather(&own.0, &mut lanes.0, n, nb);
        }
        if B::ON {
            self.1.gather(&own.1, &mut lanes.1, n, nb);
        }
    }
    #[inline(always)]
    fn pair(
        &self,
        sums: &mut PairSums,
        own: &Self::Own,
        l: &Self::Lanes,
        n: usize,
        k: &PairKinematics,
    ) {
        if A::ON {
            self.0.pair(sums, &own.0, &l.0, n, k);
        }
        if B::ON {
            self.1.pair(sums, &own.1, &l.1, n, k);
        }
    }
    #[inline(always)]
    fn far_forces(&self, lists: &NeighbourLists, out: &mut [Vec3]) {
        if A::ON && A::FAR {
            self.0.far_forces(lists, out);
        }
        if B::ON && B::FAR {
            self.1.far_forces(lists, out);
        }
    }
}
