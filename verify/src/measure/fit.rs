//! Least-squares sphere and circle fits, and the contact angle of a cap resting on a plane.
//!
//! Method (docs/model.md §7, "Contact angle"): the free-surface particles of a sessile drop in a
//! band above the wall are fitted with a sphere (a circle for a side-view profile), and the
//! contact angle follows from where the wall plane cuts it, `θ = arccos((z_w − c_z)/R)`, with
//! `z_w` the wall *surface* (top wall-particle layer + l0/2) and θ measured inside the liquid,
//! as in Natsui et al. 2021 (θ₃₁, θ₂₃ of its Eqs. 19–23) and 2016.
//!
//! The fit has two stages:
//!
//! 1. **Algebraic** ("Kåsa") fit: `|x|² = 2 c·x + k` is linear in the centre `c` and
//!    `k = R² − |c|²`; it is solved by SVD after centring the points on their centroid and
//!    scaling them to unit RMS distance. A rank test on the singular values rejects degenerate
//!    input (coplanar points for a sphere, collinear points for a circle).
//! 2. **Geometric** refinement: Gauss–Newton on the orthogonal distances `|xᵢ − c| − R`,
//!    starting from the algebraic solution, with step halving, at most 50 iterations, stopping
//!    when the step is below 1e-12 of the (normalised) size of the fit. The algebraic fit alone
//!    is biased on partial arcs with noise (it weights each residual by the distance to the
//!    centre); the geometric one is the maximum-likelihood fit for isotropic noise.
//!
//! Known biases of the *measurement*, not of the fit (see the tests): surface particles sit
//! about half a spacing inside the true free surface, so the fitted radius is ~l0/2 short and
//! θ is biased — down for θ < 90°, up for θ > 90°; the wall-position convention (z_w at the top
//! wall layer + l0/2) moves θ by 2–3° per l0/2 at l0/R = 0.06 (docs/model.md §7).

use nalgebra::{DMatrix, DVector};

/// A sphere in 3-D.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sphere {
    /// Centre `(x, y, z)` (m).
    pub center: [f64; 3],
    /// Radius (m).
    pub radius: f64,
}

/// A circle in a plane (for a side-view profile, coordinates `(x, z)`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Circle {
    /// Centre `(x, z)` (m).
    pub center: [f64; 2],
    /// Radius (m).
    pub radius: f64,
}

/// Singular-value ratio below which the algebraic system counts as rank-deficient.
const RANK_TOL: f64 = 1e-10;
/// Maximum number of Gauss–Newton iterations of the geometric refinement.
const GN_MAX_ITER: usize = 50;
/// Gauss–Newton stops when ‖step‖ ≤ GN_STEP_TOL (1 + ‖c‖ + R) in normalised coordinates.
const GN_STEP_TOL: f64 = 1e-12;

/// Sum of squared orthogonal distances of normalised points `q` to the sphere `(c, r)`.
fn geometric_cost<const D: usize>(q: &[[f64; D]], c: &[f64; D], r: f64) -> f64 {
    q.iter()
        .map(|p| {
            let d = dist(p, c) - r;
            d * d
        })
        .sum()
}

fn dist<const D: usize>(a: &[f64; D], b: &[f64; D]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y) * (x - y))
        .sum::<f64>()
        .sqrt()
}

/// Algebraic fit then Gauss–Newton refinement of a `D`-dimensional sphere (D = 2: circle).
/// Returns the centre (unit of the input) and the radius.
fn fit_hypersphere<const D: usize>(points: &[[f64; D]]) -> Result<([f64; D], f64), String> {
    let n = points.len();
    let what = if D == 2 { "circle" } else { "sphere" };
    if n < D + 1 {
        return Err(format!(
            "{what} fit needs at least {} points, got {n}",
            D + 1
        ));
    }
    if let Some(i) = points.iter().position(|p| p.iter().any(|x| !x.is_finite())) {
        return Err(format!("non-finite coordinate in point {i}"));
    }
    // Centre on the centroid, scale to unit RMS distance.
    let mut m = [0.0; D];
    for p in points {
        for k in 0..D {
            m[k] += p[k] / n as f64;
        }
    }
    let s = (points.iter().map(|p| dist(p, &m).powi(2)).sum::<f64>() / n as f64).sqrt();
    if !(s > 0.0 && s.is_finite()) {
        return Err("all points coincide".into());
    }
    let q: Vec<[f64; D]> = points
        .iter()
        .map(|p| {
            let mut o = [0.0; D];
            for k in 0..D {
                o[k] = (p[k] - m[k]) / s;
            }
            o
        })
        .collect();

    // Stage 1: algebraic fit |q|² = 2 c·q + k.
    let a = DMatrix::from_fn(n, D + 1, |i, j| if j < D { 2.0 * q[i][j] } else { 1.0 });
    let b = DVector::from_fn(n, |i, _| q[i].iter().map(|x| x * x).sum::<f64>());
    let svd = a.svd(true, true);
    let sv = &svd.singular_values;
    let (smin, smax) = (sv.min(), sv.max());
    let ratio = smin / smax;
    if !ratio.is_finite() || ratio < RANK_TOL {
        let shape = if D == 2 { "collinear" } else { "coplanar" };
        return Err(format!(
            "degenerate {what} fit: the {n} points are {shape} (singular-value ratio {ratio:.1e})"
        ));
    }
    let sol = svd
        .solve(&b, 0.0)
        .map_err(|e| format!("{what} fit: least-squares solve failed: {e}"))?;
    let mut c = [0.0; D];
    for k in 0..D {
        c[k] = sol[k];
    }
    let r2 = sol[D] + c.iter().map(|x| x * x).sum::<f64>();
    if !(r2 > 0.0 && r2.is_finite()) {
        return Err(format!("{what} fit: no real radius (R² = {r2:e})"));
    }
    let mut r = r2.sqrt();

    // Stage 2: Gauss–Newton on orthogonal distances.
    let mut cost = geometric_cost(&q, &c, r);
    for _ in 0..GN_MAX_ITER {
        let mut jtj = DMatrix::<f64>::zeros(D + 1, D + 1);
        let mut jtr = DVector::<f64>::zeros(D + 1);
        let mut row = DVector::<f64>::zeros(D + 1);
        for p in &q {
            let d = dist(p, &c);
            for k in 0..D {
                row[k] = if d > 0.0 { -(p[k] - c[k]) / d } else { 0.0 };
            }
            row[D] = -1.0;
            jtj += &row * row.transpose();
            jtr += &row * (d - r);
        }
        let Some(ch) = jtj.cholesky() else { break };
        let step = ch.solve(&(-jtr));
        if !step.iter().all(|x| x.is_finite()) {
            break;
        }
        let mut f = 1.0;
        let mut accepted = false;
        for _ in 0..30 {
            let mut c_new = c;
            for k in 0..D {
                c_new[k] += f * step[k];
            }
            let r_new = r + f * step[D];
            let cost_new = geometric_cost(&q, &c_new, r_new);
            if r_new > 0.0 && cost_new <= cost {
                c = c_new;
                r = r_new;
                cost = cost_new;
                accepted = true;
                break;
            }
            f *= 0.5;
        }
        let size = 1.0 + r + c.iter().map(|x| x * x).sum::<f64>().sqrt();
        if !accepted || f * step.norm() <= GN_STEP_TOL * size {
            break;
        }
    }

    let mut center = [0.0; D];
    for k in 0..D {
        center[k] = m[k] + s * c[k];
    }
    let radius = s * r;
    if !(radius > 0.0 && radius.is_finite() && center.iter().all(|x| x.is_finite())) {
        return Err(format!("{what} fit produced non-finite parameters"));
    }
    Ok((center, radius))
}

/// Least-squares sphere through 3-D points (m).
///
/// Algebraic fit `|x|² = 2c·x + k` (docs/model.md §7) followed by Gauss–Newton on the geometric
/// distances (module documentation). Needs at least 4 finite, non-coplanar points; coplanar
/// (including concyclic) or coincident points give Err.
pub fn fit_sphere(points: &[[f64; 3]]) -> Result<Sphere, String> {
    fit_hypersphere(points).map(|(center, radius)| Sphere { center, radius })
}

/// Least-squares circle through 2-D points (m).
///
/// Same method as [`fit_sphere`] in two dimensions: `|x|² = 2c·x + k`, then Gauss–Newton on the
/// geometric distances. Needs at least 3 finite, non-collinear points.
pub fn fit_circle(points: &[[f64; 2]]) -> Result<Circle, String> {
    fit_hypersphere(points).map(|(center, radius)| Circle { center, radius })
}

/// Contact angle (degrees) of a spherical cap resting on the plane `z = wall_z_m` (m) with the
/// liquid above it: `θ = arccos((z_w − c_z)/R)`, measured inside the liquid.
///
/// A sphere centre below the wall (`c_z < z_w`) gives θ < 90° (less than a hemisphere above the
/// wall), a centre above it θ > 90°. `sphere_center_z_m` and `radius_m` in metres. Err if the
/// plane does not cut the sphere (`|z_w − c_z| ≥ R`, including the tangent case), if the radius
/// is not positive, or on non-finite input.
pub fn cap_contact_angle_deg(
    sphere_center_z_m: f64,
    radius_m: f64,
    wall_z_m: f64,
) -> Result<f64, String> {
    if !(sphere_center_z_m.is_finite() && radius_m.is_finite() && wall_z_m.is_finite()) {
        return Err("non-finite centre, radius or wall height".into());
    }
    if radius_m <= 0.0 {
        return Err(format!("radius must be positive, got {radius_m:e} m"));
    }
    let u = (wall_z_m - sphere_center_z_m) / radius_m;
    if u >= 1.0 {
        return Err(format!(
            "wall z = {wall_z_m:e} m is at or above the top of the sphere (centre z = \
             {sphere_center_z_m:e} m, R = {radius_m:e} m): no cap above it"
        ));
    }
    if u <= -1.0 {
        return Err(format!(
            "wall z = {wall_z_m:e} m is at or below the bottom of the sphere (centre z = \
             {sphere_center_z_m:e} m, R = {radius_m:e} m): the sphere does not touch it"
        ));
    }
    Ok(u.acos().to_degrees())
}

/// Checks a height band and returns its absolute limits (m).
fn band_limits(wall_z_m: f64, band_m: (f64, f64)) -> Result<(f64, f64), String> {
    if !(wall_z_m.is_finite() && !band_m.0.is_nan() && !band_m.1.is_nan()) {
        return Err("wall height and band limits must be numbers".into());
    }
    if band_m.0 > band_m.1 {
        return Err(format!(
            "empty band: lower limit {:e} m above upper limit {:e} m",
            band_m.0, band_m.1
        ));
    }
    Ok((wall_z_m + band_m.0, wall_z_m + band_m.1))
}

/// Contact angle (degrees) from the free-surface particle positions of a sessile drop.
///
/// Selects the points with `wall_z_m + band_m.0 ≤ z ≤ wall_z_m + band_m.1` (heights above the
/// wall surface in metres; infinite limits allowed), fits a sphere to them ([`fit_sphere`]) and
/// returns `(θ, sphere)` with θ from [`cap_contact_angle_deg`]. `wall_z_m` is the wall surface
/// (top wall-particle layer + l0/2). Near-wall bands make the result insensitive to gravity
/// flattening (docs/model.md §7: Bond number above ~0.1). Err with fewer than 4 selected points,
/// a degenerate selection, or a sphere the wall plane does not cut.
pub fn contact_angle_from_surface_points(
    points: &[[f64; 3]],
    wall_z_m: f64,
    band_m: (f64, f64),
) -> Result<(f64, Sphere), String> {
    let (lo, hi) = band_limits(wall_z_m, band_m)?;
    let sel: Vec<[f64; 3]> = points
        .iter()
        .copied()
        .filter(|p| p[2] >= lo && p[2] <= hi)
        .collect();
    if sel.len() < 4 {
        return Err(format!(
            "only {} of {} surface points lie in the band {:e}..{:e} m above the wall; need 4",
            sel.len(),
            points.len(),
            band_m.0,
            band_m.1
        ));
    }
    let sphere = fit_sphere(&sel)?;
    let theta = cap_contact_angle_deg(sphere.center[2], sphere.radius, wall_z_m)?;
    Ok((theta, sphere))
}

/// Contact angle (degrees) from a side-view profile of points `(x, z)` (m).
///
/// As [`contact_angle_from_surface_points`] in two dimensions: points with
/// `wall_z_m + band_m.0 ≤ z ≤ wall_z_m + band_m.1` (m) are fitted with a circle
/// ([`fit_circle`]; use both sides of the profile when available) and
/// `θ = arccos((z_w − c_z)/R)`. Err with fewer than 3 selected points, collinear points, or a
/// circle the wall line does not cut.
pub fn contact_angle_from_profile(
    points_xz: &[[f64; 2]],
    wall_z_m: f64,
    band_m: (f64, f64),
) -> Result<(f64, Circle), String> {
    let (lo, hi) = band_limits(wall_z_m, band_m)?;
    let sel: Vec<[f64; 2]> = points_xz
        .iter()
        .copied()
        .filter(|p| p[1] >= lo && p[1] <= hi)
        .collect();
    if sel.len() < 3 {
        return Err(format!(
            "only {} of {} profile points lie in the band {:e}..{:e} m above the wall; need 3",
            sel.len(),
            points_xz.len(),
            band_m.0,
            band_m.1
        ));
    }
    let circle = fit_circle(&sel)?;
    let theta = cap_contact_angle_deg(circle.center[1], circle.radius, wall_z_m)?;
    Ok((theta, circle))
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{DMatrix, DVector};

    /// Drop radius (m) and particle spacing l0 = R/16 (m) used throughout.
    const R: f64 = 1e-3;
    const L0: f64 = R / 16.0;
    /// Wall surface height (m), arbitrary and non-zero.
    const ZW: f64 = 0.5e-3;
    /// Angles of the brief (degrees).
    const ANGLES: [f64; 4] = [30.0, 90.0, 125.0, 150.0];

    /// 64-bit LCG (Knuth's MMIX constants), uniform in (0, 1).
    struct Lcg(u64);
    impl Lcg {
        fn uniform(&mut self) -> f64 {
            self.0 = self
                .0
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            ((self.0 >> 11) as f64 + 0.5) / (1u64 << 53) as f64
        }
        /// Uniform in [−a, a].
        fn jitter(&mut self, a: f64) -> f64 {
            a * (2.0 * self.uniform() - 1.0)
        }
    }

    /// Centre of the sphere whose cap above `ZW` has contact angle `theta_deg` (off-axis in
    /// x and y on purpose).
    fn cap_center(theta_deg: f64) -> [f64; 3] {
        [0.3 * R, -0.2 * R, ZW - R * theta_deg.to_radians().cos()]
    }

    /// Points of the sphere at spacing ≈ l0 (Fibonacci lattice) lying above the wall.
    fn cap_points(theta_deg: f64) -> Vec<[f64; 3]> {
        let c = cap_center(theta_deg);
        let n = (4.0 * std::f64::consts::PI * R * R / (L0 * L0)).round() as usize;
        let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
        (0..n)
            .map(|i| {
                let z = 1.0 - (2 * i + 1) as f64 / n as f64;
                let rho = (1.0 - z * z).sqrt();
                let phi = i as f64 * golden;
                [
                    c[0] + R * rho * phi.cos(),
                    c[1] + R * rho * phi.sin(),
                    c[2] + R * z,
                ]
            })
            .filter(|p| p[2] >= ZW)
            .collect()
    }

    /// Points of the side-view circle (centre x = 0.3 R) at arc spacing ≈ l0 above the wall.
    fn profile_points(theta_deg: f64) -> Vec<[f64; 2]> {
        let th = theta_deg.to_radians();
        let c = [0.3 * R, ZW - R * th.cos()];
        let m = (2.0 * th * R / L0).round() as usize;
        (0..=m)
            .map(|i| {
                let psi = -th + 2.0 * th * i as f64 / m as f64;
                [c[0] + R * psi.sin(), c[1] + R * psi.cos()]
            })
            .collect()
    }

    /// Linearised (Gauss–Newton covariance) standard deviation of θ (degrees) for radial noise
    /// of standard deviation `sigma_r` (m) on the given points, at the true sphere/circle:
    /// J rows (−nᵢ, −1), cov = σ_r² (JᵀJ)⁻¹, ∂θ/∂c_z = 1/(R sin θ), ∂θ/∂R = cos θ/(R sin θ).
    fn theta_sigma_deg<const D: usize>(
        points: &[[f64; D]],
        center: [f64; D],
        theta_deg: f64,
        sigma_r: f64,
    ) -> f64 {
        let mut jtj = DMatrix::<f64>::zeros(D + 1, D + 1);
        for p in points {
            let d = dist(p, &center);
            let mut row = DVector::<f64>::zeros(D + 1);
            for k in 0..D {
                row[k] = -(p[k] - center[k]) / d;
            }
            row[D] = -1.0;
            jtj += &row * row.transpose();
        }
        let cov = jtj.try_inverse().expect("well-posed") * (sigma_r * sigma_r);
        let th = theta_deg.to_radians();
        let mut g = DVector::<f64>::zeros(D + 1);
        g[D - 1] = 1.0 / (R * th.sin());
        g[D] = th.cos() / (R * th.sin());
        (g.transpose() * cov * &g)[(0, 0)].sqrt().to_degrees()
    }

    #[test]
    fn cap_angle_formula() {
        // θ = arccos((z_w − c_z)/R): hemisphere 90°, centre R/2 below the wall 60°, R/2 above
        // 120°. Exact up to round-off (1e-12°).
        let close = |a: f64, b: f64| (a - b).abs() < 1e-12;
        assert!(close(cap_contact_angle_deg(ZW, R, ZW).unwrap(), 90.0));
        assert!(close(
            cap_contact_angle_deg(ZW - R / 2.0, R, ZW).unwrap(),
            60.0
        ));
        assert!(close(
            cap_contact_angle_deg(ZW + R / 2.0, R, ZW).unwrap(),
            120.0
        ));
        // The plane misses or only touches the sphere; bad radius; NaN.
        assert!(cap_contact_angle_deg(ZW - 2.0 * R, R, ZW).is_err());
        assert!(cap_contact_angle_deg(ZW + 2.0 * R, R, ZW).is_err());
        assert!(cap_contact_angle_deg(ZW - R, R, ZW).is_err());
        assert!(cap_contact_angle_deg(ZW, 0.0, ZW).is_err());
        assert!(cap_contact_angle_deg(ZW, -R, ZW).is_err());
        assert!(cap_contact_angle_deg(f64::NAN, R, ZW).is_err());
    }

    #[test]
    fn exact_sphere_and_circle_recovered() {
        // Points exactly on a full sphere far from the origin (1 km away, R = 1 mm): the
        // centring/scaling keeps the fit exact to round-off, relative 1e-9 of R (the input
        // coordinates themselves only carry ~1e3 m × 1e-16 = 1e-13 m = 1e-10 R).
        let c = [1000.0, -2000.0, 3000.0];
        let n = 500;
        let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
        let pts: Vec<[f64; 3]> = (0..n)
            .map(|i| {
                let z = 1.0 - (2 * i + 1) as f64 / n as f64;
                let rho = (1.0 - z * z).sqrt();
                let phi = i as f64 * golden;
                [
                    c[0] + R * rho * phi.cos(),
                    c[1] + R * rho * phi.sin(),
                    c[2] + R * z,
                ]
            })
            .collect();
        let s = fit_sphere(&pts).unwrap();
        assert!((s.radius / R - 1.0).abs() < 1e-9, "{s:?}");
        for (sc, cc) in s.center.iter().zip(&c) {
            assert!((sc - cc).abs() < 1e-9 * R, "{s:?}");
        }
        // Minimal sets: 4 points determine a sphere, 3 a circle.
        let s4 = fit_sphere(&[
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [-1.0, 0.0, 0.0],
            [0.0, 0.0, 1.0],
        ])
        .unwrap();
        assert!((s4.radius - 1.0).abs() < 1e-12 && s4.center.iter().all(|x| x.abs() < 1e-12));
        let c3 = fit_circle(&[[2.0, 1.0], [1.0, 2.0], [0.0, 1.0]]).unwrap();
        assert!((c3.radius - 1.0).abs() < 1e-12);
        assert!((c3.center[0] - 1.0).abs() < 1e-12 && (c3.center[1] - 1.0).abs() < 1e-12);
    }

    #[test]
    fn exact_caps_give_exact_angles() {
        // Points exactly on caps of 30°, 90°, 125°, 150° (spacing ≈ l0): the fit is exact, so θ
        // must match to round-off (1e-8°), for the whole cap and for a near-wall band
        // (0, 4 l0). Same for the 2-D profile.
        for th in ANGLES {
            let pts = cap_points(th);
            for band in [(0.0, f64::INFINITY), (0.0, 4.0 * L0)] {
                let (t, s) = contact_angle_from_surface_points(&pts, ZW, band).unwrap();
                assert!((t - th).abs() < 1e-8, "θ {th}, band {band:?}: {t}");
                assert!((s.radius / R - 1.0).abs() < 1e-10);
            }
            let prof = profile_points(th);
            for band in [(0.0, f64::INFINITY), (0.0, 4.0 * L0)] {
                let (t, c) = contact_angle_from_profile(&prof, ZW, band).unwrap();
                assert!((t - th).abs() < 1e-8, "profile θ {th}, band {band:?}: {t}");
                assert!((c.radius / R - 1.0).abs() < 1e-10);
            }
        }
    }

    #[test]
    fn jittered_caps_within_five_sigma() {
        // Each coordinate jittered uniformly in ±l0/10 (σ = l0/(10√3) along any direction).
        // Tolerance: 5 × the linearised standard deviation of θ for that noise on these points
        // (`theta_sigma_deg`), a bound a correct unbiased fit exceeds with probability < 1e-6.
        // The second-order bias of isotropic jitter (outward ~σ²/R ≈ 4e-5 l0) is negligible.
        let a = L0 / 10.0;
        let sigma_r = a / 3f64.sqrt();
        let mut rng = Lcg(2024);
        for th in ANGLES {
            let exact = cap_points(th);
            let pts: Vec<[f64; 3]> = exact
                .iter()
                .map(|p| {
                    [
                        p[0] + rng.jitter(a),
                        p[1] + rng.jitter(a),
                        p[2] + rng.jitter(a),
                    ]
                })
                .collect();
            let (t, _) = contact_angle_from_surface_points(&pts, ZW, (0.0, f64::INFINITY)).unwrap();
            let s = theta_sigma_deg(&exact, cap_center(th), th, sigma_r);
            println!(
                "3-D jitter θ {th}: error {:+.3}°, σ_θ {s:.3}°, n {}",
                t - th,
                pts.len()
            );
            assert!((t - th).abs() < 5.0 * s, "θ {th}: {t} (σ {s})");

            let exact2 = profile_points(th);
            let prof: Vec<[f64; 2]> = exact2
                .iter()
                .map(|p| [p[0] + rng.jitter(a), p[1] + rng.jitter(a)])
                .collect();
            let (t2, _) = contact_angle_from_profile(&prof, ZW, (0.0, f64::INFINITY)).unwrap();
            let c2 = [0.3 * R, ZW - R * th.to_radians().cos()];
            let s2 = theta_sigma_deg(&exact2, c2, th, sigma_r);
            println!(
                "2-D jitter θ {th}: error {:+.3}°, σ_θ {s2:.3}°, n {}",
                t2 - th,
                prof.len()
            );
            assert!((t2 - th).abs() < 5.0 * s2, "profile θ {th}: {t2} (σ {s2})");
        }
    }

    /// Surface particles of a cap voxelised on a simple cubic lattice of spacing l0: lattice
    /// points `((i + off.0) l0, (j + off.1) l0, z_w + (k + ½) l0)` inside the sphere, kept if
    /// one of their six face neighbours is outside it (a neighbour below the wall is wall,
    /// i.e. present). The first fluid layer sits l0/2 above the wall surface z_w.
    fn voxel_cap_surface(theta_deg: f64, off: (f64, f64)) -> Vec<[f64; 3]> {
        let cz = ZW - R * theta_deg.to_radians().cos();
        let pos = |i: i64, j: i64, k: i64| {
            [
                (i as f64 + off.0) * L0,
                (j as f64 + off.1) * L0,
                ZW + (k as f64 + 0.5) * L0,
            ]
        };
        let inside = |i: i64, j: i64, k: i64| {
            if k < 0 {
                return true;
            }
            let p = pos(i, j, k);
            p[0] * p[0] + p[1] * p[1] + (p[2] - cz) * (p[2] - cz) <= R * R
        };
        let m = (R / L0) as i64 + 2;
        let mut out = Vec::new();
        for i in -m..=m {
            for j in -m..=m {
                for k in 0..2 * m {
                    if !inside(i, j, k) {
                        continue;
                    }
                    let nb = [
                        (1, 0, 0),
                        (-1, 0, 0),
                        (0, 1, 0),
                        (0, -1, 0),
                        (0, 0, 1),
                        (0, 0, -1),
                    ];
                    if nb.iter().any(|&(a, b, c)| !inside(i + a, j + b, k + c)) {
                        out.push(pos(i, j, k));
                    }
                }
            }
        }
        out
    }

    #[test]
    fn voxelised_caps_show_the_surface_offset_bias() {
        // The method's bias, reported rather than hidden. Surface particles are lattice
        // centres, on average ~0.4–0.5 l0 *inside* the true surface, so the fitted radius is
        // short by δ ≈ l0/2 and cos θ = (z_w − c_z)/(R − δ) over-shoots:
        //     Δθ ≈ −cot θ · δ/R   (radians),   δ/R = 1/32 here,
        // i.e. −1.0° at 60°, 0 at 90°, +1.25° at 125°, +3.1° at 150°. Measured (three lattice
        // offsets, whole cap): −1.2…−1.5°, 0…+0.3°, +1.2…+1.3°, +2.3…+2.7°. Tolerance: within
        // 1° of that prediction (lattice staircase noise, ~0.5°, plus the scatter of δ).
        // θ = 30° (cap 2.1 l0 high: two particle layers) is worse: −3.3…−5.3° (the staircase
        // dominates); tolerance Δθ ∈ [−6°, 0°]. With R + l0/2 in place of R the error drops
        // below 1° for θ ≥ 60° and to −0.05…−2.0° at 30°.
        for off in [(0.0, 0.0), (0.5, 0.5), (0.3, 0.1)] {
            for th in [30.0, 60.0, 90.0, 125.0, 150.0] {
                let pts = voxel_cap_surface(th, off);
                let (t, s) =
                    contact_angle_from_surface_points(&pts, ZW, (0.0, f64::INFINITY)).unwrap();
                let err = t - th;
                let corrected =
                    cap_contact_angle_deg(s.center[2], s.radius + L0 / 2.0, ZW).unwrap() - th;
                let predicted = -(1.0 / th.to_radians().tan()) * (0.5 * L0 / R);
                println!(
                    "voxel off {off:?} θ {th}: n {}, Δθ {err:+.2}° (predicted {:+.2}°), \
                     R−R0 {:+.2} l0, with R+l0/2: {corrected:+.2}°",
                    pts.len(),
                    predicted.to_degrees(),
                    (s.radius - R) / L0
                );
                if th > 45.0 {
                    assert!((err - predicted.to_degrees()).abs() < 1.0, "θ {th}: {err}");
                    assert!(corrected.abs() < 1.0, "θ {th}: corrected {corrected}");
                    // Fitted radius short by 0.24–0.5 l0 (measured): the cause of the bias.
                    assert!((s.radius - R) / L0 < -0.15 && (s.radius - R) / L0 > -0.7);
                } else {
                    assert!((-6.0..0.0).contains(&err), "θ {th}: {err}");
                    assert!((-2.5..0.5).contains(&corrected), "θ {th}: {corrected}");
                }
            }
        }
        // A band holding a single lattice layer is coplanar: refused, not fitted.
        let thin = voxel_cap_surface(30.0, (0.0, 0.0));
        let e = contact_angle_from_surface_points(&thin, ZW, (L0, 8.0 * L0)).unwrap_err();
        assert!(e.contains("coplanar"), "{e}");
    }

    #[test]
    fn degenerate_input_is_rejected() {
        // Fewer than 4 (sphere) / 3 (circle) points.
        assert!(fit_sphere(&[]).is_err());
        assert!(fit_sphere(&[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]).is_err());
        assert!(fit_circle(&[[0.0, 0.0], [1.0, 0.0]]).is_err());
        // Coplanar points (a tilted grid) and concyclic points (a circle in 3-D: infinitely
        // many spheres pass through it).
        let plane: Vec<[f64; 3]> = (0..25)
            .map(|i| {
                let (u, v) = ((i % 5) as f64, (i / 5) as f64);
                [u, v, 0.3 * u - 0.7 * v + 2.0]
            })
            .collect();
        assert!(fit_sphere(&plane).unwrap_err().contains("coplanar"));
        let ring: Vec<[f64; 3]> = (0..12)
            .map(|i| {
                let a = i as f64 * 0.5;
                [a.cos(), a.sin(), 0.0]
            })
            .collect();
        assert!(fit_sphere(&ring).is_err());
        // Collinear points for a circle; coincident points; non-finite input.
        let line: Vec<[f64; 2]> = (0..10).map(|i| [i as f64, 2.0 * i as f64 + 1.0]).collect();
        assert!(fit_circle(&line).unwrap_err().contains("collinear"));
        assert!(fit_sphere(&[[1.0, 1.0, 1.0]; 6]).is_err());
        let mut bad = cap_points(90.0);
        bad[3][1] = f64::NAN;
        assert!(fit_sphere(&bad).unwrap_err().contains("non-finite"));
        // Band problems: empty selection, reversed band, NaN wall.
        let pts = cap_points(90.0);
        assert!(contact_angle_from_surface_points(&pts, ZW, (5.0 * R, 6.0 * R)).is_err());
        assert!(contact_angle_from_surface_points(&pts, ZW, (2.0 * L0, L0)).is_err());
        assert!(contact_angle_from_surface_points(&pts, f64::NAN, (0.0, R)).is_err());
        assert!(contact_angle_from_profile(&profile_points(90.0), ZW, (3.0 * R, 4.0 * R)).is_err());
        // A full sphere lying entirely above the "wall": the plane does not cut it.
        let above: Vec<[f64; 3]> = cap_points(90.0)
            .iter()
            .map(|p| [p[0], p[1], p[2] + 3.0 * R])
            .collect();
        let e = contact_angle_from_surface_points(&above, ZW, (0.0, f64::INFINITY)).unwrap_err();
        assert!(e.contains("does not touch"), "{e}");
    }
}
