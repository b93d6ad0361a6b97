//! Shape measures of a particle cloud.

/// The l = 4 cubic-harmonic moment of a body about its centroid:
/// `Q4 = Σ(x⁴ + y⁴ + z⁴) / Σ|r|⁴ − 3/5` [-].
///
/// It vanishes for a sphere (for a uniform ball `⟨x⁴⟩ = ⟨r⁴⟩/5`), is negative for a cube
/// (≈ −0.13 for a lattice cube) and positive for an octahedron-like shape, and it is first-order
/// in the amplitude of the l = 4 mode with cubic symmetry — the mode a relaxing cube excites —
/// while the second moments do not see that mode at all. As a volume average over every
/// particle it is far less noisy than an extent set by the outermost particle.
pub fn cubic_harmonic_q4(points: &[[f64; 3]]) -> f64 {
    if points.is_empty() {
        return f64::NAN;
    }
    let c = centroid(points);
    let (mut s4, mut r4) = (0.0, 0.0);
    for p in points {
        let d = [p[0] - c[0], p[1] - c[1], p[2] - c[2]];
        s4 += d[0].powi(4) + d[1].powi(4) + d[2].powi(4);
        r4 += (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).powi(2);
    }
    s4 / r4 - 0.6
}

/// The axisymmetric l = 2 moment of a body about its centroid:
/// `Q2 = Σ(z² − (x² + y²)/2) / Σ|r|²` [-].
///
/// It vanishes for a sphere and is first-order in the amplitude of the l = 2 mode about the z
/// axis (`r = R(1 + ε P2(cos θ))` gives `Q2 ≈ ε`); for a uniform spheroid of semi-axes `a`
/// (x, y) and `c` (z) it is `(c² − a²)/(2a² + c²)`. A volume average over every particle, so
/// far less noisy than an extent.
pub fn axial_quadrupole_q2(points: &[[f64; 3]]) -> f64 {
    if points.is_empty() {
        return f64::NAN;
    }
    let c = centroid(points);
    let (mut q, mut r2) = (0.0, 0.0);
    for p in points {
        let d = [p[0] - c[0], p[1] - c[1], p[2] - c[2]];
        q += d[2] * d[2] - 0.5 * (d[0] * d[0] + d[1] * d[1]);
        r2 += d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    }
    q / r2
}

/// The mean position of `points` [same unit as the points].
fn centroid(points: &[[f64; 3]]) -> [f64; 3] {
    let n = points.len() as f64;
    let mut c = [0.0; 3];
    for p in points {
        for k in 0..3 {
            c[k] += p[k] / n;
        }
    }
    c
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lattice(n: i32, keep: impl Fn(f64, f64, f64) -> bool) -> Vec<[f64; 3]> {
        let mut v = Vec::new();
        for k in -n..n {
            for j in -n..n {
                for i in -n..n {
                    let p = [i as f64 + 0.5, j as f64 + 0.5, k as f64 + 0.5];
                    if keep(p[0], p[1], p[2]) {
                        v.push(p);
                    }
                }
            }
        }
        v
    }

    #[test]
    fn q4_is_zero_for_a_ball_negative_for_a_cube() {
        // a lattice ball of radius 30 spacings: the discreteness leaves |Q4| ~ 1e-4 (the
        // lattice's own cubic anisotropy at the surface scales as (l0/R)²)
        let ball = lattice(31, |x, y, z| x * x + y * y + z * z < 900.0);
        assert!(
            cubic_harmonic_q4(&ball).abs() < 1e-3,
            "{}",
            cubic_harmonic_q4(&ball)
        );
        // continuum cube: ⟨x⁴⟩ = a⁴/80 per axis (side a, uniform), ⟨r⁴⟩ = a⁴(3/80 + 6/144)
        // → Q4 = (3/80)/(3/80 + 1/24) − 3/5 = −0.1263...; a 20³ lattice cube is within 1e-3
        let cube = lattice(10, |_, _, _| true);
        let q = cubic_harmonic_q4(&cube);
        let exact = (3.0 / 80.0) / (3.0 / 80.0 + 1.0 / 24.0) - 0.6;
        assert!((q - exact).abs() < 1e-3, "{q} vs {exact}");
        assert!(cubic_harmonic_q4(&[]).is_nan());
    }

    #[test]
    fn q2_is_zero_for_a_ball_and_that_of_a_spheroid_otherwise() {
        // the lattice ball's discreteness leaves |Q2| < 1e-3 (as for Q4 above)
        let ball = lattice(31, |x, y, z| x * x + y * y + z * z < 900.0);
        assert!(axial_quadrupole_q2(&ball).abs() < 1e-3);
        // a prolate spheroid a = 20, c = 26 spacings: (c² − a²)/(2a² + c²) = 0.2272...; the
        // lattice's surface staircase errs by O(l0/a) ~ 1e-3 on this ratio of volume sums
        let (a, c) = (20.0, 26.0);
        let spheroid = lattice(27, |x, y, z| {
            (x * x + y * y) / (a * a) + z * z / (c * c) < 1.0
        });
        let exact = (c * c - a * a) / (2.0 * a * a + c * c);
        let q = axial_quadrupole_q2(&spheroid);
        assert!((q - exact).abs() < 3e-3, "{q} vs {exact}");
        assert!(axial_quadrupole_q2(&[]).is_nan());
    }
}
