//! Running cases: simulate what is missing, reuse what is finished, measure, and write the
//! case summaries.

mod probes;
mod saved;
mod snapshots;

use super::compare::summary_csv;
use super::{Case, Fidelity, Metric, RunSpec};
use crate::output::run_info::RunInfo;
use crate::run::{resume_observed, run_scene_observed, Observer, RunError, RunOptions};
use anyhow::Context;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::atomic::AtomicBool;
use std::sync::Arc;

/// Options of a suite run.
#[derive(Clone, Debug)]
pub struct SuiteOptions {
    /// Fidelity.
    pub fidelity: Fidelity,
    /// Output folder (cases go in sub-folders).
    pub out: PathBuf,
    /// Re-run finished runs.
    pub force: bool,
    /// Worker threads per run.
    pub threads: Option<usize>,
    /// Progress bars.
    pub progress: bool,
    /// Scene keys set in every run (`--set`); empty for the cases as written.
    pub overrides: Vec<super::overrides::SceneOverride>,
    /// Simulate only the runs with these ids (`--only`); empty for all. The case is measured
    /// from the runs that exist.
    pub only: Vec<String>,
    /// Refuse a run with pre-flight findings the case does not accept (`--strict`).
    pub strict: bool,
    /// Write each run's checkpoint every this many minutes of wall time (a stopped suite
    /// resumes its stopped run where it was).
    pub checkpoint_minutes: Option<f64>,
    /// Set (by Ctrl-C or SIGTERM) to stop the running run with a checkpoint, and the suite.
    pub interrupt: Option<Arc<AtomicBool>>,
}

/// The suite stopped because its run `0` was interrupted (Ctrl-C, SIGTERM); run the same
/// command again to resume it.
#[derive(Debug)]
pub struct Interrupted(pub String);

impl std::fmt::Display for Interrupted {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{} interrupted (checkpoint written); the same command resumes it",
            self.0
        )
    }
}

impl std::error::Error for Interrupted {}

/// What `verify report` needs to know about the suite runs in a folder.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct SuiteRecord {
    /// The fidelity the runs were made at.
    pub fidelity: Fidelity,
    /// Per case, the scene keys its runs were last made with (`--set KEY=VALUE`, as given); a
    /// case absent ran as written. Absent in records written before the keys were kept.
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub set: BTreeMap<String, Vec<String>>,
}

impl SuiteRecord {
    /// The `--set` overrides `case`'s runs were last made with, parsed (none: as written).
    pub fn overrides(&self, case: &str) -> anyhow::Result<Vec<super::overrides::SceneOverride>> {
        let keys = self.set.get(case).map_or(&[][..], Vec::as_slice);
        keys.iter()
            .map(|s| s.parse().map_err(|e: String| anyhow::anyhow!(e)))
            .collect()
    }
}

/// Simulates the missing runs of `case`, then measures it; returns its metrics and writes
/// `OUT/CASE/summary.csv`.
pub fn run_case(case: &dyn Case, opts: &SuiteOptions) -> anyhow::Result<Vec<Metric>> {
    for spec in &specs_of(case, opts)? {
        run_spec(case, spec, opts)?;
    }
    analyse_case(case, opts.fidelity, &opts.out, &opts.overrides)
}

/// The runs of `case` at `opts.fidelity` as the suite runs them: `--only` kept, `--set`
/// applied, each checked to build the effects the case declares.
pub fn specs_of(case: &dyn Case, opts: &SuiteOptions) -> anyhow::Result<Vec<RunSpec>> {
    let mut specs = case.runs(opts.fidelity);
    if !opts.only.is_empty() {
        specs.retain(|s| opts.only.contains(&s.id));
    }
    for spec in &mut specs {
        let run = super::overrides::apply(&spec.scene, &opts.overrides)
            .with_context(|| format!("{}/{}", case.name(), spec.id))?;
        case.check_override(&spec.id, &spec.scene, &run)
            .with_context(|| format!("{}/{}", case.name(), spec.id))?;
        spec.scene = run;
    }
    for spec in &specs {
        if let Some(declared) = case.effects() {
            anyhow::ensure!(
                declared.matches(&spec.scene),
                "case {} declares effects ({}) that its run {} does not build",
                case.name(),
                declared.describe(),
                spec.id
            );
        }
    }
    Ok(specs)
}

/// The folder of `case`'s run `spec` under `out`.
pub fn run_dir(out: &Path, case: &dyn Case, spec: &RunSpec) -> PathBuf {
    out.join(case.name()).join(&spec.id)
}

/// Whether the run `spec` of `case` is finished in `out` (its scene, its final state).
pub fn is_finished(out: &Path, case: &dyn Case, spec: &RunSpec) -> bool {
    saved::reusable(&run_dir(out, case, spec), spec)
}

/// Simulates `case`'s run `spec` into `OUT/CASE/ID` with the case's probes and snapshots —
/// resumed from its checkpoint if it was stopped, skipped if it is finished (unless
/// `opts.force`). A simulation that fails is a result (its record says so), not an error.
pub fn run_spec(case: &dyn Case, spec: &RunSpec, opts: &SuiteOptions) -> anyhow::Result<()> {
    let rdir = run_dir(&opts.out, case, spec);
    std::fs::create_dir_all(&rdir)?;
    if !opts.force && saved::reusable(&rdir, spec) {
        return Ok(());
    }
    let resume = !opts.force && saved::resumable(&rdir, spec);
    if opts.progress {
        let how = if resume { " (resumed)" } else { "" };
        eprintln!("{} / {}{how}", case.name(), spec.id);
    }
    let observers: Vec<Box<dyn Observer + '_>> = vec![
        Box::new(probes::Probes::of(case)),
        Box::new(snapshots::Snapshots::at(spec.snapshot_times_s.clone())),
    ];
    let label = PathBuf::from(format!("{}/{}", case.name(), spec.id));
    let ropts = RunOptions {
        out_dir: rdir.clone(),
        vtk_every: None,
        threads: opts.threads,
        force: true,
        progress: opts.progress,
        strict: opts.strict,
        accepted: case.accepted_findings(opts.fidelity),
        checkpoint_minutes: opts.checkpoint_minutes,
        interrupt: opts.interrupt.clone(),
        ..Default::default()
    };
    let result = if resume {
        resume_observed(&ropts, observers)
    } else {
        run_scene_observed(&spec.scene, &label, &ropts, observers)
    };
    match result {
        Ok(_) => {}
        Err(RunError::Interrupted(_)) => {
            return Err(anyhow::Error::new(Interrupted(format!(
                "{}/{}",
                case.name(),
                spec.id
            ))))
        }
        // a run that fails is a result: its record says so and the case reports it
        Err(RunError::Simulation(e)) => eprintln!("{}/{}: {e}", case.name(), spec.id),
        Err(e) => return Err(anyhow::anyhow!("{}/{}: {e}", case.name(), spec.id)),
    }
    Ok(())
}

/// Measures `case` from the runs saved under `out` (no simulation): each run whose folder
/// holds a finished run of exactly the scene the case gives it at `fidelity` with `overrides`
/// (`--set`) applied. A folder holding another scene's run (an older design of the case,
/// another fidelity, other `--set` keys) is stale: it is named on stderr and not measured, so
/// the case reports that run as missing rather than another scene's result as its own.
pub fn analyse_case(
    case: &dyn Case,
    fidelity: Fidelity,
    out: &Path,
    overrides: &[super::overrides::SceneOverride],
) -> anyhow::Result<Vec<Metric>> {
    let dir = out.join(case.name());
    let mut runs = Vec::new();
    for mut spec in case.runs(fidelity) {
        let rdir = dir.join(&spec.id);
        // a run still going (or killed) has no final state yet: not measured
        if !(RunInfo::path(&rdir).exists() && rdir.join(crate::run::FINAL).exists()) {
            continue;
        }
        spec.scene = super::overrides::apply(&spec.scene, overrides)
            .with_context(|| format!("{}/{}", case.name(), spec.id))?;
        if !saved::reusable(&rdir, &spec) {
            eprintln!(
                "{}: a run of another scene (an older design of the case, another fidelity or \
                 other --set keys); not measured. Run the case again, or remove the folder",
                rdir.display()
            );
            continue;
        }
        runs.push(
            saved::load_run(&rdir, &spec).with_context(|| format!("reading {}", rdir.display()))?,
        );
    }
    let metrics = case.analyse(fidelity, &runs, &dir)?;
    summary_csv::write(&dir.join("summary.csv"), &metrics)?;
    let json = serde_json::to_string_pretty(&metrics)?;
    crate::output::atomic_write(&dir.join("metrics.json"), json.as_bytes())?;
    Ok(metrics)
}

/// The metrics of every one of `cases` measured so far under `out`, in their order.
pub fn saved_metrics(out: &Path, cases: &[Box<dyn Case>]) -> anyhow::Result<Vec<Metric>> {
    let mut all = Vec::new();
    for case in cases {
        let p = out.join(case.name()).join("metrics.json");
        if p.exists() {
            let ms: Vec<Metric> = serde_json::from_str(&std::fs::read_to_string(&p)?)?;
            all.extend(ms);
        }
    }
    Ok(all)
}

/// Records in `out` that `cases` were run at `fidelity` with `overrides` (`--set`). The other
/// cases keep what the record said of them if it was at the same fidelity.
pub fn write_record(
    out: &Path,
    fidelity: Fidelity,
    cases: &[&str],
    overrides: &[super::overrides::SceneOverride],
) -> anyhow::Result<()> {
    std::fs::create_dir_all(out)?;
    let mut record = match read_record(out) {
        Ok(r) if r.fidelity == fidelity => r,
        _ => SuiteRecord {
            fidelity,
            set: BTreeMap::new(),
        },
    };
    let keys: Vec<String> = overrides.iter().map(ToString::to_string).collect();
    for case in cases {
        if keys.is_empty() {
            record.set.remove(*case);
        } else {
            record.set.insert(case.to_string(), keys.clone());
        }
    }
    let json = serde_json::to_string_pretty(&record)?;
    crate::output::atomic_write(&out.join("suite.json"), json.as_bytes())?;
    Ok(())
}

/// Reads the record of the last suite run in `out`.
pub fn read_record(out: &Path) -> anyhow::Result<SuiteRecord> {
    let text = std::fs::read_to_string(out.join("suite.json")).with_context(|| {
        format!(
            "no suite run found in {} (suite.json missing)",
            out.display()
        )
    })?;
    Ok(serde_json::from_str(&text)?)
}
