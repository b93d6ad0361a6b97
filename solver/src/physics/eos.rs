//! Tait's equation of state — Eq. (14), Natsui 2021.

/// `p = (c² ρ0/γ) ((ρ/ρ0)^γ − 1)` with `γ = 7` and one sound speed for all phases.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TaitEos {
    /// Square of the artificial sound speed `c²` [m²/s²].
    pub c2: f64,
}

/// Adiabatic exponent γ of Tait's equation [-] (Natsui 2021 §2.3).
pub const GAMMA: i32 = 7;

impl TaitEos {
    /// Pressure [Pa] of density `rho` [kg/m³] for a phase of reference density `rho0` [kg/m³].
    #[inline(always)]
    pub fn pressure(&self, rho: f64, rho0: f64) -> f64 {
        let g = GAMMA as f64;
        self.c2 * rho0 / g * ((rho / rho0).powi(GAMMA) - 1.0) // Eq. (14), Natsui 2021
    }

    /// Density [kg/m³] at pressure `p` [Pa] (the inverse of [`TaitEos::pressure`]); tensions
    /// beyond the EOS's limit `−c²ρ0/γ` give a vanishing density, clipped at `1e-3 ρ0`.
    #[inline(always)]
    pub fn density(&self, p: f64, rho0: f64) -> f64 {
        let g = GAMMA as f64;
        let base = (1.0 + g * p / (self.c2 * rho0)).max(1e-21);
        rho0 * base.powf(1.0 / g)
    }

    /// Compression energy per unit mass [J/kg] at density `rho` [kg/m³] for a phase of
    /// reference density `rho0` [kg/m³]: `e(ρ) = ∫_{ρ0}^{ρ} p(ρ')/ρ'² dρ'`, the work done on one
    /// kilogram compressed from `ρ0` to `ρ`, so that `d(m e)/dt = (m p/ρ²) dρ/dt`. With
    /// `clip_negative` the pressure is `max(p, 0)` (the solver's `negative_pressure = "clip"`)
    /// and `e = 0` for `ρ < ρ0`.
    ///
    /// Closed form: with `x = ρ/ρ0`, `p = (c²ρ0/γ)(x^γ − 1)` and `dρ = ρ0 dx`,
    /// `e = (c²/γ) ∫_1^x (x'^(γ−2) − x'^(−2)) dx' = (c²/γ) [(x^(γ−1) − 1)/(γ − 1) + 1/x − 1]`.
    /// The bracket cancels to second order at `x = 1`; written as
    /// `(x − 1)² / ((γ − 1) x) · Σ_{m=0}^{γ−2} (γ − 1 − m) x^m` (expand `x^(γ−1) − 1` and
    /// `x^k − 1` in powers of `x` and collect) it has only positive terms and no cancellation,
    /// and at `x = 1` gives `e ≈ c² (x − 1)²/2` (Σ (γ − 1 − m) = γ(γ − 1)/2). `e ≥ 0` on both
    /// sides of `ρ0`: a stretched liquid (Tait's tension) stores energy too.
    #[inline]
    pub fn energy_per_kg(&self, rho: f64, rho0: f64, clip_negative: bool) -> f64 {
        let x = rho / rho0;
        if clip_negative && x < 1.0 {
            return 0.0;
        }
        let d = x - 1.0;
        // Σ_{m=0}^{γ−2} (γ − 1 − m) x^m by Horner, from the top power (coefficient 1) down
        let mut poly = 0.0;
        for k in 1..GAMMA {
            poly = poly * x + k as f64;
        }
        let g = GAMMA as f64;
        self.c2 / g * d * d / ((g - 1.0) * x) * poly
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tait_is_zero_at_rest_and_inverts() {
        // p(ρ0) = 0 exactly; dp/dρ at ρ0 equals c² (the definition of the sound speed, Eq. 9);
        // density(pressure(ρ)) returns ρ to round-off.
        let eos = TaitEos { c2: 150.0 };
        assert_eq!(eos.pressure(4500.0, 4500.0), 0.0);
        let d = 1e-3;
        let slope =
            (eos.pressure(4500.0 + d, 4500.0) - eos.pressure(4500.0 - d, 4500.0)) / (2.0 * d);
        // central difference of a degree-7 polynomial with d/ρ0 = 2e-7: relative error ~1e-12
        assert!((slope - 150.0).abs() < 1e-6, "{slope}");
        for rho in [4300.0, 4500.0, 4700.0] {
            let back = eos.density(eos.pressure(rho, 4500.0), 4500.0);
            assert!((back - rho).abs() < 1e-9 * rho);
        }
    }

    /// `∫_{ρ0}^{ρ} max(p, 0)/ρ'² dρ'` (clipped) or `∫ p/ρ'² dρ'` [J/kg] by composite Simpson
    /// with `n` intervals, from the pressure function itself.
    fn simpson(eos: &TaitEos, rho: f64, rho0: f64, clip: bool, n: usize) -> f64 {
        let f = |r: f64| {
            let p = eos.pressure(r, rho0);
            (if clip { p.max(0.0) } else { p }) / (r * r)
        };
        let h = (rho - rho0) / n as f64;
        let mut s = f(rho0) + f(rho);
        for k in 1..n {
            s += f(rho0 + k as f64 * h) * if k % 2 == 1 { 4.0 } else { 2.0 };
        }
        s * h / 3.0
    }

    #[test]
    fn compression_energy_is_the_integral_of_the_pressure_the_solver_uses() {
        let eos = TaitEos { c2: 150.0 };
        let rho0 = 997.0;
        for x in [0.3, 0.7, 0.95, 0.999, 1.0, 1.001, 1.02, 1.3, 2.0] {
            let rho = x * rho0;
            for clip in [false, true] {
                let e = eos.energy_per_kg(rho, rho0, clip);
                // Simpson on a smooth integrand (the clipped one is zero below ρ0, so each
                // interval lies on one side of the kink): error ~ h⁴ f⁗, with 2000 intervals
                // over at most ρ0 below 1e-12 relative; 1e-10 leaves margin for the round-off
                // of 2000 terms
                let q = simpson(&eos, rho, rho0, clip, 2000);
                let scale = q.abs().max(1e-300);
                assert!(
                    (e - q).abs() <= 1e-10 * scale,
                    "x = {x}, clip {clip}: {e} vs {q}"
                );
                assert!(e >= 0.0);
            }
        }
        // near ρ0: e = c²(δ²/2 + δ³/3 + …) with δ = x − 1 (integrate de/dx = (c²/γ)(x^(γ−2) −
        // x^(−2)) = c²(δ + δ² + …) for γ = 7); at δ = 2⁻³⁰ (exact in binary, with ρ0 a power of
        // two) the naive bracket would keep no digit, the closed form all but a few ulps: the
        // ratio to c²δ²/2 is 1 + 2δ/3 (6e-10) plus ~1e-15 of rounding, within 1e-12 of that
        let (rho0, d) = (1024.0, 2f64.powi(-30));
        let e = eos.energy_per_kg(rho0 + rho0 * d, rho0, false);
        let ratio = e / (0.5 * 150.0 * d * d);
        assert!((ratio - (1.0 + 2.0 * d / 3.0)).abs() < 1e-12, "{ratio}");
        assert_eq!(eos.energy_per_kg(0.9 * rho0, rho0, true), 0.0);
    }
}
