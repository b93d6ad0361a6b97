//! Running a scene: the time loop with outputs, progress and the run record.

use crate::output::run_info::{RunInfo, Status};
use crate::output::timeseries::TimeseriesWriter;
use crate::output::{atomic_write, vtk};
use indicatif::{ProgressBar, ProgressStyle};
use solver::{Scene, SimError, Simulation};
use std::path::{Path, PathBuf};
use std::time::Instant;

/// Options of a run.
#[derive(Clone, Debug, Default)]
pub struct RunOptions {
    /// Output folder.
    pub out_dir: PathBuf,
    /// Write a `.vtu` snapshot every this many outputs.
    pub vtk_every: Option<u32>,
    /// Worker threads (default: all cores).
    pub threads: Option<usize>,
    /// Overwrite an existing, non-empty output folder.
    pub force: bool,
    /// Show a progress bar on stderr.
    pub progress: bool,
}

/// Why a run did not complete. The CLI maps each kind to its exit code.
#[derive(Debug, thiserror::Error)]
pub enum RunError {
    /// The scene file is invalid (exit code 2).
    #[error("{0}")]
    Scene(String),
    /// Output folder or file problem (exit code 3).
    #[error("{0}")]
    Output(String),
    /// The simulation stopped on an error (exit code 1); outputs so far are kept.
    #[error("{0}")]
    Simulation(String),
}

impl RunError {
    /// Process exit code (see the README).
    pub fn exit_code(&self) -> i32 {
        match self {
            RunError::Simulation(_) => 1,
            RunError::Scene(_) => 2,
            RunError::Output(_) => 3,
        }
    }
}

fn io_err(what: &str, path: &Path, e: std::io::Error) -> RunError {
    RunError::Output(format!("{what} {}: {e}", path.display()))
}

/// Reads and validates a scene file.
pub fn load_scene(path: &Path) -> Result<Scene, RunError> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| RunError::Scene(format!("cannot read {}: {e}", path.display())))?;
    Scene::from_toml_str(&text).map_err(|e| RunError::Scene(format!("{}: {e}", path.display())))
}

/// Prepares the output folder: refuses a non-empty one without `force`, and proves it writable
/// before anything is simulated.
pub fn prepare_out_dir(dir: &Path, force: bool) -> Result<(), RunError> {
    if dir.exists() {
        let non_empty = std::fs::read_dir(dir)
            .map_err(|e| io_err("cannot read output folder", dir, e))?
            .next()
            .is_some();
        if non_empty && !force {
            return Err(RunError::Output(format!(
                "output folder {} exists and is not empty; pass --force to overwrite it",
                dir.display()
            )));
        }
    }
    std::fs::create_dir_all(dir).map_err(|e| io_err("cannot create output folder", dir, e))?;
    let probe = dir.join(".write-probe");
    std::fs::write(&probe, b"ok").map_err(|e| io_err("output folder is not writable:", dir, e))?;
    let _ = std::fs::remove_file(probe);
    Ok(())
}

/// Runs `scene` (read from `scene_file`) with `opts`; returns the run record (also written to
/// `run_info.json`, with status `failed` if the simulation stopped on an error).
pub fn run_scene(scene: &Scene, scene_file: &Path, opts: &RunOptions) -> Result<RunInfo, RunError> {
    prepare_out_dir(&opts.out_dir, opts.force)?;
    let pool = {
        let mut b = rayon::ThreadPoolBuilder::new();
        if let Some(n) = opts.threads {
            b = b.num_threads(n);
        }
        b.build()
            .map_err(|e| RunError::Output(format!("cannot start threads: {e}")))?
    };
    pool.install(|| run_in_pool(scene, scene_file, opts, pool.current_num_threads()))
}

fn run_in_pool(
    scene: &Scene,
    scene_file: &Path,
    opts: &RunOptions,
    threads: usize,
) -> Result<RunInfo, RunError> {
    let mut sim = Simulation::new(scene).map_err(|e| match e {
        SimError::Scene(e) => RunError::Scene(format!("{}: {e}", scene_file.display())),
        e => RunError::Simulation(e.to_string()),
    })?;
    let out = &opts.out_dir;
    let mut info = RunInfo {
        scene_file: scene_file.display().to_string(),
        scene: sim.model.scene.clone(),
        effects: sim.model.effects.names(),
        git_revision: env!("GIT_REVISION").to_string(),
        threads,
        fluid_particles: sim.particles.n_fluid,
        wall_particles: sim.particles.n_wall(),
        bodies: sim.inventory.bodies.clone(),
        walls: sim.inventory.walls.clone(),
        steps: 0,
        simulated_time_s: 0.0,
        wall_time_s: 0.0,
        particle_steps_per_second: 0.0,
        mean_neighbours: 0.0,
        neighbour_builds: 0,
        timings: Default::default(),
        status: Status::Running,
        error: None,
    };
    write_info(out, &info)?;
    let ts_path = out.join("timeseries.csv");
    let mut ts = TimeseriesWriter::create(
        &ts_path,
        &sim.model.phase_names[..sim.model.n_liquids],
        false,
    )
    .map_err(|e| io_err("cannot write", &ts_path, e))?;

    let time = &scene.time;
    let n_outputs = (time.end / time.output_interval).round() as u64;
    let bar = progress_bar(opts.progress, n_outputs);
    let start = Instant::now();
    let mut result = Ok(());
    let mut k: u64 = 0;
    let write_output =
        |sim: &Simulation, k: u64, ts: &mut TimeseriesWriter| -> Result<(), RunError> {
            ts.write(&sim.observe())
                .map_err(|e| io_err("cannot write", &ts_path, e))?;
            if let Some(every) = opts.vtk_every {
                if k % every as u64 == 0 {
                    let p = out.join(format!("particles_{:06}.vtu", k));
                    vtk::write_vtu(&p, &sim.particles, sim.particles.n_wall() > 0)
                        .map_err(|e| io_err("cannot write", &p, e))?;
                }
            }
            Ok(())
        };
    write_output(&sim, 0, &mut ts)?;
    while k < n_outputs {
        let t_next = (k + 1) as f64 * time.output_interval;
        while sim.time_s < t_next * (1.0 - 1e-12) {
            if let Err(e) = sim.step(t_next - sim.time_s) {
                result = Err(e);
                break;
            }
        }
        if result.is_err() {
            break;
        }
        k += 1;
        write_output(&sim, k, &mut ts)?;
        bar.set_position(k);
        bar.set_message(format!("t = {:.4e} s, step {}", sim.time_s, sim.step));
    }
    bar.finish_and_clear();

    let wall = start.elapsed().as_secs_f64();
    info.steps = sim.step;
    info.simulated_time_s = sim.time_s;
    info.wall_time_s = wall;
    info.particle_steps_per_second =
        sim.step as f64 * sim.particles.n_fluid as f64 / wall.max(1e-9);
    let nf = sim.particles.n_fluid.max(1);
    info.mean_neighbours = sim.search.lists.start[sim.particles.n_fluid] as f64 / nf as f64;
    info.neighbour_builds = sim.search.builds;
    info.timings = sim.timings;
    match result {
        Ok(()) => {
            info.status = Status::Completed;
            write_info(out, &info)?;
            Ok(info)
        }
        Err(e) => {
            info.status = Status::Failed;
            info.error = Some(e.to_string());
            write_info(out, &info)?;
            Err(RunError::Simulation(e.to_string()))
        }
    }
}

fn progress_bar(show: bool, len: u64) -> ProgressBar {
    if !show {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::new(len);
    bar.set_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} outputs, {msg}, ETA {eta}")
            .unwrap_or_else(|_| ProgressStyle::default_bar()),
    );
    bar
}

/// Writes `run_info.json` atomically.
pub fn write_info(out: &Path, info: &RunInfo) -> Result<(), RunError> {
    let path = out.join("run_info.json");
    let json = serde_json::to_string_pretty(info).map_err(|e| RunError::Output(e.to_string()))?;
    atomic_write(&path, json.as_bytes()).map_err(|e| io_err("cannot write", &path, e))
}
