//! Kondo et al. (2007)'s pairwise potential, `P(r) = (1/3)(r − 1.5 l0 + 0.5 r_e)(r − r_e)²` for
//! `r < r_e` [m³]; the force on `i` is `F_i = Σ_j C_ij P'(r_ij) e_ij` [N] with
//! `P'(r) = (r − l0)(r − r_e)` — Eq. (15), Natsui 2021, in the corrected form of docs/model.md §4
//! (correction C4): the pair coefficient sits inside the sum and the normalisation `S` is a constant of the reference
//! lattice, not each particle's current sum (which would blow up at the surface).
//!
//! A smoother family beside it (the project's, not the papers'): `P'(r) = (r − l0)(r − r_e)
//! |r − r_e|^(m−1) / l0^(m−1)` of order `m` = 2 or 3 — the sign of Kondo's, attractive between
//! `l0` and `r_e` — whose derivatives up to order `m − 1` vanish at the cut-off.
//! Kondo's is order 1: `P''` jumps at `r_e`, and the particle lattice's shear moduli — sums over
//! its shells that would vanish as integrals — then swing with `r_e` (`verify lattice-moduli`).
//! Every coefficient follows from the same surface sum `S`, so σ stays what the user gives.

/// The potential with spacing `l0`, cut-off `r_e` and order `m` (1: Kondo 2007).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Kondo2007Potential {
    /// Initial particle spacing `l0` [m]: the force vanishes there.
    pub l0_m: f64,
    /// Cut-off `r_e` [m]: potential and force vanish there.
    pub r_e_m: f64,
    /// Order `m` ∈ {1, 2, 3} of the force's zero at the cut-off (1: Kondo 2007).
    pub order: u8,
}

impl Kondo2007Potential {
    /// Kondo 2007's potential (order 1).
    pub fn kondo(l0_m: f64, r_e_m: f64) -> Self {
        Self {
            l0_m,
            r_e_m,
            order: 1,
        }
    }

    /// Potential `P(r)` [m³] with `P(r_e) = 0`; the physical pair energy is `−C P(r)`.
    #[inline(always)]
    pub fn p(&self, r_m: f64) -> f64 {
        if r_m >= self.r_e_m {
            return 0.0;
        }
        let a = r_m - self.r_e_m;
        match self.order {
            1 => (r_m - 1.5 * self.l0_m + 0.5 * self.r_e_m) * a * a / 3.0, // Kondo 2007
            // −∫_r^{r_e} P'(s) ds with u = s − r_e ≤ 0, |u|^(m−1) = (−1)^(m−1) u^(m−1)
            m => {
                let m = m as i32;
                let b = self.r_e_m - self.l0_m;
                let sign = if m % 2 == 0 { -1.0 } else { 1.0 };
                sign * (a.powi(m + 2) / (m + 2) as f64 + b * a.powi(m + 1) / (m + 1) as f64)
                    / self.l0_m.powi(m - 1)
            }
        }
    }

    /// Derivative `P'(r)` [m²] (0 beyond `r_e`).
    #[inline(always)]
    pub fn dp_dr(&self, r_m: f64) -> f64 {
        if r_m >= self.r_e_m {
            return 0.0;
        }
        self.pair_force_inside(1.0, r_m)
    }

    /// Second derivative `P''(r)` [m] (0 beyond `r_e`; at `r_e` itself the value from inside:
    /// for order 1, `r_e − l0`, `P''` jumps there): for the elastic moduli of the particle
    /// lattice, not used by the step.
    pub fn d2p_dr2(&self, r_m: f64) -> f64 {
        if r_m > self.r_e_m {
            return 0.0;
        }
        let m = self.order as i32;
        let a = r_m - self.r_e_m;
        let sign = if m % 2 == 0 { -1.0 } else { 1.0 };
        // d/dr [(r − l0) a^m] = a^m + m (r − l0) a^(m−1)
        sign * (a.powi(m) + m as f64 * (r_m - self.l0_m) * a.powi(m - 1)) / self.l0_m.powi(m - 1)
    }

    /// The pair force magnitude `C P'(r)` [N] of a pair with coefficient `c` [N/m²] at a
    /// distance `r < r_e` [m] (no cut-off test: the force loop masks its lanes itself).
    /// Negative is attractive: the force on `i` is this along `e_ij` (from `j` to `i`). The
    /// one place `P'` is written.
    #[inline(always)]
    pub fn pair_force_inside(&self, c_n_m2: f64, r_m: f64) -> f64 {
        let a = r_m - self.r_e_m;
        // the smoother orders' extra factor |a/l0|^(m−1) (a < 0 inside); exactly 1 for Kondo's, whose bits
        // are unchanged by the multiplication
        let u = a * (1.0 / self.l0_m);
        // 1, −u or u² as the polynomial e0 + u (e1 + u e2), without a branch: the force loops
        // are vectorised only if the pair's arithmetic has none (each form is exact: the
        // zero coefficients add only zeros)
        let o = self.order;
        let e0 = f64::from(u8::from((o != 2) & (o != 3)));
        let e1 = -f64::from(u8::from(o == 2));
        let e2 = f64::from(u8::from(o == 3));
        let extra = e0 + u * (e1 + u * e2);
        c_n_m2 * (r_m - self.l0_m) * (a * extra) // Eq. (15), Natsui 2021 (order 1)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn derivatives_agree_with_finite_differences_for_every_order() {
        for order in 1..=3 {
            let p = Kondo2007Potential {
                l0_m: 1e-4,
                r_e_m: 4.2e-4,
                order,
            };
            for r in [0.7e-4, 1e-4, 2.3e-4, 4.1e-4] {
                let d = 1e-9;
                let fd1 = (p.p(r + d) - p.p(r - d)) / (2.0 * d);
                let fd2 = (p.dp_dr(r + d) - p.dp_dr(r - d)) / (2.0 * d);
                // central differences: O(d²) truncation against values of order l0²: 1e-6
                // relative to the scale of P' (l0 r_e) and P'' (r_e)
                assert!(
                    (fd1 - p.dp_dr(r)).abs() < 1e-6 * 4.2e-8,
                    "m={order} r={r}: {fd1} {}",
                    p.dp_dr(r)
                );
                assert!(
                    (fd2 - p.d2p_dr2(r)).abs() < 1e-6 * 4.2e-4,
                    "m={order} r={r}"
                );
            }
            assert_eq!(p.p(4.2e-4), 0.0);
            // the force vanishes at the spacing and at the cut-off
            assert_eq!(p.dp_dr(1e-4), 0.0);
            assert!(p.pair_force_inside(1.0, 4.2e-4).abs() < 1e-30);
        }
    }
}
