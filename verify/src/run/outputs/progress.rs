//! The progress bar on stderr: output times reached, simulated time and step.

use crate::output::RunError;
use crate::run::observer::{Observer, RunView};
use indicatif::{ProgressBar, ProgressStyle};

/// Shows a progress bar.
pub(super) struct Progress {
    bar: ProgressBar,
}

impl Progress {
    /// A bar over the output times of `run`, at its current one.
    pub(super) fn new(run: &RunView) -> Progress {
        let bar = ProgressBar::new(run.outputs);
        bar.set_style(
            ProgressStyle::with_template("{bar:40} {pos}/{len} outputs, {msg}, ETA {eta}")
                .unwrap_or_else(|_| ProgressStyle::default_bar()),
        );
        bar.set_position(run.output);
        Progress { bar }
    }
}

impl Observer for Progress {
    fn on_output(&mut self, run: &RunView) -> Result<(), RunError> {
        self.bar.set_position(run.output);
        self.bar.set_message(format!(
            "t = {:.4e} s, step {}",
            run.sim.time_s, run.sim.step
        ));
        Ok(())
    }

    fn on_end(&mut self, _run: &RunView) -> Result<(), RunError> {
        self.bar.finish_and_clear();
        Ok(())
    }
}
