//! Running one task of a plan.

use super::{input_error, Kind, Plan};
use crate::cases;
use crate::run::{RunError, RunOptions};
use crate::suite::runner::{self, Interrupted};
use std::path::Path;
use std::sync::atomic::AtomicBool;
use std::sync::Arc;

/// How a task runs.
#[derive(Clone, Debug, Default)]
pub struct TaskOptions {
    /// Worker threads (default: all cores).
    pub threads: Option<usize>,
    /// Write the run's checkpoint every this many minutes of wall time.
    pub checkpoint_minutes: Option<f64>,
    /// Set by Ctrl-C or SIGTERM: the run stops with a checkpoint ([`Interrupted`]).
    pub interrupt: Option<Arc<AtomicBool>>,
    /// Progress on stderr (plain lines when it is not a terminal).
    pub progress: bool,
}

/// Runs task `index` of the plan in `dir`: skipped if its run is finished, resumed from its
/// checkpoint if it was stopped, else simulated. A simulation that fails is a result (its
/// record says so, `collect` reports it). A scene this binary would build differently from the
/// plan's (a plan written by another revision) is refused: its results would not be the
/// plan's.
pub fn run_task(dir: &Path, index: usize, opts: &TaskOptions) -> anyhow::Result<()> {
    let plan = Plan::read(dir)?;
    let task = plan.task(index)?;
    let scene = plan.scene_of(dir, task)?;
    let stale = |built: &solver::Scene| {
        (*built != scene).then(|| {
            input_error(format!(
                "task {index} ({}): this binary (revision {}) builds another scene than the plan's (written by revision {}); write the plan again",
                task.label,
                super::revision(),
                plan.revision
            ))
        })
    };
    match &plan.kind {
        Kind::Suite {
            fidelity,
            set,
            strict,
            ..
        } => {
            let (case_name, id) = task
                .label
                .split_once('/')
                .ok_or_else(|| input_error(format!("task {index}: no case in {}", task.label)))?;
            let all = cases::all();
            let case = all
                .iter()
                .find(|c| c.name() == case_name)
                .ok_or_else(|| input_error(format!("task {index}: no case {case_name}")))?;
            let mut sopts = super::write::suite_options(dir, *fidelity, set, *strict)?;
            sopts.only = vec![id.to_string()];
            sopts.threads = opts.threads;
            sopts.checkpoint_minutes = opts.checkpoint_minutes;
            sopts.interrupt = opts.interrupt.clone();
            sopts.progress = opts.progress;
            let specs = runner::specs_of(case.as_ref(), &sopts)?;
            let spec = specs.first().ok_or_else(|| {
                input_error(format!("task {index}: case {case_name} has no run {id}"))
            })?;
            if let Some(e) = stale(&spec.scene) {
                return Err(e);
            }
            runner::run_spec(case.as_ref(), spec, &sopts)
        }
        Kind::Study {
            grid,
            max_particles,
        } => {
            let (points, _) = crate::study::selected(*grid, *max_particles);
            let point = points
                .iter()
                .find(|p| p.id() == task.label)
                .ok_or_else(|| {
                    input_error(format!("task {index}: no study point {}", task.label))
                })?;
            if let Some(e) = stale(&point.scene()) {
                return Err(e);
            }
            crate::study::points::run_point_here(point, dir, &run_options(dir, opts)).map(|_| ())
        }
        Kind::Sweep { .. } => {
            let ropts = run_options(&dir.join(&task.dir), opts);
            match crate::run::ensure(&scene, &dir.join(&task.scene), &ropts) {
                Ok(_) | Err(RunError::Simulation(_)) => Ok(()),
                Err(RunError::Interrupted(_)) => Err(anyhow::Error::new(Interrupted(format!(
                    "task {index} ({})",
                    task.label
                )))),
                Err(e) => Err(anyhow::anyhow!("task {index} ({}): {e}", task.label)),
            }
        }
    }
}

fn run_options(out_dir: &Path, opts: &TaskOptions) -> RunOptions {
    RunOptions {
        out_dir: out_dir.to_path_buf(),
        threads: opts.threads,
        progress: opts.progress,
        checkpoint_minutes: opts.checkpoint_minutes,
        interrupt: opts.interrupt.clone(),
        ..Default::default()
    }
}
