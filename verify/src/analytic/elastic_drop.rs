//! Rayleigh's l = 2 drop made of a weak elastic solid: how much a shear modulus shortens the
//! period.
//!
//! The flow of Rayleigh's l = 2 mode is an isochoric stretch along the drop's axis: the
//! displacement `e (−x/2, −y/2, z)` turns the sphere of radius `R` into `r = R (1 + e P2(cos θ))`.
//! Taken as the trial motion of an elastic drop with surface tension (a Rayleigh–Ritz
//! estimate), it keeps Rayleigh's kinetic energy and stores two energies:
//! - capillary: the area grows by `(8π/5) R² e²` (the l = 2 term of `ΔA = ½ (l − 1)(l + 2)
//!   ∫ (R e P_l)² dΩ`), so `K_cap = d²E/de² = 16π σ R²/5`;
//! - elastic: the strain `diag(−e/2, −e/2, e)` of a solid of shear modulus `G` stores
//!   `G ε:ε = (3/2) G e²` per volume, so `K_el = 3 G V = 4π G R³`.
//!
//! Hence `ω²/ω_R² = 1 + K_el/K_cap = 1 + (5/4) G R/σ`: the elastic share grows like `R`, and a
//! particle lattice whose modulus scales like `σ/l0` makes the error grow like `R/l0`.
//!
//! A crystal has no single `G`. On a cubic lattice a stretch along a cube axis loads only
//! `C′ = (C11 − C12)/2`, one along a body diagonal only `C44` ([`cubic_stretch_modulus`]); a
//! drop on the simple cubic lattice stretched along z is the first case, and the two bracket
//! any orientation.

use std::f64::consts::PI;

/// `d²E/de²` of the capillary energy under the l = 2 stretch [J]: `16π σ R²/5`.
pub fn capillary_mode_stiffness_j(surface_tension_n_m: f64, radius_m: f64) -> f64 {
    16.0 * PI * surface_tension_n_m * radius_m * radius_m / 5.0
}

/// `d²E/de²` of an isotropic solid's elastic energy under the l = 2 stretch [J]: `3 G V`.
pub fn elastic_mode_stiffness_j(shear_modulus_pa: f64, radius_m: f64) -> f64 {
    4.0 * PI * shear_modulus_pa * radius_m.powi(3)
}

/// The l = 2 period of an elastic drop with surface tension [s], from Rayleigh's period of the
/// same drop [s] (Rayleigh–Ritz with Rayleigh's mode; module doc).
pub fn elastic_drop_period_s(
    rayleigh_period_s: f64,
    shear_modulus_pa: f64,
    surface_tension_n_m: f64,
    radius_m: f64,
) -> f64 {
    let ratio = elastic_mode_stiffness_j(shear_modulus_pa, radius_m)
        / capillary_mode_stiffness_j(surface_tension_n_m, radius_m);
    rayleigh_period_s / (1.0 + ratio).sqrt()
}

/// The shear modulus a cubic crystal shows under an isochoric stretch `e (n n − (I − n n)/2)`
/// along the unit axis `n` [Pa]: the strain energy per volume `½ C_ijkl ε_ij ε_kl` as
/// `(3/2) G_eff e²`. `C′` along a cube axis, `C44` along a body diagonal.
pub fn cubic_stretch_modulus(c_prime_pa: f64, c44_pa: f64, axis: [f64; 3]) -> f64 {
    let norm = axis.iter().map(|a| a * a).sum::<f64>().sqrt();
    let n = axis.map(|a| a / norm);
    // strain per unit e
    let eps = |i: usize, j: usize| {
        let delta = if i == j { 1.0 } else { 0.0 };
        1.5 * n[i] * n[j] - 0.5 * delta
    };
    // any C12 gives the same energy for an isochoric strain (trace zero): take C12 = 0
    let c11 = 2.0 * c_prime_pa;
    let mut energy = 0.0;
    for i in 0..3 {
        energy += 0.5 * c11 * eps(i, i) * eps(i, i);
        for j in 0..3 {
            if i != j {
                // C_ijij + C_ijji = 2 C44 for each ordered off-diagonal pair
                energy += c44_pa * eps(i, j) * eps(i, j);
            }
        }
    }
    energy / 1.5
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Area of the spheroid with semi-axes `a, a, c` [m²].
    fn spheroid_area_m2(a: f64, c: f64) -> f64 {
        if (c - a).abs() < 1e-14 * a {
            return 4.0 * PI * a * a;
        }
        if c > a {
            let e = (1.0 - a * a / (c * c)).sqrt();
            2.0 * PI * a * a * (1.0 + c / (a * e) * e.asin())
        } else {
            let e = (1.0 - c * c / (a * a)).sqrt();
            2.0 * PI * a * a * (1.0 + (1.0 - e * e) / e * e.atanh())
        }
    }

    #[test]
    fn the_capillary_stiffness_is_the_curvature_of_the_stretched_sphere_s_area() {
        // the isochoric stretch s = 1 + e: semi-axes R/√s, R/√s, R s (prolate and oblate sides)
        let (sigma, r) = (0.0728, 1e-3);
        let energy = |e: f64| sigma * spheroid_area_m2(r / (1.0 + e).sqrt(), r * (1.0 + e));
        let d = 1e-3;
        let k = (energy(d) - 2.0 * energy(0.0) + energy(-d)) / (d * d);
        let k_ref = capillary_mode_stiffness_j(sigma, r);
        // the central difference's truncation error is O(d²) of the O(1) higher derivatives
        // relative to the O(1) stiffness: 1e-6 at d = 1e-3, well above the rounding of the
        // area differences (~1e-16/d² = 1e-10)
        assert!((k / k_ref - 1.0).abs() < 1e-5, "{k} vs {k_ref}");
    }

    #[test]
    fn an_isotropic_solid_stores_three_halves_g_per_volume() {
        // isotropic: C′ = C44 = G, any axis (bounds: a few roundings of O(1) numbers)
        for axis in [[0.0, 0.0, 1.0], [1.0, 1.0, 1.0], [0.3, -0.7, 0.2]] {
            let g = cubic_stretch_modulus(2.0, 2.0, axis);
            assert!((g - 2.0).abs() < 1e-12, "{axis:?}: {g}");
        }
        // and 3 G V is the stiffness of the drop's volume
        let (g, r) = (5.0, 1e-3_f64);
        let v = 4.0 / 3.0 * PI * r.powi(3);
        assert!((elastic_mode_stiffness_j(g, r) / (3.0 * g * v) - 1.0).abs() < 1e-12);
    }

    #[test]
    fn a_cubic_crystal_shows_c_prime_along_an_axis_and_c44_along_a_body_diagonal() {
        // arbitrary moduli; the sums are exact up to a few roundings (bounds 1e-15 on O(0.1))
        let (cp, c44) = (0.047, 0.126);
        assert!((cubic_stretch_modulus(cp, c44, [0.0, 0.0, 1.0]) - cp).abs() < 1e-15);
        assert!((cubic_stretch_modulus(cp, c44, [1.0, 1.0, 1.0]) - c44).abs() < 1e-15);
        // a face diagonal mixes them: C′/4 + 3 C44/4
        let face = cubic_stretch_modulus(cp, c44, [1.0, 1.0, 0.0]);
        assert!((face - (0.25 * cp + 0.75 * c44)).abs() < 1e-15, "{face}");
    }

    #[test]
    fn the_period_falls_with_the_elastic_share_and_is_rayleigh_s_without_it() {
        let (t_r, sigma, r) = (8.22e-3, 0.0728, 1e-3);
        assert_eq!(elastic_drop_period_s(t_r, 0.0, sigma, r), t_r);
        // G R/σ = 0.8: ω² grows by 1 + (5/4)(0.8) = 2, the period by 1/√2
        let g = 0.8 * sigma / r;
        let t = elastic_drop_period_s(t_r, g, sigma, r);
        assert!((t / t_r - std::f64::consts::FRAC_1_SQRT_2).abs() < 1e-12);
    }
}
