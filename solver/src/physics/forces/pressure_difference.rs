//! The pressure force in its difference form (`density.pressure_gradient = "difference"`,
//! docs/model.md §3): between liquid particles
//!
//! `F_i = − V_i Σ_j V_j (p_j − p_i) ∇_i W_ij` [N],
//!
//! which is zero for a uniform pressure whatever the particles' arrangement (zeroth-order
//! consistent), where the symmetric form (Eq. 11, Natsui 2021, [`super::Pressure`]) loads every
//! pair with `p_i V_i² + p_j V_j²`: a pressure level then holds the arrangement like a solid's
//! stiffness. Measured on the wall normal's 120° caps (docs/findings.md): with the symmetric
//! form a receding contact line stops ~9° short of its angle, and with a background pressure of
//! 4 kPa it hardly recedes at all; with the difference form it reaches its static equilibrium.
//! Wall neighbours take the same form with the walls' extrapolated pressure (Adami et al.
//! 2012), `−V_i V_w (p_w − p_i) ∇_i W_iw`: kept symmetric beside a liquid in the difference
//! form, a wall pushed the liquid's first layers off by the pressure level (a 60° cap drew back
//! to 74°, docs/findings.md). The form is not antisymmetric in `i, j` (momentum is conserved
//! to the form's truncation error only), and its departure from the gradient of the
//! compression energy is booked in the energy budget: the pressure ledger's liquid channel for
//! liquid pairs, its wall channel for wall pairs (as the symmetric form's walls' own part).

use super::ledger::{Booking, Ledger, Part};
use super::term::{Lane, Lanes, Neighbour, PairKinematics, PairSums, PairTerm, Particle, CHUNK};

/// The pressure term in its difference form.
#[derive(Clone, Copy, Debug)]
pub struct PressureDifference<'a> {
    /// Pressure [Pa] (all particles).
    pub pressure: &'a [f64],
    /// Volume [m³] (all particles).
    pub vol: &'a [f64],
}

/// Per neighbour: `p_j V_j²` [N·m], `p_j V_j` [N], `V_j` [m³], and 1 for a wall particle (else
/// 0).
pub struct PressureDifferenceLanes {
    pv2: Lane<f64>,
    pv: Lane<f64>,
    v: Lane<f64>,
    wall: Lane<f64>,
}

impl Lanes for PressureDifferenceLanes {
    fn new() -> Self {
        PressureDifferenceLanes {
            pv2: [0.0; CHUNK],
            pv: [0.0; CHUNK],
            v: [0.0; CHUNK],
            wall: [0.0; CHUNK],
        }
    }
}

/// Of particle `i`: `p_i V_i²` [N·m], `p_i V_i` [N], `V_i` [m³].
#[derive(Clone, Copy, Debug)]
pub struct OwnPressure {
    pv2: f64,
    pv: f64,
    v: f64,
}

impl PairTerm for PressureDifference<'_> {
    /// The pairs' departure from the gradient of the compression energy (module doc).
    const BOOKING: Option<Booking> = Some(Booking {
        ledger: Ledger::Pressure,
        part: Part::Central,
        liquid: true,
        walls: true,
    });
    type Own = OwnPressure;
    type Lanes = PressureDifferenceLanes;

    #[inline(always)]
    fn own(&self, i: Particle) -> OwnPressure {
        let (p, v) = (self.pressure[i.i], self.vol[i.i]);
        OwnPressure {
            pv2: p * v * v,
            pv: p * v,
            v,
        }
    }
    #[inline(always)]
    fn gather(&self, _own: &OwnPressure, l: &mut PressureDifferenceLanes, n: usize, nb: Neighbour) {
        let (p, v) = (self.pressure[nb.j], self.vol[nb.j]);
        l.pv2[n] = p * v * v;
        l.pv[n] = p * v;
        l.v[n] = v;
        l.wall[n] = if nb.is_wall { 1.0 } else { 0.0 };
    }
    #[inline(always)]
    fn pair(
        &self,
        s: &mut PairSums,
        o: &OwnPressure,
        l: &PressureDifferenceLanes,
        n: usize,
        k: &PairKinematics,
    ) {
        let difference = o.v * l.pv[n] - o.pv * l.v[n]; // −V_i V_j (p_j − p_i) ∇_i W_ij
        s.central -= if k.inside { difference * k.dw_r } else { 0.0 };
        // booked: the departure from the gradient of the compression energy, whose pair part is
        // the symmetric form's −(p_i V_i² + p_j V_j²) ∇_i W_ij between liquid particles and
        // −p_i V_i² ∇_i W_iw with a wall particle (the wall pressure has no energy)
        let conservative = o.pv2 + (1.0 - l.wall[n]) * l.pv2[n];
        let b = conservative - difference;
        s.booked[Ledger::Pressure as usize] = if k.inside { b * k.dw_r } else { 0.0 };
    }
}
