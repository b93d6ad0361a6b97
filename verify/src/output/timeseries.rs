//! `timeseries.csv`: one row of observables per output time. Column names carry their units.

mod columns;

pub use columns::{Axis, LiquidColumn, RunColumn};

use solver::Observables;
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::Path;

/// Column names for a run with the given liquid phase names.
pub fn header(phases: &[String]) -> Vec<String> {
    let run = RunColumn::ALL.iter().map(|c| c.name());
    let liquids = phases
        .iter()
        .flat_map(|p| LiquidColumn::ALL.iter().map(move |c| c.name(p)));
    run.chain(liquids).collect()
}

/// The values of one row, in [`header`] order; `q4[a]` is the l = 4 shape moment of liquid `a`
/// ([`crate::measure::shape::cubic_harmonic_q4`]).
pub fn row(o: &Observables, q4: &[f64]) -> Vec<f64> {
    let run = RunColumn::ALL.iter().map(|c| c.value(o));
    let liquids = o.phases.iter().enumerate().flat_map(|(a, p)| {
        let q4 = q4.get(a).copied().unwrap_or(f64::NAN);
        LiquidColumn::ALL.iter().map(move |c| c.value(p, q4))
    });
    run.chain(liquids).collect()
}

/// The l = 4 shape moment of each liquid phase of a simulation [-].
pub fn phase_q4(sim: &solver::Simulation) -> Vec<f64> {
    let p = &sim.particles;
    (0..sim.model.n_liquids)
        .map(|a| {
            let pts: Vec<[f64; 3]> = (0..p.n_fluid)
                .filter(|&i| p.phase[i] as usize == a)
                .map(|i| p.pos[i].into())
                .collect();
            crate::measure::shape::cubic_harmonic_q4(&pts)
        })
        .collect()
}

/// Appends rows to a CSV file; each row is written whole and flushed, so a crash never leaves
/// half a row behind the last flush.
pub struct TimeseriesWriter {
    out: BufWriter<File>,
}

impl TimeseriesWriter {
    /// Creates `path` with the header (or, with `append`, opens it to continue a run).
    pub fn create(path: &Path, phases: &[String], append: bool) -> std::io::Result<Self> {
        let file = if append {
            std::fs::OpenOptions::new().append(true).open(path)?
        } else {
            File::create(path)?
        };
        let mut w = TimeseriesWriter {
            out: BufWriter::new(file),
        };
        if !append {
            writeln!(w.out, "{}", header(phases).join(","))?;
            w.out.flush()?;
        }
        Ok(w)
    }

    /// Writes one row and flushes it.
    pub fn write(&mut self, o: &Observables, q4: &[f64]) -> std::io::Result<()> {
        let line: Vec<String> = row(o, q4).iter().map(|v| format!("{v:e}")).collect();
        // one write call for the whole line: the buffer never splits a row between flushes
        self.out
            .write_all(format!("{}\n", line.join(",")).as_bytes())?;
        self.out.flush()
    }
}

/// A time series read back from `timeseries.csv`: column name → values.
#[derive(Debug, Clone, Default)]
pub struct Table {
    /// Column names.
    pub columns: Vec<String>,
    /// Rows of values.
    pub rows: Vec<Vec<f64>>,
}

impl Table {
    /// Reads a CSV written by [`TimeseriesWriter`].
    pub fn read(path: &Path) -> anyhow::Result<Table> {
        let mut rdr = csv::Reader::from_path(path)?;
        let columns = rdr.headers()?.iter().map(|s| s.to_string()).collect();
        let mut rows = Vec::new();
        for rec in rdr.records() {
            let rec = rec?;
            rows.push(
                rec.iter()
                    .map(|s| s.parse::<f64>().unwrap_or(f64::NAN))
                    .collect(),
            );
        }
        Ok(Table { columns, rows })
    }

    /// The values of a column, if present.
    pub fn column(&self, name: &str) -> Option<Vec<f64>> {
        let k = self.columns.iter().position(|c| c == name)?;
        Some(self.rows.iter().map(|r| r[k]).collect())
    }

    /// The values of a column of the whole run (empty if missing).
    pub fn run_column(&self, c: RunColumn) -> Vec<f64> {
        self.column(&c.name()).unwrap_or_default()
    }

    /// The values of a column of the liquid named `liquid` (empty if missing).
    pub fn liquid_column(&self, liquid: &str, c: LiquidColumn) -> Vec<f64> {
        self.column(&c.name(liquid)).unwrap_or_default()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use solver::observables::PhaseStats;

    #[test]
    fn header_and_row_agree_and_columns_read_back() {
        let phase = |name: &str, count: usize| PhaseStats {
            name: name.into(),
            count,
            mass_kg: 2.0 * count as f64,
            centroid_m: [1.0, 2.0, 3.0],
            ..Default::default()
        };
        let o = Observables {
            time_s: 0.5,
            step: 7,
            momentum_kg_m_s: [0.0, 4.0, 0.0],
            phases: vec![phase("a", 3), phase("b", 5)],
            ..Default::default()
        };
        let names: Vec<String> = o.phases.iter().map(|p| p.name.clone()).collect();
        let header = header(&names);
        let row = row(&o, &[0.1, 0.2]);
        assert_eq!(header.len(), row.len());
        assert_eq!(
            header.len(),
            RunColumn::ALL.len() + 2 * LiquidColumn::ALL.len()
        );
        let table = Table {
            columns: header,
            rows: vec![row],
        };
        assert_eq!(table.run_column(RunColumn::Step), vec![7.0]);
        assert_eq!(table.run_column(RunColumn::Momentum(Axis::Y)), vec![4.0]);
        assert_eq!(table.liquid_column("b", LiquidColumn::Count), vec![5.0]);
        assert_eq!(table.liquid_column("b", LiquidColumn::Mass), vec![10.0]);
        assert_eq!(
            table.liquid_column("a", LiquidColumn::Centroid(Axis::Z)),
            vec![3.0]
        );
        assert_eq!(table.liquid_column("b", LiquidColumn::Q4), vec![0.2]);
        assert!(table.liquid_column("c", LiquidColumn::Q4).is_empty());
    }
}
