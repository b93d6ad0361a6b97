//! Particle dumps of a case's runs at the case's snapshot times, for measurements redone
//! without simulating (every run writes its final state, [`crate::run::FINAL`], itself).

use crate::output::RunError;
use crate::run::{write_particles, Observer, RunView};

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
    /// Dumps at `times_s` [s] (ascending).
    pub(super) fn at(times_s: Vec<f64>) -> Snapshots {
        Snapshots { times_s, next: 0 }
    }
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
            write_particles(run, &snapshot_name(self.times_s[self.next]))?;
            self.next += 1;
        }
        Ok(())
    }
}
