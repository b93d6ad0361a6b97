//! Artificial viscosity (Monaghan 1992): Eqs. (12)–(13), Natsui 2021, with the `m_i m_j`
//! factor that makes the term a force (docs/model.md §3, correction C2):
//! `F_i = − Σ_j m_i m_j Π_ij ∇_i W_ij` [N] for approaching pairs (`v_ij · x_ij < 0`),
//! `Π_ij = (−α1 c φ_ij + α2 φ_ij²) / ρ̄_ij`, `φ_ij = h v_ij·x_ij / (r² + (0.1 h)²)`.
//!
//! Between fluid particles only: wall lanes are switched off.

use super::ledger::{Booking, Ledger, Part};
use super::term::{Lane, Lanes, Neighbour, PairKinematics, PairSums, PairTerm, Particle, CHUNK};

/// The artificial viscosity term.
#[derive(Clone, Copy, Debug)]
pub struct ArtificialViscosity<'a> {
    /// `α1` (linear, bulk) [-].
    pub alpha1: f64,
    /// `α2` (quadratic, von Neumann–Richtmyer) [-].
    pub alpha2: f64,
    /// Sound speed `c` [m/s] (the mean `c̄_ij` of Eq. 12: one `c` for all phases).
    pub c_m_s: f64,
    /// Smoothing length `h` [m].
    pub h_m: f64,
    /// `(0.1 h)²` [m²], Eq. (13), Natsui 2021.
    pub eta2_m2: f64,
    /// Density [kg/m³] (all particles).
    pub rho: &'a [f64],
    /// Particle mass per phase [kg].
    pub mass: &'a [f64],
}

impl<'a> ArtificialViscosity<'a> {
    /// The term with coefficients `(α1, α2)`, sound speed `c` [m/s] and smoothing length `h`
    /// [m].
    pub fn new(alpha: (f64, f64), c_m_s: f64, h_m: f64, rho: &'a [f64], mass: &'a [f64]) -> Self {
        ArtificialViscosity {
            alpha1: alpha.0,
            alpha2: alpha.1,
            c_m_s,
            h_m,
            eta2_m2: 0.01 * h_m * h_m, // (0.1 h)², Eq. (13), Natsui 2021
            rho,
            mass,
        }
    }
}

/// Per neighbour: `ρ_j` [kg/m³], `m_j` [kg], and whether the pair is a fluid pair.
pub struct ArtificialLanes {
    rho: Lane<f64>,
    m: Lane<f64>,
    fluid: Lane<bool>,
}

impl Lanes for ArtificialLanes {
    fn new() -> Self {
        // unused lanes divide by a positive density
        ArtificialLanes {
            rho: [1.0; CHUNK],
            m: [0.0; CHUNK],
            fluid: [false; CHUNK],
        }
    }
}

impl PairTerm for ArtificialViscosity<'_> {
    const USES_VELOCITY: bool = true;
    /// Dissipative, between fluid particles only.
    const BOOKING: Option<Booking> = Some(Booking {
        ledger: Ledger::Artificial,
        part: Part::Central,
        liquid: true,
        walls: false,
    });
    /// `(m_i [kg], ρ_i [kg/m³])`.
    type Own = (f64, f64);
    type Lanes = ArtificialLanes;

    #[inline(always)]
    fn own(&self, i: Particle) -> (f64, f64) {
        (self.mass[i.phase], self.rho[i.i])
    }
    #[inline(always)]
    fn gather(&self, _own: &(f64, f64), l: &mut ArtificialLanes, n: usize, nb: Neighbour) {
        l.rho[n] = self.rho[nb.j];
        l.m[n] = self.mass[nb.phase];
        l.fluid[n] = !nb.is_wall;
    }
    #[inline(always)]
    fn pair(
        &self,
        s: &mut PairSums,
        own: &(f64, f64),
        l: &ArtificialLanes,
        n: usize,
        k: &PairKinematics,
    ) {
        let (m_i, rho_i) = *own;
        let phi = self.h_m * k.vr / (k.r2 + self.eta2_m2); // Eq. (13), Natsui 2021
                                                           // Eq. (12), Natsui 2021 with m_i m_j Π_ij
        let pi_ij = (-self.alpha1 * self.c_m_s * phi + self.alpha2 * phi * phi)
            / (0.5 * (rho_i + l.rho[n]));
        let v = m_i * l.m[n] * pi_ij * k.dw_r;
        let a = if k.inside & l.fluid[n] & (k.vr < 0.0) {
            v
        } else {
            0.0
        };
        s.central -= a;
        s.booked[Ledger::Artificial as usize] = -a;
    }
}
