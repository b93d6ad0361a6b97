//! What the outputs of a run implement: an [`Observer`] is told of every step, every output
//! time and the end of the run, and sees the run through a [`RunView`].

use crate::output::run_info::RunInfo;
use crate::output::RunError;
use solver::Simulation;
use std::path::Path;

/// A run as its observers see it.
pub struct RunView<'a> {
    /// The simulation.
    pub sim: &'a Simulation,
    /// Index of the last output time reached (0 = the initial state).
    pub output: u64,
    /// Output times of the whole run (end time / output interval).
    pub outputs: u64,
    /// The run record so far; its wall time is current, its status says how the run ended once
    /// it has.
    pub info: &'a RunInfo,
    /// The output folder.
    pub out_dir: &'a Path,
}

/// One output of a run (a file, a progress bar). Every method does nothing unless implemented.
pub trait Observer: Send {
    /// Output time `run.output` is reached (0: the initial state of a run not resumed).
    fn on_output(&mut self, _run: &RunView) -> Result<(), RunError> {
        Ok(())
    }
    /// The run continues from its checkpoint, taken at output `run.output` (no output is
    /// told again): files written up to there are kept, later rows dropped.
    fn on_resume(&mut self, _run: &RunView) -> Result<(), RunError> {
        Ok(())
    }
    /// A step was taken between two output times.
    fn on_step(&mut self, _run: &RunView) -> Result<(), RunError> {
        Ok(())
    }
    /// The run ended: `run.info.status` says how (completed, failed or interrupted). The record
    /// is written after every observer's end.
    fn on_end(&mut self, _run: &RunView) -> Result<(), RunError> {
        Ok(())
    }
}

/// The observers of one run, told in order; the first error stops the run.
pub(super) struct Observers<'o>(pub(super) Vec<Box<dyn Observer + 'o>>);

impl Observers<'_> {
    /// Tells every observer of an output time.
    pub(super) fn on_output(&mut self, run: &RunView) -> Result<(), RunError> {
        self.0.iter_mut().try_for_each(|o| o.on_output(run))
    }
    /// Tells every observer that the run continues from its checkpoint.
    pub(super) fn on_resume(&mut self, run: &RunView) -> Result<(), RunError> {
        self.0.iter_mut().try_for_each(|o| o.on_resume(run))
    }
    /// Tells every observer of a step.
    pub(super) fn on_step(&mut self, run: &RunView) -> Result<(), RunError> {
        self.0.iter_mut().try_for_each(|o| o.on_step(run))
    }
    /// Tells every observer of the end.
    pub(super) fn on_end(&mut self, run: &RunView) -> Result<(), RunError> {
        self.0.iter_mut().try_for_each(|o| o.on_end(run))
    }
}
