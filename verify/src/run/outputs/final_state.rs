//! `particles_final.csv`: the fluid particles at the end of a run (positions [m], velocities
//! [m/s], phase), so that its final state can be measured without simulating again. The walls
//! are not written: they do not move, and the scene in `run_info.json` places them.

use crate::output::dump::Dump;
use crate::output::run_info::Status;
use crate::output::RunError;
use crate::run::observer::{Observer, RunView};

/// The file of the final state.
pub const FINAL: &str = "particles_final.csv";

/// Writes the fluid particles of `run` to `name` in its folder.
pub(crate) fn dump(run: &RunView, name: &str) -> Result<(), RunError> {
    let path = run.out_dir.join(name);
    Dump::of(&run.sim.particles, run.sim.time_s)
        .write(&path, false)
        .map_err(|e| RunError::io("cannot write", &path, e))
}

/// Writes [`FINAL`] when the run ends: completed, or failed (the state it failed in). An
/// interrupted run has no final state yet: it resumes from its checkpoint.
pub(super) struct FinalState;

impl Observer for FinalState {
    fn on_end(&mut self, run: &RunView) -> Result<(), RunError> {
        if run.info.status == Status::Interrupted {
            return Ok(());
        }
        dump(run, FINAL)
    }
}
