//! Walls under the continuum surface force: the contact lines pull the liquid off the walls,
//! and only a pressure that may fall below the ambient holds it there.

use super::{Check, Finding};
use solver::scene::{NegativePressure, TensionModel};
use solver::Scene;

/// The finding of a scene whose walls meet the surface force with the pressure's negative part
/// clipped: at a contact line the interfaces' terms sum to `σ_ab sin θ` per length away from
/// the wall (docs/model.md §4b), which the walls' extrapolated pressure can hold only by
/// falling below the ambient.
pub fn findings(scene: &Scene) -> Vec<Finding> {
    let clipped = scene.density.negative_pressure == NegativePressure::Clip;
    if scene.effects.interfacial_tension != TensionModel::SurfaceForce
        || scene.walls.is_empty()
        || !clipped
    {
        return Vec::new();
    }
    vec![Finding {
        check: Check::WallHold,
        subject: "the walls".into(),
        found: "the surface force's contact lines pull the liquid off the walls by σ_ab sin θ \
                per length, and the pressure's negative part is clipped (density.\
                negative_pressure = \"clip\")"
            .into(),
        cause: "the walls' pressure cannot fall below the ambient to hold them: clipped, a \
                hemisphere released at 90° spread at its foot 2.5 times as fast as kept \
                (docs/model.md §4b)"
            .into(),
        fix: "density.negative_pressure = \"keep\", with no free surface (the gas a \
              surrounding body in a box periodic along every axis)"
            .into(),
    }]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A drop of `a` on a plate in a gas `g` under the surface force, with `density` lines.
    fn cap(density: &str) -> Scene {
        Scene::from_toml_str(&format!(
            r#"
            [discretisation]
            l0 = 1e-4
            h_over_l0 = 1.3
            sound_speed = 5.0
            [time]
            end = 1e-3
            output_interval = 1e-4
            [effects]
            interfacial_tension = "surface_force"
            [density]
            {density}
            [[liquid]]
            name = "a"
            density = 1000.0
            viscosity = 1e-3
            surface_tension = 0.05
            [[liquid]]
            name = "g"
            density = 1000.0
            viscosity = 1e-3
            [[interface]]
            liquids = ["a", "g"]
            tension = 0.05
            [[solid]]
            name = "plate"
            contact_angles = {{ a = 60.0 }}
            [[body]]
            name = "cap"
            liquid = "a"
            shape = {{ kind = "hemisphere", center = [0.0, 0.0, 0.0], radius = 1.2e-3, pole = [0.0, 0.0, 1.0] }}
            [[body]]
            name = "gas"
            liquid = "g"
            shape = {{ kind = "surrounding", min = [-2e-3, -2e-3, 0.0], max = [2e-3, 2e-3, 2e-3] }}
            [[wall]]
            name = "plate"
            solid = "plate"
            shape = {{ kind = "plate", min = [-2e-3, -2e-3], max = [2e-3, 2e-3], top = 0.0 }}
            "#
        ))
        .unwrap()
    }

    #[test]
    fn walls_under_the_surface_force_with_a_clipped_pressure_are_flagged() {
        let f = findings(&cap(""));
        assert_eq!(f.len(), 1);
        assert!(f[0].fix.contains("\"keep\""), "{}", f[0]);
        assert!(findings(&cap("negative_pressure = \"keep\"")).is_empty());
    }
}
