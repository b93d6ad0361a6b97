//! Paper B's scene: a drop falling onto a plate, started one spacing above it.

use super::G_M_S2;
use crate::cases::scene::{sound_speed_for, LiquidProps, SceneBuilder};
use solver::scene::{BodyShape, Setting};

/// The drop of paper B's scenes: a sphere whose bottom starts one spacing above the plate's top
/// (z = 0), moving down at the speed a free fall from its release height gives it there.
#[derive(Clone, Copy, Debug)]
pub struct FallingDrop {
    /// The liquid.
    pub liquid: LiquidProps,
    /// Drop diameter [m].
    pub diameter_m: f64,
    /// Fall height: gap between the drop's bottom and the plate at release [m] (0: at rest on
    /// the plate, one spacing above it).
    pub fall_m: f64,
}

impl FallingDrop {
    /// Start speed [m/s] (downwards) after free fall to one spacing `l0_m` [m] above the plate.
    pub fn impact_speed_m_s(&self, l0_m: f64) -> f64 {
        (2.0 * G_M_S2 * (self.fall_m - l0_m).max(0.0)).sqrt()
    }

    /// The drop above a plate of `solid`, on which the liquid's contact angle is `theta_deg`
    /// [deg], at spacing `l0_m` [m] in a paper's `setting`, with the sound speed for the liquid
    /// and the papers' effects; the caller adds the time control, gravity and the plate.
    pub fn scene(&self, setting: Setting, l0_m: f64, solid: &str, theta_deg: f64) -> SceneBuilder {
        let l = &self.liquid;
        let r = 0.5 * self.diameter_m;
        SceneBuilder::new(l0_m, sound_speed_for(l, l0_m, 5.0))
            .setting(setting)
            .paper_effects()
            .liquid(l)
            .solid(solid, &[(l.name, theta_deg)])
            .moving_body(
                "drop",
                l.name,
                BodyShape::Sphere {
                    center: [0.0, 0.0, r + l0_m],
                    radius: r,
                },
                [0.0, 0.0, -self.impact_speed_m_s(l0_m)],
            )
    }
}

/// Diameter [m] of a drop of `mass_kg` [kg] and density `rho_kg_m3` [kg/m³].
pub fn diameter_of_mass(mass_kg: f64, rho_kg_m3: f64) -> f64 {
    (6.0 * mass_kg / (std::f64::consts::PI * rho_kg_m3)).cbrt()
}

#[cfg(test)]
mod tests {
    use super::super::{ALUMINIUM, WATER};
    use super::*;
    use solver::scene::{WallBoundary, WallShape};

    #[test]
    fn seventy_milligrams_of_aluminium_is_a_3_9_mm_drop() {
        // the sphere of that diameter holds the mass back, and paper B's rounded 3.92 mm is
        // within its last digit
        let d = diameter_of_mass(70e-6, ALUMINIUM.density_kg_m3);
        let mass = ALUMINIUM.density_kg_m3 * std::f64::consts::PI / 6.0 * d.powi(3);
        assert!((mass - 70e-6).abs() < 1e-15, "{mass}");
        assert!((d - 3.92e-3).abs() < 0.015e-3, "{d}");
    }

    #[test]
    fn impact_speed_is_free_fall_to_one_spacing() {
        let (drop, l0) = (
            FallingDrop {
                liquid: WATER,
                diameter_m: 2e-3,
                fall_m: 2e-3,
            },
            1e-4,
        );
        let scene = drop
            .scene(Setting::Natsui2016, l0, "glass", 30.0)
            .time(1e-3, 1e-4)
            .gravity([0.0, 0.0, -G_M_S2])
            .wall(
                "plate",
                "glass",
                WallShape::Disk {
                    center: [0.0; 3],
                    radius: 3.0e-3,
                },
                WallBoundary::FreeSlip,
            )
            .build();
        // the drop's bottom is one spacing above the plate (z = 0) …
        let body = &scene.bodies[0];
        let solver::scene::BodyShape::Sphere { center, radius } = body.shape else {
            panic!("a sphere");
        };
        let gap = center[2] - radius;
        assert!((gap - l0).abs() < 1e-15, "gap {gap}");
        // … moving down with the energy of a fall from H to there: ½v² = |g| (H − gap)
        let g = scene.effects.gravity.unwrap();
        let g_abs = (g[0] * g[0] + g[1] * g[1] + g[2] * g[2]).sqrt();
        let v = body.velocity;
        assert!(v[0] == 0.0 && v[1] == 0.0 && v[2] < 0.0);
        let energy = 0.5 * v[2] * v[2] - g_abs * (drop.fall_m - gap);
        assert!(energy.abs() < 1e-12, "{energy}");
        // paper B's setting
        assert_eq!(scene.discretisation.h_over_l0, 2.0);
        assert_eq!(scene.discretisation.re_over_l0, 4.0);
        assert_eq!(scene.walls[0].boundary, WallBoundary::FreeSlip);
    }
}
