//! Files a run writes: the observables' time series (CSV), the run record (JSON), particle
//! snapshots (VTK) and the checkpoint; and the error of a run that did not complete.

pub mod checkpoint;
pub mod error;
pub mod run_info;
pub mod timeseries;
pub mod vtk;

pub use error::RunError;

use std::path::Path;

/// Writes `bytes` to `path` atomically: a temporary file in the same folder, then a rename, so
/// a reader never sees a half-written file.
pub fn atomic_write(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let tmp = path.with_extension("tmp-write");
    std::fs::write(&tmp, bytes)?;
    std::fs::rename(&tmp, path)
}
