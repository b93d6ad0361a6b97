//! Starting a run: the scene file, the output folder, the worker threads, and the simulation
//! and record a run starts from — fresh, or restored from a checkpoint.

use super::stepping::Run;
use crate::output::run_info::{RunInfo, Status};
use crate::output::{checkpoint, RunError};
use solver::scene::TensionCalibration;
use solver::{Scene, SimError, Simulation};
use std::path::Path;

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
            .map_err(|e| RunError::io("cannot read output folder", dir, e))?
            .next()
            .is_some();
        if non_empty && !force {
            return Err(RunError::Output(format!(
                "output folder {} exists and is not empty; pass --force to overwrite it",
                dir.display()
            )));
        }
    }
    std::fs::create_dir_all(dir)
        .map_err(|e| RunError::io("cannot create output folder", dir, e))?;
    let probe = dir.join(".write-probe");
    std::fs::write(&probe, b"ok")
        .map_err(|e| RunError::io("output folder is not writable:", dir, e))?;
    let _ = std::fs::remove_file(probe);
    Ok(())
}

/// Runs `f` on a pool of `threads` worker threads (default: all cores), passing it their
/// number.
pub(super) fn in_pool<T: Send>(
    threads: Option<usize>,
    f: impl FnOnce(usize) -> Result<T, RunError> + Send,
) -> Result<T, RunError> {
    let mut builder = rayon::ThreadPoolBuilder::new();
    if let Some(n) = threads {
        builder = builder.num_threads(n);
    }
    let pool = builder
        .build()
        .map_err(|e| RunError::Output(format!("cannot start threads: {e}")))?;
    let n = pool.current_num_threads();
    pool.install(|| f(n))
}

impl<'a> Run<'a> {
    /// A run of `scene` (read from `scene_file`) from its initial state, writing into `out`.
    pub(super) fn fresh(
        scene: &Scene,
        scene_file: &Path,
        out: &'a Path,
        threads: usize,
    ) -> Result<Run<'a>, RunError> {
        if scene.discretisation.tension_calibration == TensionCalibration::RelaxedSlab {
            eprintln!(
                "{}: calibrating the tension on relaxed slabs (a few minutes, once per process)",
                scene_file.display()
            );
        }
        let sim = Simulation::new(scene).map_err(|e| match e {
            SimError::Scene(e) => RunError::Scene(format!("{}: {e}", scene_file.display())),
            e => RunError::Simulation(e.to_string()),
        })?;
        let info = RunInfo::new(&sim, scene_file, threads);
        Ok(Run::new(sim, 0, info, out, false))
    }

    /// The run in `out`, continued from its checkpoint on `threads` threads.
    pub(super) fn resumed(out: &'a Path, threads: usize) -> Result<Run<'a>, RunError> {
        let mut info = RunInfo::read(out).map_err(|e| {
            RunError::Output(format!("no run to resume in {} ({e})", out.display()))
        })?;
        if matches!(info.status, Status::Completed | Status::Failed) {
            let how = if info.status == Status::Completed {
                "completed".to_string()
            } else {
                format!("failed ({})", info.error.clone().unwrap_or_default())
            };
            return Err(RunError::Output(format!(
                "nothing to resume: the run in {} is finished: {how} at t = {:e} s after {} steps; \
                 `run SCENE --out DIR --force` runs it again",
                out.display(),
                info.simulated_time_s,
                info.steps
            )));
        }
        let (sim, output) = checkpoint::restore(out)?;
        info.status = Status::Running;
        info.threads = threads;
        Ok(Run::new(sim, output, info, out, true))
    }
}
