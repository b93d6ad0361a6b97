//! Plans: a set of runs written down as independent tasks — run in any order, on any machine,
//! as the array tasks of a batch scheduler — then collected into the summaries a serial run
//! writes, byte for byte.
//!
//! `verify plan suite|study|sweep … --out PLAN` writes `PLAN/plan.json` (the tasks), each
//! task's resolved scene (`PLAN/scenes/NNNN.toml`) and a SLURM array job (`PLAN/run.sbatch`,
//! `PLAN/submit.sh`). `verify task PLAN --index N` runs one task: skipped if its run is
//! finished, resumed from its checkpoint if it was stopped. `verify collect PLAN` measures the
//! finished runs and writes the summaries, naming the tasks not finished. A task's results go
//! where the serial command puts them (`PLAN/CASE/RUN` for the suite, `PLAN/POINT` for the
//! study), so `verify report --out PLAN` and `verify study … --out PLAN` read them too.

mod collect;
mod slurm;
mod sweep;
mod task;
mod write;

pub use collect::{collect, Collected};
pub use slurm::SlurmOptions;
pub use sweep::sweep_tasks;
pub use task::{run_task, TaskOptions};
pub use write::{study_tasks, suite_tasks, write_plan};

use crate::study::Grid;
use crate::suite::Fidelity;
use serde::{Deserialize, Serialize};
use solver::Scene;
use std::path::{Path, PathBuf};

/// The version of `plan.json`'s layout; a plan of another version is refused, both named.
pub const FORMAT: u32 = 1;

/// The plan's file in its folder.
pub const FILE: &str = "plan.json";

/// A written plan.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Plan {
    /// [`FORMAT`] of the writer.
    pub format: u32,
    /// Git revision of the binary that wrote it (see `run_info.json`).
    pub revision: String,
    /// What the tasks are.
    pub kind: Kind,
    /// The tasks, in the order of the serial command.
    pub tasks: Vec<Task>,
}

/// What a plan's tasks are runs of.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Kind {
    /// Runs of the verification cases (`verify all` / `verify case`).
    Suite {
        /// Fidelity.
        fidelity: Fidelity,
        /// The cases, in the suite's order.
        cases: Vec<String>,
        /// Scene keys set in every run (`--set KEY=VALUE`).
        set: Vec<String>,
        /// Refuse runs with pre-flight findings the case does not accept.
        strict: bool,
    },
    /// Points of the accuracy–cost study.
    Study {
        /// The grid.
        grid: Grid,
        /// Points with more fluid particles left out.
        max_particles: Option<usize>,
    },
    /// A user's scene over every combination of values of some keys.
    Sweep {
        /// The scene file the sweep started from, as given.
        base: String,
        /// The keys and their values, as given (`KEY=V1,V2`).
        set: Vec<String>,
    },
}

/// One task: one run.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Task {
    /// What it is: `case/run`, a study point's id, or a sweep's `KEY=VALUE …`.
    pub label: String,
    /// Its output folder, relative to the plan's folder.
    pub dir: String,
    /// Its resolved scene, relative to the plan's folder.
    pub scene: String,
    /// A sweep's `KEY=VALUE` of this task, one per key (empty otherwise).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub set: Vec<String>,
}

/// Errors of the plan commands that are the user's input (exit 2), not the machine's.
#[derive(Debug)]
pub struct InputError(pub String);

impl std::fmt::Display for InputError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for InputError {}

fn input_error(msg: String) -> anyhow::Error {
    anyhow::Error::new(InputError(msg))
}

impl Plan {
    /// Reads the plan in `dir`; a missing plan or one of another [`FORMAT`] is an
    /// [`InputError`].
    pub fn read(dir: &Path) -> anyhow::Result<Plan> {
        let path = dir.join(FILE);
        let text = std::fs::read_to_string(&path).map_err(|e| {
            input_error(format!(
                "no plan in {} ({FILE}: {e}); write one with `verify plan`",
                dir.display()
            ))
        })?;
        let v: serde_json::Value = serde_json::from_str(&text)
            .map_err(|e| input_error(format!("{}: not a plan ({e})", path.display())))?;
        let format = v.get("format").and_then(serde_json::Value::as_u64);
        if format != Some(u64::from(FORMAT)) {
            return Err(input_error(format!(
                "{}: plan format {} but this binary reads format {FORMAT}; write the plan again with this binary",
                path.display(),
                format.map_or("missing".to_string(), |f| f.to_string())
            )));
        }
        serde_json::from_value(v)
            .map_err(|e| input_error(format!("{}: not a plan ({e})", path.display())))
    }

    /// Task `index`, or an [`InputError`] naming the range.
    pub fn task(&self, index: usize) -> anyhow::Result<&Task> {
        self.tasks.get(index).ok_or_else(|| {
            input_error(format!(
                "task {index} out of range: the plan has {} task(s), 0 to {}",
                self.tasks.len(),
                self.tasks.len().saturating_sub(1)
            ))
        })
    }

    /// The resolved scene of `task`, read from the plan's folder `dir`.
    pub fn scene_of(&self, dir: &Path, task: &Task) -> anyhow::Result<Scene> {
        let path = dir.join(&task.scene);
        let text = std::fs::read_to_string(&path)
            .map_err(|e| input_error(format!("{}: {e}", path.display())))?;
        Scene::from_toml_str(&text).map_err(|e| input_error(format!("{}: {e}", path.display())))
    }
}

/// A task with the scene it runs, before the plan is written.
#[derive(Clone, Debug)]
pub struct Planned {
    /// What it is (see [`Task::label`]).
    pub label: String,
    /// Output folder relative to the plan's folder.
    pub dir: PathBuf,
    /// The resolved scene.
    pub scene: Scene,
    /// A sweep's `KEY=VALUE` of this task (see [`Task::set`]).
    pub set: Vec<String>,
}

/// The revision stamped into this binary.
pub fn revision() -> &'static str {
    env!("GIT_REVISION")
}
