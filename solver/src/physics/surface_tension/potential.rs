//! Kondo et al. (2007)'s pairwise potential, `P(r) = (1/3)(r − 1.5 l0 + 0.5 r_e)(r − r_e)²` for
//! `r < r_e` [m³]; the force on `i` is `F_i = Σ_j C_ij P'(r_ij) e_ij` [N] with
//! `P'(r) = (r − l0)(r − r_e)` — Eq. (15), Natsui 2021, in the corrected form of physics.md §4: the pair
//! coefficient sits inside the sum and the normalisation `S` is a constant of the reference
//! lattice, not each particle's current sum (which would blow up at the surface).

/// Kondo et al. (2007)'s pairwise potential with spacing `l0` and cut-off `r_e`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Kondo2007Potential {
    /// Initial particle spacing `l0` [m]: the force vanishes there.
    pub l0_m: f64,
    /// Cut-off `r_e` [m]: potential and force vanish there.
    pub r_e_m: f64,
}

impl Kondo2007Potential {
    /// Potential `P(r)` [m³]; the physical pair energy is `−C P(r)`.
    #[inline(always)]
    pub fn p(&self, r_m: f64) -> f64 {
        if r_m >= self.r_e_m {
            return 0.0;
        }
        let a = r_m - self.r_e_m;
        (r_m - 1.5 * self.l0_m + 0.5 * self.r_e_m) * a * a / 3.0 // Kondo 2007
    }

    /// Derivative `P'(r) = (r − l0)(r − r_e)` [m²] (0 beyond `r_e`).
    #[inline(always)]
    pub fn dp_dr(&self, r_m: f64) -> f64 {
        if r_m >= self.r_e_m {
            return 0.0;
        }
        self.pair_force_inside(1.0, r_m)
    }

    /// Second derivative `P''(r) = 2r − l0 − r_e` [m] (0 beyond `r_e`; at `r_e` itself the
    /// value from inside, `r_e − l0`: `P''` jumps there): for the elastic moduli of the
    /// particle lattice, not used by the step.
    pub fn d2p_dr2(&self, r_m: f64) -> f64 {
        if r_m > self.r_e_m {
            return 0.0;
        }
        2.0 * r_m - self.l0_m - self.r_e_m
    }

    /// The pair force magnitude `C P'(r)` [N] of a pair with coefficient `c` [N/m²] at a
    /// distance `r < r_e` [m] (no cut-off test: the force loop masks its lanes itself).
    /// Positive is attractive. The one place `P'` is written.
    #[inline(always)]
    pub fn pair_force_inside(&self, c_n_m2: f64, r_m: f64) -> f64 {
        c_n_m2 * (r_m - self.l0_m) * (r_m - self.r_e_m) // Eq. (15), Natsui 2021
    }
}
