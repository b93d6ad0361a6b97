//! `checkpoint.bin`: a run's state between two steps, written atomically (temporary file, then
//! rename), so that a run stopped at any moment — Ctrl-C, a crash, a killed job — continues with
//! `verify run --resume DIR` and gives bitwise the result of a run never stopped.

use super::{atomic_write, RunError};
use serde::{Deserialize, Serialize};
use solver::{Checkpoint, Simulation};
use std::path::Path;

/// What the file holds: the solver's checkpoint and the outputs already written.
#[derive(Serialize, Deserialize)]
struct File {
    /// Index of the last output row written (0 = the initial state).
    outputs_written: u64,
    state: Checkpoint,
}

const NAME: &str = "checkpoint.bin";

/// Writes the checkpoint of `sim`, taken after output `k`, into `out`.
pub fn save(out: &Path, sim: &Simulation, k: u64) -> Result<(), RunError> {
    let bytes = bincode::serialize(&File {
        outputs_written: k,
        state: sim.checkpoint(),
    })
    .map_err(|e| RunError::Output(format!("cannot encode the checkpoint: {e}")))?;
    let path = out.join(NAME);
    atomic_write(&path, &bytes).map_err(|e| RunError::io("cannot write", &path, e))
}

/// Reads the checkpoint in `out`: the simulation and the index of the last output written.
pub fn restore(out: &Path) -> Result<(Simulation, u64), RunError> {
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
    Ok((sim, file.outputs_written))
}

/// Removes the checkpoint of a completed run.
pub fn remove(out: &Path) {
    let _ = std::fs::remove_file(out.join(NAME));
}
