//! `probes.csv`: the values a case records at every output time of its runs
//! ([`Case::probe`]), if it records any.

use crate::output::timeseries::RunColumn;
use crate::output::RunError;
use crate::run::{Observer, RunView};
use crate::suite::Case;
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::PathBuf;

/// Writes a case's probes.
pub(super) struct Probes<'c> {
    case: &'c dyn Case,
    file: Option<(BufWriter<File>, PathBuf)>,
}

impl<'c> Probes<'c> {
    /// The probes of `case`.
    pub(super) fn of(case: &'c dyn Case) -> Probes<'c> {
        Probes { case, file: None }
    }
}

impl Observer for Probes<'_> {
    fn on_resume(&mut self, run: &RunView) -> Result<(), RunError> {
        let path = run.out_dir.join("probes.csv");
        if !path.exists() {
            return Ok(());
        }
        crate::output::keep_csv_rows(&path, run.output + 1)
            .map_err(|e| RunError::io("cannot rewrite", &path, e))?;
        let f = std::fs::OpenOptions::new()
            .append(true)
            .open(&path)
            .map_err(|e| RunError::io("cannot append to", &path, e))?;
        self.file = Some((BufWriter::new(f), path));
        Ok(())
    }

    fn on_output(&mut self, run: &RunView) -> Result<(), RunError> {
        let values = self.case.probe(run.sim);
        if run.output == 0 && !values.is_empty() {
            let path = run.out_dir.join("probes.csv");
            let names: Vec<&str> = values.iter().map(|v| v.0).collect();
            let mut w = BufWriter::new(
                File::create(&path).map_err(|e| RunError::io("cannot write", &path, e))?,
            );
            writeln!(w, "{},{}", RunColumn::Time.name(), names.join(","))
                .map_err(|e| RunError::io("cannot write", &path, e))?;
            self.file = Some((w, path));
        }
        if let Some((w, path)) = &mut self.file {
            let row: Vec<String> = values.iter().map(|v| format!("{:e}", v.1)).collect();
            writeln!(w, "{:e},{}", run.sim.time_s, row.join(","))
                .and_then(|()| w.flush())
                .map_err(|e| RunError::io("cannot write", path, e))?;
        }
        Ok(())
    }
}
