//! A case's runs read back from their folders: whether a finished run can be reused, and its
//! record, time series, probes and particle dumps.

use super::snapshots::snapshot_name;
use crate::output::dump::Dump;
use crate::output::run_info::RunInfo;
use crate::output::timeseries::Table;
use crate::run::Saved;
use crate::run::FINAL;
use crate::suite::{RunData, RunSpec};
use std::path::Path;

/// Whether `dir` holds a finished run of exactly `spec`'s scene, with its final state.
pub(super) fn reusable(dir: &Path, spec: &RunSpec) -> bool {
    crate::run::saved(dir, &spec.scene) == Saved::Finished && dir.join(FINAL).exists()
}

/// Whether `dir` holds a stopped run of exactly `spec`'s scene with a checkpoint to resume.
pub(super) fn resumable(dir: &Path, spec: &RunSpec) -> bool {
    crate::run::saved(dir, &spec.scene) == Saved::Stopped
}

/// Reads the run of `spec` back from its folder `dir`.
pub(super) fn load_run(dir: &Path, spec: &RunSpec) -> anyhow::Result<RunData> {
    let info = RunInfo::read(dir)?;
    let timeseries = Table::read(&dir.join("timeseries.csv"))?;
    let probes = if dir.join("probes.csv").exists() {
        Table::read(&dir.join("probes.csv"))?
    } else {
        Table::default()
    };
    // walls never move: rebuilt from the scene rather than stored
    let walls = Dump::walls_of(&info.scene)?;
    let with_walls = |d: Dump| d.with_walls(walls.as_ref());
    let last = with_walls(Dump::read(&dir.join(FINAL))?);
    let mut snapshots = Vec::new();
    for &t in &spec.snapshot_times_s {
        let p = dir.join(snapshot_name(t));
        if p.exists() {
            snapshots.push((t, with_walls(Dump::read(&p)?)));
        }
    }
    Ok(RunData {
        id: spec.id.clone(),
        dir: dir.to_path_buf(),
        info,
        timeseries,
        probes,
        last,
        snapshots,
    })
}
