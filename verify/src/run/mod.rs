//! Running a scene: the time loop and the outputs that observe it.
//!
//! The loop (`stepping`) only steps the simulation and tells its [`Observer`]s of every step,
//! every output time and the end. Each output is one observer in `outputs`, built from its
//! option in [`RunOptions`]; callers add their own (the suite's probes and particle dumps at
//! its snapshot times). Every run that ends, completed or failed, writes its final particle
//! state ([`FINAL`]). The run record (`run_info.json`) is written at the start and, last, at
//! the end.

mod observer;
mod outputs;
mod start;
mod stepping;

pub use crate::output::RunError;
pub use observer::{Observer, RunView};
pub(crate) use outputs::final_state::dump as write_particles;
pub use outputs::final_state::FINAL;
pub use start::{load_scene, prepare_out_dir};

use crate::output::run_info::RunInfo;
use crate::preflight::{self, Check};
use solver::Scene;
use std::path::{Path, PathBuf};
use std::sync::atomic::AtomicBool;
use std::sync::Arc;
use stepping::Run;

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
    /// Set (e.g. by Ctrl-C) to stop after the current step with a checkpoint.
    pub interrupt: Option<Arc<AtomicBool>>,
    /// Refuse a scene with pre-flight findings instead of warning ([`crate::preflight`]).
    pub strict: bool,
    /// Pre-flight checks the caller makes on purpose, and why: recorded, not warned about.
    pub accepted: Vec<(Check, String)>,
}

/// Runs `scene` (read from `scene_file`) with `opts`; returns the run record (also written to
/// `run_info.json`, with status `failed` if the simulation stopped on an error).
pub fn run_scene(scene: &Scene, scene_file: &Path, opts: &RunOptions) -> Result<RunInfo, RunError> {
    run_scene_observed(scene, scene_file, opts, Vec::new())
}

/// [`run_scene`] with more observers, told of the run after the standard outputs.
pub fn run_scene_observed(
    scene: &Scene,
    scene_file: &Path,
    opts: &RunOptions,
    observers: Vec<Box<dyn Observer + '_>>,
) -> Result<RunInfo, RunError> {
    let warnings = preflight_warnings(scene, scene_file, opts)?;
    prepare_out_dir(&opts.out_dir, opts.force)?;
    start::in_pool(opts.threads, |threads| {
        let mut run = Run::fresh(scene, scene_file, &opts.out_dir, threads)?;
        run.info.warnings = warnings;
        run.drive(opts, observers)
    })
}

/// The scene's pre-flight findings: printed on stderr and returned as the run record's
/// warnings (with the accepted ones), or the scene refused with them under `opts.strict`.
fn preflight_warnings(
    scene: &Scene,
    scene_file: &Path,
    opts: &RunOptions,
) -> Result<Vec<String>, RunError> {
    let (warn, accepted) = preflight::sort_out(scene, &opts.accepted);
    let lines: Vec<String> = warn.iter().map(|f| f.to_string()).collect();
    if opts.strict && !lines.is_empty() {
        return Err(RunError::Scene(format!(
            "{} (--strict):\n  {}",
            scene_file.display(),
            lines.join("\n  ")
        )));
    }
    for l in &lines {
        eprintln!("warning: {}: {l}", scene_file.display());
    }
    Ok(lines.into_iter().chain(accepted).collect())
}

/// Continues the run in `opts.out_dir` from its checkpoint, as if it had never stopped.
pub fn resume(opts: &RunOptions) -> Result<RunInfo, RunError> {
    resume_observed(opts, Vec::new())
}

/// [`resume`] with more observers (told [`Observer::on_resume`] first).
pub fn resume_observed(
    opts: &RunOptions,
    observers: Vec<Box<dyn Observer + '_>>,
) -> Result<RunInfo, RunError> {
    start::in_pool(opts.threads, |threads| {
        Run::resumed(&opts.out_dir, threads)?.drive(opts, observers)
    })
}

/// What an output folder holds of a scene's run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Saved {
    /// A run of exactly this scene that ended (completed, or failed: a result either way).
    Finished,
    /// A run of exactly this scene stopped with a checkpoint to resume from.
    Stopped,
    /// Nothing of this scene's run (no record, another scene, or a stopped run without a
    /// checkpoint).
    Nothing,
}

/// What `dir` holds of `scene`'s run.
pub fn saved(dir: &Path, scene: &Scene) -> Saved {
    use crate::output::run_info::Status;
    match RunInfo::read(dir) {
        Ok(info) if info.scene != *scene => Saved::Nothing,
        Ok(info) if matches!(info.status, Status::Completed | Status::Failed) => Saved::Finished,
        Ok(_) if crate::output::checkpoint::exists(dir) => Saved::Stopped,
        _ => Saved::Nothing,
    }
}

/// Runs `scene` into `opts.out_dir` unless a finished run of it is there (then `None`), and
/// resumes it if it was stopped with a checkpoint; `opts.force` runs it afresh either way.
pub fn ensure(
    scene: &Scene,
    scene_file: &Path,
    opts: &RunOptions,
) -> Result<Option<RunInfo>, RunError> {
    match (opts.force, saved(&opts.out_dir, scene)) {
        (false, Saved::Finished) => Ok(None),
        (false, Saved::Stopped) => resume(opts).map(Some),
        _ => {
            let fresh = RunOptions {
                force: true,
                ..opts.clone()
            };
            run_scene(scene, scene_file, &fresh).map(Some)
        }
    }
}
