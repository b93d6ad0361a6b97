//! The surface of a spheroid, and the surface energy a stretched drop releases on its way to
//! a sphere: the energy of its l = 2 mode at release, against which the convergence case
//! reads its energy budget's trend.

use super::is_positive_finite;
use std::f64::consts::PI;

/// Surface area [m²] of the spheroid with equatorial semi-axis `a_m` [m] and polar semi-axis
/// `c_m` [m] (prolate for `c > a`, oblate for `c < a`, a sphere for `c = a`); NaN for a
/// non-positive or non-finite semi-axis.
pub fn spheroid_area_m2(a_m: f64, c_m: f64) -> f64 {
    if !(is_positive_finite(a_m) && is_positive_finite(c_m)) {
        return f64::NAN;
    }
    let cap = 2.0 * PI * a_m * a_m;
    if c_m > a_m {
        // prolate: A = 2πa²(1 + c asin(e)/(a e)), e² = 1 − a²/c²
        let e = (1.0 - (a_m / c_m).powi(2)).sqrt();
        cap * (1.0 + c_m * e.asin() / (a_m * e))
    } else if c_m < a_m {
        // oblate: A = 2πa²(1 + (1 − e²) atanh(e)/e), e² = 1 − c²/a²
        let e = (1.0 - (c_m / a_m).powi(2)).sqrt();
        cap * (1.0 + (1.0 - e * e) * e.atanh() / e)
    } else {
        4.0 * PI * a_m * a_m
    }
}

/// The surface energy [J] a drop of radius `radius_m` [m] and tension `sigma_n_m` [N/m] holds
/// beyond a sphere's when released as the volume-keeping spheroid of stretch `eps` [-]
/// (semi-axes `R/√(1 + ε)` across and `R(1 + ε)` along its axis, as the convergence case
/// builds it): `σ (A − 4πR²)`, about `(8π/5) σ R² ε²` for a small stretch (the l = 2 mode of
/// amplitude ε). NaN for a non-positive radius or a stretch at or below −1.
pub fn stretched_drop_excess_energy_j(sigma_n_m: f64, radius_m: f64, eps: f64) -> f64 {
    if !(is_positive_finite(radius_m) && eps > -1.0) {
        return f64::NAN;
    }
    let area = spheroid_area_m2(radius_m / (1.0 + eps).sqrt(), radius_m * (1.0 + eps));
    sigma_n_m * (area - 4.0 * PI * radius_m * radius_m)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The area by quadrature of the surface of revolution `x = a sin t, z = c cos t`:
    /// `A = ∫₀^π 2π a sin t √(a² cos² t + c² sin² t) dt` (composite Simpson), independent of
    /// the closed forms.
    fn quadrature_area(a: f64, c: f64) -> f64 {
        let n = 20_000;
        let h = PI / n as f64;
        let f = |t: f64| {
            2.0 * PI * a * t.sin() * (a * a * t.cos().powi(2) + c * c * t.sin().powi(2)).sqrt()
        };
        let inner: f64 = (1..n)
            .map(|k| f(k as f64 * h) * if k % 2 == 1 { 4.0 } else { 2.0 })
            .sum();
        (f(0.0) + inner + f(PI)) * h / 3.0
    }

    #[test]
    fn the_closed_forms_match_the_quadrature_prolate_and_oblate() {
        for (a, c) in [
            (1.0, 2.0),
            (1.0, 1.1),
            (2.0, 1.0),
            (1.0, 0.3),
            (1e-3, 1.2e-3),
        ] {
            let exact = quadrature_area(a, c);
            let rel = (spheroid_area_m2(a, c) - exact).abs() / exact;
            // Simpson's error at 20,000 intervals on a smooth integrand: far below 1e-10
            assert!(rel < 1e-10, "a {a}, c {c}: relative error {rel:e}");
        }
        assert!((spheroid_area_m2(1.5, 1.5) - 4.0 * PI * 2.25).abs() < 1e-12);
    }

    #[test]
    fn a_small_stretch_holds_the_l2_mode_s_energy() {
        let (sigma, r) = (0.0728, 1e-3);
        for eps in [1e-3, -1e-3, 1e-4] {
            let mode = 8.0 * PI / 5.0 * sigma * r * r * eps * eps;
            let rel = (stretched_drop_excess_energy_j(sigma, r, eps) - mode).abs() / mode;
            // the next order is O(ε³): a relative difference of a few ε
            assert!(
                rel < 5.0 * eps.abs(),
                "ε {eps}: relative difference {rel:e}"
            );
        }
        assert_eq!(stretched_drop_excess_energy_j(sigma, r, 0.0), 0.0);
        assert!(stretched_drop_excess_energy_j(sigma, r, 0.1) > 0.0);
        assert!(stretched_drop_excess_energy_j(sigma, r, -1.0).is_nan());
    }
}
