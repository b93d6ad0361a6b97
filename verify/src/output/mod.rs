//! Files a run writes: the observables' time series (CSV), the run record (JSON), particle
//! dumps (CSV: the final state, a case's snapshot times), particle snapshots (VTK) and the
//! checkpoint; and the error of a run that did not complete.

pub mod checkpoint;
pub mod dump;
pub mod error;
pub mod machine;
pub mod run_info;
pub mod timeseries;
pub mod vtk;
pub mod vtk_read;

pub use error::RunError;

use std::path::Path;

/// Writes `bytes` to `path` atomically: a temporary file in the same folder, synced to disk,
/// then a rename (synced too), so a reader never sees a half-written file, even after a crash.
pub fn atomic_write(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    use std::io::Write;
    let tmp = path.with_extension("tmp-write");
    let mut f = std::fs::File::create(&tmp)?;
    f.write_all(bytes)?;
    // on disk before the rename: a crash (or a node lost by a batch job) leaves the old file
    // or the new one, never a renamed empty one
    f.sync_all()?;
    drop(f);
    std::fs::rename(&tmp, path)?;
    // and the rename itself on disk (the folder's entry)
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::File::open(dir)?.sync_all()?;
    }
    Ok(())
}

/// Keeps the header and the first `rows` data rows of a CSV file (dropping a half-written last
/// line too): a resumed run writes the rows after its checkpoint again.
pub fn keep_csv_rows(path: &Path, rows: u64) -> std::io::Result<()> {
    use std::io::BufRead;
    let lines: Vec<String> = std::io::BufReader::new(std::fs::File::open(path)?)
        .lines()
        .take(rows as usize + 1)
        .collect::<Result<_, _>>()?;
    let mut text = lines.join("\n");
    text.push('\n');
    atomic_write(path, text.as_bytes())
}
