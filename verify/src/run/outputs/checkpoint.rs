//! `checkpoint.bin`: written every so many steps or minutes of wall time (with the run record,
//! whose wall time a resumed run continues from) and when the run is interrupted; removed when
//! it completes.

use crate::output::run_info::Status;
use crate::output::{checkpoint, RunError};
use crate::run::observer::{Observer, RunView};
use crate::run::RunOptions;
use std::time::Instant;

/// Writes checkpoints.
pub(super) struct Checkpoints {
    every_steps: Option<u64>,
    every_minutes: Option<f64>,
    /// Step and wall-clock instant of the last checkpoint (or of the start).
    last: (u64, Instant),
}

impl Checkpoints {
    /// Checkpoints as `opts` asks, counted from the state of `run`.
    pub(super) fn new(opts: &RunOptions, run: &RunView) -> Checkpoints {
        Checkpoints {
            every_steps: opts.checkpoint_steps,
            every_minutes: opts.checkpoint_minutes,
            last: (run.sim.step, Instant::now()),
        }
    }
}

impl Observer for Checkpoints {
    fn on_step(&mut self, run: &RunView) -> Result<(), RunError> {
        let due_steps = self
            .every_steps
            .is_some_and(|n| run.sim.step - self.last.0 >= n);
        let due_time = self
            .every_minutes
            .is_some_and(|m| self.last.1.elapsed().as_secs_f64() >= 60.0 * m);
        if due_steps || due_time {
            checkpoint::save(run.out_dir, run.sim, run.output)?;
            run.info.write(run.out_dir)?;
            self.last = (run.sim.step, Instant::now());
        }
        Ok(())
    }

    fn on_end(&mut self, run: &RunView) -> Result<(), RunError> {
        match run.info.status {
            Status::Interrupted => checkpoint::save(run.out_dir, run.sim, run.output),
            Status::Completed => {
                checkpoint::remove(run.out_dir);
                Ok(())
            }
            Status::Running | Status::Failed => Ok(()),
        }
    }
}
