//! `timeseries.csv`: a row of observables at every output time.

use crate::output::timeseries::{phase_q4, TimeseriesWriter};
use crate::output::{keep_csv_rows, RunError};
use crate::run::observer::{Observer, RunView};
use std::path::PathBuf;

/// Writes `timeseries.csv`.
pub(super) struct Timeseries {
    writer: TimeseriesWriter,
    path: PathBuf,
}

impl Timeseries {
    /// Creates the file with its header, or — for a `resumed` run — drops the rows written after
    /// the checkpoint (the resumed run writes them again) and appends to it.
    pub(super) fn open(run: &RunView, resumed: bool) -> Result<Timeseries, RunError> {
        let path = run.out_dir.join("timeseries.csv");
        let model = &run.sim.model;
        let phases = &model.phase_names[..model.n_liquids];
        let writer = if resumed {
            keep_csv_rows(&path, run.output + 1)
                .map_err(|e| RunError::io("cannot rewrite", &path, e))?;
            TimeseriesWriter::create(&path, phases, true)
                .map_err(|e| RunError::io("cannot append to", &path, e))?
        } else {
            TimeseriesWriter::create(&path, phases, false)
                .map_err(|e| RunError::io("cannot write", &path, e))?
        };
        Ok(Timeseries { writer, path })
    }
}

impl Observer for Timeseries {
    fn on_output(&mut self, run: &RunView) -> Result<(), RunError> {
        self.writer
            .write(&run.sim.observe(), &phase_q4(run.sim))
            .map_err(|e| RunError::io("cannot write", &self.path, e))
    }
}
