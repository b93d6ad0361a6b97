//! Small-amplitude shape oscillations of a viscous drop in an unbounded viscous host liquid,
//! at low viscosity (Miller & Scriven 1968, "The oscillations of a fluid droplet immersed in
//! another fluid", J. Fluid Mech. 32, 417–435).
//!
//! # What is computed
//!
//! Lamb's inviscid mode ([`super::lamb::lamb_angular_frequency_in_host`]) slips at the
//! interface: its tangential velocity jumps there by `(2l+1)/(l+1)` times the inner one's. A
//! viscous pair of liquids cannot slip, and the jump is taken up by an oscillating Stokes
//! layer of thickness `δ = √(2ν/ω)` on either side. When `δ ≪ R` it dominates the damping,
//! at order `√ν`, where a free drop's (Lamb's `(l−1)(2l+1)ν/R²`) is of order `ν`:
//!
//! ```text
//! γ_bl = (2l+1)² √(ω₀/2) · S / (2 R ((l+1) ρ_i + l ρ_o)),   S = s_i s_o/(s_i + s_o), s = √(μρ)
//! γ_bulk = (2l+1) ((l+1)(l−1) μ_i + l(l+2) μ_o) / (R² ((l+1) ρ_i + l ρ_o))
//! ω ≈ ω₀ − γ_bl
//! ```
//!
//! - `γ_bl` is the Stokes layers' time-averaged dissipation over twice the mode's energy. Each
//!   side's layer carries the share of the jump that makes the shear stress continuous
//!   (`s_i`-weighted), and its dissipation per area is `μ |V|²/(2δ)`. This is Miller &
//!   Scriven's `½ α ω₀^{1/2}` with `α = (2l+1)² S / (√2 R ((l+1)ρ_i + lρ_o))`.
//! - The layer's impedance is proportional to `√(iω) = (1+i) √(ω/2)`: it adds as much
//!   inertia as it dissipates, so the frequency falls by the same `γ_bl` (Miller & Scriven's
//!   `ω = ω₀ − ½ α ω₀^{1/2}`).
//! - `γ_bulk` is the dissipation `2μ ∫ |∇∇φ|² dV` of the inviscid flow on both sides, over
//!   twice its energy. With `ρ_o = μ_o = 0` it is Lamb's free drop, `(l−1)(2l+1)ν/R²`.
//!
//! # Assumptions
//!
//! - Linear theory, a clean interface (constant, uniform tension), incompressible liquids.
//! - `δ ≪ R`: the corrections are the first terms of expansions in `√(ν/(ω R²))`. Dropped:
//!   the next order of the frequency (Miller & Scriven's `+¼ α² = γ_bl²/ω₀`, 0.13 % of `ω₀`
//!   for a 1 mm water drop in a water-like host) and the layer's own `O(ν)` corrections to
//!   the damping, beside which `γ_bulk` stands.
//!
//! # Invalid input
//!
//! Non-finite or negative properties, or a mode the inviscid formula refuses, give `NAN`.

use super::lamb::lamb_angular_frequency_in_host;
use std::f64::consts::PI;

/// A liquid's density \[kg/m³\] and dynamic viscosity \[Pa·s\].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Liquid {
    /// Density \[kg/m³\].
    pub density_kg_m3: f64,
    /// Dynamic viscosity \[Pa·s\].
    pub viscosity_pa_s: f64,
}

impl Liquid {
    fn is_valid(&self) -> bool {
        let ok = |x: f64| x.is_finite() && x >= 0.0;
        ok(self.density_kg_m3) && ok(self.viscosity_pa_s)
    }
    /// `√(μρ)` \[kg/(m² s^{1/2})\]: a Stokes layer's shear stress per velocity and `√ω`.
    fn layer_admittance(&self) -> f64 {
        (self.viscosity_pa_s * self.density_kg_m3).sqrt()
    }
}

/// The mode of degree `l` of a drop in a host, to first order in the viscosities.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HostMode {
    /// Lamb's inviscid angular frequency `ω₀` \[rad/s\].
    pub inviscid_rad_s: f64,
    /// The interface's boundary-layer decay rate `γ_bl` \[1/s\] (also the frequency's shift).
    pub boundary_layer_per_s: f64,
    /// The bulk decay rate `γ_bulk` \[1/s\].
    pub bulk_per_s: f64,
}

impl HostMode {
    /// The angular frequency `ω₀ − γ_bl` \[rad/s\].
    pub fn angular_frequency_rad_s(&self) -> f64 {
        // Miller & Scriven (1968): ω = ω₀ − ½ α ω₀^{1/2} = ω₀ − γ_bl
        self.inviscid_rad_s - self.boundary_layer_per_s
    }
    /// The period `2π/(ω₀ − γ_bl)` \[s\].
    pub fn period_s(&self) -> f64 {
        2.0 * PI / self.angular_frequency_rad_s()
    }
    /// The inviscid period `2π/ω₀` \[s\].
    pub fn inviscid_period_s(&self) -> f64 {
        2.0 * PI / self.inviscid_rad_s
    }
    /// The amplitude's decay rate `γ_bl + γ_bulk` \[1/s\].
    pub fn damping_rate_per_s(&self) -> f64 {
        self.boundary_layer_per_s + self.bulk_per_s
    }
}

/// The mode of degree `l` of a drop (`drop`) of radius `radius_m` \[m\] in an unbounded host
/// (`host`), with the interfacial tension `sigma_n_m` \[N/m\].
pub fn mode_in_host(l: u32, sigma_n_m: f64, drop: Liquid, host: Liquid, radius_m: f64) -> HostMode {
    let nan = HostMode {
        inviscid_rad_s: f64::NAN,
        boundary_layer_per_s: f64::NAN,
        bulk_per_s: f64::NAN,
    };
    if !drop.is_valid() || !host.is_valid() {
        return nan;
    }
    let omega0 = lamb_angular_frequency_in_host(
        l,
        sigma_n_m,
        drop.density_kg_m3,
        host.density_kg_m3,
        radius_m,
    );
    if !omega0.is_finite() {
        return nan;
    }
    let d = f64::from(l);
    let inertia = (d + 1.0) * drop.density_kg_m3 + d * host.density_kg_m3;
    let (si, so) = (drop.layer_admittance(), host.layer_admittance());
    // the layers in series: the shear stress is continuous, the velocity jump shared
    let s = if si + so > 0.0 {
        si * so / (si + so)
    } else {
        0.0
    };
    let two_l1 = 2.0 * d + 1.0;
    HostMode {
        inviscid_rad_s: omega0,
        // Miller & Scriven (1968): γ_bl = ½ α ω₀^{1/2}, α = (2l+1)² S/(√2 R ((l+1)ρ_i + lρ_o))
        boundary_layer_per_s: two_l1 * two_l1 * (0.5 * omega0).sqrt() * s
            / (2.0 * radius_m * inertia),
        // the inviscid flow's dissipation 2μ∫|∇∇φ|² on both sides over twice its energy
        bulk_per_s: two_l1
            * ((d + 1.0) * (d - 1.0) * drop.viscosity_pa_s + d * (d + 2.0) * host.viscosity_pa_s)
            / (radius_m * radius_m * inertia),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analytic::lamb::lamb_damping_rate;

    const WATER: Liquid = Liquid {
        density_kg_m3: 997.0,
        viscosity_pa_s: 1.0e-3,
    };
    const GAS: Liquid = Liquid {
        density_kg_m3: 0.0,
        viscosity_pa_s: 0.0,
    };

    /// The inviscid l-mode's potentials, inside `A r^l P_l` and outside
    /// `−l/(l+1) A R^{2l+1} r^{−l−1} P_l` (A = 1), evaluated by quadrature: the energy, the
    /// bulk dissipation and the slip's `∫ |Δu_t|² dS`, with R = 1, for l = 2.
    fn quadrature(rho_i: f64, rho_o: f64, mu_i: f64, mu_o: f64) -> (f64, f64, f64) {
        let (l, r) = (2.0f64, 1.0f64);
        let p = |c: f64| 0.5 * (3.0 * c * c - 1.0);
        let dp = |c: f64, s: f64| -3.0 * c * s; // dP₂/dθ
        let b = -l / (l + 1.0) * r.powf(2.0 * l + 1.0);
        // velocity (radial, tangential) at (ρ, θ)
        let vel = |rho: f64, c: f64, s: f64| {
            if rho < r {
                (l * rho.powf(l - 1.0) * p(c), rho.powf(l - 1.0) * dp(c, s))
            } else {
                (
                    -(l + 1.0) * b * rho.powf(-l - 2.0) * p(c),
                    b * rho.powf(-l - 2.0) * dp(c, s),
                )
            }
        };
        let n_theta = 400;
        let (mut energy, mut dissipation, mut slip) = (0.0, 0.0, 0.0);
        for k in 0..n_theta {
            let theta = (k as f64 + 0.5) * PI / n_theta as f64;
            let (c, s) = (theta.cos(), theta.sin());
            let d_omega = 2.0 * PI * s * PI / n_theta as f64;
            let (_, ti) = vel(r - 1e-12, c, s);
            let (_, to) = vel(r + 1e-12, c, s);
            slip += (ti - to).powi(2) * r * r * d_omega;
            // radial quadrature of ½ρ|u|² and 2μ Σ(∂i∂jφ)² = μ ∇²|u|² (harmonic φ), the
            // latter as μ ∂|u|²/∂n on the sphere (Green), by a one-sided difference
            let u2 = |rho: f64| {
                let (a, t) = vel(rho, c, s);
                a * a + t * t
            };
            let h = 1e-6;
            dissipation += mu_i * (u2(r - 1e-9) - u2(r - 1e-9 - h)) / h * r * r * d_omega;
            dissipation += mu_o * (u2(r + 1e-9) - u2(r + 1e-9 + h)) / h * r * r * d_omega;
            let n_r = 2000;
            for m in 0..n_r {
                // inside ρ ∈ (0, R), outside ρ = R/x for x ∈ (0, 1) (dρ = R/x² dx)
                let x = (m as f64 + 0.5) / n_r as f64;
                energy += 0.5 * rho_i * u2(x * r) * (x * r).powi(2) * r / n_r as f64 * d_omega;
                let rho = r / x;
                energy += 0.5 * rho_o * u2(rho) * rho * rho * (r / (x * x)) / n_r as f64 * d_omega;
            }
        }
        (energy, dissipation, slip)
    }

    #[test]
    fn a_drop_in_a_gas_has_lambs_damping_and_no_boundary_layer() {
        let m = mode_in_host(2, 0.0728, WATER, GAS, 1e-3);
        assert_eq!(m.boundary_layer_per_s, 0.0);
        let lamb = lamb_damping_rate(2, WATER.viscosity_pa_s / WATER.density_kg_m3, 1e-3);
        // the same closed form, rearranged: round-off
        assert!((m.bulk_per_s / lamb - 1.0).abs() < 1e-12, "{m:?} {lamb}");
        assert_eq!(m.period_s(), m.inviscid_period_s());
    }

    #[test]
    fn the_rates_are_the_inviscid_flows_dissipation_over_its_energy() {
        // unequal liquids, so that each side's weight is tested
        let (rho_i, rho_o, mu_i, mu_o) = (997.0, 700.0, 1.0e-3, 4.0e-3);
        let (energy, dissipation, slip) = quadrature(rho_i, rho_o, mu_i, mu_o);
        // peak dissipation over twice the energy, halved for the time average
        let bulk = 0.5 * dissipation / (2.0 * energy);
        let drop = Liquid {
            density_kg_m3: rho_i,
            viscosity_pa_s: mu_i,
        };
        let host = Liquid {
            density_kg_m3: rho_o,
            viscosity_pa_s: mu_o,
        };
        let m = mode_in_host(2, 0.05, drop, host, 1.0);
        // midpoint quadratures (400 × 2000 cells) and a one-sided difference of step 1e-6:
        // 1e-4 relative is well above their errors and far below any wrong factor
        assert!((bulk / m.bulk_per_s - 1.0).abs() < 1e-4, "{bulk} {m:?}");
        // the layers: time-averaged μ|V|²/(2δ) per side, V_i = S/s_i × jump, δ = √(2μ/(ρω))
        let omega = m.inviscid_rad_s;
        let (si, so) = ((mu_i * rho_i).sqrt(), (mu_o * rho_o).sqrt());
        let side = |mu: f64, rho: f64, share: f64| {
            let delta = (2.0 * mu / (rho * omega)).sqrt();
            mu * share * share / (2.0 * delta)
        };
        let per_jump = side(mu_i, rho_i, so / (si + so)) + side(mu_o, rho_o, si / (si + so));
        let layer = per_jump * slip / (2.0 * energy);
        assert!(
            (layer / m.boundary_layer_per_s - 1.0).abs() < 1e-4,
            "{layer} {m:?}"
        );
    }

    #[test]
    fn a_water_drop_in_water_is_slowed_by_its_boundary_layer() {
        let m = mode_in_host(2, 0.0728, WATER, WATER, 1e-3);
        // δ = √(2ν/ω) ≈ 58 µm ≪ R = 1 mm; the shift is a few per cent of ω₀ and the layer
        // damps more than the bulk (order √ν against ν)
        let shift = m.boundary_layer_per_s / m.inviscid_rad_s;
        assert!(shift > 0.01 && shift < 0.1, "{m:?}");
        assert!(m.boundary_layer_per_s > m.bulk_per_s, "{m:?}");
        assert!(m.period_s() > m.inviscid_period_s());
    }
}
