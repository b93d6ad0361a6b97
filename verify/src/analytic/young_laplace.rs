//! Axisymmetric sessile drop under gravity: the Young–Laplace (Bashforth–Adams) profile.
//!
//! # What is computed
//!
//! A drop of given volume `V` \[m³\], density `ρ` \[kg/m³\] and surface tension `σ` \[N/m\]
//! rests on a horizontal plate with equilibrium contact angle `θ` (measured inside the liquid);
//! gravity `g` \[m/s²\] points down into the plate. [`sessile_drop`] returns its height, contact
//! radius, apex radius of curvature, volume and meridian profile; [`spherical_cap`] is the
//! closed-form `g = 0` shape; [`capillary_length`] is `κ⁻¹ = √(σ/(ρ g))`.
//!
//! # Equations
//!
//! The meridian is parametrised by the arc length `s` from the apex, `x(s)` the distance from
//! the axis, `z(s)` the depth below the apex and `φ(s)` the angle of the tangent with the
//! horizontal (Bashforth & Adams 1883; the standard axisymmetric Young–Laplace form):
//!
//! ```text
//! dx/ds = cos φ,   dz/ds = sin φ,   dφ/ds = 2/b + (ρ g/σ) z − sin φ / x,   dV/ds = π x² sin φ
//! ```
//!
//! with `x = z = φ = V = 0` at the apex, where the apex limit is `dφ/ds = 1/b` (`sin φ / x → 1/b`).
//! `b` is the apex radius of curvature. The profile ends where `φ = θ`: height `H = z`, contact
//! radius `x`, volume `π ∫ x² dz`.
//!
//! # Assumptions
//!
//! - Static equilibrium, axisymmetry, uniform σ and ρ, a passive surrounding gas, a flat and
//!   homogeneous plate (one contact angle, no hysteresis).
//! - The meridional curvature `dφ/ds` stays positive for `0 < φ < π` (the sessile profile is
//!   convex up to its lowest point). Proof: the Young–Laplace equation gives
//!   `d(x sin φ)/ds = x cos φ K`, `K = 2/b + (ρg/σ) z`, so with `K` growing downwards
//!   `sin φ / x ≤ K/2` along the whole first arc, hence `dφ/ds ≥ K/2 > 0`. `φ` is therefore a
//!   valid independent variable, `z` increases monotonically, `x(z)` is single valued and
//!   `θ > 90°` needs no special case (the solver nevertheless checks monotonicity).
//!
//! # Method
//!
//! *Scaling.* Lengths are scaled by `L = (1/b² + ρg/σ)^{−1/2}`, the smaller of the apex radius and
//! the capillary length in effect, so that all curvatures along the profile are O(1) from tiny
//! drops (`L ≈ b`) to large puddles (`L ≈ κ⁻¹`). With the apex Bond number `Bo = ρ g b²/σ` the
//! scaled equation has the coefficients `c = L/b = (1 + Bo)^{−1/2}` and `B = ρ g L²/σ =
//! Bo/(1 + Bo)`, `c² + B = 1`.
//!
//! *Integration.* Classical RK4 in `s` with step doubling: each step is taken once with `h` and
//! twice with `h/2`; `|y_{h/2} − y_h|/15` estimates the local error of the two half steps, which
//! must stay below `STEP_TOLERANCE` times `max(|y_old|, |y_new|, floor)` for each of `x, z, φ, V`
//! (relative control, so that the exponentially small `φ` and `z` on the flat top of a puddle are
//! still resolved). Accepted steps use the Richardson-extrapolated value (fifth order); the next
//! step is `h · clamp(0.9 err^{−1/5}, 0.2, 5)`, capped at `MAX_STEP_L`. When a step would carry
//! `φ` past `θ` it is discarded and the rest of the profile is integrated from the last accepted
//! point with `φ` as the independent variable (`d(·)/dφ = (d(·)/ds)/(dφ/ds)`, RK4 with sub-steps
//! of at most `EVENT_PHI_STEP_RAD` and `EVENT_PHI_FRACTION · (π − φ)`), so the contact line is
//! reached exactly at `φ = θ`, also for `θ` close to 180°.
//!
//! *Volume constraint.* For `g > 0` the scaled volume depends on `Bo` only; the dimensional
//! volume `L³ v(Bo)` is matched to `V` by solving `F(u) = ln(L³ v) − ln V = 0` in `u = ln Bo`,
//! starting from the zero-gravity apex radius, expanding a bracket geometrically until `F`
//! changes sign and then refining it with the Illinois variant of regula falsi (superlinear,
//! order ≈ 1.44), which always keeps the root bracketed; a bisection step is forced whenever the
//! bracket has not halved within three iterations, so convergence is guaranteed. Iteration stops
//! at `|F| ≤ ROOT_TOLERANCE_LN` or when the bracket reaches round-off width; the returned profile
//! is recomputed at the best `u` with the same deterministic integration, so its volume matches
//! `V` to that residual (≤ 1e-12 relative in practice). `F` increases with `u` in every case
//! tried (a larger apex radius holds more liquid), so the root is unique; the search itself only
//! needs the sign change. For `g = 0` (or a zero-gravity Bond number below `e^{−190}`) the same
//! integration is run with `Bo = 0` and the exact scaling `V ∝ b³` gives `b` directly.
//!
//! # Accuracy
//!
//! The force balances of the exact solution (tests) hold to ≲ 1e-11 relative, the `g = 0`
//! profile matches the spherical cap to ≲ 1e-11. One inherent exception: for `g = 0` and
//! `θ → 180°` the contact radius (→ 0) is ill-conditioned as an initial-value problem (relative
//! errors near the bottom pole grow like `(π − φ)⁻²`), so its relative error is about
//! `1e-12 (π − θ)⁻²` (6e-7 at 179.9°); height and volume are unaffected.
//!
//! Cost: a few hundred RK4 steps per profile, a few tens of profiles per call; a puddle of
//! radius `R` needs `O(R/κ⁻¹)` times more steps (its flat top is long).

use super::is_positive_finite;
use std::f64::consts::PI;

/// Local error tolerance of one integration step, relative to the size of each state component.
const STEP_TOLERANCE: f64 = 1e-11;
/// Initial arc-length step in scaled units `L`.
const INITIAL_STEP_L: f64 = 1e-3;
/// Largest arc-length step in scaled units `L` (curvature along the profile is O(1) in these
/// units, so this also keeps the returned profile smooth).
const MAX_STEP_L: f64 = 0.05;
/// Smallest arc-length step in scaled units `L` before the integration gives up.
const MIN_STEP_L: f64 = 1e-13;
/// Maximum number of attempted steps of one profile integration.
const MAX_STEPS: usize = 2_000_000;
/// Largest RK4 sub-step in `φ` \[rad\] used to land exactly on `φ = θ`.
const EVENT_PHI_STEP_RAD: f64 = 1e-3;
/// Largest RK4 sub-step in `φ`, as a fraction of `π − φ` (dimensionless), near the bottom pole.
const EVENT_PHI_FRACTION: f64 = 0.02;
/// Floors of the error scale for `(x, z, φ, V)` in scaled units: `x` has an absolute floor
/// because it returns towards zero when `θ → 180°`; the others start at zero and only grow.
const ERROR_FLOOR: [f64; 4] = [1e-6, 0.0, 0.0, 0.0];
/// Convergence threshold on `|ln(volume / target)|` for the apex-radius search.
const ROOT_TOLERANCE_LN: f64 = 1e-12;
/// Maximum number of root-finding iterations after bracketing.
const MAX_ROOT_ITERATIONS: usize = 400;
/// Smallest `ln Bo` explored by the bracket search (`Bo ≈ 1e-87`: gravity irrelevant).
const LN_BOND_MIN: f64 = -200.0;
/// Largest `ln Bo` explored by the bracket search (a puddle of radius ≈ 150 κ⁻¹).
const LN_BOND_MAX: f64 = 300.0;
/// A zero-gravity apex Bond number below `e^{LN_BOND_MIN + NEGLIGIBLE_BOND_MARGIN_LN}`
/// (≈ 1e-83) is treated as `g = 0`: gravity changes the shape by a relative O(Bo).
const NEGLIGIBLE_BOND_MARGIN_LN: f64 = 10.0;
/// Number of points of the closed-form spherical-cap profile.
const CAP_PROFILE_POINTS: usize = 201;

/// Index of `x` (distance from the axis, scaled units `L`) in the integration state.
const IX: usize = 0;
/// Index of `z` (depth below the apex, scaled units `L`) in the integration state.
const IZ: usize = 1;
/// Index of `φ` (tangent angle \[rad\]) in the arc-length integration state.
const IPHI: usize = 2;
/// Index of the volume `π∫x² dz` (scaled units `L³`) in the arc-length integration state.
const IVOL: usize = 3;
/// Index of the section moment `∫ 2x (2c + B z) dz` (dimensionless) in the arc-length state.
const IMOM: usize = 4;

/// Equilibrium sessile drop: geometry and meridian profile.
#[derive(Debug, Clone, PartialEq)]
pub struct SessileDrop {
    /// Drop height above the plate (apex to plate) \[m\].
    pub height_m: f64,
    /// Radius of the circular contact line on the plate \[m\].
    pub contact_radius_m: f64,
    /// Radius of curvature at the apex, `b` \[m\].
    pub apex_radius_m: f64,
    /// Volume of the computed profile, `π ∫ x² dz` \[m³\].
    pub volume_m3: f64,
    /// Meridian from the apex to the contact line as pairs (x \[m\], z \[m\]), `x` the distance
    /// from the symmetry axis and `z` the height measured up from the plate: first point
    /// `(0, height_m)`, last point `(contact_radius_m, 0)`, `z` decreasing along the list.
    pub profile: Vec<(f64, f64)>,
}

/// Capillary length `κ⁻¹ = √(σ/(ρ g))` \[m\] for surface tension `σ` \[N/m\], density `ρ` \[kg/m³\]
/// and gravity `g` \[m/s²\].
///
/// Returns `+∞` for `g = 0` and `f64::NAN` for non-finite inputs, `σ ≤ 0`, `ρ ≤ 0` or `g < 0`.
pub fn capillary_length(
    surface_tension_n_per_m: f64,
    density_kg_m3: f64,
    gravity_m_s2: f64,
) -> f64 {
    if !is_positive_finite(surface_tension_n_per_m)
        || !is_positive_finite(density_kg_m3)
        || !is_non_negative_finite(gravity_m_s2)
    {
        return f64::NAN;
    }
    // Capillary length: κ⁻¹ = √(σ/(ρg)) (de Gennes, Brochard-Wyart & Quéré 2004, ch. 2)
    (surface_tension_n_per_m / (density_kg_m3 * gravity_m_s2)).sqrt()
}

/// The contact angle [deg] of the spherical cap of volume `volume_m3` [m³] whose height is
/// `height_m` [m] (the inverse of [`spherical_cap`]'s height, which rises monotonically with the
/// angle): bisection over (0°, 180°) to 1e-10°. `None` if no cap of that volume has that height.
pub fn spherical_cap_angle_from_height(volume_m3: f64, height_m: f64) -> Option<f64> {
    let positive = |x: f64| x.is_finite() && x > 0.0;
    if !positive(volume_m3) || !positive(height_m) {
        return None;
    }
    let h = |deg: f64| spherical_cap(volume_m3, deg).height_m;
    let (mut lo, mut hi) = (1e-6, 180.0 - 1e-6);
    if height_m < h(lo) || height_m > h(hi) {
        return None;
    }
    while hi - lo > 1e-10 {
        let mid = 0.5 * (lo + hi);
        if h(mid) < height_m {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Some(0.5 * (lo + hi))
}

/// Spherical cap of volume `volume_m3` \[m³\] and contact angle `contact_angle_deg` \[deg\]: the
/// exact sessile shape without gravity (closed form).
///
/// Sphere radius `R = (3V / (π (1 − cos θ)² (2 + cos θ)))^{1/3}`, height `R (1 − cos θ)`,
/// contact radius `R sin θ`, apex radius `R`; the profile has 201 points
/// evenly spaced in `φ`. Invalid input (volume not finite and positive, angle outside
/// (0°, 180°)) gives `NaN` fields and an empty profile; use [`sessile_drop`] with `g = 0` for a
/// checked result.
pub fn spherical_cap(volume_m3: f64, contact_angle_deg: f64) -> SessileDrop {
    if validate_volume_and_angle(volume_m3, contact_angle_deg).is_err() {
        return SessileDrop {
            height_m: f64::NAN,
            contact_radius_m: f64::NAN,
            apex_radius_m: f64::NAN,
            volume_m3: f64::NAN,
            profile: Vec::new(),
        };
    }
    let theta = contact_angle_deg.to_radians();
    let radius_m = (volume_m3 / unit_cap_volume(theta)).cbrt();
    // 1 − cos θ = 2 sin²(θ/2), written so that small angles keep full precision.
    let one_minus_cos = 2.0 * (0.5 * theta).sin().powi(2);
    // Spherical cap of a sphere of radius R cut at polar angle θ: height R(1 − cos θ)
    let height_m = radius_m * one_minus_cos;
    // Spherical cap: base radius R sin θ
    let contact_radius_m = radius_m * theta.sin();
    let profile = (0..CAP_PROFILE_POINTS)
        .map(|i| {
            let phi = theta * i as f64 / (CAP_PROFILE_POINTS - 1) as f64;
            // Circle of radius R centred on the axis: x = R sin φ, height above the plate
            // R (cos φ − cos θ), written as 2R sin((θ+φ)/2) sin((θ−φ)/2) to avoid cancellation.
            let z_up_m = 2.0 * radius_m * (0.5 * (theta + phi)).sin() * (0.5 * (theta - phi)).sin();
            (radius_m * phi.sin(), z_up_m)
        })
        .collect();
    SessileDrop {
        height_m,
        contact_radius_m,
        apex_radius_m: radius_m,
        volume_m3,
        profile,
    }
}

/// Axisymmetric sessile drop with gravity, from the Young–Laplace equation (module docs).
///
/// - `volume_m3`: drop volume `V` \[m³\], finite and `> 0`.
/// - `density_kg_m3`: liquid density `ρ` \[kg/m³\], finite and `> 0`.
/// - `surface_tension_n_per_m`: surface tension `σ` \[N/m\], finite and `> 0`.
/// - `contact_angle_deg`: equilibrium contact angle `θ` \[deg\] inside the liquid, in (0, 180).
/// - `gravity_m_s2`: gravity magnitude `g` \[m/s²\], finite and `≥ 0` (`0`: spherical cap).
///
/// Errors: invalid input (message names the argument), a drop too large for the explored range
/// of apex Bond numbers (radius beyond ~150 capillary lengths), or an integration failure.
pub fn sessile_drop(
    volume_m3: f64,
    density_kg_m3: f64,
    surface_tension_n_per_m: f64,
    contact_angle_deg: f64,
    gravity_m_s2: f64,
) -> Result<SessileDrop, String> {
    validate_volume_and_angle(volume_m3, contact_angle_deg)?;
    if !is_positive_finite(density_kg_m3) {
        return Err(format!(
            "density must be finite and positive, got {density_kg_m3} kg/m³"
        ));
    }
    if !is_positive_finite(surface_tension_n_per_m) {
        return Err(format!(
            "surface tension must be finite and positive, got {surface_tension_n_per_m} N/m"
        ));
    }
    if !is_non_negative_finite(gravity_m_s2) {
        return Err(format!(
            "gravity must be finite and non-negative, got {gravity_m_s2} m/s²"
        ));
    }
    let theta = contact_angle_deg.to_radians();

    let capillary_length_m = capillary_length(surface_tension_n_per_m, density_kg_m3, gravity_m_s2);
    // Start of the apex-radius search, the zero-gravity apex radius: Bo₀ = (R_cap/κ⁻¹)².
    let cap_radius_m = (volume_m3 / unit_cap_volume(theta)).cbrt();
    let ln_bond_start = 2.0 * (cap_radius_m / capillary_length_m).ln();

    if gravity_m_s2 == 0.0 || ln_bond_start < LN_BOND_MIN + NEGLIGIBLE_BOND_MARGIN_LN {
        // No gravity, or gravity below any measurable effect (Bo < e^{-190}): Bo = 0, L = b, and
        // the scaled volume fixes b through V = b³ v.
        let shape = ScaledShape::from_ln_bond(f64::NEG_INFINITY);
        let solution = integrate_profile(shape, theta, true)?;
        let apex_radius_m = (volume_m3 / solution.volume).cbrt();
        return Ok(solution.to_drop(apex_radius_m, apex_radius_m));
    }

    let ln_target = volume_m3.ln();
    let ln_capillary = capillary_length_m.ln();
    // Residual F(u) = ln(L³ v(Bo)) − ln V with u = ln Bo and L = κ⁻¹ √B.
    let residual = |ln_bond: f64| -> Result<f64, String> {
        let shape = ScaledShape::from_ln_bond(ln_bond);
        let solution = integrate_profile(shape, theta, false)?;
        Ok(
            solution.volume.ln() + 3.0 * (ln_capillary + shape.ln_length_over_capillary)
                - ln_target,
        )
    };
    let ln_bond = find_root(residual, ln_bond_start.min(LN_BOND_MAX))?;

    let shape = ScaledShape::from_ln_bond(ln_bond);
    let solution = integrate_profile(shape, theta, true)?;
    let length_m = capillary_length_m * shape.ln_length_over_capillary.exp();
    // Apex Bond number Bo = ρ g b²/σ, so b = κ⁻¹ √Bo.
    let apex_radius_m = capillary_length_m * (0.5 * ln_bond).exp();
    Ok(solution.to_drop(length_m, apex_radius_m))
}

/// `true` when `value` is a finite number `≥ 0`.
fn is_non_negative_finite(value: f64) -> bool {
    value.is_finite() && value >= 0.0
}

/// Checks a drop volume \[m³\] and a contact angle \[deg\]; the error message names the argument.
fn validate_volume_and_angle(volume_m3: f64, contact_angle_deg: f64) -> Result<(), String> {
    if !is_positive_finite(volume_m3) {
        return Err(format!(
            "drop volume must be finite and positive, got {volume_m3} m³"
        ));
    }
    if !(contact_angle_deg.is_finite() && contact_angle_deg > 0.0 && contact_angle_deg < 180.0) {
        return Err(format!(
            "contact angle must lie strictly between 0° and 180°, got {contact_angle_deg}°"
        ));
    }
    Ok(())
}

/// Volume of a spherical cap of unit sphere radius and contact angle `theta_rad` \[rad\]
/// (dimensionless, in units of R³): `π (1 − cos θ)² (2 + cos θ) / 3`.
fn unit_cap_volume(theta_rad: f64) -> f64 {
    let one_minus_cos = 2.0 * (0.5 * theta_rad).sin().powi(2);
    // Spherical cap V = πh²(3R − h)/3 with h = R(1 − cos θ)
    PI * one_minus_cos * one_minus_cos * (2.0 + theta_rad.cos()) / 3.0
}

/// `ln(1 + eᵘ)` without overflow for large `u` and without loss of precision for negative `u`.
fn softplus(u: f64) -> f64 {
    if u > 0.0 {
        u + (-u).exp().ln_1p()
    } else {
        u.exp().ln_1p()
    }
}

/// Coefficients of the scaled Young–Laplace equation `dφ/dS = 2c + B Z − sin φ / X`, lengths in
/// units of `L = (1/b² + ρg/σ)^{−1/2}`.
#[derive(Debug, Clone, Copy)]
struct ScaledShape {
    /// Apex curvature in units of `1/L`: `c = L/b = (1 + Bo)^{−1/2}` (dimensionless).
    apex_curvature: f64,
    /// Gravity coefficient `B = ρ g L²/σ = Bo/(1 + Bo)` (dimensionless).
    gravity_coefficient: f64,
    /// `ln(L/κ⁻¹) = ln √B` (dimensionless; `−∞` without gravity).
    ln_length_over_capillary: f64,
}

impl ScaledShape {
    /// Coefficients for the apex Bond number `Bo = e^{ln_bond}` (`ln_bond = −∞`: no gravity).
    fn from_ln_bond(ln_bond: f64) -> Self {
        if ln_bond == f64::NEG_INFINITY {
            return Self {
                apex_curvature: 1.0,
                gravity_coefficient: 0.0,
                ln_length_over_capillary: f64::NEG_INFINITY,
            };
        }
        let ln_one_plus_bond = softplus(ln_bond);
        Self {
            // c = (1 + Bo)^{−1/2}
            apex_curvature: (-0.5 * ln_one_plus_bond).exp(),
            // B = Bo/(1 + Bo)
            gravity_coefficient: (ln_bond - ln_one_plus_bond).exp(),
            // L/κ⁻¹ = √B
            ln_length_over_capillary: 0.5 * (ln_bond - ln_one_plus_bond),
        }
    }

    /// Meridional curvature `dφ/dS` (units `1/L`) at scaled position `x`, depth `z` and tangent
    /// angle with sine `sin_phi`. Exactly at the apex (`x = 0`, `φ = 0`) the limit `c` is used;
    /// `x ≤ 0` elsewhere means the profile reached the axis and gives `NaN`.
    fn meridional_curvature(&self, x: f64, z: f64, sin_phi: f64) -> f64 {
        if x <= 0.0 {
            return if x == 0.0 && sin_phi == 0.0 {
                // Apex limit: sin φ / x → 1/b, so dφ/ds → 1/b (c in scaled units)
                self.apex_curvature
            } else {
                f64::NAN
            };
        }
        // Bashforth & Adams (1883), axisymmetric Young–Laplace: dφ/ds = 2/b + (ρg/σ) z − sin φ/x
        2.0 * self.apex_curvature + self.gravity_coefficient * z - sin_phi / x
    }

    /// Total curvature `K = 2/b + (ρg/σ) z` in units of `1/L` at scaled depth `z`.
    fn total_curvature(&self, z: f64) -> f64 {
        // Young–Laplace with hydrostatics: Δp/σ = 2/b + (ρg/σ) z
        2.0 * self.apex_curvature + self.gravity_coefficient * z
    }

    /// Derivatives with respect to the scaled arc length of `[x, z, φ, V, M]`
    /// (`M` the section moment, see [`ScaledSolution::section_moment`]).
    fn rhs_arc(&self, y: &[f64; 5]) -> [f64; 5] {
        let (sin_phi, cos_phi) = y[IPHI].sin_cos();
        let curvature = self.meridional_curvature(y[IX], y[IZ], sin_phi);
        [
            // Bashforth & Adams (1883): dx/ds = cos φ, dz/ds = sin φ
            cos_phi,
            sin_phi,
            curvature,
            // Volume of revolution: dV = π x² dz
            PI * y[IX] * y[IX] * sin_phi,
            // Section moment: dM = 2x K dz
            2.0 * y[IX] * self.total_curvature(y[IZ]) * sin_phi,
        ]
    }

    /// Derivatives with respect to `φ` \[rad\] of `[x, z, V, M, s]`
    /// (`d(·)/dφ = (d(·)/ds)/(dφ/ds)`), used to land on the contact line; `NaN` if `dφ/ds ≤ 0`
    /// (not a convex profile).
    fn rhs_angle(&self, phi: f64, y: &[f64; 5]) -> [f64; 5] {
        let (sin_phi, cos_phi) = phi.sin_cos();
        let curvature = self.meridional_curvature(y[0], y[1], sin_phi);
        if curvature.is_nan() || curvature <= 0.0 {
            return [f64::NAN; 5];
        }
        let ds_dphi = 1.0 / curvature;
        [
            // Bashforth & Adams (1883) with φ as the variable: dx/dφ = cos φ/(dφ/ds)
            cos_phi * ds_dphi,
            // dz/dφ = sin φ/(dφ/ds)
            sin_phi * ds_dphi,
            // dV/dφ = π x² sin φ/(dφ/ds)
            PI * y[0] * y[0] * sin_phi * ds_dphi,
            // dM/dφ = 2x K sin φ/(dφ/ds)
            2.0 * y[0] * self.total_curvature(y[1]) * sin_phi * ds_dphi,
            // ds/dφ = 1/(dφ/ds)
            ds_dphi,
        ]
    }
}

/// One classical fourth-order Runge–Kutta step of size `h` from `(t, y)` for `dy/dt = f(t, y)`.
fn rk4_step<const N: usize>(
    f: &impl Fn(f64, &[f64; N]) -> [f64; N],
    t: f64,
    y: &[f64; N],
    h: f64,
) -> [f64; N] {
    let shifted = |base: &[f64; N], k: &[f64; N], factor: f64| -> [f64; N] {
        std::array::from_fn(|i| base[i] + factor * k[i])
    };
    // Classical RK4 (Kutta 1901)
    let k1 = f(t, y);
    let k2 = f(t + 0.5 * h, &shifted(y, &k1, 0.5 * h));
    let k3 = f(t + 0.5 * h, &shifted(y, &k2, 0.5 * h));
    let k4 = f(t + h, &shifted(y, &k3, h));
    std::array::from_fn(|i| y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]))
}

/// Sessile profile in scaled units (lengths in `L`, depth `z` measured down from the apex).
#[derive(Debug, Clone)]
struct ScaledSolution {
    /// Contact radius (units `L`).
    contact_radius: f64,
    /// Drop height = depth of the contact line below the apex (units `L`).
    height: f64,
    /// Volume `π∫x² dz` (units `L³`).
    volume: f64,
    /// Arc length of the meridian from the apex to the contact line (units `L`), used by the
    /// horizontal force-balance test.
    #[cfg_attr(not(test), allow(dead_code))]
    arc_length: f64,
    /// Section moment `∫₀ᴴ 2x (2c + B z) dz` (units `L`): the pressure force on the meridional
    /// half-section divided by σ, used by the horizontal force-balance test.
    #[cfg_attr(not(test), allow(dead_code))]
    section_moment: f64,
    /// Meridian points `(x, z)` (units `L`, `z` down from the apex), apex first; empty when not
    /// requested.
    points: Vec<(f64, f64)>,
}

impl ScaledSolution {
    /// Converts to a [`SessileDrop`] with the length scale `length_m` \[m\] and apex radius
    /// `apex_radius_m` \[m\].
    fn to_drop(&self, length_m: f64, apex_radius_m: f64) -> SessileDrop {
        let height_m = self.height * length_m;
        let mut profile: Vec<(f64, f64)> = self
            .points
            .iter()
            .map(|&(x, z)| (x * length_m, (self.height - z) * length_m))
            .collect();
        // The last point is the contact line: make it exactly (contact radius, 0).
        if let Some(last) = profile.last_mut() {
            *last = (self.contact_radius * length_m, 0.0);
        }
        SessileDrop {
            height_m,
            contact_radius_m: self.contact_radius * length_m,
            apex_radius_m,
            volume_m3: self.volume * length_m.powi(3),
            profile,
        }
    }
}

/// Integrates the scaled sessile profile from the apex to `φ = theta_rad` (module docs, "Method").
/// `record_points` keeps every accepted step in [`ScaledSolution::points`].
fn integrate_profile(
    shape: ScaledShape,
    theta_rad: f64,
    record_points: bool,
) -> Result<ScaledSolution, String> {
    let arc_rhs = |_s: f64, y: &[f64; 5]| shape.rhs_arc(y);
    let angle_rhs = |phi: f64, y: &[f64; 5]| shape.rhs_angle(phi, y);

    let mut s = 0.0;
    let mut y = [0.0; 5];
    let mut h = INITIAL_STEP_L;
    let mut points = Vec::new();
    if record_points {
        points.push((0.0, 0.0));
    }
    for _ in 0..MAX_STEPS {
        let full = rk4_step(&arc_rhs, s, &y, h);
        let half = rk4_step(&arc_rhs, s, &y, 0.5 * h);
        let two_halves = rk4_step(&arc_rhs, s + 0.5 * h, &half, 0.5 * h);
        // Step doubling (Richardson): the error of the two half steps is (y_{h/2} − y_h)/15.
        let mut error = 0.0_f64;
        for i in 0..4 {
            let scale = y[i].abs().max(two_halves[i].abs()).max(ERROR_FLOOR[i]);
            let component = (two_halves[i] - full[i]).abs() / (15.0 * STEP_TOLERANCE * scale);
            error = error.max(if component.is_nan() {
                f64::INFINITY
            } else {
                component
            });
        }
        if error > 1.0 {
            let factor = if error.is_finite() {
                (0.9 * error.powf(-0.2)).max(0.2)
            } else {
                0.2
            };
            h *= factor;
            if h < MIN_STEP_L {
                return Err(format!(
                    "Young–Laplace integration: step size underflow at s = {s:.6e} L, \
                     φ = {:.6} rad",
                    y[IPHI]
                ));
            }
            continue;
        }
        // Local (Richardson) extrapolation: fifth-order accurate value.
        let next: [f64; 5] =
            std::array::from_fn(|i| two_halves[i] + (two_halves[i] - full[i]) / 15.0);
        if next[IPHI].is_nan() || next[IPHI] <= y[IPHI] {
            return Err(format!(
                "Young–Laplace integration: tangent angle stopped increasing at φ = {:.6} rad \
                 before reaching the contact angle",
                y[IPHI]
            ));
        }
        if next[IPHI] >= theta_rad {
            // Event: finish from the last accepted point with φ as the independent variable.
            let mut phi = y[IPHI];
            let mut state = [y[IX], y[IZ], y[IVOL], y[IMOM], s];
            while phi < theta_rad {
                // Sub-steps shrink geometrically towards φ = π, where x → 0 for g = 0 and
                // relative errors in x grow like (π − φ)⁻².
                let dphi_max = EVENT_PHI_STEP_RAD.min(EVENT_PHI_FRACTION * (PI - phi));
                let remaining = theta_rad - phi;
                if remaining <= dphi_max {
                    state = rk4_step(&angle_rhs, phi, &state, remaining);
                    phi = theta_rad;
                } else {
                    state = rk4_step(&angle_rhs, phi, &state, dphi_max);
                    phi += dphi_max;
                }
            }
            if state.iter().any(|v| !v.is_finite()) || state[0] <= 0.0 {
                return Err(format!(
                    "Young–Laplace integration failed on the final arc to θ = {theta_rad:.6} rad"
                ));
            }
            if record_points {
                points.push((state[0], state[1]));
            }
            return Ok(ScaledSolution {
                contact_radius: state[0],
                height: state[1],
                volume: state[2],
                section_moment: state[3],
                arc_length: state[4],
                points,
            });
        }
        s += h;
        y = next;
        if record_points {
            points.push((y[IX], y[IZ]));
        }
        let growth = if error > 0.0 {
            (0.9 * error.powf(-0.2)).clamp(0.2, 5.0)
        } else {
            5.0
        };
        h = (h * growth).min(MAX_STEP_L);
    }
    Err(format!(
        "Young–Laplace integration: no contact line after {MAX_STEPS} steps (φ = {:.6} rad)",
        y[IPHI]
    ))
}

/// Finds a root of `residual(u)` (increasing in `u`) near `start`: geometric bracket expansion
/// within [`LN_BOND_MIN`], [`LN_BOND_MAX`], then Illinois regula falsi with forced bisection
/// (module docs, "Volume constraint"). Returns the evaluated point with the smallest
/// `|residual|`.
fn find_root(residual: impl Fn(f64) -> Result<f64, String>, start: f64) -> Result<f64, String> {
    let f_start = residual(start)?;
    if f_start.abs() <= ROOT_TOLERANCE_LN {
        return Ok(start);
    }
    // Bracket [lo, hi] with residual(lo) < 0 < residual(hi).
    let direction = if f_start < 0.0 { 1.0 } else { -1.0 };
    let (mut inner, mut f_inner) = (start, f_start);
    let mut step = 1.0;
    let (mut outer, mut f_outer);
    loop {
        outer = (inner + direction * step).clamp(LN_BOND_MIN, LN_BOND_MAX);
        f_outer = residual(outer)?;
        if f_outer.signum() != f_start.signum() || f_outer == 0.0 {
            break;
        }
        if outer <= LN_BOND_MIN || outer >= LN_BOND_MAX {
            let reason = if direction > 0.0 {
                "the drop is too large relative to the capillary length (puddle radius beyond \
                 ~150 κ⁻¹)"
            } else {
                "the volume residual did not change sign down to negligible gravity"
            };
            return Err(format!(
                "sessile drop: no apex radius found for this volume (searched apex Bond numbers \
                 e^{LN_BOND_MIN} to e^{LN_BOND_MAX}): {reason}"
            ));
        }
        inner = outer;
        f_inner = f_outer;
        step *= 2.0;
    }
    let (mut lo, mut f_lo, mut hi, mut f_hi) = if direction > 0.0 {
        (inner, f_inner, outer, f_outer)
    } else {
        (outer, f_outer, inner, f_inner)
    };
    // Illinois iteration; `retained` remembers which end was kept last (−1 lo, +1 hi).
    let mut retained = 0;
    let mut width_reference = hi - lo;
    let mut since_check = 0;
    let mut force_bisection = false;
    // Best point so far (u, residual); the Illinois halving below alters f_lo / f_hi, so the
    // true residuals are tracked here.
    let mut best = if f_lo.abs() < f_hi.abs() {
        (lo, f_lo)
    } else {
        (hi, f_hi)
    };
    for _ in 0..MAX_ROOT_ITERATIONS {
        if best.1.abs() <= ROOT_TOLERANCE_LN || hi - lo <= 4.0 * f64::EPSILON * (1.0 + best.0.abs())
        {
            return Ok(best.0);
        }
        let secant = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
        let u = if force_bisection || !(secant > lo && secant < hi) {
            0.5 * (lo + hi)
        } else {
            secant
        };
        force_bisection = false;
        let f_u = residual(u)?;
        if f_u.abs() < best.1.abs() {
            best = (u, f_u);
        }
        if f_u < 0.0 {
            lo = u;
            f_lo = f_u;
            if retained == 1 {
                f_hi *= 0.5; // Illinois: hi kept twice in a row
            }
            retained = 1;
        } else {
            hi = u;
            f_hi = f_u;
            if retained == -1 {
                f_lo *= 0.5; // Illinois: lo kept twice in a row
            }
            retained = -1;
        }
        since_check += 1;
        if since_check == 3 {
            force_bisection = hi - lo > 0.5 * width_reference;
            width_reference = hi - lo;
            since_check = 0;
        }
    }
    Err(format!(
        "sessile drop: apex-radius search did not converge in {MAX_ROOT_ITERATIONS} iterations \
         (bracket ln Bo ∈ [{lo}, {hi}])"
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Standard gravity used by docs/model.md R17–R19 \[m/s²\].
    const G_STANDARD_M_S2: f64 = 9.81;

    /// Relative difference |a − b| / |b|.
    fn rel_diff(a: f64, b: f64) -> f64 {
        (a - b).abs() / b.abs()
    }

    /// Volume \[m³\] of a sphere of diameter `diameter_m` \[m\].
    fn sphere_volume_m3(diameter_m: f64) -> f64 {
        PI / 6.0 * diameter_m.powi(3)
    }

    /// Solves the drop or fails the test with the solver's message.
    fn solve(volume_m3: f64, rho: f64, sigma: f64, theta_deg: f64, g: f64) -> SessileDrop {
        match sessile_drop(volume_m3, rho, sigma, theta_deg, g) {
            Ok(drop) => drop,
            Err(message) => panic!("sessile_drop failed: {message}"),
        }
    }

    /// Without gravity the Young–Laplace integration must reproduce the closed-form spherical cap
    /// (height, contact radius, apex radius) for acute, right and obtuse angles up to 179.5°.
    #[test]
    fn the_cap_angle_from_its_height_inverts_the_cap() {
        for theta in [15.0, 30.0, 60.0, 90.0, 135.0, 170.0] {
            let v = 2.1e-9;
            let h = spherical_cap(v, theta).height_m;
            let back = spherical_cap_angle_from_height(v, h).expect("a cap");
            // bisection to 1e-10°, and the height's own rounding: 1e-8°
            assert!((back - theta).abs() < 1e-8, "{theta} → {back}");
        }
        assert!(spherical_cap_angle_from_height(2.1e-9, 1.0).is_none());
        assert!(spherical_cap_angle_from_height(-1.0, 1e-3).is_none());
    }

    #[test]
    fn zero_gravity_equals_spherical_cap() {
        for &theta_deg in &[1.0, 10.0, 30.0, 60.0, 90.0, 120.0, 150.0, 175.0, 179.5] {
            let volume_m3 = 2.0e-9;
            let drop = solve(volume_m3, 1000.0, 0.07, theta_deg, 0.0);
            let cap = spherical_cap(volume_m3, theta_deg);
            // Local step tolerance 1e-11: observed ≤ 1e-11, except the ill-conditioned contact
            // radius at 179.5° (~3e-8, module docs "Accuracy"); 1e-6 leaves margin.
            let tol = 1e-6;
            assert!(
                rel_diff(drop.height_m, cap.height_m) < tol,
                "θ={theta_deg}: height"
            );
            assert!(
                rel_diff(drop.contact_radius_m, cap.contact_radius_m) < tol,
                "θ={theta_deg}: contact radius {} vs {}",
                drop.contact_radius_m,
                cap.contact_radius_m
            );
            assert!(
                rel_diff(drop.apex_radius_m, cap.apex_radius_m) < tol,
                "θ={theta_deg}: b"
            );
        }
    }

    /// A vanishing but non-zero gravity (Bond number ~1e-13) goes through the root search and
    /// must give the spherical cap: the g → 0 limit is continuous.
    #[test]
    fn tiny_gravity_approaches_spherical_cap() {
        let volume_m3 = sphere_volume_m3(2e-3);
        let drop = solve(volume_m3, 997.0, 0.073, 60.0, 1e-11);
        let cap = spherical_cap(volume_m3, 60.0);
        // Gravity correction to the height is O(Bo) ≈ ρgR²/σ ≈ 1.4e-13 here, below the
        // integration error (≲ 1e-11, see zero_gravity_equals_spherical_cap); 1e-6 leaves margin.
        assert!(rel_diff(drop.height_m, cap.height_m) < 1e-6);
        assert!(rel_diff(drop.contact_radius_m, cap.contact_radius_m) < 1e-6);
        // Gravity so small that ρg underflows towards zero (Bo ~ 1e-300): treated as g = 0,
        // same 1e-6 tolerance as zero_gravity_equals_spherical_cap.
        let drop = solve(volume_m3, 997.0, 0.073, 60.0, 1e-300);
        assert!(rel_diff(drop.height_m, cap.height_m) < 1e-6);
    }

    /// The closed-form cap is self-consistent: hemisphere at 90°, and its volume recomputed from
    /// height h and contact radius a by the independent formula V = πh(3a² + h²)/6.
    #[test]
    fn spherical_cap_geometry() {
        let radius_m: f64 = 1.5e-3;
        let hemisphere = spherical_cap(2.0 / 3.0 * PI * radius_m.powi(3), 90.0);
        // Closed form, round-off only: 1e-12 relative.
        assert!(rel_diff(hemisphere.height_m, radius_m) < 1e-12);
        assert!(rel_diff(hemisphere.contact_radius_m, radius_m) < 1e-12);
        for &theta_deg in &[0.5, 20.0, 90.0, 140.0, 179.0] {
            let volume_m3 = 3.0e-9;
            let cap = spherical_cap(volume_m3, theta_deg);
            let (h, a) = (cap.height_m, cap.contact_radius_m);
            // Archimedes' cap volume from base radius and height; round-off only: 1e-12.
            let volume_from_geometry = PI * h * (3.0 * a * a + h * h) / 6.0;
            assert!(
                rel_diff(volume_from_geometry, volume_m3) < 1e-12,
                "θ={theta_deg}"
            );
            // Profile runs from the apex (0, h) to the contact line (a, 0).
            let first = cap.profile[0];
            let last = cap.profile[cap.profile.len() - 1];
            assert!(first.0.abs() < 1e-18 && rel_diff(first.1, h) < 1e-12);
            assert!(rel_diff(last.0, a) < 1e-12 && last.1.abs() < 1e-15);
        }
        // Invalid input: NaN geometry and no profile.
        let bad = spherical_cap(-1.0, 90.0);
        assert!(bad.height_m.is_nan() && bad.profile.is_empty());
    }

    /// The volume constraint V(b) = V is met to 1e-8 relative over five decades of Bond number
    /// and acute/obtuse angles. The root search stops at |ln(V(b)/V)| ≤ 1e-12 and the returned
    /// volume is integrated at that b (observed ≤ 1e-14), so 1e-8 leaves a wide margin.
    #[test]
    fn volume_constraint_is_met() {
        for &(volume_m3, rho, sigma, theta_deg) in &[
            (1e-12, 1000.0, 0.07, 45.0),
            (sphere_volume_m3(2e-3), 997.0, 0.073, 30.0),
            (sphere_volume_m3(5e-3), 7020.0, 1.8, 125.0),
            (1e-6, 1000.0, 0.07, 90.0),
            (1e-5, 1000.0, 0.07, 170.0),
        ] {
            let drop = solve(volume_m3, rho, sigma, theta_deg, G_STANDARD_M_S2);
            let error = rel_diff(drop.volume_m3, volume_m3);
            assert!(
                error < 1e-8,
                "V = {volume_m3}, θ = {theta_deg}: error {error}"
            );
        }
    }

    /// The returned profile is consistent with the scalar results: apex at (0, H), contact line
    /// at (R_c, 0), height decreasing monotonically along it, and π∫x² dz over the profile
    /// (trapezoid rule) equal to the volume.
    #[test]
    fn profile_is_consistent() {
        for &theta_deg in &[30.0, 90.0, 150.0] {
            let volume_m3 = sphere_volume_m3(4e-3);
            let drop = solve(volume_m3, 1000.0, 0.07, theta_deg, G_STANDARD_M_S2);
            let profile = &drop.profile;
            assert!(profile.len() > 20);
            assert_eq!(profile[0], (0.0, drop.height_m));
            assert_eq!(profile[profile.len() - 1], (drop.contact_radius_m, 0.0));
            let mut volume_trapezoid = 0.0;
            for pair in profile.windows(2) {
                let ((x0, z0), (x1, z1)) = (pair[0], pair[1]);
                assert!(z1 < z0, "height must decrease from apex to contact line");
                volume_trapezoid += PI * 0.5 * (x0 * x0 + x1 * x1) * (z0 - z1);
            }
            // Trapezoid rule on points ≤ 0.05 L apart (L ≤ κ⁻¹ = 2.7 mm), curvature O(1/L):
            // error ≲ (Δs)²/12 ~ 2e-4 relative (observed ≤ 8e-5); 1e-3 leaves margin.
            assert!(
                rel_diff(volume_trapezoid, volume_m3) < 1e-3,
                "θ={theta_deg}: {volume_trapezoid} vs {volume_m3}"
            );
            if theta_deg > 90.0 {
                let x_max = profile.iter().map(|p| p.0).fold(0.0, f64::max);
                assert!(
                    x_max > drop.contact_radius_m,
                    "θ > 90°: the drop overhangs its foot"
                );
            }
        }
    }

    /// Exact force balances of the Young–Laplace solution, independent of the discretisation:
    /// vertical, on the whole drop: 2π R_c sin θ = π R_c² K(H) − (ρg/σ) V, and horizontal, on a
    /// meridional half: ∫₀ᴴ 2x K dz = ℓ − 2 R_c cos θ (ℓ the meridian length, K = 2/b + ρgz/σ).
    /// Checked from the sphere (Bo = 0) to a puddle (Bo = e⁴⁰) and for θ from 0.5° to 179.9°.
    #[test]
    fn force_balances_hold() {
        for &ln_bond in &[f64::NEG_INFINITY, -5.0, 0.0, 3.0, 12.0, 40.0] {
            for &theta_deg in &[0.5, 20.0, 90.0, 125.0, 178.0, 179.9] {
                let theta: f64 = f64::to_radians(theta_deg);
                let shape = ScaledShape::from_ln_bond(ln_bond);
                let sol = match integrate_profile(shape, theta, false) {
                    Ok(sol) => sol,
                    Err(message) => panic!("integration failed: {message}"),
                };
                let rc = sol.contact_radius;
                let line_force = 2.0 * PI * rc * theta.sin();
                let pressure_force = PI * rc * rc * shape.total_curvature(sol.height);
                let weight = shape.gravity_coefficient * sol.volume;
                // Force scale: the largest term, or σ times the drop's perimeter 2πH when the
                // contact-line terms vanish (θ → 180° without gravity: R_c → 0).
                let vertical_scale = line_force
                    .abs()
                    .max(pressure_force)
                    .max(weight)
                    .max(2.0 * PI * sol.height);
                let vertical_residual = (line_force - pressure_force + weight) / vertical_scale;
                let meridian_tension = 2.0 * sol.arc_length;
                let foot_tension = 2.0 * rc * theta.cos();
                let horizontal_scale = sol.section_moment.max(meridian_tension);
                let horizontal_residual =
                    (sol.section_moment - meridian_tension + foot_tension) / horizontal_scale;
                // Relative to that scale: local step tolerance 1e-11 accumulated over up to
                // ~2000 steps gives ≲ 1e-11 (observed ≤ 1e-12); 1e-9 leaves margin while any
                // modelling error (wrong sign, missing term, wrong end point) gives O(1).
                assert!(
                    vertical_residual.abs() < 1e-9,
                    "vertical, ln Bo={ln_bond}, θ={theta_deg}: {vertical_residual:e}"
                );
                assert!(
                    horizontal_residual.abs() < 1e-9,
                    "horizontal, ln Bo={ln_bond}, θ={theta_deg}: {horizontal_residual:e}"
                );
            }
        }
    }

    /// The dimensional outputs (H, R_c, b, V) obey the vertical force balance on the drop,
    /// 2π R_c σ sin θ = π R_c² (2σ/b + ρ g H) − ρ g V: contact-line tension plus weight equal the
    /// plate's pressure force. Checks the unit conversion of every returned scalar.
    #[test]
    fn returned_drop_satisfies_vertical_force_balance() {
        for &(volume_m3, rho, sigma, theta_deg, g) in &[
            (sphere_volume_m3(5e-3), 7020.0, 1.8, 125.0, G_STANDARD_M_S2),
            (70e-6 / 2240.0, 2240.0, 0.9, 90.0, G_STANDARD_M_S2),
            (sphere_volume_m3(2e-3), 997.0, 0.073, 30.0, G_STANDARD_M_S2),
            (sphere_volume_m3(2e-3), 4500.0, 0.4, 90.0, 9.8),
            (1e-6, 1000.0, 0.07, 160.0, G_STANDARD_M_S2),
        ] {
            let drop = solve(volume_m3, rho, sigma, theta_deg, g);
            let theta = f64::to_radians(theta_deg);
            let rc = drop.contact_radius_m;
            let line_force_n = 2.0 * PI * rc * sigma * theta.sin();
            let pressure_force_n =
                PI * rc * rc * (2.0 * sigma / drop.apex_radius_m + rho * g * drop.height_m);
            let weight_n = rho * g * drop.volume_m3;
            let residual = (line_force_n + weight_n - pressure_force_n) / pressure_force_n;
            // Integration error ≲ 1e-10 relative (see force_balances_hold); 1e-8 leaves margin,
            // while a 1e-4 error in any returned scalar would show.
            assert!(
                residual.abs() < 1e-8,
                "θ={theta_deg}: residual {residual:e}"
            );
        }
    }

    /// Heavier gravity flattens the drop: at fixed volume the height decreases strictly and the
    /// contact radius grows as g increases from 0 to 100 m/s².
    #[test]
    fn height_decreases_with_gravity() {
        let volume_m3 = sphere_volume_m3(3e-3);
        for &theta_deg in &[40.0, 90.0, 140.0] {
            let mut previous: Option<SessileDrop> = None;
            for &g in &[0.0, 0.01, 0.3, 1.0, 3.0, 9.81, 30.0, 100.0] {
                let drop = solve(volume_m3, 1000.0, 0.07, theta_deg, g);
                if let Some(prev) = &previous {
                    assert!(
                        drop.height_m < prev.height_m,
                        "θ={theta_deg}, g={g}: height"
                    );
                    assert!(
                        drop.contact_radius_m > prev.contact_radius_m,
                        "θ={theta_deg}, g={g}: contact radius"
                    );
                }
                previous = Some(drop);
            }
        }
    }

    /// Large Bond number: a puddle whose height tends to the 2D (infinite puddle) value
    /// H∞ = 2 κ⁻¹ sin(θ/2) (de Gennes, Brochard-Wyart & Quéré 2004, ch. 2). The leading
    /// axisymmetric correction, derived for this test by evaluating the two exact force balances
    /// of `force_balances_hold` on the 2D meniscus z = 2κ⁻¹ sin(φ/2), is
    /// H/H∞ − 1 = C(θ) κ⁻¹/R_c + O((κ⁻¹/R_c)²), C(θ) = (1 − cos³(θ/2)) / (3 sin²(θ/2)).
    #[test]
    fn puddle_height_limit() {
        let (rho, sigma, g) = (1000.0, 0.07, G_STANDARD_M_S2);
        let kappa_inv_m = capillary_length(sigma, rho, g);
        for &theta_deg in &[30.0, 90.0, 150.0] {
            let half_angle = 0.5 * f64::to_radians(theta_deg);
            let h_inf = 2.0 * kappa_inv_m * half_angle.sin();
            let coefficient = (1.0 - half_angle.cos().powi(3)) / (3.0 * half_angle.sin().powi(2));
            for &radius_over_kappa in &[20.0, 40.0] {
                let radius_m = radius_over_kappa * kappa_inv_m;
                let volume_m3 = PI * radius_m * radius_m * h_inf;
                let drop = solve(volume_m3, rho, sigma, theta_deg, g);
                let epsilon = kappa_inv_m / drop.contact_radius_m;
                let deviation = drop.height_m / h_inf - 1.0;
                // The limit itself: C(θ) ≤ 1/2, so at R_c ≥ 20 κ⁻¹ the height is within 3 %.
                assert!(
                    deviation.abs() < 0.03,
                    "θ={theta_deg}: deviation {deviation}"
                );
                // First-order asymptote; the remainder is O(ε²) with an O(1) coefficient
                // (ε = κ⁻¹/R_c ≤ 0.05), so ε² bounds it (observed ≤ 0.4 ε²).
                assert!(
                    (deviation - coefficient * epsilon).abs() < epsilon * epsilon,
                    "θ={theta_deg}, R_c/κ⁻¹={}: deviation {deviation}, asymptote {}",
                    1.0 / epsilon,
                    coefficient * epsilon
                );
            }
        }
    }

    /// Small non-wetting drop (θ → 180°, R ≪ κ⁻¹): it rests on a flat foot of radius
    /// ℓ = √(2/3) R²/κ⁻¹ (Mahadevan & Pomeau 1999), R the radius of the undeformed sphere.
    #[test]
    fn non_wetting_drop_foot_radius() {
        let (rho, sigma, g) = (997.0, 0.073, G_STANDARD_M_S2);
        let kappa_inv_m = capillary_length(sigma, rho, g);
        let radius_m = 0.05 * kappa_inv_m;
        let volume_m3 = 4.0 / 3.0 * PI * radius_m.powi(3);
        let drop = solve(volume_m3, rho, sigma, 179.999, g);
        let foot_m = (2.0_f64 / 3.0).sqrt() * radius_m * radius_m / kappa_inv_m;
        // Leading-order theory: relative corrections O(Bo) = (R/κ⁻¹)² = 2.5e-3, plus the
        // 0.001° angle deficit, R(π − θ)/ℓ ≈ 4e-4; 5e-3 covers both (observed 6e-4), while a
        // wrong prefactor (e.g. √(1/2)) would be off by 13 %.
        assert!(
            rel_diff(drop.contact_radius_m, foot_m) < 5e-3,
            "foot {} vs {}",
            drop.contact_radius_m,
            foot_m
        );
    }

    /// docs/model.md R17: Fe drop of a 5 mm sphere's volume, ρ 7020, σ 1.8, θ 125°, g 9.81:
    /// height 3.80 mm, and 4.10 mm without gravity.
    #[test]
    fn reference_r17_iron() {
        let volume_m3 = sphere_volume_m3(5e-3);
        let drop = solve(volume_m3, 7020.0, 1.8, 125.0, G_STANDARD_M_S2);
        let cap = spherical_cap(volume_m3, 125.0);
        // 3 significant digits in docs/model.md: half a unit in the last digit, 0.005 mm.
        assert!(
            (drop.height_m - 3.80e-3).abs() <= 0.5e-5,
            "H = {}",
            drop.height_m
        );
        assert!(
            (cap.height_m - 4.10e-3).abs() <= 0.5e-5,
            "H0 = {}",
            cap.height_m
        );
    }

    /// docs/model.md R18: Al drop of 70 mg (V = 70e-6 kg / 2240 kg/m³), σ 0.9, θ 90°, g 9.81:
    /// height 2.41 mm.
    #[test]
    fn reference_r18_aluminium() {
        let drop = solve(70e-6 / 2240.0, 2240.0, 0.9, 90.0, G_STANDARD_M_S2);
        // 3 significant digits: half a unit in the last digit, 0.005 mm.
        assert!(
            (drop.height_m - 2.41e-3).abs() <= 0.5e-5,
            "H = {}",
            drop.height_m
        );
    }

    /// docs/model.md R19: water drop of a 2 mm sphere's volume, ρ 997, σ 0.073, g 9.81:
    /// height 0.553 mm at θ 30° and 1.222 mm at θ 90°.
    #[test]
    fn reference_r19_water() {
        let volume_m3 = sphere_volume_m3(2e-3);
        let glass = solve(volume_m3, 997.0, 0.073, 30.0, G_STANDARD_M_S2);
        let teflon = solve(volume_m3, 997.0, 0.073, 90.0, G_STANDARD_M_S2);
        // 4 significant digits in docs/model.md (1.222 mm; 0.553 mm has 3): half a unit in the
        // last digit, 0.5 µm.
        assert!(
            (glass.height_m - 0.553e-3).abs() <= 0.5e-6,
            "H30 = {}",
            glass.height_m
        );
        assert!(
            (teflon.height_m - 1.222e-3).abs() <= 0.5e-6,
            "H90 = {}",
            teflon.height_m
        );
    }

    /// docs/model.md R20: matte drop of a 2 mm sphere's volume, ρ 4500, σ 0.4, θ 90°, g 9.8:
    /// height 1.229 mm.
    #[test]
    fn reference_r20_matte() {
        let drop = solve(sphere_volume_m3(2e-3), 4500.0, 0.4, 90.0, 9.8);
        // 4 significant digits: half a unit in the last digit, 0.5 µm.
        assert!(
            (drop.height_m - 1.229e-3).abs() <= 0.5e-6,
            "H = {}",
            drop.height_m
        );
    }

    /// The capillary length of water at 25 °C is about 2.7 mm: κ⁻¹ = √(0.072/(997·9.81)).
    #[test]
    fn capillary_length_value() {
        let kappa_inv_m = capillary_length(0.072, 997.0, 9.81);
        // Hand value √(0.072/9780.57) = 2.71322e-3 m to 6 digits: 1e-5 relative.
        assert!(rel_diff(kappa_inv_m, 2.71322e-3) < 1e-5, "{kappa_inv_m}");
        assert!(capillary_length(0.072, 997.0, 0.0).is_infinite());
        assert!(capillary_length(-0.072, 997.0, 9.81).is_nan());
    }

    /// Invalid inputs are rejected with a message naming the offending argument.
    #[test]
    fn invalid_inputs_are_rejected() {
        let v = 1e-9;
        let cases: [(f64, f64, f64, f64, f64, &str); 9] = [
            (0.0, 1000.0, 0.07, 90.0, 9.81, "volume"),
            (-v, 1000.0, 0.07, 90.0, 9.81, "volume"),
            (f64::NAN, 1000.0, 0.07, 90.0, 9.81, "volume"),
            (v, 0.0, 0.07, 90.0, 9.81, "density"),
            (v, 1000.0, -0.07, 90.0, 9.81, "surface tension"),
            (v, 1000.0, 0.07, 0.0, 9.81, "contact angle"),
            (v, 1000.0, 0.07, 180.0, 9.81, "contact angle"),
            (v, 1000.0, 0.07, f64::NAN, 9.81, "contact angle"),
            (v, 1000.0, 0.07, 90.0, -9.81, "gravity"),
        ];
        for (volume, rho, sigma, theta, g, word) in cases {
            match sessile_drop(volume, rho, sigma, theta, g) {
                Ok(_) => panic!("accepted invalid input ({volume}, {rho}, {sigma}, {theta}, {g})"),
                Err(message) => assert!(message.contains(word), "{message}"),
            }
        }
    }

    /// Angles close to the ends of (0°, 180°) still give a valid drop: tiny θ a thin film-like
    /// cap, θ → 180° a drop sitting on a small flattened foot.
    #[test]
    fn extreme_contact_angles() {
        let volume_m3 = sphere_volume_m3(2e-3);
        let flat = solve(volume_m3, 997.0, 0.073, 0.5, G_STANDARD_M_S2);
        let round = solve(volume_m3, 997.0, 0.073, 179.9, G_STANDARD_M_S2);
        for drop in [&flat, &round] {
            // Same volume-constraint tolerance as volume_constraint_is_met.
            assert!(rel_diff(drop.volume_m3, volume_m3) < 1e-8);
            assert!(drop.height_m > 0.0 && drop.contact_radius_m > 0.0);
        }
        // Near 180° the drop is almost a flattened sphere: height below its diameter but above
        // the 90° height; the foot is set by gravity, much smaller than the radius.
        let hemi = solve(volume_m3, 997.0, 0.073, 90.0, G_STANDARD_M_S2);
        assert!(round.height_m < 2e-3 && round.height_m > hemi.height_m);
        assert!(
            round.contact_radius_m < 0.5e-3,
            "foot {}",
            round.contact_radius_m
        );
        // Near 0° the cap is thin: height much smaller than the contact radius.
        assert!(flat.height_m < 0.05 * flat.contact_radius_m);
    }
}
