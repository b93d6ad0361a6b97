//! Running a scene: the time loop with outputs, progress and the run record.

use crate::output::run_info::{RunInfo, Status};
use crate::output::timeseries::TimeseriesWriter;
use crate::output::{atomic_write, checkpoint, vtk};
use indicatif::{ProgressBar, ProgressStyle};
use solver::{Scene, SimError, Simulation};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
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
    /// Write a checkpoint every this many steps.
    pub checkpoint_steps: Option<u64>,
    /// Write a checkpoint every this many minutes of wall time.
    pub checkpoint_minutes: Option<f64>,
    /// Continue the run in `out_dir` from its checkpoint.
    pub resume: bool,
    /// Set (e.g. by Ctrl-C) to stop after the current step with a checkpoint.
    pub interrupt: Option<Arc<AtomicBool>>,
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
    /// Stopped by the user (exit code 130); a checkpoint allows `--resume`.
    #[error("{0}")]
    Interrupted(String),
}

impl RunError {
    /// Process exit code (see the README).
    pub fn exit_code(&self) -> i32 {
        match self {
            RunError::Simulation(_) => 1,
            RunError::Interrupted(_) => 130,
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

/// Called at every output of a run (after the time-series row is written) and once more at the
/// end, to record what a caller needs beyond the standard outputs.
pub trait Observer: Send {
    /// Output number `k` (0 at the start) of `sim`, written to `out_dir`.
    fn on_output(&mut self, sim: &Simulation, k: u64, out_dir: &Path) -> std::io::Result<()>;
    /// The run ended (completed or failed) at the state of `sim`.
    fn on_end(&mut self, sim: &Simulation, out_dir: &Path) -> std::io::Result<()>;
}

/// Runs `scene` (read from `scene_file`) with `opts`; returns the run record (also written to
/// `run_info.json`, with status `failed` if the simulation stopped on an error).
pub fn run_scene(scene: &Scene, scene_file: &Path, opts: &RunOptions) -> Result<RunInfo, RunError> {
    run_scene_observed(scene, scene_file, opts, None)
}

/// [`run_scene`] with an [`Observer`].
pub fn run_scene_observed(
    scene: &Scene,
    scene_file: &Path,
    opts: &RunOptions,
    observer: Option<&mut dyn Observer>,
) -> Result<RunInfo, RunError> {
    if !opts.resume {
        prepare_out_dir(&opts.out_dir, opts.force)?;
    }
    let pool = {
        let mut b = rayon::ThreadPoolBuilder::new();
        if let Some(n) = opts.threads {
            b = b.num_threads(n);
        }
        b.build()
            .map_err(|e| RunError::Output(format!("cannot start threads: {e}")))?
    };
    pool.install(|| {
        run_in_pool(
            scene,
            scene_file,
            opts,
            pool.current_num_threads(),
            observer,
        )
    })
}

fn run_in_pool(
    scene: &Scene,
    scene_file: &Path,
    opts: &RunOptions,
    threads: usize,
    mut observer: Option<&mut dyn Observer>,
) -> Result<RunInfo, RunError> {
    let out = &opts.out_dir;
    let ts_path = out.join("timeseries.csv");
    let (mut sim, mut k, mut info, ts) = if opts.resume {
        let (sim, k, info) = checkpoint::restore(out)?;
        // rows written after the checkpoint are dropped (the resumed run writes them again)
        checkpoint::truncate_rows(&ts_path, k + 1)
            .map_err(|e| io_err("cannot rewrite", &ts_path, e))?;
        let ts = TimeseriesWriter::create(
            &ts_path,
            &sim.model.phase_names[..sim.model.n_liquids],
            true,
        )
        .map_err(|e| io_err("cannot append to", &ts_path, e))?;
        (sim, k, info, ts)
    } else {
        let sim = Simulation::new(scene).map_err(|e| match e {
            SimError::Scene(e) => RunError::Scene(format!("{}: {e}", scene_file.display())),
            e => RunError::Simulation(e.to_string()),
        })?;
        let info = RunInfo {
            scene_file: scene_file.display().to_string(),
            scene: sim.scene.clone(),
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
            peak_memory_bytes: None,
            status: Status::Running,
            error: None,
        };
        let ts = TimeseriesWriter::create(
            &ts_path,
            &sim.model.phase_names[..sim.model.n_liquids],
            false,
        )
        .map_err(|e| io_err("cannot write", &ts_path, e))?;
        (sim, 0, info, ts)
    };
    info.status = Status::Running;
    info.threads = threads;
    write_info(out, &info)?;

    let time = sim.scene.time.clone();
    let n_outputs = (time.end / time.output_interval).round() as u64;
    let bar = progress_bar(opts.progress, n_outputs);
    bar.set_position(k);
    let start = Instant::now();
    let wall_before = info.wall_time_s;
    let mut last_checkpoint = (sim.step, Instant::now());
    let mut result = Ok(());
    let mut interrupted = false;
    let mut outputs = Outputs {
        ts,
        ts_path: &ts_path,
        out,
        vtk_every: opts.vtk_every,
        observer: observer.take(),
    };
    if !opts.resume {
        outputs.write(&sim, 0)?;
    }
    'outputs: while k < n_outputs {
        let t_next = (k + 1) as f64 * time.output_interval;
        while sim.time_s < t_next * (1.0 - 1e-12) {
            if let Err(e) = sim.step(t_next - sim.time_s) {
                result = Err(e);
                break 'outputs;
            }
            if opts
                .interrupt
                .as_ref()
                .is_some_and(|f| f.load(Ordering::SeqCst))
            {
                interrupted = true;
                break 'outputs;
            }
            let due_steps = opts
                .checkpoint_steps
                .is_some_and(|n| sim.step - last_checkpoint.0 >= n);
            let due_time = opts
                .checkpoint_minutes
                .is_some_and(|m| last_checkpoint.1.elapsed().as_secs_f64() >= 60.0 * m);
            if due_steps || due_time {
                info.wall_time_s = wall_before + start.elapsed().as_secs_f64();
                checkpoint::save(out, &sim, k, &info)?;
                last_checkpoint = (sim.step, Instant::now());
            }
        }
        k += 1;
        outputs.write(&sim, k)?;
        bar.set_position(k);
        bar.set_message(format!("t = {:.4e} s, step {}", sim.time_s, sim.step));
    }
    bar.finish_and_clear();
    if let Some(obs) = outputs.observer {
        obs.on_end(&sim, out)
            .map_err(|e| io_err("cannot write into", out, e))?;
    }

    let wall = wall_before + start.elapsed().as_secs_f64();
    info.steps = sim.step;
    info.simulated_time_s = sim.time_s;
    info.wall_time_s = wall;
    info.particle_steps_per_second =
        sim.step as f64 * sim.particles.n_fluid as f64 / wall.max(1e-9);
    info.mean_neighbours = sim.mean_neighbours();
    info.neighbour_builds = sim.search.builds;
    info.timings = sim.timings;
    info.peak_memory_bytes = crate::output::run_info::peak_memory_bytes();
    if interrupted {
        info.status = Status::Interrupted;
        checkpoint::save(out, &sim, k, &info)?;
        write_info(out, &info)?;
        return Err(RunError::Interrupted(format!(
            "interrupted at step {}, t = {:e} s; checkpoint written: continue with `verify run --resume {}`",
            sim.step,
            sim.time_s,
            out.display()
        )));
    }
    match result {
        Ok(()) => {
            info.status = Status::Completed;
            write_info(out, &info)?;
            checkpoint::remove(out);
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

/// The writers of one run's outputs.
struct Outputs<'a, 'o> {
    ts: TimeseriesWriter,
    ts_path: &'a Path,
    out: &'a Path,
    vtk_every: Option<u32>,
    observer: Option<&'o mut dyn Observer>,
}

impl Outputs<'_, '_> {
    /// Output number `k`: a time-series row, a snapshot if due, and the observer's record.
    fn write(&mut self, sim: &Simulation, k: u64) -> Result<(), RunError> {
        self.ts
            .write(&sim.observe(), &crate::output::timeseries::phase_q4(sim))
            .map_err(|e| io_err("cannot write", self.ts_path, e))?;
        if let Some(every) = self.vtk_every {
            if k % every as u64 == 0 {
                let p = self.out.join(format!("particles_{k:06}.vtu"));
                vtk::write_vtu(&p, &sim.particles, sim.particles.n_wall() > 0)
                    .map_err(|e| io_err("cannot write", &p, e))?;
            }
        }
        if let Some(obs) = self.observer.as_deref_mut() {
            obs.on_output(sim, k, self.out)
                .map_err(|e| io_err("cannot write into", self.out, e))?;
        }
        Ok(())
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
