//! Bodies too coarse for the measurements, or thinner than the potential reaches.

use super::{Check, Finding};
use solver::scene::{BodyShape, TensionModel};
use solver::Scene;

/// Fewest spacings across a body's smallest half-thickness (a drop's radius). The harness's
/// measurements have tested error bounds only from R/l0 = 8 up (`measure::geometry` and
/// `measure::side_view` tests at R/8, R/10, R/16); the accuracy–cost study
/// (`verify study accuracy-cost`, reports/study) measures the error at each resolution.
pub const MIN_RADIUS_L0: f64 = 8.0;

/// Fewest colour-kernel reaches `r_e` across a drop's radius under the surface force: at
/// R = 1.2 and 1.4 r_e (R/l0 = 5 and 6 at r_e = 4.2 l0) its drop in a host gains energy and
/// drifts instead of ringing down; at 2.4 r_e (R/l0 = 10) it rings down (docs/findings.md).
pub const SURFACE_FORCE_MIN_RADIUS_RE: f64 = 1.5;

/// The body's smallest half-thickness [m] along the axes that are not periodic (a body that
/// fills a periodic axis has no size along it), or `None` if every axis is periodic.
fn half_thickness_m(shape: &BodyShape, periodic: [bool; 3]) -> Option<f64> {
    match *shape {
        BodyShape::Sphere { radius, .. } => Some(radius),
        // its thickness is the gaps between what it surrounds and its box's faces, which the
        // other bodies' own findings and the box's size bound: not checked here
        BodyShape::Surrounding { .. } => None,
        // its height is its radius
        BodyShape::Hemisphere { radius, .. } => Some(0.5 * radius),
        // its height is R (1 − cos θ)
        BodyShape::Cap {
            radius, angle_deg, ..
        } => Some(0.5 * radius * (1.0 - angle_deg.to_radians().cos())),
        BodyShape::Shell {
            inner_radius,
            outer_radius,
            ..
        } => Some(0.5 * (outer_radius - inner_radius)),
        BodyShape::Ellipsoid { semi_axes, .. } => (0..3)
            .filter(|&k| !periodic[k])
            .map(|k| semi_axes[k])
            .reduce(f64::min),
        BodyShape::Box { min, max } => (0..3)
            .filter(|&k| !periodic[k])
            .map(|k| 0.5 * (max[k] - min[k]))
            .reduce(f64::min),
        // its thinnest wall: between the ellipsoid and the box's faces
        BodyShape::BoxAroundEllipsoid {
            min,
            max,
            center,
            semi_axes,
        } => (0..3)
            .filter(|&k| !periodic[k])
            .map(|k| {
                let below = center[k] - semi_axes[k] - min[k];
                let above = max[k] - center[k] - semi_axes[k];
                0.5 * below.min(above)
            })
            .reduce(f64::min),
    }
}

/// The findings on the bodies' sizes against `l0` and `r_e`.
pub fn findings(scene: &Scene) -> Vec<Finding> {
    let l0 = scene.discretisation.l0;
    let r_e = scene.r_e();
    let periodic = scene.periodic.ranges().map(|r| r.is_some());
    let mut out = Vec::new();
    for b in &scene.bodies {
        let Some(half) = half_thickness_m(&b.shape, periodic) else {
            continue;
        };
        let across = half / l0;
        if 2.0 * half < r_e {
            out.push(Finding {
                check: Check::Film,
                subject: format!("body {}", b.name),
                found: format!(
                    "{:.3} mm thick, thinner than the potential's cut-off r_e = {:.3} mm: its particles feel both faces, so its tension is not σ",
                    2e3 * half,
                    1e3 * r_e
                ),
                cause: "a film or thread below the particle scale".into(),
                fix: format!(
                    "l0 ≤ {:.3e} m (r_e = {} l0 across the film), or a thicker body",
                    2.0 * half / scene.discretisation.re_over_l0,
                    scene.discretisation.re_over_l0
                ),
            });
        } else if scene.effects.interfacial_tension == TensionModel::SurfaceForce
            && half < SURFACE_FORCE_MIN_RADIUS_RE * r_e
        {
            out.push(Finding {
                check: Check::Resolution,
                subject: format!("body {}", b.name),
                found: format!(
                    "{:.2} colour-kernel reaches r_e = {:.3} mm across its smallest half-thickness ({:.3} mm)",
                    half / r_e,
                    1e3 * r_e,
                    1e3 * half
                ),
                cause: format!(
                    "the surface force's curvature spans the whole body: below {SURFACE_FORCE_MIN_RADIUS_RE} r_e its drops gained energy instead of ringing down (docs/findings.md)"
                ),
                fix: format!(
                    "l0 ≤ {:.3e} m",
                    half / (SURFACE_FORCE_MIN_RADIUS_RE * scene.discretisation.re_over_l0)
                ),
            });
        } else if across < MIN_RADIUS_L0 {
            out.push(Finding {
                check: Check::Resolution,
                subject: format!("body {}", b.name),
                found: format!(
                    "{across:.1} spacings across its smallest half-thickness ({:.3} mm at l0 = {:.3} mm)",
                    1e3 * half,
                    1e3 * l0
                ),
                cause: format!(
                    "a coarse l0: below {MIN_RADIUS_L0} spacings the measurements have no tested error bound (the accuracy–cost study, reports/study, gives the error per resolution)"
                ),
                fix: format!("l0 ≤ {:.3e} m", half / MIN_RADIUS_L0),
            });
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scene(l0: f64, shape: &str) -> Scene {
        super::super::water_scene(l0, 10.0, "", shape)
    }

    #[test]
    fn a_drop_of_eight_spacings_is_resolved_and_of_five_is_not() {
        let sphere = r#"{ kind = "sphere", center = [0.0, 0.0, 0.0], radius = 1e-3 }"#;
        assert!(findings(&scene(1.25e-4, sphere)).is_empty());
        let f = findings(&scene(2e-4, sphere));
        assert_eq!(f.len(), 1);
        assert_eq!(f[0].check, Check::Resolution);
        assert!(f[0].fix.contains("1.250e-4"), "{}", f[0]);
    }

    #[test]
    fn under_the_surface_force_a_drop_within_one_and_a_half_reaches_is_flagged() {
        let toml = |l0: f64| {
            format!(
                r#"
                [discretisation]
                l0 = {l0}
                h_over_l0 = 1.3
                re_over_l0 = 6.0
                sound_speed = 4.0
                [time]
                end = 1e-3
                output_interval = 1e-4
                [effects]
                interfacial_tension = "surface_force"
                [periodic]
                x = [-3e-3, 3e-3]
                y = [-3e-3, 3e-3]
                z = [-3e-3, 3e-3]
                [[liquid]]
                name = "water"
                density = 1000.0
                viscosity = 1e-3
                surface_tension = 0.072
                [[liquid]]
                name = "host"
                density = 1000.0
                viscosity = 1e-3
                surface_tension = 0.072
                [[interface]]
                liquids = ["water", "host"]
                tension = 0.072
                [[body]]
                name = "drop"
                liquid = "water"
                shape = {{ kind = "sphere", center = [0.0, 0.0, 0.0], radius = 1e-3 }}
                [[body]]
                name = "host"
                liquid = "host"
                shape = {{ kind = "box_around_ellipsoid", min = [-3e-3, -3e-3, -3e-3], max = [3e-3, 3e-3, 3e-3], center = [0.0, 0.0, 0.0], semi_axes = [1e-3, 1e-3, 1e-3] }}
                "#
            )
        };
        // R = 1 mm at r_e = 6 l0: l0 = 0.1 mm gives 10 spacings (resolved by the generic
        // bound) but 1.67 reaches; l0 = 0.125 mm gives 8 spacings and 1.33 reaches
        let coarse = Scene::from_toml_str(&toml(1.25e-4)).unwrap();
        let f = findings(&coarse);
        assert_eq!(f.len(), 1, "{f:?}");
        assert!(
            f[0].found.contains("1.33 colour-kernel reaches"),
            "{}",
            f[0]
        );
        assert!(f[0].fix.contains("1.111e-4"), "{}", f[0]);
        assert!(findings(&Scene::from_toml_str(&toml(1e-4)).unwrap()).is_empty());
    }

    #[test]
    fn a_slab_thinner_than_the_cut_off_is_a_film() {
        // 0.6 mm thick at l0 = 0.2 mm: 3 l0 < r_e = 4.2 l0
        let slab = r#"{ kind = "box", min = [-2e-3, -2e-3, 0.0], max = [2e-3, 2e-3, 6e-4] }"#;
        let f = findings(&scene(2e-4, slab));
        assert_eq!(f.len(), 1);
        assert_eq!(f[0].check, Check::Film, "{}", f[0]);
        // 1.2 mm thick: 6 l0 ≥ r_e, but 3 spacings across its half-thickness
        let thicker = r#"{ kind = "box", min = [-2e-3, -2e-3, 0.0], max = [2e-3, 2e-3, 1.2e-3] }"#;
        assert_eq!(findings(&scene(2e-4, thicker))[0].check, Check::Resolution);
    }
}
