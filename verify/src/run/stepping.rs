//! The time loop: steps the simulation from one output time to the next until the end time,
//! telling the observers; stops early on a simulation error or an interrupt.

use super::observer::{Observer, Observers, RunView};
use super::{outputs, RunOptions};
use crate::output::run_info::{RunInfo, Status};
use crate::output::RunError;
use solver::{SimError, Simulation};
use std::path::Path;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Instant;

/// A run in progress: the simulation, the output times it has reached, and its record.
pub(super) struct Run<'a> {
    sim: Simulation,
    /// Index of the last output time reached (0 = the initial state).
    output: u64,
    pub(super) info: RunInfo,
    out_dir: &'a Path,
    /// Continued from a checkpoint (its initial state was written before).
    resumed: bool,
    /// Output times of the whole run.
    outputs: u64,
    /// Time between outputs [s].
    output_interval_s: f64,
    /// When this part of the run started, and the wall time [s] of the parts before it.
    started: Instant,
    wall_before_s: f64,
}

/// How the time loop ended.
enum Ending {
    Completed,
    Interrupted,
    Failed(SimError),
}

impl<'a> Run<'a> {
    /// A run of `sim`, at output `output`, recorded in `info`, writing into `out_dir`.
    pub(super) fn new(
        sim: Simulation,
        output: u64,
        info: RunInfo,
        out_dir: &'a Path,
        resumed: bool,
    ) -> Run<'a> {
        let time = &sim.scene.time;
        let (outputs, output_interval_s) = (
            (time.end / time.output_interval).round() as u64,
            time.output_interval,
        );
        let wall_before_s = info.wall_time_s;
        Run {
            sim,
            output,
            info,
            out_dir,
            resumed,
            outputs,
            output_interval_s,
            started: Instant::now(),
            wall_before_s,
        }
    }

    /// Runs to the end with the outputs of `opts` and then `extra`; returns the final record.
    pub(super) fn drive<'o>(
        mut self,
        opts: &RunOptions,
        extra: Vec<Box<dyn Observer + 'o>>,
    ) -> Result<RunInfo, RunError> {
        let mut observers = outputs::from_options(opts, &self.view(), self.resumed, extra)?;
        self.info.write(self.out_dir)?;
        if self.resumed {
            observers.on_resume(&self.view())?;
        } else {
            observers.on_output(&self.view())?;
        }
        let ending = self.advance(&mut observers, opts.interrupt.as_deref())?;
        self.finish(ending, &mut observers)
    }

    fn view(&self) -> RunView<'_> {
        RunView {
            sim: &self.sim,
            output: self.output,
            outputs: self.outputs,
            info: &self.info,
            out_dir: self.out_dir,
        }
    }

    /// Wall time of the time loop over every part of the run [s].
    fn wall_time_s(&self) -> f64 {
        self.wall_before_s + self.started.elapsed().as_secs_f64()
    }

    /// Steps to the end time (or the first error or interrupt), telling the observers of every
    /// step and output time.
    fn advance(
        &mut self,
        observers: &mut Observers,
        interrupt: Option<&AtomicBool>,
    ) -> Result<Ending, RunError> {
        while self.output < self.outputs {
            let t_next = (self.output + 1) as f64 * self.output_interval_s;
            while self.sim.time_s < t_next * (1.0 - 1e-12) {
                if let Err(e) = self.sim.step(t_next - self.sim.time_s) {
                    return Ok(Ending::Failed(e));
                }
                if interrupt.is_some_and(|f| f.load(Ordering::SeqCst)) {
                    return Ok(Ending::Interrupted);
                }
                self.info.wall_time_s = self.wall_time_s();
                observers.on_step(&self.view())?;
            }
            self.output += 1;
            observers.on_output(&self.view())?;
        }
        Ok(Ending::Completed)
    }

    /// Records how the run ended, tells the observers, writes the record last.
    fn finish(mut self, ending: Ending, observers: &mut Observers) -> Result<RunInfo, RunError> {
        self.info.record_progress(&self.sim, self.wall_time_s());
        (self.info.status, self.info.error) = match &ending {
            Ending::Completed => (Status::Completed, None),
            Ending::Interrupted => (Status::Interrupted, None),
            Ending::Failed(e) => (Status::Failed, Some(e.to_string())),
        };
        observers.on_end(&self.view())?;
        self.info.write(self.out_dir)?;
        match ending {
            Ending::Completed => Ok(self.info),
            Ending::Interrupted => Err(RunError::Interrupted(format!(
                "interrupted at step {}, t = {:e} s; checkpoint written: continue with `verify run --resume {}`",
                self.sim.step,
                self.sim.time_s,
                self.out_dir.display()
            ))),
            Ending::Failed(e) => Err(RunError::Simulation(e.to_string())),
        }
    }
}
