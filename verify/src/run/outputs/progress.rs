//! Progress on stderr: a bar on a terminal; in a batch job's log (stderr not a terminal) a plain
//! line every [`LINE_INTERVAL`] of wall time and at the end — outputs done, simulated time,
//! particle-steps per second and the estimated time left.

use crate::output::RunError;
use crate::run::observer::{Observer, RunView};
use indicatif::{ProgressBar, ProgressStyle};
use std::io::IsTerminal;
use std::time::{Duration, Instant};

/// Wall time between two plain progress lines.
pub const LINE_INTERVAL: Duration = Duration::from_secs(30);

/// Shows a run's progress.
pub(super) enum Progress {
    /// On a terminal.
    Bar(ProgressBar),
    /// In a log.
    Lines(Lines),
}

/// What the plain lines need: where the run stood when progress began.
pub(super) struct Lines {
    start: Instant,
    last: Instant,
    step0: u64,
    output0: u64,
}

impl Progress {
    /// Progress over the output times of `run`, at its current one.
    pub(super) fn new(run: &RunView) -> Progress {
        if !std::io::stderr().is_terminal() {
            let now = Instant::now();
            return Progress::Lines(Lines {
                start: now,
                last: now,
                step0: run.sim.step,
                output0: run.output,
            });
        }
        let bar = ProgressBar::new(run.outputs);
        bar.set_style(
            ProgressStyle::with_template("{bar:40} {pos}/{len} outputs, {msg}, ETA {eta}")
                .unwrap_or_else(|_| ProgressStyle::default_bar()),
        );
        bar.set_position(run.output);
        Progress::Bar(bar)
    }
}

/// One plain progress line: `outputs` of `total` done at `time_s` [s], `rate` particle-steps
/// per second, and the time left if the outputs still to come take as long as those since
/// `output0` took in `elapsed`.
pub fn line(
    (output, output0, total): (u64, u64, u64),
    time_s: f64,
    rate: f64,
    elapsed: Duration,
) -> String {
    let done = output.saturating_sub(output0);
    let left = if done > 0 {
        let per = elapsed.as_secs_f64() / done as f64;
        format!("{:.0} s", per * total.saturating_sub(output) as f64)
    } else {
        "unknown".to_string()
    };
    format!("progress: {output}/{total} outputs, t = {time_s:.4e} s, {rate:.3e} particle-steps/s, ETA {left}")
}

impl Lines {
    fn print(&mut self, run: &RunView) {
        let now = Instant::now();
        let elapsed = now - self.start;
        let steps = run.sim.step.saturating_sub(self.step0) as f64;
        let rate = steps * run.sim.particles.n_fluid as f64 / elapsed.as_secs_f64().max(1e-9);
        eprintln!(
            "{}",
            line(
                (run.output, self.output0, run.outputs),
                run.sim.time_s,
                rate,
                elapsed
            )
        );
        self.last = now;
    }
}

impl Observer for Progress {
    fn on_output(&mut self, run: &RunView) -> Result<(), RunError> {
        match self {
            Progress::Bar(bar) => {
                bar.set_position(run.output);
                bar.set_message(format!(
                    "t = {:.4e} s, step {}",
                    run.sim.time_s, run.sim.step
                ));
            }
            Progress::Lines(l) => {
                if l.last.elapsed() >= LINE_INTERVAL {
                    l.print(run);
                }
            }
        }
        Ok(())
    }

    fn on_end(&mut self, run: &RunView) -> Result<(), RunError> {
        match self {
            Progress::Bar(bar) => bar.finish_and_clear(),
            Progress::Lines(l) => l.print(run),
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_line_says_outputs_time_rate_and_time_left() {
        // outputs 5 → 15 of 100 in 40 s (a resumed run): 4 s each, 85 to go
        let l = line((15, 5, 100), 1.5e-3, 2.0e5, Duration::from_secs(40));
        assert_eq!(
            l,
            "progress: 15/100 outputs, t = 1.5000e-3 s, 2.000e5 particle-steps/s, ETA 340 s"
        );
        assert!(line((5, 5, 100), 0.0, 0.0, Duration::ZERO).ends_with("ETA unknown"));
    }
}
