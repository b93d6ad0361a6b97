//! The angle at the foot of a liquid/liquid interface on a horizontal wall, read from a
//! quadric fitted to the interface near the wall.
//!
//! Eq. 23's θ12 is the angle the 1–2 interface makes with the wall *at the wall*. The line fit
//! of [`super::geometry::solid_liquid_liquid_angle`] (a plane, or a sphere, through the
//! interface points less than 8 l0 above the wall) reads the mean tilt of that band, and an
//! interface that bends over the band (a saddle, as between two liquids of one drop that must
//! turn to meet the gas) is read towards its bend (that function's tests).
//!
//! Here the unlike-pair midpoints less than [`FOOT_BAND_L0`] = 12 l0 above the wall are
//! fitted with a height function over the band's plane: with `u` the horizontal part of the plane's normal (from
//! liquid 1 into liquid 2), `v = ẑ × u` along the contact line and the height `z` above the
//! wall (all in units of l0, from the band's centroid),
//!
//! `s = a0 + a1 z + a2 t + a3 z² + a4 z t + a5 t²`,  `s = (x − c)·u`, `t = (x − c)·v`,
//!
//! least squares over the midpoints. Its normal at the foot (`z = 0`) under the band's
//! centroid (`t = 0`), `u − a2 v − a1 ẑ`, gives `θ12 = arccos(n_z)` inside liquid 1. The
//! quadric holds planes, spheres to second order and the saddle exactly; its curvature terms
//! take the bend out of the slope at the foot. The price is noise: the slope at the band's
//! edge rests on fewer points than the band's mean tilt, so on a lattice staircase it scatters
//! more ([`FOOT_ANGLE_BOUNDS`], measured in the tests). Smoothing the staircase first (the
//! ½ level of a kernel-smoothed colour between each pair, supports of 2, 2.6 and 3.5 l0) was
//! tried and scattered more at R/8: near the wall and the gas the smoothing is cut.
//!
//! Only a *sheet* is read: an interface that crosses the band from the contact line upwards,
//! as between two liquids side by side on the wall. A lens of one liquid closed under the other
//! within the band, or a layer, is no height function over a vertical plane; it is told by the
//! band's plane lying within 5° of the wall's, or by the quadric's RMS distance
//! ([`SHEET_RMS_LIMIT_L0`]), and gives an error.

use super::geometry::{wall_band, WallBand};
use super::surface::{Classes, Cloud};
use nalgebra::{DMatrix, DVector, Vector3};

/// A band whose plane normal is within this many degrees of the wall normal is nearly parallel
/// to the wall (a layer, or a lens closed within the band): it has no direction across the
/// contact line, and no foot angle is read.
const PARALLEL_LIMIT_DEG: f64 = 5.0;

/// Height, in units of l0, of the band above the wall whose 1–2 interface points the quadric
/// fits. On tilted planes at R/16 (tests) the worst error was 6.1° with 8 l0 and 1.5° with
/// 12 l0: the slope at the band's edge needs more of the staircase than the band's mean tilt.
/// At R/8 a drop is about 8 l0 high, and both bands hold all of it.
pub const FOOT_BAND_L0: f64 = 12.0;

/// The quadric's RMS distance [l0] above which the interface is not a sheet across the band
/// (a lens of one liquid under the other, a layer), and no foot angle is read. On the tests'
/// voxelised sheets it is 0.19–0.44 l0 (the staircase); in the plate_eq23 runs (read with an
/// 8 l0 band while the fit was built) 0.07–0.50 l0 where the interface crosses the drop and
/// 1.0–4.4 l0 where one liquid lies over the other.
pub const SHEET_RMS_LIMIT_L0: f64 = 0.75;

/// Error bounds [deg] of [`foot_angle_deg`] on voxelised interfaces, as its tests check them:
/// `(R/l0 at least, bound)`, R the drop radius. Measured over 120 sheets per resolution (tilted
/// planes; spheres of radius 3R and 4R, 45–135°, and saddles bent with radius 3R, each at four
/// offsets against the lattice): at R/16 worst 2.66° (RMS 0.8° planes, 0.6° saddles, 1.1°
/// spheres); at R/8 worst 7.89° (RMS 1.5°, 2.4°, 3.8°), both signs, no bias (mean within
/// ±0.4°). At R/8 the quadric's slope at the band's edge rests on a staircase eight layers
/// high: the reading scatters with where the lattice cuts the interface.
pub const FOOT_ANGLE_BOUNDS: [(f64, f64); 2] = [(16.0, 3.0), (8.0, 8.0)];

/// The error bound [deg] of [`foot_angle_deg`] at `r_over_l0` spacings per drop radius
/// ([`FOOT_ANGLE_BOUNDS`]); None below R/8, which the tests do not cover.
pub fn foot_angle_error_deg(r_over_l0: f64) -> Option<f64> {
    FOOT_ANGLE_BOUNDS
        .iter()
        .find(|(r, _)| r_over_l0 >= *r)
        .map(|(_, b)| *b)
}

/// θ12 [deg] at the foot of the 1–2 interface on the wall surface `z = wall_z_m` (m), inside
/// liquid 1 (phase 0): the quadric of the module documentation fitted to the unlike-pair
/// midpoints less than [`FOOT_BAND_L0`] above the wall. 90° for a vertical interface, < 90° when liquid 1
/// runs under liquid 2.
///
/// Err (never a panic) as [`super::geometry::solid_liquid_liquid_angle`], when the quadric's
/// least squares are singular (the band's points do not span the contact line and the
/// height), or when the interface is not a sheet across the band ([`SHEET_RMS_LIMIT_L0`]).
pub fn foot_angle_deg(cloud: &Cloud, classes: &Classes, wall_z_m: f64) -> Result<f64, String> {
    let WallBand {
        mid,
        centre,
        normal,
        ..
    } = wall_band(cloud, classes, wall_z_m, FOOT_BAND_L0)?;
    let horizontal = Vector3::new(normal[0], normal[1], 0.0);
    if horizontal.norm() < PARALLEL_LIMIT_DEG.to_radians().sin() {
        return Err(format!(
            "foot angle: the 1–2 interface within {FOOT_BAND_L0} l0 of the wall is not a sheet \
             across the band (its plane is within {PARALLEL_LIMIT_DEG}° of the wall's): a lens \
             or a layer"
        ));
    }
    let u = horizontal.normalize();
    let v = Vector3::new(-u[1], u[0], 0.0);
    let l0 = cloud.l0_m;
    let rows = mid.len();
    let mut a = DMatrix::<f64>::zeros(rows, 6);
    let mut b = DVector::<f64>::zeros(rows);
    for (k, m) in mid.iter().enumerate() {
        let d = Vector3::from(*m) - centre;
        let (s, t, z) = (d.dot(&u) / l0, d.dot(&v) / l0, (m[2] - wall_z_m) / l0);
        for (col, value) in [1.0, z, t, z * z, z * t, t * t].into_iter().enumerate() {
            a[(k, col)] = value;
        }
        b[k] = s;
    }
    let coef = a
        .clone()
        .svd(true, true)
        .solve(&b, 1e-10)
        .map_err(|e| format!("foot angle: the quadric's least squares failed: {e}"))?;
    if coef.iter().any(|c| !c.is_finite()) {
        return Err("foot angle: the quadric's least squares are singular".into());
    }
    let rms_l0 = ((&a * &coef - &b).norm_squared() / rows as f64).sqrt();
    if rms_l0 > SHEET_RMS_LIMIT_L0 {
        return Err(format!(
            "foot angle: the 1–2 interface within {FOOT_BAND_L0} l0 of the wall is not a sheet \
             across the band (the quadric's RMS distance is {rms_l0:.2} l0, above \
             {SHEET_RMS_LIMIT_L0} l0): a lens or a layer"
        ));
    }
    // The normal of s − f(t, z) = 0 at (t, z) = (0, 0): u − a2 v − a1 ẑ.
    let n = (u - coef[2] * v - coef[1] * Vector3::z()).normalize();
    Ok(n[2].clamp(-1.0, 1.0).acos().to_degrees())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::measure::surface::classify;
    use crate::measure::surface::lattice_shapes::{add_wall, in_ball, plane_normal, voxelise};

    /// Drop radius (m).
    const R: f64 = 1e-3;

    /// A hemisphere of radius R on a lattice wall (surface z = 0) whose liquid 1 is where
    /// `liquid1(x)` holds.
    fn hemisphere(l0: f64, liquid1: impl Fn([f64; 3]) -> bool) -> Cloud {
        let mut cloud = voxelise([-R - l0, -R - l0, 0.0], [R + l0, R + l0, R + l0], l0, |x| {
            (x[2] > 0.0 && in_ball(x, [0.0; 3], R)).then(|| u8::from(!liquid1(x)))
        });
        add_wall(&mut cloud, 1.5 * R, 3);
        cloud
    }

    fn read(cloud: &Cloud) -> f64 {
        foot_angle_deg(cloud, &classify(cloud), 0.0).unwrap()
    }

    /// Worst |error| [deg] per resolution over the shapes of `shapes`: (label, cloud, exact).
    fn worst(div: f64, shapes: Vec<(String, Cloud, f64)>) -> (f64, Vec<String>) {
        let tol = foot_angle_error_deg(div).unwrap();
        let mut w: f64 = 0.0;
        let mut bad = Vec::new();
        for (label, cloud, exact) in shapes {
            let t = read(&cloud);
            println!(
                "R/{div} {label}: foot {t:.2}° (exact {exact:.2}°, {:+.2}°)",
                t - exact
            );
            w = w.max((t - exact).abs());
            if (t - exact).abs() >= tol {
                bad.push(format!("R/{div} {label}: {t} against {exact}"));
            }
        }
        (w, bad)
    }

    #[test]
    fn tilted_planes_read_their_angle() {
        for div in [8.0, 16.0] {
            let l0 = R / div;
            let shapes = [
                (90.0, 0.0),
                (90.0, 20.0),
                (60.0, 0.0),
                (60.0, 30.0),
                (120.0, 0.0),
                (45.0, 10.0),
                (110.0, 7.0),
                (135.0, 0.0),
            ]
            .into_iter()
            .map(|(beta, phi)| {
                let n = plane_normal(beta, phi);
                let cloud = hemisphere(l0, |x| x[0] * n[0] + x[1] * n[1] + x[2] * n[2] <= 0.0);
                (format!("plane β {beta}° φ {phi}°"), cloud, beta)
            })
            .collect();
            let (w, bad) = worst(div, shapes);
            println!("R/{div} planes: worst {w:.2}°");
            assert!(bad.is_empty(), "{bad:#?}");
        }
    }

    #[test]
    fn spheres_read_their_angle() {
        // The interface a sphere of radius 3R or 4R (the runs' bends) through the foot point
        // (x0 l0, 0, 0), meeting the wall at θ inside it, liquid 1 inside; and swapped (liquid
        // 1 outside: 180° − θ). Below 90° inside it bends away from 90° upwards, above 90°
        // towards it.
        for div in [8.0, 16.0] {
            let l0 = R / div;
            let mut shapes = Vec::new();
            for rs in [3.0 * R, 4.0 * R] {
                for th in [45.0_f64, 60.0, 80.0, 100.0, 120.0, 135.0] {
                    for x0 in [0.0, 0.21, 0.44, 0.5] {
                        let c = [
                            x0 * l0 - rs * th.to_radians().sin(),
                            0.0,
                            -rs * th.to_radians().cos(),
                        ];
                        for swap in [false, true] {
                            let cloud = hemisphere(l0, |x| in_ball(x, c, rs) != swap);
                            let exact = if swap { 180.0 - th } else { th };
                            let label =
                                format!("sphere {:.0}R {th}° x0 {x0} l0 swap {swap}", rs / R);
                            shapes.push((label, cloud, exact));
                        }
                    }
                }
            }
            let (w, bad) = worst(div, shapes);
            println!("R/{div} spheres: worst {w:.2}°");
            assert!(bad.is_empty(), "{bad:#?}");
        }
    }

    #[test]
    fn a_lens_is_not_read() {
        // Liquid 1 a cap of radius R/2 at 90° inside a hemisphere of liquid 2: the interface
        // closes over liquid 1 within the band, no height function over a vertical plane.
        for div in [8.0, 16.0] {
            let l0 = R / div;
            let cloud = hemisphere(l0, |x| in_ball(x, [0.1 * R, 0.05 * R, 0.0], 0.5 * R));
            let e = foot_angle_deg(&cloud, &classify(&cloud), 0.0).unwrap_err();
            println!("R/{div}: {e}");
            assert!(e.contains("not a sheet"), "R/{div}: {e}");
        }
    }

    #[test]
    fn saddles_read_their_foot() {
        // The saddle of geometry's bent-interface test: x = b z + k (z² − y²)/2, foot angle θ
        // (b = −cot θ), bending towards 90° with profile radius 3R; the line fit reads these
        // 12–22° off their foot.
        for div in [8.0, 16.0] {
            let l0 = R / div;
            let mut shapes = Vec::new();
            for th in [45.0_f64, 60.0, 120.0, 135.0] {
                let b = -1.0 / th.to_radians().tan();
                let k = -b.signum() * (1.0 + b * b).powf(1.5) / (3.0 * R);
                for x0 in [0.0, 0.21, 0.44, 0.5] {
                    let cloud = hemisphere(l0, |x| {
                        x[0] - x0 * l0 <= b * x[2] + 0.5 * k * (x[2] * x[2] - x[1] * x[1])
                    });
                    shapes.push((format!("saddle {th}° x0 {x0} l0"), cloud, th));
                }
            }
            let (w, bad) = worst(div, shapes);
            println!("R/{div} saddles: worst {w:.2}°");
            assert!(bad.is_empty(), "{bad:#?}");
        }
    }
}
