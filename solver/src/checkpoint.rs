//! Checkpoints: everything a run's next step depends on, so that a resumed run continues bit for
//! bit as if it had never stopped.
//!
//! The neighbour lists are not stored: they are rebuilt from the positions at the last build
//! (`Particles::x_ref`) in the stored particle order, which reproduces them exactly. The model
//! is rebuilt from the scene by the same assembly as a new run ([`Simulation::new`]). Writing the bytes is the caller's business (`verify` uses a
//! compact binary encoding and an atomic rename).

use crate::error::SimError;
use crate::physics::forces::Dissipation;
use crate::scene::{Scene, SceneError};
use crate::simulation::{Simulation, StepTimings};
use crate::state::Particles;
use serde::{Deserialize, Serialize};

/// The state of a simulation between two steps.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Checkpoint {
    /// Format version of this struct.
    pub version: u32,
    /// The scene (resolved); encoded as its TOML text, so that compact binary encodings that
    /// cannot read self-describing enums still round-trip it.
    #[serde(with = "scene_as_toml")]
    pub scene: Scene,
    /// Particles, in their current (cell-sorted) order.
    pub particles: Particles,
    /// Per wall particle: no-slip?
    pub wall_no_slip: Vec<bool>,
    /// Simulated time [s].
    pub time_s: f64,
    /// Steps taken.
    pub step: u64,
    /// Last step [s].
    pub last_dt_s: f64,
    /// Largest `|v|²` of the state [m²/s²] (the next step's CFL limit).
    pub max_speed2: f64,
    /// Largest `|a|²` of the state [m²/s⁴] (the next step's force limit).
    pub max_acc2: f64,
    /// Stable step of the initial state [s].
    pub first_dt_s: f64,
    /// Neighbour-list builds so far.
    pub builds: u64,
    /// Wall-clock time per part of the step so far [s].
    pub timings: StepTimings,
    /// The energy dissipated so far and the booked power of the current accelerations.
    pub dissipation: Dissipation,
}

mod scene_as_toml {
    use crate::scene::Scene;
    use serde::{Deserialize, Deserializer, Serializer};

    pub fn serialize<S: Serializer>(scene: &Scene, s: S) -> Result<S::Ok, S::Error> {
        let text = toml::to_string(scene).map_err(serde::ser::Error::custom)?;
        s.serialize_str(&text)
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Scene, D::Error> {
        let text = String::deserialize(d)?;
        toml::from_str(&text).map_err(serde::de::Error::custom)
    }
}

/// Current [`Checkpoint::version`].
pub const VERSION: u32 = 4; // 4: the non-affine viscosity's booked work in `Dissipation`

impl Simulation {
    /// The state between two steps.
    pub fn checkpoint(&self) -> Checkpoint {
        Checkpoint {
            version: VERSION,
            scene: self.scene.clone(),
            particles: self.particles.clone(),
            wall_no_slip: self.wall_no_slip.clone(),
            time_s: self.time_s,
            step: self.step,
            last_dt_s: self.last_dt_s,
            max_speed2: self.max_speed2,
            max_acc2: self.max_acc2,
            first_dt_s: self.first_dt_s,
            builds: self.search.builds,
            timings: self.timings,
            dissipation: self.dissipation,
        }
    }

    /// Continues from a checkpoint.
    pub fn resume(c: Checkpoint) -> Result<Simulation, SimError> {
        if c.version != VERSION {
            return Err(SceneError::invalid(
                "checkpoint.version",
                c.version,
                format!("this build reads version {VERSION}"),
            )
            .into());
        }
        let mut sim = Simulation::assemble(&c.scene)?;
        let (p, fresh) = (c.particles, &sim.particles);
        if p.n_fluid != fresh.n_fluid
            || p.len() != fresh.len()
            || c.wall_no_slip.len() != p.n_wall()
        {
            return Err(SceneError::invalid(
                "checkpoint.particles",
                format!("{} fluid / {} total", p.n_fluid, p.len()),
                format!(
                    "the scene builds {} fluid / {} total particles",
                    fresh.n_fluid,
                    fresh.len()
                ),
            )
            .into());
        }
        // the lists of the last build: positions then, same order
        let mut at_build = p.x_ref.clone();
        at_build.extend_from_slice(&p.pos[p.n_fluid..]);
        sim.search
            .build(&at_build, p.n_fluid)
            .map_err(|source| SimError::Escaped {
                step: c.step,
                source,
            })?;
        sim.search.builds = c.builds;
        sim.particles = p;
        sim.wall_no_slip = c.wall_no_slip;
        (sim.time_s, sim.step, sim.last_dt_s) = (c.time_s, c.step, c.last_dt_s);
        (sim.max_speed2, sim.max_acc2, sim.first_dt_s) = (c.max_speed2, c.max_acc2, c.first_dt_s);
        sim.timings = c.timings;
        sim.dissipation = c.dissipation;
        Ok(sim)
    }
}
