//! Collecting a plan: measuring its finished runs and writing the summaries the serial command
//! writes (the suite's `summary.csv` byte for byte), or a sweep's `sweep.csv`.

use super::{Kind, Plan};
use crate::cases;
use crate::output::run_info::{RunInfo, Status};
use crate::output::timeseries::Table;
use crate::report::summary;
use crate::run::Saved;
use crate::suite::runner;
use std::path::Path;

/// What `collect` found.
#[derive(Clone, Debug)]
pub struct Collected {
    /// The summary written (`summary.md`, or `sweep.csv` for a sweep).
    pub summary: std::path::PathBuf,
    /// Labels of the tasks whose runs are not finished (left out of the summaries).
    pub unfinished: Vec<String>,
}

/// Measures the finished runs of the plan in `dir` and writes its summaries; the tasks not
/// finished are returned (and left out), so a partial plan can be looked at.
pub fn collect(dir: &Path) -> anyhow::Result<Collected> {
    let plan = Plan::read(dir)?;
    let mut unfinished = Vec::new();
    for task in &plan.tasks {
        let scene = plan.scene_of(dir, task)?;
        if crate::run::saved(&dir.join(&task.dir), &scene) != Saved::Finished {
            unfinished.push(task.label.clone());
        }
    }
    let summary = match &plan.kind {
        Kind::Suite {
            fidelity,
            cases,
            set,
            ..
        } => {
            let overrides = super::write::suite_options(dir, *fidelity, set, false)?.overrides;
            let names: Vec<&str> = cases.iter().map(String::as_str).collect();
            runner::write_record(dir, *fidelity, &names, &overrides)?;
            let all = cases::all();
            for case in all.iter().filter(|c| cases.iter().any(|n| n == c.name())) {
                std::fs::create_dir_all(dir.join(case.name()))?;
                runner::analyse_case(case.as_ref(), *fidelity, dir, &overrides)?;
            }
            summary::write_all(dir, *fidelity, &all, None)?;
            dir.join("summary.md")
        }
        Kind::Study {
            grid,
            max_particles,
        } => {
            let (points, left_out) = crate::study::selected(*grid, *max_particles);
            let mut results = Vec::new();
            for p in &points {
                if crate::run::saved(&dir.join(p.id()), &p.scene()) == Saved::Finished {
                    results.push(crate::study::points::measure(p, &dir.join(p.id()))?);
                }
            }
            crate::study::write_outputs(dir, *grid, *max_particles, &results, &left_out)?;
            dir.join("summary.md")
        }
        Kind::Sweep { .. } => {
            let path = dir.join("sweep.csv");
            crate::output::atomic_write(&path, &sweep_csv(dir, &plan)?)?;
            path
        }
    };
    Ok(Collected {
        summary,
        unfinished,
    })
}

/// One row per task: its key values, how its run ended and what it cost, and the last row of
/// its time series (`final:` columns; empty for a run with none).
fn sweep_csv(dir: &Path, plan: &Plan) -> anyhow::Result<Vec<u8>> {
    let keys: Vec<String> = match &plan.kind {
        Kind::Sweep { set, .. } => set
            .iter()
            .map(|s| {
                s.split_once('=')
                    .map_or(s.as_str(), |(k, _)| k)
                    .trim()
                    .to_string()
            })
            .collect(),
        _ => Vec::new(),
    };
    let mut rows = Vec::new();
    let mut final_columns: Vec<String> = Vec::new();
    for task in &plan.tasks {
        let rdir = dir.join(&task.dir);
        let info = RunInfo::read(&rdir).ok();
        let table = Table::read(&rdir.join("timeseries.csv")).ok();
        if let Some(t) = &table {
            for c in &t.columns {
                if !final_columns.contains(c) {
                    final_columns.push(c.clone());
                }
            }
        }
        rows.push((task, info, table));
    }
    let mut w = csv::Writer::from_writer(Vec::new());
    let mut header = vec!["task".to_string(), "dir".to_string()];
    header.extend(keys.iter().cloned());
    header.extend(
        [
            "status",
            "error",
            "fluid_particles",
            "steps",
            "simulated_time_s",
            "wall_time_s",
            "particle_steps_per_second",
        ]
        .map(String::from),
    );
    header.extend(final_columns.iter().map(|c| format!("final:{c}")));
    w.write_record(&header)?;
    for (k, (task, info, table)) in rows.iter().enumerate() {
        let mut rec = vec![k.to_string(), task.dir.clone()];
        let values: Vec<&str> = task
            .set
            .iter()
            .map(|kv| kv.split_once('=').map_or("", |(_, v)| v))
            .collect();
        rec.extend((0..keys.len()).map(|i| values.get(i).copied().unwrap_or("").to_string()));
        match info {
            Some(i) => rec.extend([
                status_name(i.status).to_string(),
                i.error.clone().unwrap_or_default(),
                i.fluid_particles.to_string(),
                i.steps.to_string(),
                format!("{:e}", i.simulated_time_s),
                format!("{:.1}", i.wall_time_s),
                format!("{:.4e}", i.particle_steps_per_second),
            ]),
            None => rec.extend(["not run", "", "", "", "", "", ""].map(String::from)),
        }
        for c in &final_columns {
            let v = table
                .as_ref()
                .and_then(|t| t.column(c))
                .and_then(|col| col.last().copied());
            rec.push(v.map(|x| format!("{x:e}")).unwrap_or_default());
        }
        w.write_record(&rec)?;
    }
    Ok(w.into_inner()?)
}

fn status_name(s: Status) -> &'static str {
    match s {
        Status::Running => "running",
        Status::Completed => "completed",
        Status::Failed => "failed",
        Status::Interrupted => "interrupted",
    }
}
