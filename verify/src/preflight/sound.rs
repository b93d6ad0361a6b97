//! The sound speed against the scene's cohesion and flow, and the time step it leads to.

use super::{Check, Finding};
use crate::diagnostics::lattice_moduli;
use solver::scene::WallShape;
use solver::{Model, Scene};

/// The compression the potential's cohesive pressure may cause [-]: the sound-speed rule of docs/user-guide.md
/// `c² ≥ 1.75 σ/(0.01 ρ l0)` aims at 1 %; the 5 % margin on it covers the rule's rounding of
/// the lattice's cohesive pressure (1.755 σ/l0 at r_e = 4.2 l0) to 1.75.
pub const MAX_COHESIVE_COMPRESSION: f64 = 0.0105;
/// The sound speed must be this many times the fastest speed the scene implies (Mach 0.1:
/// density changes of about 1 %, the weakly compressible regime).
pub const MACH_FACTOR: f64 = 10.0;

fn norm(v: [f64; 3]) -> f64 {
    (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
}

/// The findings on the sound speed.
pub fn findings(scene: &Scene) -> Vec<Finding> {
    let mut out = Vec::new();
    let d = &scene.discretisation;
    let (l0, c) = (d.l0, d.sound_speed);
    if scene.effects.interfacial_tension.is_potential() {
        // the cohesive pressure the EOS carries on the reference lattice [σ/l0]
        let p_b = lattice_moduli::lattice_elasticity(
            d.kernel,
            d.h_over_l0,
            d.re_over_l0,
            d.potential_order,
        )
        .background_pressure;
        for l in &scene.liquids {
            let Some(sigma) = l.surface_tension else {
                continue;
            };
            let compression = p_b * sigma / (l0 * l.density * c * c);
            if compression > MAX_COHESIVE_COMPRESSION {
                let needed = (p_b * sigma / (l0 * l.density * 0.01)).sqrt();
                out.push(Finding {
                    check: Check::CohesiveSoundSpeed,
                    subject: format!("liquid {}", l.name),
                    found: format!(
                        "the potential's cohesive pressure {p_b:.3} σ/l0 = {:.4e} Pa compresses it by {:.1} % at c = {c} m/s",
                        p_b * sigma / l0,
                        100.0 * compression
                    ),
                    cause: "a sound speed below the cohesion rule c² ≥ p_b/(0.01 ρ): the drop's interior is compressed and its density, not only its shape, responds to tension".into(),
                    fix: format!("discretisation.sound_speed ≥ {needed:.3} m/s"),
                });
            }
        }
    }
    let (v, why) = fastest_speed(scene);
    if c < MACH_FACTOR * v {
        out.push(Finding {
            check: Check::FlowSoundSpeed,
            subject: "the scene".into(),
            found: format!(
                "c = {c} m/s is below {MACH_FACTOR} × the fastest speed the scene implies, {v:.3} m/s ({why})"
            ),
            cause: "a sound speed chosen for a slower flow: density changes of more than ~1 %, or a run stopped by the Mach check".into(),
            fix: format!("discretisation.sound_speed ≥ {:.3} m/s", MACH_FACTOR * v),
        });
    }
    out
}

/// The fastest speed the scene implies [m/s] and where it comes from: the bodies' initial
/// velocities, free fall over the scene's height along gravity, and the capillary velocity
/// `√(σ/(ρ l0))` of a particle-scale wave.
pub fn fastest_speed(scene: &Scene) -> (f64, String) {
    let mut best = (0.0, "at rest".to_string());
    let mut consider = |v: f64, why: String| {
        if v > best.0 {
            best = (v, why);
        }
    };
    for b in &scene.bodies {
        let wave = b.velocity_wave.as_ref().map_or(0.0, |w| norm(w.amplitude));
        consider(
            norm(b.velocity) + wave,
            format!("body {}'s initial velocity", b.name),
        );
    }
    if let Some(g) = scene.effects.gravity {
        let (g_abs, h) = (norm(g), height_m(scene, g));
        consider(
            (2.0 * g_abs * h).sqrt(),
            format!("free fall over the scene's {:.2} mm height", h * 1e3),
        );
    }
    if scene.effects.interfacial_tension.is_potential() {
        let l0 = scene.discretisation.l0;
        for l in &scene.liquids {
            if let Some(s) = l.surface_tension {
                consider(
                    (s / (l.density * l0)).sqrt(),
                    format!("the capillary velocity √(σ/(ρ l0)) of {}", l.name),
                );
            }
        }
    }
    best
}

/// The scene's height along gravity `g` [m]: from the highest body point to the lowest body
/// point or wall surface.
fn height_m(scene: &Scene, g: [f64; 3]) -> f64 {
    let gn = norm(g);
    if gn == 0.0 {
        return 0.0;
    }
    let up = |x: [f64; 3]| -(x[0] * g[0] + x[1] * g[1] + x[2] * g[2]) / gn;
    let corners = |lo: [f64; 3], hi: [f64; 3]| {
        (0..8).map(move |k| {
            [
                if k & 1 == 0 { lo[0] } else { hi[0] },
                if k & 2 == 0 { lo[1] } else { hi[1] },
                if k & 4 == 0 { lo[2] } else { hi[2] },
            ]
        })
    };
    let mut top = f64::NEG_INFINITY;
    let mut bottom = f64::INFINITY;
    for b in &scene.bodies {
        let (lo, hi) = b.shape.bounds();
        for x in corners(lo, hi) {
            top = top.max(up(x));
            bottom = bottom.min(up(x));
        }
    }
    for w in &scene.walls {
        let (lo, hi) = match w.shape {
            WallShape::Disk { center: c, radius } => (
                [c[0] - radius, c[1] - radius, c[2]],
                [c[0] + radius, c[1] + radius, c[2]],
            ),
            WallShape::Plate { min, max, top } => ([min[0], min[1], top], [max[0], max[1], top]),
            WallShape::Box { min, max, .. } => (min, max),
        };
        for x in corners(lo, hi) {
            bottom = bottom.min(up(x));
        }
    }
    if top.is_finite() && bottom.is_finite() {
        (top - bottom).max(0.0)
    } else {
        0.0
    }
}

/// The first time step and the steps the run needs at it.
#[derive(Clone, Debug, PartialEq)]
pub struct StepEstimate {
    /// The step [s].
    pub dt_s: f64,
    /// The constraint that sets it (or "fixed").
    pub limited_by: &'static str,
    /// `time.end / dt` [-].
    pub steps: f64,
}

/// The step the scene starts with: fixed, or the smallest of the CFL limit at the sound speed
/// plus the fastest implied speed, the viscous and capillary limits, and the force limit at
/// gravity (docs/model.md §3).
pub fn step_estimate(scene: &Scene) -> Result<StepEstimate, String> {
    let m = Model::from_scene(scene).map_err(|e| e.to_string())?;
    let t = &scene.time;
    if let Some(dt) = t.dt {
        return Ok(StepEstimate {
            dt_s: dt,
            limited_by: "fixed",
            steps: t.end / dt,
        });
    }
    let f = &t.factors;
    let (viscous, capillary) = m.static_step_limits();
    let v = fastest_speed(scene).0;
    let g = scene.effects.gravity.map_or(0.0, norm);
    let mut best = (f.cfl * m.h_m / (m.c_m_s + v), "CFL (sound speed)");
    for (limit, name) in [
        (viscous, "viscous"),
        (capillary, "capillary"),
        (
            (g > 0.0).then(|| f.force * (m.h_m / g).sqrt()),
            "force (gravity)",
        ),
    ] {
        if let Some(dt) = limit.filter(|&dt| dt < best.0) {
            best = (dt, name);
        }
    }
    Ok(StepEstimate {
        dt_s: best.0,
        limited_by: best.1,
        steps: t.end / best.0,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn drop_scene(c: f64, extra: &str) -> Scene {
        let sphere = r#"{ kind = "sphere", center = [0.0, 0.0, 0.0], radius = 1e-3 }"#;
        super::super::water_scene(
            1e-4,
            c,
            &format!("interfacial_tension = true\n{extra}"),
            sphere,
        )
    }

    #[test]
    fn the_cohesion_rule_is_met_at_its_sound_speed_and_not_below() {
        // the sound-speed rule of docs/user-guide.md: c² ≥ 1.75 σ/(0.01 ρ l0) = 126 m²/s² here, c = 11.2 m/s
        let c = (1.75f64 * 0.072 / (0.01 * 1000.0 * 1e-4)).sqrt();
        assert!(findings(&drop_scene(c, "")).is_empty());
        let f = findings(&drop_scene(0.5 * c, ""));
        assert!(
            f.iter().any(|f| f.check == Check::CohesiveSoundSpeed),
            "{f:?}"
        );
    }

    #[test]
    fn a_fast_drop_needs_ten_times_its_speed() {
        let moving = drop_scene(20.0, "");
        assert!(findings(&moving).is_empty());
        let mut fast = moving.clone();
        fast.bodies[0].velocity = [0.0, 0.0, -3.0];
        let f = findings(&fast);
        assert_eq!(f.len(), 1);
        assert!(
            f[0].check == Check::FlowSoundSpeed && f[0].fix.contains("30.000"),
            "{}",
            f[0]
        );
    }

    #[test]
    fn free_fall_counts_the_height_to_the_plate() {
        // a drop 1 mm above its lowest point falls onto a plate 1 m below: √(2 g 1.002 m)
        let mut s = drop_scene(20.0, "gravity = [0.0, 0.0, -9.81]");
        s.walls.push(solver::scene::Wall {
            name: "floor".into(),
            solid: "glass".into(),
            shape: WallShape::Plate {
                min: [-2e-3, -2e-3],
                max: [2e-3, 2e-3],
                top: -1.0,
            },
            layers: None,
            boundary: Default::default(),
        });
        let (v, why) = fastest_speed(&s);
        assert!(
            (v - (2.0f64 * 9.81 * 1.001).sqrt()).abs() < 1e-9,
            "{v} {why}"
        );
        assert!(why.contains("free fall"));
    }

    #[test]
    fn the_step_estimate_names_its_limit() {
        let e = step_estimate(&drop_scene(20.0, "")).unwrap();
        assert!(e.dt_s > 0.0 && e.steps > 0.0);
        assert_eq!(e.limited_by, "CFL (sound speed)");
    }
}
