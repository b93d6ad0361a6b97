//! Why a run did not complete, by kind; the command line maps each kind to its exit code.

use std::path::Path;

/// Why a run did not complete. The CLI maps each kind to its exit code.
#[derive(Debug, thiserror::Error)]
pub enum RunError {
    /// The scene file is invalid (exit code 2).
    #[error("{0}")]
    Scene(String),
    /// Output folder or file problem (exit code 3).
    #[error("{0}")]
    Output(String),
    /// The simulation stopped on an error (exit code 1); outputs so far are kept.
    #[error("{0}")]
    Simulation(String),
    /// Stopped by the user (exit code 130); a checkpoint allows `--resume`.
    #[error("{0}")]
    Interrupted(String),
}

impl RunError {
    /// Process exit code (see docs/user-guide.md, "Running a scene").
    pub fn exit_code(&self) -> i32 {
        match self {
            RunError::Simulation(_) => 1,
            RunError::Interrupted(_) => 130,
            RunError::Scene(_) => 2,
            RunError::Output(_) => 3,
        }
    }

    /// A file or folder problem: `"{what} {path}: {e}"`.
    pub fn io(what: &str, path: &Path, e: std::io::Error) -> RunError {
        RunError::Output(format!("{what} {}: {e}", path.display()))
    }
}
