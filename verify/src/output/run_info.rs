//! `run_info.json`: the record of a run — the scene as resolved, the effects built, where and
//! how it ran, and how it ended. [`RunInfo::read`] and [`RunInfo::write`] are the only readers
//! and writer of the file.

use super::{atomic_write, RunError};
use serde::{Deserialize, Serialize};
use solver::simulation::{StepTimings, ViscousSolves};
use solver::Simulation;
use std::path::{Path, PathBuf};

/// How a run ended (or that it is still going).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Status {
    /// Still running (or killed without a chance to say so).
    Running,
    /// Reached the end time.
    Completed,
    /// Stopped by an error; see `error`.
    Failed,
    /// Stopped by the user (Ctrl-C); a checkpoint allows `--resume`.
    Interrupted,
}

/// The run record.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct RunInfo {
    /// Path of the scene file.
    pub scene_file: String,
    /// The scene with every default filled in.
    pub scene: solver::Scene,
    /// The effects built, in words.
    pub effects: Vec<String>,
    /// Git revision of the build: the commit, 12 hex digits, `-dirty` if the sources differed
    /// from it (`verify/build.rs`).
    pub git_revision: String,
    /// Worker threads.
    pub threads: usize,
    /// The machine the run started on: CPU model, logical cores, vector extensions
    /// ([`super::machine`]; absent in records written before it was kept).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub machine: Option<String>,
    /// Fluid particles.
    pub fluid_particles: usize,
    /// Wall particles.
    pub wall_particles: usize,
    /// The relaxed-slab calibration's factor on each liquid's potential coefficients
    /// (`tension_calibration = "relaxed_slab"`; absent with the lattice calibration).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub tension_scales: Vec<f64>,
    /// The relaxed-slab calibration's factor on the coefficient of each pair of liquids
    /// (beyond `√(f_a f_b)`) and of each liquid and solid (beyond `f_a`), `(phase a, phase b,
    /// factor)` (absent with the lattice calibration).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub pair_tension_scales: Vec<(String, String, f64)>,
    /// Particles per body `(name, count)`.
    pub bodies: Vec<(String, usize)>,
    /// Particles and layers per wall `(name, count, layers)`.
    pub walls: Vec<(String, usize, u32)>,
    /// Steps taken.
    pub steps: u64,
    /// Simulated time reached [s].
    pub simulated_time_s: f64,
    /// Wall-clock time of the time loop [s].
    pub wall_time_s: f64,
    /// Fluid particles × steps / wall time [1/s].
    pub particle_steps_per_second: f64,
    /// Mean neighbours per fluid particle within the largest interaction radius (kernel
    /// support, or r_e with tension) at the end: the pairs a step evaluates per particle.
    pub mean_neighbours: f64,
    /// Neighbour-list builds.
    pub neighbour_builds: u64,
    /// Wall-clock time per part of the step [s].
    pub timings: StepTimings,
    /// With implicit viscosity: its solves in this process (a resumed run counts from the
    /// resume).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub viscous_solves: Option<ViscousSolves>,
    /// Peak resident memory of the process at the end of the run [bytes] (Linux `VmHWM`; the
    /// run's own peak when it ran in its own process, as `verify run` does).
    #[serde(default)]
    pub peak_memory_bytes: Option<u64>,
    /// The scene's pre-flight findings (`verify::preflight`): warnings, then those the
    /// caller accepted on purpose, each `"accepted (why): …"`.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub warnings: Vec<String>,
    /// How the run ended.
    pub status: Status,
    /// The error, if it failed.
    pub error: Option<String>,
}

impl RunInfo {
    /// The record of a run of `sim` (just built from `scene_file`) on `threads` threads, before
    /// its first step.
    pub fn new(sim: &Simulation, scene_file: &Path, threads: usize) -> RunInfo {
        RunInfo {
            scene_file: scene_file.display().to_string(),
            scene: sim.scene.clone(),
            effects: sim.model.effects.names(),
            git_revision: env!("GIT_REVISION").to_string(),
            threads,
            machine: Some(super::machine::describe()),
            fluid_particles: sim.particles.n_fluid,
            wall_particles: sim.particles.n_wall(),
            tension_scales: if sim.model.tension_scales.iter().all(|&f| f == 1.0) {
                Vec::new()
            } else {
                sim.model.tension_scales.clone()
            },
            pair_tension_scales: (sim.model.pair_tension_scales.iter())
                .map(|&(a, b, f)| {
                    let nl = sim.scene.liquids.len();
                    let name = |k: usize| match k < nl {
                        true => sim.scene.liquids[k].name.clone(),
                        false => sim.scene.solids[k - nl].name.clone(),
                    };
                    (name(a), name(b), f)
                })
                .collect(),
            bodies: sim.inventory.bodies.clone(),
            walls: sim.inventory.walls.clone(),
            steps: 0,
            simulated_time_s: 0.0,
            wall_time_s: 0.0,
            particle_steps_per_second: 0.0,
            mean_neighbours: 0.0,
            neighbour_builds: 0,
            timings: Default::default(),
            viscous_solves: None,
            peak_memory_bytes: None,
            warnings: Vec::new(),
            status: Status::Running,
            error: None,
        }
    }

    /// Records where `sim` got to after `wall_time_s` [s] of time loop (over every part of the
    /// run, resumed ones included): steps, time, rates, neighbours, timings and peak memory.
    pub fn record_progress(&mut self, sim: &Simulation, wall_time_s: f64) {
        self.steps = sim.step;
        self.simulated_time_s = sim.time_s;
        self.wall_time_s = wall_time_s;
        self.particle_steps_per_second =
            sim.step as f64 * sim.particles.n_fluid as f64 / wall_time_s.max(1e-9);
        self.mean_neighbours = sim.mean_neighbours();
        self.neighbour_builds = sim.search.builds;
        self.timings = sim.timings;
        self.viscous_solves =
            (sim.model.effects.implicit_viscosity.is_some()).then_some(sim.viscous_solves);
        self.peak_memory_bytes = peak_memory_bytes();
    }

    /// The path of the record of the run in `dir`.
    pub fn path(dir: &Path) -> PathBuf {
        dir.join("run_info.json")
    }

    /// Reads the record of the run in `dir`.
    pub fn read(dir: &Path) -> Result<RunInfo, RunError> {
        let path = Self::path(dir);
        let text =
            std::fs::read_to_string(&path).map_err(|e| RunError::io("cannot read", &path, e))?;
        serde_json::from_str(&text)
            .map_err(|e| RunError::Output(format!("{}: {e}", path.display())))
    }

    /// Writes the record into `dir`, atomically.
    pub fn write(&self, dir: &Path) -> Result<(), RunError> {
        let path = Self::path(dir);
        let json =
            serde_json::to_string_pretty(self).map_err(|e| RunError::Output(e.to_string()))?;
        atomic_write(&path, json.as_bytes()).map_err(|e| RunError::io("cannot write", &path, e))
    }
}

/// The process's peak resident memory [bytes], from `/proc/self/status` (`VmHWM`); `None`
/// where that file does not exist.
pub fn peak_memory_bytes() -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kb: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kb * 1024)
}

#[cfg(test)]
mod tests {
    /// A finished run is reused when its recorded scene equals the one asked for, so the scene
    /// must come back from `run_info.json` bit for bit. serde_json's default float parsing is
    /// best-effort (1 ULP off for some values, e.g. the sound speed √(1.75σ/(0.01ρ l0)) of paper
    /// B's water drop); the workspace enables its `float_roundtrip` feature. Without it, this
    /// test fails and every finished run of that case was simulated again.
    #[test]
    fn floats_of_a_scene_survive_the_json_record_bit_for_bit() {
        let values: [f64; 4] = [
            11.319646779366787,
            8.004198998326718,
            0.1879255171603899,
            1.2000000000000001e-3,
        ];
        for v in values {
            let back: f64 = serde_json::from_str(&serde_json::to_string(&v).unwrap()).unwrap();
            assert_eq!(back.to_bits(), v.to_bits(), "{v}");
        }
        // and a pseudo-random sample of magnitudes
        let mut x = 0x2545_f491_4f6c_dd1du64;
        for _ in 0..10_000 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            let v = f64::from_bits((x >> 2) | 0x3000_0000_0000_0000) * 1e-3;
            let back: f64 = serde_json::from_str(&serde_json::to_string(&v).unwrap()).unwrap();
            assert_eq!(back.to_bits(), v.to_bits(), "{v:e}");
        }
    }
}
