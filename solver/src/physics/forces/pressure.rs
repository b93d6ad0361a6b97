//! The pressure force: Eq. (11), Natsui 2021 (the Hu & Adams 2006 form),
//! `F_i = − Σ_j (p_i V_i² + p_j V_j²) ∇_i W_ij` [N].
//!
//! Acting on wall neighbours too, with the walls' extrapolated pressure (Adami et al. 2012):
//! that is what keeps the liquid out of a wall. The walls' own part `−p_w V_w² ∇_i W_iw` is
//! the gradient of no energy of the liquid (the wall pressure is extrapolated, not a state):
//! its work is booked in the energy budget ([`super::ledger`]); the rest of the term is the
//! gradient of the compression energy (`crate::observables::compression_energy`).

use super::ledger::{Booking, Ledger, Part};
use super::term::{Lane, Lanes, Neighbour, PairKinematics, PairSums, PairTerm, Particle, CHUNK};

/// The pressure term.
#[derive(Clone, Copy, Debug)]
pub struct Pressure<'a> {
    /// Pressure [Pa] (all particles).
    pub pressure: &'a [f64],
    /// Volume [m³] (all particles).
    pub vol: &'a [f64],
}

/// `p_j V_j²` [N·m] per neighbour.
pub struct PressureLanes {
    pv: Lane<f64>,
}

impl Lanes for PressureLanes {
    fn new() -> Self {
        PressureLanes { pv: [0.0; CHUNK] }
    }
}

impl PairTerm for Pressure<'_> {
    /// The walls' own part (module doc).
    const BOOKING: Option<Booking> = Some(Booking {
        ledger: Ledger::Pressure,
        part: Part::Central,
        liquid: false,
        walls: true,
    });
    /// `p_i V_i²` [N·m].
    type Own = f64;
    type Lanes = PressureLanes;

    #[inline(always)]
    fn own(&self, i: Particle) -> f64 {
        let v_i = self.vol[i.i];
        self.pressure[i.i] * v_i * v_i
    }
    #[inline(always)]
    fn gather(&self, _own: &f64, l: &mut PressureLanes, n: usize, nb: Neighbour) {
        let v_j = self.vol[nb.j];
        l.pv[n] = self.pressure[nb.j] * v_j * v_j;
    }
    #[inline(always)]
    fn pair(&self, s: &mut PairSums, pv_i: &f64, l: &PressureLanes, n: usize, k: &PairKinematics) {
        let v = (pv_i + l.pv[n]) * k.dw_r; // Eq. (11), Natsui 2021: −(p_i V_i² + p_j V_j²) ∇_i W_ij
        s.central -= if k.inside { v } else { 0.0 };
        // the neighbour's own part, booked for wall neighbours only
        let w = l.pv[n] * k.dw_r;
        s.booked[Ledger::Pressure as usize] = if k.inside { -w } else { 0.0 };
    }
}
