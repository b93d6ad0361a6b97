//! Particle dumps of a case's runs: at the case's snapshot times and at the end
//! (`particles_final.csv`), for measurements redone without simulating.

use crate::output::run_info::Status;
use crate::output::RunError;
use crate::run::{Observer, RunView};
use crate::suite::dump::Dump;

/// The dump of a run's final state.
pub(super) const FINAL: &str = "particles_final.csv";

/// The dump file of snapshot time `t_s` [s].
pub(super) fn snapshot_name(t_s: f64) -> String {
    format!("particles_t{:.6}ms.csv", t_s * 1e3)
}

/// Writes the dumps of one run.
pub(super) struct Snapshots {
    /// Snapshot times [s], ascending.
    times_s: Vec<f64>,
    /// The first of `times_s` not dumped yet.
    next: usize,
}

impl Snapshots {
    /// Dumps at `times_s` [s] (ascending) and at the end.
    pub(super) fn at(times_s: Vec<f64>) -> Snapshots {
        Snapshots { times_s, next: 0 }
    }
}

/// Writes the fluid particles of `run` to `name` in its folder.
fn dump(run: &RunView, name: &str) -> Result<(), RunError> {
    let path = run.out_dir.join(name);
    Dump::of(&run.sim.particles, run.sim.time_s)
        .write(&path, false)
        .map_err(|e| RunError::io("cannot write", &path, e))
}

impl Observer for Snapshots {
    fn on_resume(&mut self, run: &RunView) -> Result<(), RunError> {
        // the times up to the checkpoint were dumped before it
        while self.next < self.times_s.len()
            && run.sim.time_s >= self.times_s[self.next] * (1.0 - 1e-9)
        {
            self.next += 1;
        }
        Ok(())
    }

    fn on_output(&mut self, run: &RunView) -> Result<(), RunError> {
        while self.next < self.times_s.len()
            && run.sim.time_s >= self.times_s[self.next] * (1.0 - 1e-9)
        {
            dump(run, &snapshot_name(self.times_s[self.next]))?;
            self.next += 1;
        }
        Ok(())
    }

    fn on_end(&mut self, run: &RunView) -> Result<(), RunError> {
        // an interrupted run has no final state yet: it resumes from its checkpoint
        if run.info.status == Status::Interrupted {
            return Ok(());
        }
        dump(run, FINAL)
    }
}
