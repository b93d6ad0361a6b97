//! Laminar viscosity, in one of two pair forms (`effects.laminar_form`, docs/model.md §3):
//!
//! - [`LaminarViscosity`], Eq. (11), Natsui 2021 (the Hu & Adams 2006 form),
//!   `F_i = Σ_j μ_ij (V_i² + V_j²) ((dW/dr)/r) v_ij` [N]. The kernel factor is the scalar
//!   `(dW/dr)/r` times `v_ij` (docs/model.md §3, correction C3).
//! - [`MonaghanClearyGingold`] (Monaghan 2005, after Monaghan & Gingold 1983 and Cleary 1998),
//!   `F_i = Σ_j 2(d + 2) μ_ij V_i V_j (v_ij·x_ij)/(r² + η²) ((dW/dr)/r) x_ij` [N], `d = 3`,
//!   `η = 0.1 h`: central, so it conserves angular momentum and a rigid rotation feels none of
//!   it; Colagrossi et al. 2011 show it stays consistent at a free surface.
//!
//! Both tend to `μ∇²v` for a divergence-free flow (the lattice moments of either are measured
//! by the tests). The pair viscosity `μ_ij` of the model is the harmonic mean
//! `2μ_iμ_j/(μ_i + μ_j)` between liquids and the liquid's own `μ` against a no-slip wall.
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

/// Per neighbour: the pair viscosity [Pa·s] (zero against a free-slip wall) and `V_j` \[m³\].
pub struct LaminarLanes {
    mu: Lane<f64>,
    v: Lane<f64>,
}

impl Lanes for LaminarLanes {
    fn new() -> Self {
        LaminarLanes {
            mu: [0.0; CHUNK],
            v: [0.0; CHUNK],
        }
    }
}

/// Of particle `i`: `V_i` \[m³\], `V_i²` \[m⁶\] and its row of pair viscosities [Pa·s].
#[derive(Clone, Copy)]
pub struct LaminarOwn<'a> {
    v: f64,
    v2: f64,
    mu_row: &'a [f64],
}

impl<'a> LaminarViscosity<'a> {
    #[inline(always)]
    fn own_values(&self, i: Particle) -> LaminarOwn<'a> {
        let v_i = self.vol[i.i];
        let nph = self.n_phases;
        LaminarOwn {
            v: v_i,
            v2: v_i * v_i,
            mu_row: &self.mu_pair[i.phase * nph..(i.phase + 1) * nph],
        }
    }

    #[inline(always)]
    fn gather_lane(&self, own: &LaminarOwn<'a>, l: &mut LaminarLanes, n: usize, nb: Neighbour) {
        l.v[n] = self.vol[nb.j];
        let coupled = !nb.is_wall || self.wall_no_slip[nb.j - self.n_fluid];
        l.mu[n] = if coupled { own.mu_row[nb.phase] } else { 0.0 };
    }
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
        self.own_values(i)
    }
    #[inline(always)]
    fn gather(&self, own: &LaminarOwn<'a>, l: &mut LaminarLanes, n: usize, nb: Neighbour) {
        self.gather_lane(own, l, n, nb);
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
        let v = l.mu[n] * (own.v2 + l.v[n] * l.v[n]) * k.dw_r;
        let b = if k.inside { v } else { 0.0 };
        s.shear += b;
        s.booked[Ledger::Laminar as usize] = b;
    }
}

/// `2(d + 2)` with `d = 3`: the factor that makes the central form tend to `μ∇²v`
/// (Monaghan 2005; the lattice moment is measured in the solver's tests).
pub const MCG_FACTOR: f64 = 10.0;

/// The Monaghan–Cleary–Gingold form of the laminar viscosity: the same pair viscosities and
/// walls as [`LaminarViscosity`], a central force.
#[derive(Clone, Copy, Debug)]
pub struct MonaghanClearyGingold<'a> {
    /// The pair viscosities, volumes and walls.
    pub base: LaminarViscosity<'a>,
    /// `η²` = `(0.1 h)²` [m²], keeping coincident pairs finite (as in the artificial viscosity).
    pub eta2_m2: f64,
}

impl<'a> PairTerm for MonaghanClearyGingold<'a> {
    const USES_VELOCITY: bool = true;
    /// Dissipative; at no-slip walls it couples the liquid to the walls' ghost velocity.
    const BOOKING: Option<Booking> = Some(Booking {
        ledger: Ledger::Laminar,
        part: Part::Central,
        liquid: true,
        walls: true,
    });
    type Own = LaminarOwn<'a>;
    type Lanes = LaminarLanes;

    #[inline(always)]
    fn own(&self, i: Particle) -> LaminarOwn<'a> {
        self.base.own_values(i)
    }
    #[inline(always)]
    fn gather(&self, own: &LaminarOwn<'a>, l: &mut LaminarLanes, n: usize, nb: Neighbour) {
        self.base.gather_lane(own, l, n, nb);
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
        // Monaghan 2005: 2(d+2) μ_ij V_i V_j (v_ij·x_ij)/(r² + η²) (dW/dr / r) x_ij; V_i V_j
        // first, so that the j-on-i coefficient is bitwise the i-on-j one
        let vv = own.v * l.v[n];
        let v = MCG_FACTOR * (vv * l.mu[n]) * (k.vr / (k.r2 + self.eta2_m2)) * k.dw_r;
        let a = if k.inside { v } else { 0.0 };
        s.central += a;
        s.booked[Ledger::Laminar as usize] = a;
    }
}
