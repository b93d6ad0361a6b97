//! The walls as solids that liquid must stay out of (for the health check and the harness's
//! invariants).

use crate::scene::{Scene, WallShape};

/// A wall's solid as the health check sees it.
#[derive(Clone, Debug, PartialEq)]
pub struct WallSolid {
    /// The wall's name in the scene.
    pub name: String,
    /// The region liquid must stay out of ([`WallShape::liquid_exclusion`]).
    pub exclusion: WallShape,
    /// Thickness of the wall's particle layers [m].
    pub thickness_m: f64,
}

impl WallSolid {
    /// The wall solids of a validated scene, in scene order.
    pub fn of(scene: &Scene) -> Vec<WallSolid> {
        let l0 = scene.discretisation.l0;
        scene
            .walls
            .iter()
            .map(|w| WallSolid {
                name: w.name.clone(),
                exclusion: w.shape.liquid_exclusion(l0),
                thickness_m: scene.wall_layers(w) as f64 * l0,
            })
            .collect()
    }

    /// Whether a liquid particle at `p` [m] is inside the solid deeper than `depth_m` [m] past
    /// every face.
    pub fn holds(&self, p: [f64; 3], depth_m: f64) -> bool {
        self.exclusion.solid_contains(p, self.thickness_m, depth_m)
    }
}
