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
}
