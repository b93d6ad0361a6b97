//! The continuity density rate: `dρ_i/dt = ρ_i Σ_j V_j v_ij · ∇_i W_ij` [kg/(m³ s)]
//! (the density scheme `continuity`; the loop multiplies the sum by `ρ_i`).

use super::term::{Lane, Lanes, Neighbour, PairKinematics, PairSums, PairTerm, Particle, CHUNK};

/// The continuity density rate.
#[derive(Clone, Copy, Debug)]
pub struct ContinuityRate<'a> {
    /// Volume [m³] (all particles).
    pub vol: &'a [f64],
}

/// `V_j` [m³] per neighbour.
pub struct ContinuityLanes {
    vol: Lane<f64>,
}

impl Lanes for ContinuityLanes {
    fn new() -> Self {
        ContinuityLanes { vol: [0.0; CHUNK] }
    }
}

impl PairTerm for ContinuityRate<'_> {
    const USES_VELOCITY: bool = true;
    const RATE: bool = true;
    type Own = ();
    type Lanes = ContinuityLanes;

    #[inline(always)]
    fn own(&self, _i: Particle) {}
    #[inline(always)]
    fn gather(&self, _own: &(), l: &mut ContinuityLanes, n: usize, nb: Neighbour) {
        l.vol[n] = self.vol[nb.j];
    }
    #[inline(always)]
    fn pair(&self, s: &mut PairSums, _own: &(), l: &ContinuityLanes, n: usize, k: &PairKinematics) {
        let v = l.vol[n] * k.vr * k.dw_r; // V_j v_ij·∇_i W_ij
        s.rate += if k.inside { v } else { 0.0 };
    }
}
