//! Walls a continuum capillarity model sees through.

use super::{Check, Finding};
use solver::scene::{BodyShape, WallShape};
use solver::Scene;

/// The findings on the walls' thickness against the colour kernel's reach. Under a continuum
/// model a wall particle holds the colour of the fluid within `r_e` of it (docs/model.md §4b),
/// so a plate thinner than `2 r_e` with fluid under it as well as on it has middle layers that
/// hold both sides' colours, and each side's force sees the other through the plate: in the
/// `convergence` case's caps (a host filling a box periodic along z, so that it met the
/// plate's underside; five layers at `r_e = 4.2 l0`) the cap's first layer and the host under
/// the plate were pulled towards each other at the axis, until a host particle was past the
/// underside (docs/findings.md). Fluid can be under a plate where the scene is periodic along
/// z or a body reaches below the plate's bottom.
pub fn findings(scene: &Scene) -> Vec<Finding> {
    if scene.effects.interfacial_tension.is_potential() {
        return Vec::new();
    }
    let (l0, r_e) = (scene.discretisation.l0, scene.r_e());
    let needed = (2.0 * r_e / l0 - 1e-9).ceil() as u32;
    scene
        .walls
        .iter()
        .filter_map(|w| {
            let top = match w.shape {
                WallShape::Plate { top, .. } => top,
                WallShape::Disk { center, .. } => center[2],
                // a container's outside holds no fluid unless a periodic box wraps around it,
                // which the scene's validation leaves to the box's size
                WallShape::Box { .. } => return None,
            };
            let layers = scene.wall_layers(w);
            let bottom = top - f64::from(layers) * l0;
            let under = scene.periodic.z.is_some()
                || scene.bodies.iter().any(|b| reaches_below(&b.shape, bottom, l0));
            (under && layers < needed).then(|| Finding {
                check: Check::ThinWall,
                subject: format!("wall '{}'", w.name),
                found: format!(
                    "{layers} layers ({:.3e} m) with fluid able to reach its underside, thinner than twice the colour kernel's reach 2 r_e = {:.3e} m",
                    f64::from(layers) * l0,
                    2.0 * r_e
                ),
                cause: "a wall particle holds the colour of the fluid on both faces, and the surface force on each side sees the other through the wall".into(),
                fix: format!("layers = {needed} on the wall"),
            })
        })
        .collect()
}

/// Whether `shape` holds a lattice site `(i + ½) l0` below the height `z` [m] (a body's
/// bounding box is its ball's for a hemisphere on a plate, so the sites are looked at).
fn reaches_below(shape: &BodyShape, z: f64, l0: f64) -> bool {
    let (lo, hi) = shape.bounds();
    if lo[2] >= z {
        return false;
    }
    let sites = |a: f64, b: f64| {
        let first = (a / l0 - 0.5).floor() as i64;
        let last = (b / l0 - 0.5).ceil() as i64;
        (first..=last).map(move |i| (i as f64 + 0.5) * l0)
    };
    sites(lo[2], z.min(hi[2])).filter(|&pz| pz < z).any(|pz| {
        sites(lo[1], hi[1]).any(|py| sites(lo[0], hi[0]).any(|px| shape.contains([px, py, pz])))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The example `scenes/cap_in_host.toml` (a hemisphere on a plate in a host, periodic
    /// along z) with its plate of `layers` layers (none: the default), and its z axis periodic
    /// or not.
    fn cap(layers: Option<u32>, periodic_z: bool) -> Scene {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../scenes/cap_in_host.toml");
        let mut scene = Scene::from_toml_str(&std::fs::read_to_string(path).unwrap()).unwrap();
        scene.walls[0].layers = layers;
        if !periodic_z {
            scene.periodic.z = None;
        }
        scene
    }

    #[test]
    fn a_hemisphere_on_a_plate_does_not_reach_below_it_and_a_ball_does() {
        let l0 = 1e-4;
        let hemisphere = BodyShape::Hemisphere {
            center: [0.0; 3],
            radius: 1e-3,
            pole: [0.0, 0.0, 1.0],
        };
        assert!(!reaches_below(&hemisphere, 0.0, l0));
        let ball = BodyShape::Sphere {
            center: [0.0; 3],
            radius: 1e-3,
        };
        assert!(reaches_below(&ball, 0.0, l0));
        assert!(!reaches_below(&ball, -1.1e-3, l0));
    }

    #[test]
    fn a_plate_thinner_than_two_colour_reaches_with_fluid_under_it_is_found() {
        // the default layers reach r_e = 4.2 l0 from one face: 5, below 2 r_e = 8.4 l0
        let found = findings(&cap(None, true));
        assert_eq!(found.len(), 1, "{found:?}");
        assert_eq!(found[0].check, Check::ThinWall);
        assert!(found[0].fix.contains("layers = 9"), "{}", found[0]);
        // thick enough: nothing
        assert!(findings(&cap(Some(9), true)).is_empty());
        // no fluid can reach the underside (not periodic along z, no body below): nothing
        assert!(findings(&cap(None, false)).is_empty());
    }
}
