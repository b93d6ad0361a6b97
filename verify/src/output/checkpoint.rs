//! `checkpoint.bin`: a run's state between two steps, written atomically (temporary file synced,
//! then rename), so that a run stopped at any moment — Ctrl-C, SIGTERM from a scheduler, a
//! crash, a killed job — continues with `verify run --resume DIR` and gives bitwise the result
//! of a run never stopped.
//!
//! Layout: the 8 bytes [`MAGIC`], the solver's checkpoint format version (`u32`, little endian,
//! `solver::checkpoint::VERSION`), then the state in postcard (a maintained, documented and
//! stable serde encoding). A file of another version is refused by its header, with the
//! version it has and the one this build reads, before any of it is decoded.

use super::{atomic_write, RunError};
use serde::{Deserialize, Serialize};
use solver::checkpoint::VERSION;
use solver::{Checkpoint, Simulation};
use std::path::Path;

/// The first bytes of every checkpoint file.
pub const MAGIC: &[u8; 8] = b"SPHCKPT\0";

/// What the file holds after its header: the solver's checkpoint and the outputs already written.
#[derive(Serialize, Deserialize)]
struct File {
    /// Index of the last output row written (0 = the initial state).
    outputs_written: u64,
    state: Checkpoint,
}

const NAME: &str = "checkpoint.bin";

/// Writes the checkpoint of `sim`, taken after output `k`, into `out`.
pub fn save(out: &Path, sim: &Simulation, k: u64) -> Result<(), RunError> {
    let mut bytes = MAGIC.to_vec();
    bytes.extend_from_slice(&VERSION.to_le_bytes());
    let body = postcard::to_stdvec(&File {
        outputs_written: k,
        state: sim.checkpoint(),
    })
    .map_err(|e| RunError::Output(format!("cannot encode the checkpoint: {e}")))?;
    bytes.extend_from_slice(&body);
    let path = out.join(NAME);
    atomic_write(&path, &bytes).map_err(|e| RunError::io("cannot write", &path, e))
}

/// The body of a checkpoint file after its header, or why it cannot be read by this build.
fn body<'b>(bytes: &'b [u8], path: &Path) -> Result<&'b [u8], RunError> {
    let not = |why: String| RunError::Output(format!("cannot resume: {}: {why}", path.display()));
    if bytes.len() < 12 || &bytes[..8] != MAGIC {
        return Err(not("not a checkpoint of this program (no header)".into()));
    }
    let version = u32::from_le_bytes([bytes[8], bytes[9], bytes[10], bytes[11]]);
    if version != VERSION {
        return Err(not(format!(
            "checkpoint format version {version}; this build reads version {VERSION}: resume with the build that wrote it (its revision is in run_info.json), or run again"
        )));
    }
    Ok(&bytes[12..])
}

/// Reads the checkpoint in `out`: the simulation and the index of the last output written.
pub fn restore(out: &Path) -> Result<(Simulation, u64), RunError> {
    let path = out.join(NAME);
    let bytes = std::fs::read(&path)
        .map_err(|e| RunError::Output(format!("cannot resume: {}: {e}", path.display())))?;
    let file: File = postcard::from_bytes(body(&bytes, &path)?).map_err(|e| {
        RunError::Output(format!("cannot resume: {} is damaged: {e}", path.display()))
    })?;
    let sim = Simulation::resume(file.state)
        .map_err(|e| RunError::Scene(format!("cannot resume: {e}")))?;
    Ok((sim, file.outputs_written))
}

/// Whether `out` holds a checkpoint file.
pub fn exists(out: &Path) -> bool {
    out.join(NAME).is_file()
}

/// Removes the checkpoint of a completed run.
pub fn remove(out: &Path) {
    let _ = std::fs::remove_file(out.join(NAME));
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn another_version_or_no_header_is_refused_by_the_header() {
        let p = Path::new("checkpoint.bin");
        let mut other = MAGIC.to_vec();
        other.extend_from_slice(&(VERSION + 1).to_le_bytes());
        other.extend_from_slice(&[0; 16]);
        let e = body(&other, p).unwrap_err().to_string();
        assert!(
            e.contains(&format!("version {}", VERSION + 1))
                && e.contains(&format!("reads version {VERSION}")),
            "{e}"
        );
        let e = body(b"not a checkpoint at all", p).unwrap_err().to_string();
        assert!(e.contains("no header"), "{e}");
        let mut ok = MAGIC.to_vec();
        ok.extend_from_slice(&VERSION.to_le_bytes());
        ok.push(7);
        assert_eq!(body(&ok, p).unwrap(), &[7]);
    }
}
