//! `timeseries.csv`: one row of observables per output time. Column names carry their units.

use solver::observables::PhaseStats;
use solver::Observables;
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::Path;

/// A coordinate axis.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Axis {
    /// x.
    X,
    /// y.
    Y,
    /// z.
    Z,
}

impl Axis {
    /// x, y, z.
    pub const ALL: [Axis; 3] = [Axis::X, Axis::Y, Axis::Z];

    /// `x`, `y` or `z`.
    pub fn name(self) -> &'static str {
        ["x", "y", "z"][self.index()]
    }

    /// 0, 1 or 2.
    pub fn index(self) -> usize {
        self as usize
    }
}

/// A column of the whole run; its name carries its unit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RunColumn {
    /// Simulated time [s].
    Time,
    /// Last time step [s].
    Dt,
    /// Steps taken.
    Step,
    /// Total kinetic energy [J].
    KineticEnergy,
    /// Interfacial energy [J].
    InterfacialEnergy,
    /// Total momentum along an axis [kg m/s].
    Momentum(Axis),
    /// Largest particle speed [m/s].
    MaxSpeed,
    /// Largest `|ρ/ρ0 − 1|` [-].
    MaxDensityDeviation,
    /// Largest compression `ρ/ρ0 − 1` [-].
    MaxCompression,
}

impl RunColumn {
    /// Every column of the whole run, in file order.
    pub const ALL: [RunColumn; 11] = [
        RunColumn::Time,
        RunColumn::Dt,
        RunColumn::Step,
        RunColumn::KineticEnergy,
        RunColumn::InterfacialEnergy,
        RunColumn::Momentum(Axis::X),
        RunColumn::Momentum(Axis::Y),
        RunColumn::Momentum(Axis::Z),
        RunColumn::MaxSpeed,
        RunColumn::MaxDensityDeviation,
        RunColumn::MaxCompression,
    ];

    /// The column's name in `timeseries.csv`.
    pub fn name(self) -> String {
        match self {
            RunColumn::Time => "time_s".into(),
            RunColumn::Dt => "dt_s".into(),
            RunColumn::Step => "step".into(),
            RunColumn::KineticEnergy => "kinetic_energy_J".into(),
            RunColumn::InterfacialEnergy => "interfacial_energy_J".into(),
            RunColumn::Momentum(ax) => format!("momentum_{}_kg_m_s", ax.name()),
            RunColumn::MaxSpeed => "max_speed_m_s".into(),
            RunColumn::MaxDensityDeviation => "max_density_deviation".into(),
            RunColumn::MaxCompression => "max_compression".into(),
        }
    }

    fn value(self, o: &Observables) -> f64 {
        match self {
            RunColumn::Time => o.time_s,
            RunColumn::Dt => o.dt_s,
            RunColumn::Step => o.step as f64,
            RunColumn::KineticEnergy => o.kinetic_energy_j,
            RunColumn::InterfacialEnergy => o.interfacial_energy_j,
            RunColumn::Momentum(ax) => o.momentum_kg_m_s[ax.index()],
            RunColumn::MaxSpeed => o.max_speed_m_s,
            RunColumn::MaxDensityDeviation => o.max_density_deviation,
            RunColumn::MaxCompression => o.max_compression,
        }
    }
}

/// A column of each liquid phase; its name is the liquid's name, the quantity and its unit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LiquidColumn {
    /// Number of particles.
    Count,
    /// Mass [kg].
    Mass,
    /// Mass centroid [m].
    Centroid(Axis),
    /// Velocity of the centroid [m/s].
    CentroidVelocity(Axis),
    /// Extent (max − min of the particle positions) [m].
    Extent(Axis),
    /// Lowest particle position [m].
    Min(Axis),
    /// Highest particle position [m].
    Max(Axis),
    /// Kinetic energy [J].
    KineticEnergy,
    /// The l = 4 shape moment ([`crate::measure::shape::cubic_harmonic_q4`]) [-].
    Q4,
}

impl LiquidColumn {
    /// Every column of a liquid, in file order.
    pub const ALL: [LiquidColumn; 19] = {
        use Axis::{X, Y, Z};
        use LiquidColumn::*;
        [
            Count,
            Mass,
            Centroid(X),
            Centroid(Y),
            Centroid(Z),
            CentroidVelocity(X),
            CentroidVelocity(Y),
            CentroidVelocity(Z),
            Extent(X),
            Extent(Y),
            Extent(Z),
            Min(X),
            Min(Y),
            Min(Z),
            Max(X),
            Max(Y),
            Max(Z),
            KineticEnergy,
            Q4,
        ]
    };

    /// The column's name in `timeseries.csv` for the liquid named `liquid`.
    pub fn name(self, liquid: &str) -> String {
        let axis = |q: &str, ax: Axis, unit: &str| format!("{liquid}_{q}_{}_{unit}", ax.name());
        match self {
            LiquidColumn::Count => format!("{liquid}_count"),
            LiquidColumn::Mass => format!("{liquid}_mass_kg"),
            LiquidColumn::Centroid(ax) => axis("centroid", ax, "m"),
            LiquidColumn::CentroidVelocity(ax) => axis("centroid_velocity", ax, "m_s"),
            LiquidColumn::Extent(ax) => axis("extent", ax, "m"),
            LiquidColumn::Min(ax) => axis("min", ax, "m"),
            LiquidColumn::Max(ax) => axis("max", ax, "m"),
            LiquidColumn::KineticEnergy => format!("{liquid}_kinetic_energy_J"),
            LiquidColumn::Q4 => format!("{liquid}_q4"),
        }
    }

    fn value(self, p: &PhaseStats, q4: f64) -> f64 {
        match self {
            LiquidColumn::Count => p.count as f64,
            LiquidColumn::Mass => p.mass_kg,
            LiquidColumn::Centroid(ax) => p.centroid_m[ax.index()],
            LiquidColumn::CentroidVelocity(ax) => p.centroid_velocity_m_s[ax.index()],
            LiquidColumn::Extent(ax) => p.extent_m[ax.index()],
            LiquidColumn::Min(ax) => p.min_m[ax.index()],
            LiquidColumn::Max(ax) => p.max_m[ax.index()],
            LiquidColumn::KineticEnergy => p.kinetic_energy_j,
            LiquidColumn::Q4 => q4,
        }
    }
}

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
