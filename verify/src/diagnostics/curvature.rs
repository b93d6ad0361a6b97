//! The surface force's curvature on a lattice sphere (docs/model.md §4b): how its mean, its
//! particle-scale spread and the inward force's total depend on the drop's resolution `R/l0`
//! and the colour kernel's reach `r_e/l0`.
//!
//! A sphere of radius `R` of one liquid in a cube of another ([`SphereCloud`]), σ = 1 N/m,
//! the Wendland C2 colour kernel with support `r_e`. Over the band's particles (those with a
//! force):
//! - the curvature's mean and spread, weighted by each particle's share of the force
//!   `V σ |∇c|`, in units of the sphere's `2/R`;
//! - the inward force's total over the Laplace jump's `2σ/R` on the area `4πR²`, `8πσR`.
//!
//! A curvature that converges has its spread fall as `R/l0` grows; the total's shortfall is
//! the band's threshold (the part of `∫|∇c|` left out).

use super::sphere_cloud::SphereCloud;
use solver::physics::surface_tension::surface_force::{ForceScratch, Walls};
use solver::state::Vec3;

/// The curvature of one sphere.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SphereCurvature {
    /// Particles of the cloud.
    pub particles: usize,
    /// The force-weighted mean of `κ R/2` over the band [-].
    pub mean: f64,
    /// The force-weighted standard deviation of `κ R/2` [-].
    pub spread: f64,
    /// The inward force's total over `8πσR` [-].
    pub inward: f64,
}

/// Measures the sphere of `r_over_l0` spacings with the colour kernel's support
/// `re_over_l0` spacings, jittered by up to `±jitter_over_l0` spacings (lattice units:
/// l0 = 1 m, σ = 1 N/m; the ratios do not depend on them).
pub fn sphere(r_over_l0: f64, re_over_l0: f64, jitter_over_l0: f64) -> SphereCurvature {
    let cloud = SphereCloud::new(r_over_l0, re_over_l0, jitter_over_l0, |_| Vec3::zeros());
    let mut force = ForceScratch::default();
    force.evaluate(
        &cloud.input(),
        2,
        |a, b| if a != b { 1.0 } else { 0.0 },
        Walls::Absent,
    );
    let (mut weight, mut m1, mut m2, mut inward) = (0.0, 0.0, 0.0, 0.0);
    for ((x, f), k) in cloud
        .reference
        .iter()
        .zip(&force.force)
        .zip(&force.curvature)
    {
        if *k == 0.0 {
            continue;
        }
        inward -= f.dot(&x.normalize());
        // the particle's share V σ |∇c| of the force
        let w = f.norm() / k.abs();
        let scaled = k * r_over_l0 / 2.0;
        weight += w;
        m1 += w * scaled;
        m2 += w * scaled * scaled;
    }
    let mean = m1 / weight;
    SphereCurvature {
        particles: cloud.pos.len(),
        mean,
        spread: (m2 / weight - mean * mean).max(0.0).sqrt(),
        inward: inward / (8.0 * std::f64::consts::PI * r_over_l0),
    }
}

/// The table of [`sphere`] over every `r_e/l0` × `R/l0`, at one jitter.
pub fn table(re_over_l0: &[f64], r_over_l0: &[f64], jitter_over_l0: f64) -> String {
    let mut out = format!(
        "The surface force's curvature on a lattice sphere (jitter ±{jitter_over_l0} l0 per axis), in units of 2/R:\n\n\
         | r_e/l0 | R/l0 | particles | mean κR/2 | spread of κR/2 | inward force / 8πσR |\n\
         |---|---|---|---|---|---|\n"
    );
    for &re in re_over_l0 {
        for &r in r_over_l0 {
            let s = sphere(r, re, jitter_over_l0);
            out.push_str(&format!(
                "| {re} | {r} | {} | {:.4} | {:.4} | {:.4} |\n",
                s.particles, s.mean, s.spread, s.inward
            ));
        }
    }
    out.push_str(
        "\nMean and spread are weighted by each band particle's share V σ |∇c| of the force; a curvature that \
         converges has its spread fall as R/l0 grows. The inward total's shortfall is the band's threshold.\n",
    );
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_sphere_has_the_curvature_of_a_sphere_on_average() {
        let s = sphere(6.0, 4.2, 0.05);
        // the mean is 2/R up to the band's lattice sampling (1.002 measured at this size); a
        // wrong normalisation of the divergence (the 2D moment, or a missing ½) is off by 2×
        assert!((s.mean - 1.0).abs() < 0.05, "{s:?}");
        // the force pulls inward, short of 8πσR by the band's threshold (0.972 measured)
        assert!(s.inward > 0.9 && s.inward < 1.0, "{s:?}");
        // a jittered lattice has some spread (0.191 measured at this size, `verify curvature`
        // 0.188 at R/l0 = 10); half of 2/R would be normals gone wrong, not lattice noise
        assert!(s.spread > 0.0 && s.spread < 0.5, "{s:?}");
        assert!(table(&[4.2], &[5.0], 0.0).contains("| 4.2 | 5 |"));
    }
}
