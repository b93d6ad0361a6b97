//! Time-step constraints of the active effects (docs/model.md §3).

use serde::Serialize;

/// The limits on the time step [s]; `None` where the effect is not built.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct StepLimits {
    /// CFL: `cfl · h/(c + |v|max)` [s]. Always present (pressure is always built).
    pub cfl_s: f64,
    /// Viscous: `viscous · ρ h²/μ` (smallest over liquids) [s], with laminar viscosity.
    pub viscous_s: Option<f64>,
    /// Capillary: `capillary · √(ρ h³/(2πσ))` [s], with interfacial tension.
    pub capillary_s: Option<f64>,
    /// Body force: `force · √(h/|a|max)` [s] (infinite at rest).
    pub force_s: f64,
}

impl StepLimits {
    /// The smallest limit [s] and the constraint's name.
    pub fn min(&self) -> (f64, &'static str) {
        let mut best = (self.cfl_s, "CFL (sound speed)");
        for (v, name) in [
            (self.viscous_s, "viscous"),
            (self.capillary_s, "capillary"),
            (Some(self.force_s), "force (acceleration)"),
        ] {
            if let Some(v) = v {
                if v < best.0 {
                    best = (v, name);
                }
            }
        }
        best
    }
}
