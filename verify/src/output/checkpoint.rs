//! `checkpoint.bin`: a run's state between two steps, written atomically (temporary file, then
//! rename), so that a run stopped at any moment — Ctrl-C, a crash, a killed job — continues with
//! `verify run --resume DIR` and gives bitwise the result of a run never stopped.

use crate::output::run_info::RunInfo;
use crate::run::RunError;
use serde::{Deserialize, Serialize};
use solver::{Checkpoint, Simulation};
use std::io::{BufRead, BufReader, Write};
use std::path::Path;

/// What the file holds: the solver's checkpoint and the outputs already written.
#[derive(Serialize, Deserialize)]
struct File {
    /// Index of the last output row written (0 = the initial state).
    outputs_written: u64,
    state: Checkpoint,
}

const NAME: &str = "checkpoint.bin";

/// Writes the checkpoint of `sim` (after output `k`) and the run record.
pub fn save(out: &Path, sim: &Simulation, k: u64, info: &RunInfo) -> Result<(), RunError> {
    let bytes = bincode::serialize(&File {
        outputs_written: k,
        state: sim.checkpoint(),
    })
    .map_err(|e| RunError::Output(format!("cannot encode the checkpoint: {e}")))?;
    let path = out.join(NAME);
    crate::output::atomic_write(&path, &bytes)
        .map_err(|e| RunError::Output(format!("cannot write {}: {e}", path.display())))?;
    crate::run::write_info(out, info)
}

/// Reads the checkpoint and run record of the run in `out`.
pub fn restore(out: &Path) -> Result<(Simulation, u64, RunInfo), RunError> {
    let info_path = out.join("run_info.json");
    let info: RunInfo = std::fs::read_to_string(&info_path)
        .ok()
        .and_then(|t| serde_json::from_str(&t).ok())
        .ok_or_else(|| {
            RunError::Output(format!(
                "no run to resume in {} (run_info.json missing or unreadable)",
                out.display()
            ))
        })?;
    let path = out.join(NAME);
    let bytes = std::fs::read(&path)
        .map_err(|e| RunError::Output(format!("cannot resume: {}: {e}", path.display())))?;
    let file: File = bincode::deserialize(&bytes).map_err(|e| {
        RunError::Output(format!(
            "cannot resume: {} is not a checkpoint: {e}",
            path.display()
        ))
    })?;
    let sim = Simulation::resume(file.state)
        .map_err(|e| RunError::Scene(format!("cannot resume: {e}")))?;
    Ok((sim, file.outputs_written, info))
}

/// Removes the checkpoint of a completed run.
pub fn remove(out: &Path) {
    let _ = std::fs::remove_file(out.join(NAME));
}

/// Keeps the header and the first `rows` data rows of a CSV file (dropping a half-written
/// last line too).
pub fn truncate_rows(path: &Path, rows: u64) -> std::io::Result<()> {
    let lines: Vec<String> = BufReader::new(std::fs::File::open(path)?)
        .lines()
        .take(rows as usize + 1)
        .collect::<Result<_, _>>()?;
    let mut text = lines.join("\n");
    text.push('\n');
    let tmp = path.with_extension("tmp-write");
    let mut f = std::fs::File::create(&tmp)?;
    f.write_all(text.as_bytes())?;
    f.sync_all()?;
    std::fs::rename(&tmp, path)
}

/// The scene and scene file recorded in the run folder `out` (for `--resume`).
pub fn scene_of(out: &Path) -> Result<(solver::Scene, std::path::PathBuf), RunError> {
    let info: RunInfo = std::fs::read_to_string(out.join("run_info.json"))
        .ok()
        .and_then(|t| serde_json::from_str(&t).ok())
        .ok_or_else(|| {
            RunError::Output(format!(
                "no run to resume in {} (run_info.json missing or unreadable)",
                out.display()
            ))
        })?;
    Ok((info.scene, info.scene_file.into()))
}
