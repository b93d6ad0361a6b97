//! The standard outputs of a run, one observer per file: the time series and the final
//! particle state (always), `.vtu` snapshots (`vtk_every`), checkpoints (`checkpoint_steps`,
//! `checkpoint_minutes`, and on an interrupt) and the progress bar (`progress`). A new output
//! is one file here and its option.

mod checkpoint;
pub(crate) mod final_state;
mod progress;
mod timeseries;
mod vtu;

use super::observer::{Observer, Observers, RunView};
use super::RunOptions;
use crate::output::RunError;

/// The observers of a run with `opts` that starts (or, `resumed`, continues) at `run`: the
/// standard outputs, then `extra`, then the checkpoints, then the progress bar.
pub(super) fn from_options<'o>(
    opts: &RunOptions,
    run: &RunView,
    resumed: bool,
    extra: Vec<Box<dyn Observer + 'o>>,
) -> Result<Observers<'o>, RunError> {
    let mut list: Vec<Box<dyn Observer + 'o>> =
        vec![Box::new(timeseries::Timeseries::open(run, resumed)?)];
    if let Some(every) = opts.vtk_every {
        list.push(Box::new(vtu::Vtu::every(every)));
    }
    list.extend(extra);
    list.push(Box::new(final_state::FinalState));
    // after every file of an output: a checkpoint taken at output k finds all of k written
    list.push(Box::new(checkpoint::Checkpoints::new(opts, run)));
    if opts.progress {
        list.push(Box::new(progress::Progress::new(run)));
    }
    Ok(Observers(list))
}
