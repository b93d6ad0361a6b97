//! Laminar viscosity: Eq. (11), Natsui 2021 (the Hu & Adams 2006 form),
//! `F_i = Σ_j μ_ij (V_i² + V_j²) ((dW/dr)/r) v_ij` [N] with the pair viscosity `μ_ij` of the
//! model (the harmonic mean `2μ_iμ_j/(μ_i + μ_j)` between liquids, the liquid's own `μ` against a
//! no-slip wall). The kernel factor is the scalar `(dW/dr)/r` times `v_ij` (docs/model.md §3,
//! correction C3).
//!
//! Free-slip walls take no part: their lanes carry `μ = 0`.

use super::ledger::{Booking, Ledger, Part};
use super::term::{Lane, Lanes, Neighbour, PairKinematics, PairSums, PairTerm, Particle, CHUNK};

/// The laminar viscosity term.
#[derive(Clone, Copy, Debug)]
pub struct LaminarViscosity<'a> {
    /// Pair viscosity [Pa·s], row-major by phase.
    pub mu_pair: &'a [f64],
    /// Number of phases (row length of `mu_pair`).
    pub n_phases: usize,
    /// Volume [m³] (all particles).
    pub vol: &'a [f64],
    /// Number of fluid particles (wall `k` is particle `n_fluid + k`).
    pub n_fluid: usize,
    /// Per wall particle: no-slip?
    pub wall_no_slip: &'a [bool],
}

/// Per neighbour: the pair viscosity [Pa·s] (zero against a free-slip wall) and `V_j²` \[m⁶\].
pub struct LaminarLanes {
    mu: Lane<f64>,
    v2: Lane<f64>,
}

impl Lanes for LaminarLanes {
    fn new() -> Self {
        LaminarLanes {
            mu: [0.0; CHUNK],
            v2: [0.0; CHUNK],
        }
    }
}

/// Of particle `i`: `V_i²` \[m⁶\] and its row of pair viscosities [Pa·s].
#[derive(Clone, Copy)]
pub struct LaminarOwn<'a> {
    v2: f64,
    mu_row: &'a [f64],
}

impl<'a> PairTerm for LaminarViscosity<'a> {
    const USES_VELOCITY: bool = true;
    /// Dissipative; at no-slip walls it couples the liquid to the walls' ghost velocity.
    const BOOKING: Option<Booking> = Some(Booking {
        ledger: Ledger::Laminar,
        part: Part::Shear,
        liquid: true,
        walls: true,
    });
    type Own = LaminarOwn<'a>;
    type Lanes = LaminarLanes;

    #[inline(always)]
    fn own(&self, i: Particle) -> LaminarOwn<'a> {
        let v_i = self.vol[i.i];
        let nph = self.n_phases;
        LaminarOwn {
            v2: v_i * v_i,
            mu_row: &self.mu_pair[i.phase * nph..(i.phase + 1) * nph],
        }
    }
    #[inline(always)]
    fn gather(&self, own: &LaminarOwn<'a>, l: &mut LaminarLanes, n: usize, nb: Neighbour) {
        let v_j = self.vol[nb.j];
        l.v2[n] = v_j * v_j;
        let coupled = !nb.is_wall || self.wall_no_slip[nb.j - self.n_fluid];
        l.mu[n] = if coupled { own.mu_row[nb.phase] } else { 0.0 };
    }
    #[inline(always)]
    fn pair(
        &self,
        s: &mut PairSums,
        own: &LaminarOwn<'a>,
        l: &LaminarLanes,
        n: usize,
        k: &PairKinematics,
    ) {
        // Eq. (11), Natsui 2021: 2μiμj/(μi+μj) (V_i² + V_j²) (dW/dr / r) v_ij
        let v = l.mu[n] * (own.v2 + l.v2[n]) * k.dw_r;
        let b = if k.inside { v } else { 0.0 };
        s.shear += b;
        s.booked[Ledger::Laminar as usize] = b;
    }
}
