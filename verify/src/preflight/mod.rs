//! Checks of a resolved scene before its first step: inputs no real liquid or solid has (a unit
//! slipped: 72.8 typed for σ in N/m), bodies too coarse or too thin for the potential, a
//! sound speed the scene's cohesion or flow cannot live with, and walls a continuum model's
//! colour crosses.
//!
//! Each [`Finding`] says what was found, the likely cause, and the value that would fix it.
//! They are warnings: a run prints them on stderr and records them in `run_info.json`;
//! `--strict` refuses the scene instead. A case that makes a finding on purpose (a sweep across
//! σ1 + σ2, a coarse smoke run) accepts it and says why (`suite::Case::accepted_findings`).
//! `verify check SCENE` prints them with the step estimate.

mod inputs;
mod resolution;
mod sound;
mod walls;

pub use sound::{step_estimate, StepEstimate};

use serde::{Deserialize, Serialize};
use solver::Scene;

/// What a finding is about.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Check {
    /// A liquid's surface tension outside the range of real liquids.
    SurfaceTension,
    /// A liquid's density outside the range of real liquids.
    Density,
    /// A liquid's viscosity outside the range of real liquids.
    Viscosity,
    /// An interfacial tension too large for any pair of liquids, or at which they separate.
    InterfacialTension,
    /// A contact angle within 1° of 0° or 180°.
    ContactAngle,
    /// A body resolved by fewer than [`resolution::MIN_RADIUS_L0`] spacings across its radius.
    Resolution,
    /// A body thinner than the potential's cut-off `r_e`.
    Film,
    /// A sound speed that lets the potential's cohesion compress the liquid by more than 1 %.
    CohesiveSoundSpeed,
    /// A sound speed below ten times the fastest speed the scene implies.
    FlowSoundSpeed,
    /// A wall a continuum model's colour crosses: thinner than `2 r_e` with fluid on both
    /// faces.
    ThinWall,
}

impl Check {
    /// Its name in messages and records.
    pub fn name(self) -> &'static str {
        match self {
            Check::SurfaceTension => "surface tension",
            Check::Density => "density",
            Check::Viscosity => "viscosity",
            Check::InterfacialTension => "interfacial tension",
            Check::ContactAngle => "contact angle",
            Check::Resolution => "resolution",
            Check::Film => "film",
            Check::CohesiveSoundSpeed => "sound speed (cohesion)",
            Check::FlowSoundSpeed => "sound speed (flow)",
            Check::ThinWall => "thin wall",
        }
    }
}

/// One thing a scene should not be, as found.
#[derive(Clone, Debug, PartialEq)]
pub struct Finding {
    /// The check that found it.
    pub check: Check,
    /// What it is about (a liquid, a body, a pair), as the scene names it.
    pub subject: String,
    /// What was found, with the value and its unit.
    pub found: String,
    /// The likely cause.
    pub cause: String,
    /// The value that would fix it.
    pub fix: String,
}

impl std::fmt::Display for Finding {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{} of {}: {}. Likely cause: {}. Fix: {}.",
            self.check.name(),
            self.subject,
            self.found,
            self.cause,
            self.fix
        )
    }
}

/// Every finding of `scene` (validated), in the order of the checks.
pub fn check(scene: &Scene) -> Vec<Finding> {
    let mut out = inputs::findings(scene);
    out.extend(resolution::findings(scene));
    out.extend(sound::findings(scene));
    out.extend(walls::findings(scene));
    out
}

/// The findings of `scene` split by `accepted` (a check and why it is accepted): the ones to
/// warn about, and the accepted ones as records (`"accepted (why): finding"`).
pub fn sort_out(scene: &Scene, accepted: &[(Check, String)]) -> (Vec<Finding>, Vec<String>) {
    let mut warn = Vec::new();
    let mut kept = Vec::new();
    for f in check(scene) {
        match accepted.iter().find(|(c, _)| *c == f.check) {
            Some((_, why)) => kept.push(format!("accepted ({why}): {f}")),
            None => warn.push(f),
        }
    }
    (warn, kept)
}

/// A one-body water scene for the checks' tests: spacing `l0` [m], sound speed `c` [m/s],
/// lines `effects` under `[effects]`, and the body's `shape` (an inline TOML table).
#[cfg(test)]
fn water_scene(l0: f64, c: f64, effects: &str, shape: &str) -> Scene {
    Scene::from_toml_str(&format!(
        r#"
        [discretisation]
        l0 = {l0}
        sound_speed = {c}
        [time]
        end = 1e-3
        output_interval = 1e-4
        [effects]
        {effects}
        [[liquid]]
        name = "water"
        density = 1000.0
        viscosity = 1e-3
        surface_tension = 0.072
        [[body]]
        name = "drop"
        liquid = "water"
        shape = {shape}
        "#
    ))
    .unwrap()
}
