//! `timeseries.csv`: one row of observables per output time. Column names carry their units.

use solver::Observables;
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::Path;

/// Column names for a run with the given liquid phase names.
pub fn header(phases: &[String]) -> Vec<String> {
    let mut h: Vec<String> = [
        "time_s",
        "dt_s",
        "step",
        "kinetic_energy_J",
        "interfacial_energy_J",
        "momentum_x_kg_m_s",
        "momentum_y_kg_m_s",
        "momentum_z_kg_m_s",
        "max_speed_m_s",
        "max_density_deviation",
        "max_compression",
    ]
    .iter()
    .map(|s| s.to_string())
    .collect();
    for p in phases {
        h.push(format!("{p}_count"));
        h.push(format!("{p}_mass_kg"));
        for q in ["centroid", "centroid_velocity", "extent", "min", "max"] {
            let unit = if q == "centroid_velocity" { "m_s" } else { "m" };
            for ax in ["x", "y", "z"] {
                h.push(format!("{p}_{q}_{ax}_{unit}"));
            }
        }
        h.push(format!("{p}_kinetic_energy_J"));
        h.push(format!("{p}_q4"));
    }
    h
}

/// The values of one row, in [`header`] order; `q4[a]` is the l = 4 shape moment of liquid `a`
/// ([`crate::measure::shape::cubic_harmonic_q4`]).
pub fn row(o: &Observables, q4: &[f64]) -> Vec<f64> {
    let mut r = vec![
        o.time_s,
        o.dt_s,
        o.step as f64,
        o.kinetic_energy_j,
        o.interfacial_energy_j,
        o.momentum_kg_m_s[0],
        o.momentum_kg_m_s[1],
        o.momentum_kg_m_s[2],
        o.max_speed_m_s,
        o.max_density_deviation,
        o.max_compression,
    ];
    for (a, p) in o.phases.iter().enumerate() {
        r.push(p.count as f64);
        r.push(p.mass_kg);
        for v in [
            p.centroid_m,
            p.centroid_velocity_m_s,
            p.extent_m,
            p.min_m,
            p.max_m,
        ] {
            r.extend_from_slice(&v);
        }
        r.push(p.kinetic_energy_j);
        r.push(q4.get(a).copied().unwrap_or(f64::NAN));
    }
    r
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
}
