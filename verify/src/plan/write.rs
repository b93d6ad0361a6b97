//! Writing a plan: the tasks of the suite or the study, their scenes, `plan.json` and the
//! SLURM scripts.

use super::{input_error, slurm, Kind, Plan, Planned, SlurmOptions, Task, FILE, FORMAT};
use crate::cases;
use crate::output::atomic_write;
use crate::study::Grid;
use crate::suite::overrides::SceneOverride;
use crate::suite::runner::{self, SuiteOptions};
use crate::suite::Fidelity;
use std::path::{Path, PathBuf};

/// The suite's options a plan's tasks run with (results in the plan's folder `out`).
pub(super) fn suite_options(
    out: &Path,
    fidelity: Fidelity,
    set: &[String],
    strict: bool,
) -> anyhow::Result<SuiteOptions> {
    let overrides = set
        .iter()
        .map(|s| s.parse::<SceneOverride>().map_err(input_error))
        .collect::<anyhow::Result<Vec<_>>>()?;
    Ok(SuiteOptions {
        fidelity,
        out: out.to_path_buf(),
        force: false,
        threads: None,
        progress: true,
        overrides,
        only: Vec::new(),
        strict,
        checkpoint_minutes: None,
        interrupt: None,
    })
}

/// Every run of the named cases (all if `names` is empty) at `fidelity` with `set` applied, in
/// the order `verify all` runs them; an unknown case or key is an input error.
pub fn suite_tasks(
    fidelity: Fidelity,
    names: &[String],
    set: &[String],
    strict: bool,
) -> anyhow::Result<(Kind, Vec<Planned>)> {
    let all = cases::all();
    for n in names {
        if !all.iter().any(|c| c.name() == n) {
            let known: Vec<&str> = all.iter().map(|c| c.name()).collect();
            return Err(input_error(format!(
                "no case named {n:?}; cases: {}",
                known.join(", ")
            )));
        }
    }
    let opts = suite_options(Path::new(""), fidelity, set, strict)?;
    let mut chosen = Vec::new();
    let mut tasks = Vec::new();
    for case in all
        .iter()
        .filter(|c| names.is_empty() || names.iter().any(|n| n == c.name()))
    {
        chosen.push(case.name().to_string());
        let specs =
            runner::specs_of(case.as_ref(), &opts).map_err(|e| input_error(format!("{e:#}")))?;
        for spec in specs {
            tasks.push(Planned {
                label: format!("{}/{}", case.name(), spec.id),
                dir: runner::run_dir(Path::new(""), case.as_ref(), &spec),
                scene: spec.scene,
                set: Vec::new(),
            });
        }
    }
    let kind = Kind::Suite {
        fidelity,
        cases: chosen,
        set: set.to_vec(),
        strict,
    };
    Ok((kind, tasks))
}

/// The study's points of `grid` up to `max_particles` (points that share a run once).
pub fn study_tasks(grid: Grid, max_particles: Option<usize>) -> (Kind, Vec<Planned>) {
    let (points, _) = crate::study::selected(grid, max_particles);
    let mut tasks: Vec<Planned> = Vec::new();
    for p in points {
        let id = p.id();
        if tasks.iter().any(|t| t.label == id) {
            continue;
        }
        tasks.push(Planned {
            dir: PathBuf::from(&id),
            label: id,
            scene: p.scene(),
            set: Vec::new(),
        });
    }
    (
        Kind::Study {
            grid,
            max_particles,
        },
        tasks,
    )
}

/// Writes the plan of `tasks` into `dir`: their scenes, `plan.json`, `run.sbatch` and
/// `submit.sh`. A folder holding another plan (other tasks) is refused unless `force`; the
/// same plan is written again (e.g. with other SLURM options), its results kept.
pub fn write_plan(
    dir: &Path,
    kind: Kind,
    tasks: Vec<Planned>,
    slurm_opts: &SlurmOptions,
    force: bool,
) -> anyhow::Result<Plan> {
    if tasks.is_empty() {
        return Err(input_error("the plan has no tasks".into()));
    }
    std::fs::create_dir_all(dir.join("scenes"))?;
    std::fs::create_dir_all(dir.join("logs"))?;
    let width = (tasks.len() - 1).to_string().len().max(4);
    let plan = Plan {
        format: FORMAT,
        revision: super::revision().to_string(),
        kind,
        tasks: tasks
            .iter()
            .enumerate()
            .map(|(k, t)| Task {
                label: t.label.clone(),
                dir: t.dir.to_string_lossy().replace('\\', "/"),
                scene: format!("scenes/{k:0width$}.toml"),
                set: t.set.clone(),
            })
            .collect(),
    };
    if dir.join(FILE).exists() && !force {
        match Plan::read(dir) {
            Ok(old) if old.kind == plan.kind && old.tasks == plan.tasks => {}
            _ => {
                return Err(input_error(format!(
                    "{} holds another plan; use another folder or --force",
                    dir.display()
                )))
            }
        }
    }
    for (t, p) in plan.tasks.iter().zip(&tasks) {
        atomic_write(&dir.join(&t.scene), toml::to_string(&p.scene)?.as_bytes())?;
    }
    atomic_write(
        &dir.join(FILE),
        serde_json::to_string_pretty(&plan)?.as_bytes(),
    )?;
    slurm::write_scripts(dir, &plan, slurm_opts)?;
    Ok(plan)
}
