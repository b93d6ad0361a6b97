//! Gas/liquid/liquid triple line (Neumann triangle) and the zero-gravity
//! equilibrium shape of a binary droplet (a "doublet").
//!
//! Source: Natsui et al., Chem. Eng. Sci. 229 (2021) 116035 ("paper A"), §3,
//! Eqs. (24)–(27) and Fig. 12. The printed equations are damaged by OCR;
//! `docs/model.md` §5 and §8 (R13, R15, R16) is the authoritative text and
//! is what this module implements.
//!
//! # Regimes (Eq. 24)
//!
//! The three tensions σ1 (gas–liquid 1), σ2 (gas–liquid 2) and σ12 (liquid 1–
//! liquid 2), all in N/m, must close a triangle (`σ1 t1 + σ2 t2 + σ12 t12 = 0`,
//! t the unit tangents leaving the line) for a triple line to exist:
//! a lens (partial engulfing) needs `|σ1 − σ2| < σ12 < σ1 + σ2`. Below, the
//! liquid of lower surface tension engulfs the other; at or above `σ1 + σ2` the
//! drops touch at a point or part.
//!
//! # Geometry of the doublet
//!
//! The equilibrium shape in zero gravity is axisymmetric and bounded by three
//! spherical caps (constant mean curvature, Young–Laplace) that meet on one
//! circle, the triple line, of radius `a` (m).
//!
//! Frame: meridian half-plane `(r, z)`, `r ≥ 0` the distance from the symmetry
//! axis (m), `z` along the axis (m), pointing from liquid 1 to liquid 2 (liquid
//! 1 on −z, as in docs/model.md §5). Origin: centre of the triple-line circle, so
//! the line is at `z = 0, r = a`.
//!
//! Each cap spans the disc `r ≤ a, z = 0` and crosses the axis at its apex, at
//! signed height `h` (m). Its *rim angle* `γ ∈ (−180°, 180°)` is the direction
//! of the tangent leaving the triple line along the cap, measured from the
//! inward radial direction (−r), positive towards +z: the unit tangent is
//! `(t_r, t_z) = (−cos γ, sin γ)`. With `η = h/a = tan(γ/2)`, standard facts
//! of the sphere give
//!
//! - sphere radius `R = a / |sin γ|`, centre on the axis at `z_c = −a cot γ`;
//! - signed volume between the plane `z = 0` and the cap
//!   `V(η) = π a³ η (3 + η²) / 6` (the spherical-cap volume `π h (3a² + h²)/6`);
//! - its first moment about `z = 0`: `M(η) = π a⁴ η² (2 + η²) / 12` (cap
//!   volume times the cap-centroid height `h (2a² + h²) / (2 (3a² + h²))`).
//!
//! Both formulas hold for caps larger than a hemisphere too. Liquid 1 lies
//! between the gas–1 cap (`η1 < 0`) and the interface cap (`η12`), liquid 2
//! between the interface cap and the gas–2 cap (`η2 > 0`); two spheres through
//! the same circle meet nowhere else, so `V1 = V(η12) − V(η1)`,
//! `V2 = V(η2) − V(η12)`, and likewise for the moments; the centroids are
//! `z_G = M / V`.
//!
//! # Solution
//!
//! The Neumann triangle fixes the three wedge angles at the line (each phase's
//! wedge is 180° minus the triangle's interior angle between the two tensions
//! that bound it), so the triad of tangents has a single free rotation. With
//! `A1`, `A2` the interior angles opposite σ1 and σ2 and `S = A1 + A2`, write
//! `u = γ12 + A2 ∈ (0, S)`; then `γ1 = u − 180°`, `γ12 = u − A2`,
//! `γ2 = 180° − (S − u)`. The volume ratio `V2/V1` depends on `u` only (the shape
//! is scale free) and runs from 0 (`u → 0`, liquid 1 becomes a full sphere) to
//! ∞ (`u → S`): `u` is found by bisection on `ln(V2/V1) − ln(V2/V1)_target`,
//! which cannot fail to bracket and is run to the resolution of `f64`; the
//! tests check that the function is strictly monotone (so the root is unique).
//! The scale `a` then follows from `V1`.
//!
//! The Laplace relations `p1 = 2σ1/R1`, `p2 = 2σ2/R2`, `p1 − p2 = 2σ12/R12` are
//! not imposed: on a common circle they are equivalent to the axial component of
//! the Neumann balance (`σk sin γk` summed), and the tests check them
//! independently. The interface bulges into the liquid of lower pressure.

use std::f64::consts::PI;

/// Relative band, as a fraction of `σ1 + σ2`, within which σ12 counts as equal
/// to a regime boundary (`|σ1 − σ2|` or `σ1 + σ2`). It absorbs only rounding of
/// tensions typed in decimal (e.g. 0.4 − 0.2 vs 0.2): 1e-12 is ~4500 ulp.
const BOUNDARY_REL_TOL: f64 = 1e-12;

/// Equilibrium topology of two liquids in contact in a gas (docs/model.md §5,
/// Eq. (24), Natsui 2021).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Regime {
    /// `σ12 < |σ1 − σ2|`: no triple line; the liquid of lower surface tension
    /// (1 or 2, in `engulfing_liquid`) coats the other completely (core–shell).
    CompleteEngulfing {
        /// Index (1 or 2) of the liquid that forms the shell.
        engulfing_liquid: u8,
    },
    /// `σ12 = |σ1 − σ2|` (within a relative 1e-12 of `σ1 + σ2`): the boundary
    /// between complete engulfing and a lens; the Neumann triangle is flat.
    EngulfingBoundary,
    /// `|σ1 − σ2| < σ12 < σ1 + σ2`: partial engulfing, a doublet with a
    /// gas/liquid/liquid triple line.
    Lens,
    /// `σ12 ≥ σ1 + σ2`: non-engulfing; the drops touch at a point or part.
    /// Their centroid distance is [`separated_g1g2`].
    PointContact,
}

/// Checks that a tension is finite and positive (`allow_zero` admits 0).
fn check_tension(name: &str, value_n_per_m: f64, allow_zero: bool) -> Result<(), String> {
    let ok =
        value_n_per_m.is_finite() && (value_n_per_m > 0.0 || (allow_zero && value_n_per_m == 0.0));
    if ok {
        Ok(())
    } else {
        let bound = if allow_zero { "≥ 0" } else { "> 0" };
        Err(format!(
            "{name} = {value_n_per_m} N/m: a tension must be finite and {bound}"
        ))
    }
}

/// Classifies the equilibrium topology of liquid 1 and liquid 2 in a gas from
/// the Neumann triangle inequalities, Eq. (24), Natsui 2021 (docs/model.md §5).
///
/// Inputs are the surface tensions `sigma1_n_per_m`, `sigma2_n_per_m` (> 0) and
/// the liquid–liquid interfacial tension `sigma12_n_per_m` (≥ 0), all in N/m.
/// Equality with a boundary is decided within a relative 1e-12 of `σ1 + σ2`.
/// Returns an error for non-finite or out-of-range tensions.
pub fn regime(
    sigma1_n_per_m: f64,
    sigma2_n_per_m: f64,
    sigma12_n_per_m: f64,
) -> Result<Regime, String> {
    check_tension("sigma1", sigma1_n_per_m, false)?;
    check_tension("sigma2", sigma2_n_per_m, false)?;
    check_tension("sigma12", sigma12_n_per_m, true)?;
    let sum = sigma1_n_per_m + sigma2_n_per_m;
    let diff = (sigma1_n_per_m - sigma2_n_per_m).abs();
    let tol = BOUNDARY_REL_TOL * sum;
    // Eq. (24), Natsui 2021: |σ1 − σ2| < σ12 < σ1 + σ2 for a lens.
    let r = if sigma12_n_per_m >= sum - tol {
        Regime::PointContact
    } else if (sigma12_n_per_m - diff).abs() <= tol {
        Regime::EngulfingBoundary
    } else if sigma12_n_per_m < diff {
        let engulfing_liquid = if sigma1_n_per_m < sigma2_n_per_m {
            1
        } else {
            2
        };
        Regime::CompleteEngulfing { engulfing_liquid }
    } else {
        Regime::Lens
    };
    Ok(r)
}

/// Angles of the Neumann triangle with sides σ1, σ2, σ12 and the wedge angle
/// each phase occupies at the triple line, all in degrees.
///
/// The triangle closes because `σ1 t1 + σ2 t2 + σ12 t12 = 0`. The wedge of a
/// phase is 180° minus the interior angle between the two tensions that bound
/// it; the three wedges add up to 360°.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NeumannAngles {
    /// Interior angle opposite the side σ1 (between the sides σ2 and σ12), degrees.
    pub opposite_sigma1_deg: f64,
    /// Interior angle opposite the side σ2 (between the sides σ1 and σ12), degrees.
    pub opposite_sigma2_deg: f64,
    /// Interior angle opposite the side σ12 (between the sides σ1 and σ2), degrees.
    pub opposite_sigma12_deg: f64,
    /// Wedge occupied by the gas, between the gas–1 and gas–2 surfaces, degrees
    /// (= 180° − `opposite_sigma12_deg`).
    pub gas_wedge_deg: f64,
    /// Wedge occupied by liquid 1, between the gas–1 surface and the 1–2
    /// interface, degrees (= 180° − `opposite_sigma2_deg`).
    pub liquid1_wedge_deg: f64,
    /// Wedge occupied by liquid 2, between the 1–2 interface and the gas–2
    /// surface, degrees (= 180° − `opposite_sigma1_deg`).
    pub liquid2_wedge_deg: f64,
}

/// Interior angle (rad) opposite side `x` of a triangle with sides `x, y, z`
/// (any length unit), by the half-angle formula
/// `tan(A/2) = √((s−y)(s−z) / (s(s−x)))`, which stays accurate for flat
/// triangles, unlike `acos` of the law of cosines.
fn angle_opposite(x: f64, y: f64, z: f64) -> f64 {
    let s = 0.5 * (x + y + z);
    let num = ((s - y).max(0.0) * (s - z).max(0.0)).sqrt();
    let den = (s * (s - x).max(0.0)).sqrt();
    2.0 * num.atan2(den)
}

/// Neumann triangle of the gas/liquid 1/liquid 2 triple line (docs/model.md §5).
///
/// Tensions in N/m. Returns `None` when no lens exists (the regime is not
/// [`Regime::Lens`]) or the input is invalid; [`regime`] tells which.
pub fn neumann_angles(
    sigma1_n_per_m: f64,
    sigma2_n_per_m: f64,
    sigma12_n_per_m: f64,
) -> Option<NeumannAngles> {
    if regime(sigma1_n_per_m, sigma2_n_per_m, sigma12_n_per_m).ok()? != Regime::Lens {
        return None;
    }
    let (s1, s2, s12) = (sigma1_n_per_m, sigma2_n_per_m, sigma12_n_per_m);
    let a1 = angle_opposite(s1, s2, s12).to_degrees();
    let a2 = angle_opposite(s2, s12, s1).to_degrees();
    let a12 = angle_opposite(s12, s1, s2).to_degrees();
    Some(NeumannAngles {
        opposite_sigma1_deg: a1,
        opposite_sigma2_deg: a2,
        opposite_sigma12_deg: a12,
        gas_wedge_deg: 180.0 - a12,
        liquid1_wedge_deg: 180.0 - a2,
        liquid2_wedge_deg: 180.0 - a1,
    })
}

/// Zero-gravity equilibrium shape of a binary droplet with a lens (partial
/// engulfing), in the frame of the module doc: axis z from liquid 1 to liquid
/// 2, origin at the centre of the triple-line circle.
///
/// Tangent directions `psi*_deg` use the convention of
/// [`neumann_vector_residual`]: angle from +z, positive towards the outward
/// radial direction (away from the axis), in (−180°, 180°].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Doublet {
    /// Radius of the gas–liquid 1 sphere, m.
    pub r1_m: f64,
    /// Radius of the gas–liquid 2 sphere, m.
    pub r2_m: f64,
    /// Radius of the liquid 1–liquid 2 interface sphere, m; `f64::INFINITY`
    /// when the interface is exactly flat. Prefer `curvature12_per_m`, which
    /// never divides by zero.
    pub r12_m: f64,
    /// Signed curvature 1/R12 of the 1–2 interface, 1/m: positive when it bulges
    /// into liquid 2 (+z, liquid 1 at the higher pressure), 0 when flat.
    pub curvature12_per_m: f64,
    /// Radius `a` of the triple-line circle, m.
    pub contact_radius_m: f64,
    /// Axial position of the centre of the gas–1 sphere, m.
    pub centre1_z_m: f64,
    /// Axial position of the centre of the gas–2 sphere, m.
    pub centre2_z_m: f64,
    /// Axial position of the centre of the 1–2 interface sphere, m; `None` when
    /// the interface is exactly flat.
    pub centre12_z_m: Option<f64>,
    /// Axial position of the gas–1 cap's apex (the bottom of liquid 1), m (< 0).
    pub apex1_z_m: f64,
    /// Axial position of the gas–2 cap's apex (the top of liquid 2), m (> 0).
    pub apex2_z_m: f64,
    /// Axial position of the 1–2 interface's apex on the axis, m.
    pub apex12_z_m: f64,
    /// Volume of liquid 1 computed from the solved geometry, m³.
    pub volume1_m3: f64,
    /// Volume of liquid 2 computed from the solved geometry, m³.
    pub volume2_m3: f64,
    /// Axial position of the centroid G1 of liquid 1's volume, m.
    pub g1_z_m: f64,
    /// Axial position of the centroid G2 of liquid 2's volume, m.
    pub g2_z_m: f64,
    /// Centroid distance G1G2 = `g2_z_m − g1_z_m`, m. docs/model.md R13/R15 quote
    /// it over the initial drop radius R0 (not the diameter).
    pub g1g2_m: f64,
    /// Laplace pressure of liquid 1 over the gas, 2σ1/R1, Pa.
    pub pressure1_pa: f64,
    /// Laplace pressure of liquid 2 over the gas, 2σ2/R2, Pa.
    pub pressure2_pa: f64,
    /// Angle between the gas–1 tangent at the triple line and −z, degrees
    /// (θ1 of Eq. (27), Natsui 2021; docs/model.md §5).
    pub theta1_deg: f64,
    /// Angle between the gas–2 tangent at the triple line and +z, degrees
    /// (θ2 of Eq. (27)).
    pub theta2_deg: f64,
    /// Angle between the 1–2 interface tangent at the triple line and +z,
    /// degrees (θ12 of Eq. (27)).
    pub theta12_deg: f64,
    /// Direction of the gas–1 tangent leaving the triple line, degrees from +z
    /// towards outward radial.
    pub psi1_deg: f64,
    /// Direction of the gas–2 tangent leaving the triple line, degrees from +z
    /// towards outward radial.
    pub psi2_deg: f64,
    /// Direction of the 1–2 interface tangent leaving the triple line, degrees
    /// from +z towards outward radial.
    pub psi12_deg: f64,
}

/// Signed volume between the plane z = 0 and a cap of height ratio `eta = h/a`,
/// in units of a³ (standard spherical-cap volume π h (3a² + h²)/6).
fn cap_volume(eta: f64) -> f64 {
    PI * eta * (3.0 + eta * eta) / 6.0
}

/// First moment about z = 0 of the volume between the plane and a cap of height
/// ratio `eta = h/a`, in units of a⁴ (cap volume times the standard cap-centroid
/// height h (2a² + h²)/(2 (3a² + h²))).
fn cap_moment(eta: f64) -> f64 {
    PI * eta * eta * (2.0 + eta * eta) / 12.0
}

/// Dimensionless shape of the doublet for the rotation parameter `u` (rad)
/// (module doc): the height ratios η1, η12, η2 (apex height / a).
fn height_ratios(u: f64, a1: f64, a2: f64) -> (f64, f64, f64) {
    let s = a1 + a2;
    let eta1 = -1.0 / (0.5 * u).tan(); // tan(γ1/2), γ1 = u − π
    let eta12 = (0.5 * (u - a2)).tan(); // tan(γ12/2), γ12 = u − A2
    let eta2 = 1.0 / (0.5 * (s - u)).tan(); // tan(γ2/2), γ2 = π − (S − u)
    (eta1, eta12, eta2)
}

/// Volumes of liquids 1 and 2 in units of a³ for the rotation parameter `u` (rad).
fn unit_volumes(u: f64, a1: f64, a2: f64) -> (f64, f64) {
    let (eta1, eta12, eta2) = height_ratios(u, a1, a2);
    (
        cap_volume(eta12) - cap_volume(eta1),
        cap_volume(eta2) - cap_volume(eta12),
    )
}

/// Checks a volume: finite and positive.
fn check_volume(name: &str, value_m3: f64) -> Result<(), String> {
    if value_m3.is_finite() && value_m3 > 0.0 {
        Ok(())
    } else {
        Err(format!(
            "{name} = {value_m3} m³: a volume must be finite and > 0"
        ))
    }
}

/// Angle (rad) in (−π, π] of the unit vector `(t_r, t_z)` measured from +z
/// towards +r (the ψ convention of [`neumann_vector_residual`]).
fn psi_of(t_r: f64, t_z: f64) -> f64 {
    t_r.atan2(t_z)
}

/// Solves the zero-gravity doublet for surface tensions `sigma1_n_per_m`,
/// `sigma2_n_per_m`, interfacial tension `sigma12_n_per_m` (N/m) and liquid
/// volumes `volume1_m3`, `volume2_m3` (m³); see the module doc for the frame,
/// the geometry and the root find.
///
/// Errors: invalid input, or a regime other than [`Regime::Lens`] (for
/// `σ12 ≥ σ1 + σ2` use [`separated_g1g2`]; for complete engulfing there is no
/// triple line).
pub fn doublet(
    sigma1_n_per_m: f64,
    sigma2_n_per_m: f64,
    sigma12_n_per_m: f64,
    volume1_m3: f64,
    volume2_m3: f64,
) -> Result<Doublet, String> {
    check_volume("volume1", volume1_m3)?;
    check_volume("volume2", volume2_m3)?;
    let reg = regime(sigma1_n_per_m, sigma2_n_per_m, sigma12_n_per_m)?;
    if reg != Regime::Lens {
        let hint = match reg {
            Regime::PointContact => "; the drops touch at a point or part: use separated_g1g2",
            _ => "; no triple line exists",
        };
        return Err(format!(
            "no lens for sigma1 = {sigma1_n_per_m}, sigma2 = {sigma2_n_per_m}, \
             sigma12 = {sigma12_n_per_m} N/m: regime {reg:?} (Eq. (24) needs \
             |σ1 − σ2| < σ12 < σ1 + σ2){hint}"
        ));
    }
    let (s1, s2, s12) = (sigma1_n_per_m, sigma2_n_per_m, sigma12_n_per_m);
    // Interior angles of the Neumann triangle (rad).
    let a1 = angle_opposite(s1, s2, s12);
    let a2 = angle_opposite(s2, s12, s1);
    let s = a1 + a2;
    if !(s > 0.0 && s < PI) {
        return Err(format!(
            "degenerate Neumann triangle (A1 + A2 = {s} rad) for sigma1 = {s1}, \
             sigma2 = {s2}, sigma12 = {s12} N/m"
        ));
    }

    // Bisection on g(u) = ln(V2/V1)(u) − ln(V2/V1)_target over u ∈ (0, S):
    // g → −∞ as u → 0 and g → +∞ as u → S, so the bracket always holds.
    let target = (volume2_m3 / volume1_m3).ln();
    let g = |u: f64| {
        let (v1, v2) = unit_volumes(u, a1, a2);
        (v2 / v1).ln() - target
    };
    let (mut lo, mut hi) = (0.0_f64, s);
    let mut u = 0.5 * s;
    for _ in 0..2000 {
        u = 0.5 * (lo + hi);
        if u <= lo || u >= hi {
            break; // interval at the resolution of f64
        }
        let gu = g(u);
        if !gu.is_finite() {
            return Err(format!(
                "volume-ratio function not finite at u = {u} rad (sigma1 = {s1}, \
                 sigma2 = {s2}, sigma12 = {s12} N/m, V2/V1 = {})",
                volume2_m3 / volume1_m3
            ));
        }
        if gu == 0.0 {
            break;
        } else if gu < 0.0 {
            lo = u;
        } else {
            hi = u;
        }
    }

    let (eta1, eta12, eta2) = height_ratios(u, a1, a2);
    let (v1_unit, v2_unit) = unit_volumes(u, a1, a2);
    // Scale from liquid 1's volume.
    let a = (volume1_m3 / v1_unit).cbrt();
    if !(a.is_finite() && a > 0.0) {
        return Err(format!(
            "contact radius not finite ({a} m) for sigma1 = {s1}, sigma2 = {s2}, \
             sigma12 = {s12} N/m"
        ));
    }

    // Rim angles γ (rad) and tangents (t_r, t_z) = (−cos γ, sin γ).
    let gamma12 = u - a2;
    let (sin1, cos1) = (-u.sin(), -u.cos()); // γ1 = u − π
    let (sin2, cos2) = ((s - u).sin(), -(s - u).cos()); // γ2 = π − (S − u)
    let (sin12, cos12) = (gamma12.sin(), gamma12.cos());
    let t1 = (-cos1, sin1);
    let t2 = (-cos2, sin2);
    let t12 = (-cos12, sin12);

    // Sphere radii R = a/|sin γ| and centres z_c = −a cot γ (standard facts).
    let r1 = a / sin1.abs();
    let r2 = a / sin2.abs();
    let curvature12 = sin12 / a;
    let r12 = if curvature12 == 0.0 {
        f64::INFINITY
    } else {
        1.0 / curvature12.abs()
    };
    let centre1 = -a * cos1 / sin1;
    let centre2 = -a * cos2 / sin2;
    let centre12 = if sin12 == 0.0 {
        None
    } else {
        Some(-a * cos12 / sin12)
    };

    let volume1 = a.powi(3) * v1_unit;
    let volume2 = a.powi(3) * v2_unit;
    let g1_z = a * (cap_moment(eta12) - cap_moment(eta1)) / v1_unit;
    let g2_z = a * (cap_moment(eta2) - cap_moment(eta12)) / v2_unit;

    // Axial angles of Eq. (27), Natsui 2021 (docs/model.md §5): θ1 from −z,
    // θ2 and θ12 from +z, each in [0°, 180°].
    let theta1 = t1.0.abs().atan2(-t1.1);
    let theta2 = t2.0.abs().atan2(t2.1);
    let theta12 = t12.0.abs().atan2(t12.1);

    Ok(Doublet {
        r1_m: r1,
        r2_m: r2,
        r12_m: r12,
        curvature12_per_m: curvature12,
        contact_radius_m: a,
        centre1_z_m: centre1,
        centre2_z_m: centre2,
        centre12_z_m: centre12,
        apex1_z_m: a * eta1,
        apex2_z_m: a * eta2,
        apex12_z_m: a * eta12,
        volume1_m3: volume1,
        volume2_m3: volume2,
        g1_z_m: g1_z,
        g2_z_m: g2_z,
        g1g2_m: g2_z - g1_z,
        // Eq. (26), Natsui 2021: ΔP = 2σ/R across each free surface.
        pressure1_pa: 2.0 * s1 / r1,
        pressure2_pa: 2.0 * s2 / r2,
        theta1_deg: theta1.to_degrees(),
        theta2_deg: theta2.to_degrees(),
        theta12_deg: theta12.to_degrees(),
        psi1_deg: psi_of(t1.0, t1.1).to_degrees(),
        psi2_deg: psi_of(t2.0, t2.1).to_degrees(),
        psi12_deg: psi_of(t12.0, t12.1).to_degrees(),
    })
}

/// Radius (m) of the sphere of volume `volume_m3` (m³): `(3V/(4π))^(1/3)`.
/// NaN for a negative or non-finite volume.
pub fn equivalent_sphere_radius(volume_m3: f64) -> f64 {
    if volume_m3.is_finite() && volume_m3 >= 0.0 {
        (3.0 * volume_m3 / (4.0 * PI)).cbrt()
    } else {
        f64::NAN
    }
}

/// Centroid distance G1G2 (m) of two spheres of radii `radius1_m` and
/// `radius2_m` (m) touching at a point (`σ12 ≥ σ1 + σ2`, [`Regime::PointContact`]):
/// `R1 + R2`. Apart, the distance is at least this. NaN for a negative or
/// non-finite radius.
pub fn separated_g1g2(radius1_m: f64, radius2_m: f64) -> f64 {
    let ok = |r: f64| r.is_finite() && r >= 0.0;
    if ok(radius1_m) && ok(radius2_m) {
        radius1_m + radius2_m
    } else {
        f64::NAN
    }
}

/// Axial residual of the tension balance, Eq. (27), Natsui 2021, normalised by
/// σ1 as in paper A's Table 1:
/// `(σ1 cos θ1 − σ2 cos θ2 − σ12 cos θ12) / σ1` (dimensionless).
///
/// Tensions in N/m; angles in degrees with the meaning of docs/model.md §5: θ1
/// between the gas–1 tangent and −z, θ2 between the gas–2 tangent and +z, θ12
/// between the 1–2 tangent and +z (z from liquid 1 to liquid 2). NaN if σ1 is
/// not positive and finite.
pub fn eq27_residual(
    sigma1_n_per_m: f64,
    sigma2_n_per_m: f64,
    sigma12_n_per_m: f64,
    theta1_deg: f64,
    theta2_deg: f64,
    theta12_deg: f64,
) -> f64 {
    if !(sigma1_n_per_m.is_finite() && sigma1_n_per_m > 0.0) {
        return f64::NAN;
    }
    // Eq. (27), Natsui 2021.
    (sigma1_n_per_m * theta1_deg.to_radians().cos()
        - sigma2_n_per_m * theta2_deg.to_radians().cos()
        - sigma12_n_per_m * theta12_deg.to_radians().cos())
        / sigma1_n_per_m
}

/// Full vector residual of the Neumann balance `σ1 t1 + σ2 t2 + σ12 t12 = 0`
/// at a gas/liquid/liquid line, normalised by σ1: `|Σ σk tk| / σ1`
/// (dimensionless). Tensions in N/m.
///
/// Convention: the three unit tangents leave the triple line along the gas–1
/// surface (`psi1_deg`), the gas–2 surface (`psi2_deg`) and the 1–2 interface
/// (`psi12_deg`), all in one meridian half-plane `(r, z)` with r pointing away
/// from the symmetry axis and z along it from liquid 1 to liquid 2. Each angle
/// is in degrees, measured from +z towards +r: `t = (sin ψ, cos ψ)` as
/// `(t_r, t_z)`; ψ = 0 is +z, 90° outward radial, 180° is −z, −90° towards the
/// axis. Then θ1 = 180° − |ψ1|, θ2 = |ψ2|, θ12 = |ψ12| (ψ in (−180°, 180°]).
/// NaN if σ1 is not positive and finite.
pub fn neumann_vector_residual(
    sigma1_n_per_m: f64,
    sigma2_n_per_m: f64,
    sigma12_n_per_m: f64,
    psi1_deg: f64,
    psi2_deg: f64,
    psi12_deg: f64,
) -> f64 {
    if !(sigma1_n_per_m.is_finite() && sigma1_n_per_m > 0.0) {
        return f64::NAN;
    }
    let (r1, z1) = psi1_deg.to_radians().sin_cos();
    let (r2, z2) = psi2_deg.to_radians().sin_cos();
    let (r12, z12) = psi12_deg.to_radians().sin_cos();
    let fr = sigma1_n_per_m * r1 + sigma2_n_per_m * r2 + sigma12_n_per_m * r12;
    let fz = sigma1_n_per_m * z1 + sigma2_n_per_m * z2 + sigma12_n_per_m * z12;
    fr.hypot(fz) / sigma1_n_per_m
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Volume (m³) of a sphere of radius `r_m` (m).
    fn sphere_volume(r_m: f64) -> f64 {
        4.0 / 3.0 * PI * r_m.powi(3)
    }

    /// R0 of paper A §3: 1 mm drops.
    const R0: f64 = 1.0e-3;

    /// A set of lens cases spanning equal, unequal and swapped tensions and
    /// volume ratios from 1/8 to 8.
    fn lens_cases() -> Vec<(f64, f64, f64, f64, f64)> {
        let v = sphere_volume(R0);
        let mut c = Vec::new();
        for &(s1, s2, s12) in &[
            (0.4, 0.4, 0.1),
            (0.4, 0.4, 0.4),
            (0.4, 0.4, 0.79),
            (0.4, 0.2, 0.21),
            (0.4, 0.2, 0.3),
            (0.4, 0.2, 0.5),
            (0.4, 0.2, 0.59),
            (0.2, 0.4, 0.3),
            (0.0728, 0.0201, 0.06),
        ] {
            for &ratio in &[0.125, 0.5, 1.0, 3.0, 8.0] {
                c.push((s1, s2, s12, v, v * ratio));
            }
        }
        c
    }

    /// Unit tangent (t_r, t_z) of a ψ angle (deg) (convention of
    /// `neumann_vector_residual`).
    fn tangent(psi_deg: f64) -> (f64, f64) {
        psi_deg.to_radians().sin_cos()
    }

    /// Physics: paper A §3.2 / docs/model.md R16 — matte/slag (σ1 0.4, σ2 0.2):
    /// σ12 = 0.1 complete engulfing (slag, the lower tension, is the shell),
    /// 0.2 engulfing boundary, 0.3–0.5 lens, 0.6 point contact; equal matte
    /// drops: lens up to 0.79, point contact at 0.8 and 1.0 (paper A §3.1).
    #[test]
    fn regimes_match_r16_and_eq24() {
        let ce2 = Regime::CompleteEngulfing {
            engulfing_liquid: 2,
        };
        assert_eq!(regime(0.4, 0.2, 0.1), Ok(ce2));
        assert_eq!(regime(0.4, 0.2, 0.2), Ok(Regime::EngulfingBoundary));
        for s12 in [0.3, 0.4, 0.5] {
            assert_eq!(regime(0.4, 0.2, s12), Ok(Regime::Lens));
        }
        assert_eq!(regime(0.4, 0.2, 0.6), Ok(Regime::PointContact));
        // Swapping the liquids swaps the shell.
        assert_eq!(
            regime(0.2, 0.4, 0.1),
            Ok(Regime::CompleteEngulfing {
                engulfing_liquid: 1
            })
        );
        assert_eq!(regime(0.4, 0.4, 0.79), Ok(Regime::Lens));
        assert_eq!(regime(0.4, 0.4, 0.8), Ok(Regime::PointContact));
        assert_eq!(regime(0.4, 0.4, 1.0), Ok(Regime::PointContact));
        // σ12 = 0 with equal tensions: the flat-triangle boundary.
        assert_eq!(regime(0.4, 0.4, 0.0), Ok(Regime::EngulfingBoundary));
    }

    /// Bad input gives an error or None, never a panic.
    #[test]
    fn bad_input_is_rejected() {
        assert!(regime(-0.4, 0.2, 0.3).is_err());
        assert!(regime(0.4, 0.0, 0.3).is_err());
        assert!(regime(0.4, 0.2, -0.1).is_err());
        assert!(regime(f64::NAN, 0.2, 0.3).is_err());
        assert!(regime(0.4, f64::INFINITY, 0.3).is_err());
        assert!(neumann_angles(0.4, 0.2, f64::NAN).is_none());
        let v = sphere_volume(R0);
        assert!(doublet(0.4, 0.2, 0.3, 0.0, v).is_err());
        assert!(doublet(0.4, 0.2, 0.3, v, -v).is_err());
        assert!(doublet(0.4, 0.2, 0.3, v, f64::NAN).is_err());
        assert!(doublet(0.4, 0.2, 0.3, f64::INFINITY, v).is_err());
        assert!(separated_g1g2(-1.0, 1.0).is_nan());
        assert!(equivalent_sphere_radius(-1.0).is_nan());
        assert!(eq27_residual(0.0, 0.2, 0.3, 10.0, 10.0, 10.0).is_nan());
        assert!(neumann_vector_residual(-1.0, 0.2, 0.3, 10.0, 10.0, 10.0).is_nan());
    }

    /// Physics: no lens, no triple line — neumann_angles is None and doublet
    /// errs for σ12 outside (|σ1 − σ2|, σ1 + σ2) (Eq. 24).
    #[test]
    fn no_lens_outside_eq24() {
        let v = sphere_volume(R0);
        for &(s1, s2, s12) in &[
            (0.4, 0.2, 0.1),
            (0.4, 0.2, 0.2),
            (0.4, 0.2, 0.6),
            (0.4, 0.4, 0.8),
        ] {
            assert!(neumann_angles(s1, s2, s12).is_none());
            let e = doublet(s1, s2, s12, v, v).unwrap_err();
            assert!(e.contains("no lens"), "{e}");
        }
        assert!(doublet(0.4, 0.4, 0.8, v, v)
            .unwrap_err()
            .contains("separated_g1g2"));
    }

    /// Physics: the Neumann triangle closes — interior angles add to 180°, the
    /// phase wedges to 360°; equal tensions give 60° and 120° (double bubble);
    /// tangents placed at the wedges balance to rounding. Tolerance 1e-12:
    /// rounding of a few trigonometric evaluations.
    #[test]
    fn neumann_triangle_closes() {
        let eq = neumann_angles(0.4, 0.4, 0.4).unwrap();
        for a in [
            eq.opposite_sigma1_deg,
            eq.opposite_sigma2_deg,
            eq.opposite_sigma12_deg,
        ] {
            assert!((a - 60.0).abs() < 1e-12, "{a}");
        }
        assert!((eq.gas_wedge_deg - 120.0).abs() < 1e-12);
        for &(s1, s2, s12, _, _) in &lens_cases() {
            let n = neumann_angles(s1, s2, s12).unwrap();
            let sum = n.opposite_sigma1_deg + n.opposite_sigma2_deg + n.opposite_sigma12_deg;
            assert!((sum - 180.0).abs() < 1e-12, "{sum}");
            let wedges = n.gas_wedge_deg + n.liquid1_wedge_deg + n.liquid2_wedge_deg;
            assert!((wedges - 360.0).abs() < 1e-12, "{wedges}");
            // Law of cosines as an independent check of one angle.
            let cos12 = (s1 * s1 + s2 * s2 - s12 * s12) / (2.0 * s1 * s2);
            assert!((n.opposite_sigma12_deg.to_radians().cos() - cos12).abs() < 1e-12);
            // Tangents: gas-1 at ψ = 0, liquid 1 wedge, then the interface,
            // then liquid 2 wedge, then the gas-2 surface.
            let psi1 = 0.0;
            let psi12 = psi1 + n.liquid1_wedge_deg;
            let psi2 = psi12 + n.liquid2_wedge_deg;
            let res = neumann_vector_residual(s1, s2, s12, psi1, psi2, psi12);
            assert!(res < 1e-12, "residual {res} for {s1} {s2} {s12}");
        }
    }

    /// Physics: at the doublet's triple line the three tensions balance
    /// (σ1 t1 + σ2 t2 + σ12 t12 = 0) and the axial component Eq. (27) vanishes.
    /// Each tangent is checked to be tangent to its sphere (perpendicular to
    /// the radius from the sphere's centre) and to point to the right side.
    /// Tolerance 1e-9 (the brief's bar); the construction reaches ~1e-15.
    #[test]
    fn doublet_satisfies_neumann_at_triple_line() {
        for &(s1, s2, s12, v1, v2) in &lens_cases() {
            let d = doublet(s1, s2, s12, v1, v2).unwrap();
            let vec_res = neumann_vector_residual(s1, s2, s12, d.psi1_deg, d.psi2_deg, d.psi12_deg);
            assert!(vec_res < 1e-9, "vector residual {vec_res}");
            let ax_res = eq27_residual(s1, s2, s12, d.theta1_deg, d.theta2_deg, d.theta12_deg);
            assert!(ax_res.abs() < 1e-9, "Eq. 27 residual {ax_res}");
            // θ–ψ relations of the documented convention.
            assert!((d.theta1_deg - (180.0 - d.psi1_deg.abs())).abs() < 1e-9);
            assert!((d.theta2_deg - d.psi2_deg.abs()).abs() < 1e-9);
            assert!((d.theta12_deg - d.psi12_deg.abs()).abs() < 1e-9);
            // Tangency to the spheres at P = (a, 0): t · (P − C) = 0.
            let a = d.contact_radius_m;
            let (t1r, t1z) = tangent(d.psi1_deg);
            let (t2r, t2z) = tangent(d.psi2_deg);
            let (t12r, t12z) = tangent(d.psi12_deg);
            assert!((t1r * a - t1z * d.centre1_z_m).abs() / d.r1_m < 1e-9);
            assert!((t2r * a - t2z * d.centre2_z_m).abs() / d.r2_m < 1e-9);
            if let Some(c12) = d.centre12_z_m {
                assert!((t12r * a - t12z * c12).abs() / d.r12_m < 1e-9);
            }
            // Spheres pass through the triple line: |P − C| = R.
            assert!((a.hypot(d.centre1_z_m) / d.r1_m - 1.0).abs() < 1e-9);
            assert!((a.hypot(d.centre2_z_m) / d.r2_m - 1.0).abs() < 1e-9);
            // Gas-1 surface leaves towards −z, gas-2 towards +z.
            assert!(t1z < 0.0 && t2z > 0.0);
            // Liquid bodies ordered along z: bottom < G1 < G2 < top.
            assert!(d.apex1_z_m < d.g1_z_m && d.g1_z_m < d.g2_z_m && d.g2_z_m < d.apex2_z_m);
        }
    }

    /// Physics: Young–Laplace, p1 = 2σ1/R1, p2 = 2σ2/R2 and
    /// p1 − p2 = 2σ12/R12 with the interface bulging into the lower-pressure
    /// liquid (Eq. (26), Natsui 2021). Not imposed by the solver, so this can
    /// fail. Tolerance 1e-9 relative to p1 (the brief's bar).
    #[test]
    fn doublet_satisfies_laplace() {
        for &(s1, s2, s12, v1, v2) in &lens_cases() {
            let d = doublet(s1, s2, s12, v1, v2).unwrap();
            let lhs = d.pressure1_pa - d.pressure2_pa;
            let rhs = 2.0 * s12 * d.curvature12_per_m;
            assert!(
                (lhs - rhs).abs() < 1e-9 * d.pressure1_pa,
                "p1 - p2 = {lhs} Pa, 2σ12/R12 = {rhs} Pa"
            );
            // Sign: the apex of the interface lies on the lower-pressure side.
            if lhs.abs() > 1e-6 * d.pressure1_pa {
                assert_eq!(d.apex12_z_m > 0.0, lhs > 0.0);
            }
        }
    }

    /// Volume (m³) and first moment about z = 0 (m⁴) of a solid of revolution
    /// whose cross-section area is π(R² − (z − c)²) on [z0, z1]: Simpson's rule,
    /// exact for the quadratic and cubic integrands.
    fn slab(c: f64, r: f64, z0: f64, z1: f64) -> (f64, f64) {
        let area = |z: f64| PI * (r * r - (z - c) * (z - c));
        let zm = 0.5 * (z0 + z1);
        let w = (z1 - z0) / 6.0;
        (
            w * (area(z0) + 4.0 * area(zm) + area(z1)),
            w * (z0 * area(z0) + 4.0 * zm * area(zm) + z1 * area(z1)),
        )
    }

    /// Signed volume and moment between z = 0 and the cap of the sphere
    /// (centre c, radius r) with apex `apex` on the axis: slices of the sphere
    /// between the plane and the apex.
    fn region(c: f64, r: f64, apex: f64) -> (f64, f64) {
        if apex >= 0.0 {
            slab(c, r, 0.0, apex)
        } else {
            let (v, m) = slab(c, r, apex, 0.0);
            (-v, -m)
        }
    }

    /// Physics: the solved shape holds the prescribed volumes (1e-10 relative,
    /// the brief's bar), and its volumes and centroids agree with an independent
    /// slice integration of the three spheres from their centres and radii
    /// (1e-9 relative: rounding of the slice sums, which subtract nearly equal
    /// terms for nearly flat interfaces).
    #[test]
    fn doublet_volumes_and_centroids_by_slices() {
        for &(s1, s2, s12, v1, v2) in &lens_cases() {
            let d = doublet(s1, s2, s12, v1, v2).unwrap();
            assert!((d.volume1_m3 / v1 - 1.0).abs() < 1e-10);
            assert!((d.volume2_m3 / v2 - 1.0).abs() < 1e-10);
            let (bv1, bm1) = region(d.centre1_z_m, d.r1_m, d.apex1_z_m);
            let (bv2, bm2) = region(d.centre2_z_m, d.r2_m, d.apex2_z_m);
            let (iv, im) = match d.centre12_z_m {
                Some(c12) => region(c12, d.r12_m, d.apex12_z_m),
                None => (0.0, 0.0),
            };
            let (vol1, mom1) = (iv - bv1, im - bm1);
            let (vol2, mom2) = (bv2 - iv, bm2 - im);
            assert!((vol1 / v1 - 1.0).abs() < 1e-9, "V1 {vol1} vs {v1}");
            assert!((vol2 / v2 - 1.0).abs() < 1e-9, "V2 {vol2} vs {v2}");
            let g1g2 = mom2 / vol2 - mom1 / vol1;
            assert!(
                (g1g2 / d.g1g2_m - 1.0).abs() < 1e-9,
                "G1G2 {g1g2} vs {}",
                d.g1g2_m
            );
        }
    }

    /// Unique real root h of π h (3a² + h²)/6 = w (a monotone cubic), Cardano.
    fn height_for_volume(a: f64, w: f64) -> f64 {
        let p = 3.0 * a * a;
        let q = -6.0 * w / PI;
        let disc = (0.25 * q * q + p * p * p / 27.0).sqrt();
        (-0.5 * q + disc).cbrt() + (-0.5 * q - disc).cbrt()
    }

    /// Surface energy (J) of three caps on a common circle of radius `a` (m),
    /// interface apex `h12` (m), with the outer caps fitted to the volumes.
    /// Cap area π(a² + h²) is a standard fact.
    fn energy(s: (f64, f64, f64), v: (f64, f64), a: f64, h12: f64) -> f64 {
        let w12 = PI * h12 * (3.0 * a * a + h12 * h12) / 6.0;
        let h1 = height_for_volume(a, w12 - v.0);
        let h2 = height_for_volume(a, w12 + v.1);
        let area = |h: f64| PI * (a * a + h * h);
        s.0 * area(h1) + s.1 * area(h2) + s.2 * area(h12)
    }

    /// Physics: the doublet minimises the surface energy
    /// σ1 A1 + σ2 A2 + σ12 A12 at fixed volumes over all three-cap shapes on a
    /// common circle (parameters a and the interface apex h12) — a check that
    /// uses neither the Neumann angles nor Laplace. The gradient, by central
    /// differences with steps of 1e-4 of the length scale, vanishes to 1e-6
    /// (truncation ~1e-8 plus cancellation ~1e-16/1e-8); every step of 1 %
    /// raises the energy.
    #[test]
    fn doublet_minimises_surface_energy() {
        for &(s1, s2, s12, v1, v2) in &lens_cases() {
            let d = doublet(s1, s2, s12, v1, v2).unwrap();
            let s = (s1, s2, s12);
            let v = (v1, v2);
            let (a, h12) = (d.contact_radius_m, d.apex12_z_m);
            let e0 = energy(s, v, a, h12);
            let step = 1e-4 * a;
            let de_da = (energy(s, v, a + step, h12) - energy(s, v, a - step, h12)) / (2.0 * step);
            let de_dh = (energy(s, v, a, h12 + step) - energy(s, v, a, h12 - step)) / (2.0 * step);
            // Scale of an energy derivative: E / a.
            let scale = e0 / a;
            assert!(de_da.abs() < 1e-6 * scale, "dE/da = {de_da} ({s:?}, {v:?})");
            assert!(
                de_dh.abs() < 1e-6 * scale,
                "dE/dh12 = {de_dh} ({s:?}, {v:?})"
            );
            let big = 1e-2 * a;
            for (da, dh) in [
                (big, 0.0),
                (-big, 0.0),
                (0.0, big),
                (0.0, -big),
                (big, big),
                (big, -big),
            ] {
                assert!(energy(s, v, a + da, h12 + dh) > e0);
            }
        }
    }

    /// Physics: equal tensions and volumes — mirror symmetry: a flat interface
    /// (zero curvature, no division by zero), equal caps, G1 and G2 at ±G1G2/2.
    /// Tolerance 1e-12 relative: rounding only.
    #[test]
    fn symmetric_doublet_has_flat_interface() {
        let v = sphere_volume(R0);
        for s12 in [0.05, 0.1, 0.4, 0.7] {
            let d = doublet(0.4, 0.4, s12, v, v).unwrap();
            assert!(d.curvature12_per_m.abs() * R0 < 1e-12);
            assert!(d.r12_m.is_infinite() || d.r12_m > 1e12 * R0);
            assert!(d.apex12_z_m.abs() < 1e-12 * R0);
            assert!((d.r1_m / d.r2_m - 1.0).abs() < 1e-12);
            assert!((d.g1_z_m + d.g2_z_m).abs() < 1e-12 * R0);
            assert!((d.theta1_deg - d.theta2_deg).abs() < 1e-9);
            assert!((d.theta12_deg - 90.0).abs() < 1e-9);
            assert!((d.pressure1_pa / d.pressure2_pa - 1.0).abs() < 1e-12);
        }
    }

    /// Physics: swapping the two liquids (tensions and volumes) mirrors the
    /// shape: same radii and G1G2, θ1 ↔ θ2, θ12 → 180° − θ12. Tolerance 1e-9:
    /// rounding of the two independent root finds.
    #[test]
    fn swapping_liquids_mirrors_the_shape() {
        for &(s1, s2, s12, v1, v2) in &lens_cases() {
            let d = doublet(s1, s2, s12, v1, v2).unwrap();
            let m = doublet(s2, s1, s12, v2, v1).unwrap();
            assert!((d.g1g2_m / m.g1g2_m - 1.0).abs() < 1e-9);
            assert!((d.r1_m / m.r2_m - 1.0).abs() < 1e-9);
            assert!((d.contact_radius_m / m.contact_radius_m - 1.0).abs() < 1e-9);
            assert!((d.theta1_deg - m.theta2_deg).abs() < 1e-7);
            assert!((d.theta12_deg - (180.0 - m.theta12_deg)).abs() < 1e-7);
        }
    }

    /// Physics: the shape is scale free — 8× the volumes doubles every length.
    /// Tolerance 1e-12: rounding.
    #[test]
    fn doublet_scales_with_volume() {
        let v = sphere_volume(R0);
        let d = doublet(0.4, 0.2, 0.4, v, 2.0 * v).unwrap();
        let e = doublet(0.4, 0.2, 0.4, 8.0 * v, 16.0 * v).unwrap();
        assert!((e.g1g2_m / d.g1g2_m - 2.0).abs() < 1e-12);
        assert!((e.contact_radius_m / d.contact_radius_m - 2.0).abs() < 1e-12);
        assert!((e.theta12_deg - d.theta12_deg).abs() < 1e-9);
    }

    /// Physics: the interface bulges into the larger drop of two equal-tension
    /// drops (smaller drop, higher Laplace pressure).
    #[test]
    fn interface_bulges_into_larger_drop() {
        let v = sphere_volume(R0);
        let d = doublet(0.4, 0.4, 0.3, v, 3.0 * v).unwrap();
        assert!(d.curvature12_per_m > 0.0 && d.apex12_z_m > 0.0);
        assert!(d.pressure1_pa > d.pressure2_pa);
        let e = doublet(0.4, 0.4, 0.3, 3.0 * v, v).unwrap();
        assert!(e.curvature12_per_m < 0.0);
    }

    /// The root find is unique: ln(V2/V1) is strictly increasing in the
    /// rotation parameter u on (0, S) for every test case (sampled at 2000
    /// points).
    #[test]
    fn volume_ratio_is_monotone() {
        for &(s1, s2, s12, _, _) in &lens_cases() {
            let a1 = angle_opposite(s1, s2, s12);
            let a2 = angle_opposite(s2, s12, s1);
            let s = a1 + a2;
            let n = 2000;
            let mut prev = f64::NEG_INFINITY;
            for i in 1..n {
                let u = s * i as f64 / n as f64;
                let (v1, v2) = unit_volumes(u, a1, a2);
                let g = (v2 / v1).ln();
                assert!(g > prev, "not monotone at u = {u} for {s1} {s2} {s12}");
                prev = g;
            }
        }
    }

    /// Physics: σ12 → 0 with σ1 = σ2 and V1 = V2 merges the drops into one
    /// sphere of volume 2V split by a flat plane into two hemispheres, whose
    /// centroids sit 3R_s/8 from the plane: G1G2 → (3/4) R_s, R_s = 2^(1/3) R0.
    /// First order: each outer cap's rim angle exceeds 90° by half the triangle
    /// angle opposite σ12, i.e. η = h/a = 1 + x/2 with x = σ12/σ; at fixed
    /// volume the cap centroid height a η (2 + η²)/(2 (3 + η²)) then grows by
    /// the factor 1 + (2/3)(x/2), so G1G2 = (3/4) R_s (1 + x/3) + O(x²).
    /// Bound: x² R_s (second order).
    #[test]
    fn small_sigma12_tends_to_split_sphere() {
        let v = sphere_volume(R0);
        let rs = equivalent_sphere_radius(2.0 * v);
        assert!((rs / R0 - 2f64.cbrt()).abs() < 1e-14);
        for s12 in [4e-2, 4e-3, 4e-4, 4e-5, 4e-6] {
            let x = s12 / 0.4;
            let d = doublet(0.4, 0.4, s12, v, v).unwrap();
            let predicted = 0.75 * rs * (1.0 + x / 3.0);
            let err = (d.g1g2_m - predicted).abs();
            assert!(err < x * x * rs, "σ12 = {s12}: error {err} m");
        }
    }

    /// Physics: σ12 → σ1 + σ2 turns the doublet into two spheres touching at a
    /// point: G1G2 → R1 + R2 (2R0 for equal drops, docs/model.md R13 "≥ 0.8: 2").
    /// First order in the contact radius a: each sphere is cut by the plane of
    /// the triple line at the sagitta a²/(2Rk), so the centres, and with them
    /// the centroids (the cut caps hold only O(a⁴) volume), are
    /// a²/2 (1/R1 + 1/R2) closer: G1G2 = R1 + R2 − a²/2 (1/R1 + 1/R2) + O(a⁴/R³).
    /// Bound on the relative error of the a² term: (a/R0)² (next order) plus
    /// 1e-6 (rounding of G1G2, ~1e-16 R0, over a²/R0 ≥ 2e-7 R0).
    #[test]
    fn large_sigma12_tends_to_touching_spheres() {
        let v = sphere_volume(R0);
        let r3 = equivalent_sphere_radius(3.0 * v);
        for (s1, s2, v2, r2) in [(0.4, 0.4, v, R0), (0.4, 0.2, 3.0 * v, r3)] {
            let touching = separated_g1g2(R0, r2);
            assert!((touching - (R0 + r2)).abs() < 1e-15);
            let mut prev_a = f64::INFINITY;
            for rel in [1e-3, 1e-5, 1e-7] {
                let s12 = (s1 + s2) * (1.0 - rel);
                let d = doublet(s1, s2, s12, v, v2).unwrap();
                let a = d.contact_radius_m;
                assert!(a < prev_a, "the contact circle must shrink");
                prev_a = a;
                let predicted_shift = -0.5 * a * a * (1.0 / R0 + 1.0 / r2);
                let shift = d.g1g2_m - touching;
                let rel_err = (shift / predicted_shift - 1.0).abs();
                assert!(
                    rel_err < (a / R0).powi(2) + 1e-6,
                    "rel {rel}: shift {shift} m vs {predicted_shift} m"
                );
            }
            assert!(prev_a < 1e-3 * R0);
        }
    }

    /// Physics (paper A §3.1.2, Fig. 6): G1G2 grows monotonically with σ12.
    #[test]
    fn g1g2_grows_with_sigma12() {
        let v = sphere_volume(R0);
        let mut prev = 0.0;
        for i in 1..80 {
            let s12 = 0.01 * i as f64;
            let g = doublet(0.4, 0.4, s12, v, v).unwrap().g1g2_m;
            assert!(g > prev);
            prev = g;
        }
    }

    /// Reference: docs/model.md R13 — equal matte drops (σ1 = σ2 = 0.4 N/m),
    /// V = 4/3 π R0³ each, zero gravity: G1G2/R0 at σ12 = 0.1 … 0.7 N/m, and 2
    /// from 0.8 on. Tolerance 5e-4 abs: R13 gives 4 decimals.
    #[test]
    fn r13_equal_doublet_g1g2() {
        let v = sphere_volume(R0);
        let expected = [1.0265, 1.1149, 1.2127, 1.3228, 1.4494, 1.5982, 1.7775];
        for (i, &e) in expected.iter().enumerate() {
            let s12 = 0.1 * (i + 1) as f64;
            let d = doublet(0.4, 0.4, s12, v, v).unwrap();
            let g = d.g1g2_m / R0;
            assert!((g - e).abs() < 5e-4, "σ12 = {s12}: G1G2/R0 = {g}, R13 {e}");
        }
        for s12 in [0.8, 1.0] {
            assert_eq!(regime(0.4, 0.4, s12), Ok(Regime::PointContact));
            assert!((separated_g1g2(R0, R0) / R0 - 2.0).abs() < 1e-15);
        }
    }

    /// Reference: docs/model.md R15 — matte/slag (σ1 0.4, σ2 0.2 N/m), equal
    /// volumes 4/3 π R0³: G1G2/R0 and the Eq. (27) angles at σ12 = 0.3, 0.4,
    /// 0.5 N/m. Tolerances: 5e-4 abs on G1G2/R0 (4 decimals given), 0.02° on
    /// the angles (2 decimals given, plus margin).
    #[test]
    fn r15_matte_slag_doublet() {
        let v = sphere_volume(R0);
        let expected = [
            (0.3, 1.2094, [19.12, 27.45, 48.08]),
            (0.4, 1.4320, [36.82, 38.70, 65.78]),
            (0.5, 1.6796, [53.98, 54.23, 76.31]),
        ];
        for (s12, g_ref, th_ref) in expected {
            let d = doublet(0.4, 0.2, s12, v, v).unwrap();
            let g = d.g1g2_m / R0;
            assert!(
                (g - g_ref).abs() < 5e-4,
                "σ12 = {s12}: G1G2/R0 = {g}, R15 {g_ref}"
            );
            let th = [d.theta1_deg, d.theta2_deg, d.theta12_deg];
            for k in 0..3 {
                assert!(
                    (th[k] - th_ref[k]).abs() < 0.02,
                    "σ12 = {s12}: angle {k} = {}, R15 {}",
                    th[k],
                    th_ref[k]
                );
            }
            // The interface bulges into the slag (paper A §3.2: p1 > p2).
            assert!(d.curvature12_per_m > 0.0);
        }
    }

    /// Sign convention of Eq. (27): the R15 angles rounded to 0.01° give a
    /// residual of order the rounding, |Δθ| σ/σ1 ≲ 3 × 1e-4 (0.005° = 9e-5 rad,
    /// three terms of weight ≤ 1).
    #[test]
    fn eq27_residual_of_r15_angles_is_small() {
        for (s12, th) in [
            (0.3, [19.12, 27.45, 48.08]),
            (0.4, [36.82, 38.70, 65.78]),
            (0.5, [53.98, 54.23, 76.31]),
        ] {
            let r = eq27_residual(0.4, 0.2, s12, th[0], th[1], th[2]);
            assert!(r.abs() < 3e-4, "σ12 = {s12}: residual {r}");
        }
        // A wrong sign on any term gives an O(1) residual.
        assert!(eq27_residual(0.4, 0.2, 0.3, 19.12, 180.0 - 27.45, 48.08).abs() > 0.1);
    }
}
