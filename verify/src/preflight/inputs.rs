//! Inputs no real liquid or solid has: the ranges of the property tables users copy from, and
//! the unit slip that most likely produced a value outside them.

use super::{Check, Finding};
use solver::Scene;

/// Surface tensions of real liquids [N/m]: from about 0.01 (fluorocarbons; water 0.0728, mercury
/// 0.485 at room temperature — CRC Handbook of Chemistry and Physics, "Surface tension of
/// common liquids") to about 2.5 for refractory liquid metals (Keene 1993, Int. Mater. Rev. 38,
/// 157, a review of pure metals), widened to 0.001–3.
pub const SURFACE_TENSION_N_M: (f64, f64) = (1e-3, 3.0);
/// Densities of real liquids [kg/m³]: from about 600 (light alkanes: n-pentane 626, CRC
/// Handbook) to about 20 000 (the densest liquid metals at their melting points: gold 17 300,
/// rhenium and platinum about 19 000 — Iida & Guthrie, The Physical Properties of Liquid
/// Metals, 1988), widened to 500–25 000.
pub const DENSITY_KG_M3: (f64, f64) = (500.0, 25_000.0);
/// Dynamic viscosities of real liquids [Pa·s]: from about 2e-4 (acetone 3.1e-4, CRC Handbook;
/// liquid metals 1e-3 to 6e-3, Iida & Guthrie) over glycerol's 1.4 and slags' 0.1–10 to about
/// 1e3 for glass near its working point; gases are about 1.8e-5 (air). Widened to 1e-5–1e5.
/// A viscosity of exactly 0 is an inviscid liquid asked for, not a slip.
pub const VISCOSITY_PA_S: (f64, f64) = (1e-5, 1e5);
/// Contact angles closer than this to 0° or 180° [deg]: complete wetting or drying.
pub const CONTACT_ANGLE_MARGIN_DEG: f64 = 1.0;

fn inside((lo, hi): (f64, f64), v: f64) -> bool {
    v >= lo && v <= hi
}

/// The findings on the liquids', pairs' and solids' inputs.
pub fn findings(scene: &Scene) -> Vec<Finding> {
    let mut out = Vec::new();
    for l in &scene.liquids {
        if let Some(s) = l.surface_tension {
            out.extend(surface_tension(&l.name, s));
        }
        out.extend(density(&l.name, l.density));
        out.extend(viscosity(&l.name, l.viscosity, l.density));
    }
    for i in &scene.interfaces {
        let sigma = |name: &str| {
            scene
                .liquids
                .iter()
                .find(|l| l.name == name)
                .and_then(|l| l.surface_tension)
        };
        let [a, b] = &i.liquids;
        out.extend(interfacial_tension(
            &format!("{a}/{b}"),
            i.tension,
            sigma(a).zip(sigma(b)),
        ));
    }
    for s in &scene.solids {
        for (liquid, &theta) in &s.contact_angles {
            out.extend(contact_angle(&format!("{liquid} on {}", s.name), theta));
        }
    }
    out
}

fn finding(check: Check, subject: &str, found: String, cause: String, fix: String) -> Finding {
    Finding {
        check,
        subject: subject.to_string(),
        found,
        cause,
        fix,
    }
}

/// σ against [`SURFACE_TENSION_N_M`], and the mN/m slip.
pub fn surface_tension(subject: &str, sigma_n_m: f64) -> Option<Finding> {
    let range = SURFACE_TENSION_N_M;
    if inside(range, sigma_n_m) {
        return None;
    }
    let found = format!(
        "σ = {sigma_n_m} N/m is outside the {}–{} N/m of real liquids",
        range.0, range.1
    );
    let (cause, fix) = if inside(range, sigma_n_m * 1e-3) {
        (
            format!("a value in mN/m (= dyn/cm) typed into a field in N/m: did you mean {sigma_n_m} mN/m?"),
            format!("surface_tension = {:e} (N/m)", sigma_n_m * 1e-3),
        )
    } else if inside(range, sigma_n_m * 1e3) {
        (
            format!("a value in N/m converted to mN/m twice (paper A prints 0.40 mN/m for 0.40 N/m): did you mean {sigma_n_m} N/m × 1000?"),
            format!("surface_tension = {:e} (N/m)", sigma_n_m * 1e3),
        )
    } else {
        ("a wrong unit or a typing error".into(), "σ in N/m".into())
    };
    Some(finding(Check::SurfaceTension, subject, found, cause, fix))
}

/// ρ against [`DENSITY_KG_M3`], and the g/cm³ slip.
pub fn density(subject: &str, rho_kg_m3: f64) -> Option<Finding> {
    let range = DENSITY_KG_M3;
    if inside(range, rho_kg_m3) {
        return None;
    }
    let found = format!(
        "ρ = {rho_kg_m3} kg/m³ is outside the {}–{} kg/m³ of real liquids",
        range.0, range.1
    );
    let (cause, fix) = if inside(range, rho_kg_m3 * 1e3) {
        (
            format!("a density in g/cm³ (= kg/L) typed into a field in kg/m³: did you mean {rho_kg_m3} g/cm³?"),
            format!("density = {:e} (kg/m³)", rho_kg_m3 * 1e3),
        )
    } else {
        ("a wrong unit or a typing error".into(), "ρ in kg/m³".into())
    };
    Some(finding(Check::Density, subject, found, cause, fix))
}

/// μ against [`VISCOSITY_PA_S`] (0 is allowed), and the mPa·s and kinematic slips.
pub fn viscosity(subject: &str, mu_pa_s: f64, rho_kg_m3: f64) -> Option<Finding> {
    let range = VISCOSITY_PA_S;
    if mu_pa_s == 0.0 || inside(range, mu_pa_s) {
        return None;
    }
    let found = format!(
        "μ = {mu_pa_s} Pa·s is outside the {:e}–{:e} Pa·s of real liquids",
        range.0, range.1
    );
    let (cause, fix) = if mu_pa_s > range.1 && inside(range, mu_pa_s * 1e-3) {
        (
            format!(
                "a value in mPa·s (= cP) typed into a field in Pa·s: did you mean {mu_pa_s} mPa·s?"
            ),
            format!("viscosity = {:e} (Pa·s)", mu_pa_s * 1e-3),
        )
    } else if mu_pa_s < range.0 && inside(range, mu_pa_s * rho_kg_m3) {
        (
            format!("a kinematic viscosity ν in m²/s typed into the dynamic viscosity μ: μ = ρν = {:e} Pa·s", mu_pa_s * rho_kg_m3),
            format!("viscosity = {:e} (Pa·s)", mu_pa_s * rho_kg_m3),
        )
    } else {
        (
            "a wrong unit or a typing error".into(),
            "μ in Pa·s (0 for an inviscid liquid)".into(),
        )
    };
    Some(finding(Check::Viscosity, subject, found, cause, fix))
}

/// σ_ab against the upper end of [`SURFACE_TENSION_N_M`] and, given the two liquids' own
/// tensions, against `σ_a + σ_b`, at and above which the pair strength `(σ_a + σ_b − σ_ab)/2`
/// (Eq. 18, Natsui 2021) is not positive: the liquids do not stick together.
pub fn interfacial_tension(
    subject: &str,
    sigma_ab_n_m: f64,
    own: Option<(f64, f64)>,
) -> Option<Finding> {
    let hi = SURFACE_TENSION_N_M.1;
    if sigma_ab_n_m > hi {
        let (cause, fix) = if sigma_ab_n_m * 1e-3 <= hi {
            (
                format!(
                    "a value in mN/m typed into a field in N/m: did you mean {sigma_ab_n_m} mN/m?"
                ),
                format!("tension = {:e} (N/m)", sigma_ab_n_m * 1e-3),
            )
        } else {
            (
                "a wrong unit or a typing error".into(),
                "σ_ab in N/m".into(),
            )
        };
        return Some(finding(
            Check::InterfacialTension,
            subject,
            format!("σ_ab = {sigma_ab_n_m} N/m is above the {hi} N/m of any real liquid"),
            cause,
            fix,
        ));
    }
    let (sa, sb) = own?;
    (sigma_ab_n_m >= sa + sb).then(|| {
        finding(
            Check::InterfacialTension,
            subject,
            format!(
                "σ_ab = {sigma_ab_n_m} N/m ≥ σ_a + σ_b = {} N/m: the pair strength is clipped to 0, the two liquids do not stick and part (Eq. 25)",
                sa + sb
            ),
            "intended only for a separation test; a measured interfacial tension is always below σ_a + σ_b".into(),
            format!("σ_ab < {} N/m for liquids that stay together", sa + sb),
        )
    })
}

/// θ typed in radians (in (0, π] with a fractional part: 1.2217 for 70°), or within
/// [`CONTACT_ANGLE_MARGIN_DEG`] of 0° or 180°.
pub fn contact_angle(subject: &str, theta_deg: f64) -> Option<Finding> {
    let m = CONTACT_ANGLE_MARGIN_DEG;
    if theta_deg > 0.0 && theta_deg <= std::f64::consts::PI && theta_deg.fract() != 0.0 {
        let deg = theta_deg.to_degrees();
        return Some(finding(
            Check::ContactAngle,
            subject,
            format!("θ = {theta_deg}° is between 0 and π with a fractional part: {theta_deg} rad would be {deg:.1}°"),
            "an angle in radians typed into a field in degrees (contact angles are in degrees, measured inside the liquid)".into(),
            format!("θ = {deg:.1} (degrees), if {theta_deg} was meant in radians"),
        ));
    }
    let (what, fix) = if theta_deg < m {
        ("complete wetting: the liquid spreads into a film as thin as the particles allow, whose angle the particles cannot show", format!("θ ≥ {m}°"))
    } else if theta_deg > 180.0 - m {
        ("complete drying: the liquid–solid adhesion is zero and the drop touches the solid at a point the particles cannot resolve", format!("θ ≤ {}°", 180.0 - m))
    } else {
        return None;
    };
    Some(finding(
        Check::ContactAngle,
        subject,
        format!("θ = {theta_deg}° is within {m}° of 0° or 180°: {what}"),
        "intended for a limiting case; tabulated contact angles of real pairs lie inside this range".into(),
        fix,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn water_in_mn_per_m_is_caught_with_the_value_in_n_per_m() {
        // the slip a new user made: 72.8 (mN/m) typed for σ in N/m
        let f = surface_tension("water", 72.8).expect("72.8 N/m is not a liquid's σ");
        assert!(f.cause.contains("mN/m") && f.fix.contains("7.28e-2"), "{f}");
        assert!(surface_tension("water", 0.0728).is_none());
        // paper A's "0.40 mN/m" for the matte's 0.40 N/m
        let f = surface_tension("matte", 0.40e-3).unwrap();
        assert!(f.fix.contains("4e-1"), "{f}");
        assert!(surface_tension("matte", 0.40).is_none());
    }

    #[test]
    fn density_in_g_per_cm3_is_caught() {
        let f = density("water", 1.0).unwrap();
        assert!(f.fix.contains("1e3"), "{f}");
        assert!(density("water", 997.0).is_none() && density("iron", 7000.0).is_none());
    }

    #[test]
    fn viscosity_slips_are_caught_and_zero_is_inviscid() {
        // 1e-6: water's kinematic viscosity in m²/s typed as μ
        let f = viscosity("water", 1e-6, 1000.0).unwrap();
        assert!(
            f.cause.contains("kinematic") && f.fix.contains("1e-3"),
            "{f}"
        );
        // 9350 mPa·s of a silicone oil typed as Pa·s... still in range; 9.35e5 (cP) is not
        let f = viscosity("oil", 9.35e5, 970.0).unwrap();
        assert!(f.cause.contains("mPa·s"), "{f}");
        for ok in [0.0, 1e-3, 9.35] {
            assert!(viscosity("x", ok, 1000.0).is_none(), "{ok}");
        }
    }

    #[test]
    fn interfacial_tension_too_large_or_at_separation() {
        assert!(interfacial_tension("a/b", 52.0, None)
            .unwrap()
            .cause
            .contains("mN/m"));
        let f = interfacial_tension("a/b", 0.8, Some((0.4, 0.4))).unwrap();
        assert!(f.found.contains("do not stick"), "{f}");
        assert!(interfacial_tension("a/b", 0.79, Some((0.4, 0.4))).is_none());
        assert!(interfacial_tension("w/o", 0.052, Some((0.0728, 0.0201))).is_none());
    }

    #[test]
    fn an_angle_in_radians_is_caught_with_the_value_in_degrees() {
        let f = contact_angle("water on teflon", 1.2217).expect("70° typed in radians");
        assert!(f.cause.contains("radians") && f.fix.contains("70"), "{f}");
        // 30° in radians (π/6) is also below the 1° margin: named as radians first
        assert!(contact_angle("w", std::f64::consts::FRAC_PI_6)
            .unwrap()
            .cause
            .contains("radians"));
        // whole degrees in the same range are degrees (2° and 3° are rare but possible)
        assert!(contact_angle("w", 3.0).is_none());
    }

    #[test]
    fn contact_angles_at_the_limits() {
        assert!(contact_angle("w on glass", 0.5).is_some());
        assert!(contact_angle("w on x", 179.5).is_some());
        for ok in [1.0, 30.0, 179.0] {
            assert!(contact_angle("w", ok).is_none(), "{ok}");
        }
    }
}
