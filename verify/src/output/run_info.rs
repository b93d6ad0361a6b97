//! `run_info.json`: the record of a run — the scene as resolved, the effects built, where and
//! how it ran, and how it ended.

use serde::{Deserialize, Serialize};
use solver::simulation::StepTimings;

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
    /// Git revision of the build (`git describe --always --dirty`).
    pub git_revision: String,
    /// Worker threads.
    pub threads: usize,
    /// Fluid particles.
    pub fluid_particles: usize,
    /// Wall particles.
    pub wall_particles: usize,
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
    /// Peak resident memory of the process at the end of the run [bytes] (Linux `VmHWM`; the
    /// run's own peak when it ran in its own process, as `verify run` does).
    #[serde(default)]
    pub peak_memory_bytes: Option<u64>,
    /// How the run ended.
    pub status: Status,
    /// The error, if it failed.
    pub error: Option<String>,
}

/// The process's peak resident memory [bytes], from `/proc/self/status` (`VmHWM`); `None`
/// where that file does not exist.
pub fn peak_memory_bytes() -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kb: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kb * 1024)
}
