//! `summary.csv`: metrics as CSV — written for every case and for the whole suite, and read
//! back as the baseline of the regression check ([`super`]). It holds results only, so the same
//! revision writes the same bytes however its runs were scheduled (serially, as plan tasks in any
//! order, resumed or not); what the runs cost in wall time goes to `costs.csv` beside it.

use crate::output::atomic_write;
use crate::suite::Metric;
use std::path::Path;

const COLUMNS: [&str; 12] = [
    "case",
    "name",
    "unit",
    "value",
    "reference",
    "paper",
    "error",
    "tolerance",
    "tolerance_source",
    "pass",
    "particles",
    "note",
];

const COST_COLUMNS: [&str; 4] = ["case", "name", "particles", "wall_time_s"];

fn opt(v: Option<f64>) -> String {
    v.map(|x| format!("{x:e}")).unwrap_or_default()
}

/// Writes metrics as CSV.
pub fn write(path: &Path, metrics: &[Metric]) -> anyhow::Result<()> {
    write_rows(path, &COLUMNS, metrics, |m| {
        vec![
            m.case.clone(),
            m.name.clone(),
            m.unit.clone(),
            format!("{:e}", m.value),
            opt(m.reference),
            opt(m.paper),
            opt(m.error()),
            opt(m.tolerance.as_ref().map(|t| t.abs)),
            m.tolerance
                .as_ref()
                .map(|t| t.source.clone())
                .unwrap_or_default(),
            m.pass()
                .map(|p| if p { "pass" } else { "FAIL" }.to_string())
                .unwrap_or_default(),
            m.particles.to_string(),
            m.note.clone(),
        ]
    })
}

/// Writes what each metric's run cost: wall time [s] of its time loop, particles.
pub fn write_costs(path: &Path, metrics: &[Metric]) -> anyhow::Result<()> {
    write_rows(path, &COST_COLUMNS, metrics, |m| {
        vec![
            m.case.clone(),
            m.name.clone(),
            m.particles.to_string(),
            format!("{:.1}", m.wall_time_s),
        ]
    })
}

/// Writes `columns`, then one row per metric, to `path` (synced, then renamed).
fn write_rows(
    path: &Path,
    columns: &[&str],
    metrics: &[Metric],
    row: impl Fn(&Metric) -> Vec<String>,
) -> anyhow::Result<()> {
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record(columns)?;
    for m in metrics {
        w.write_record(row(m))?;
    }
    atomic_write(path, &w.into_inner()?)?;
    Ok(())
}

/// What the regression check reads of a row.
#[derive(Clone, Debug)]
pub(super) struct Row {
    /// Case.
    pub case: String,
    /// Metric.
    pub name: String,
    /// Error against the reference (in the metric's unit), if measured.
    pub error: Option<f64>,
    /// Acceptance tolerance (in the metric's unit), if judged.
    pub tolerance: Option<f64>,
}

/// Reads the rows of a `summary.csv` (columns found by name).
pub(super) fn read(path: &Path) -> anyhow::Result<Vec<Row>> {
    let mut rdr = csv::Reader::from_path(path)?;
    let headers = rdr.headers()?.clone();
    let col = |n: &str| {
        headers
            .iter()
            .position(|h| h == n)
            .ok_or_else(|| anyhow::anyhow!("baseline lacks column {n}"))
    };
    let (c_case, c_name, c_err, c_tol) =
        (col("case")?, col("name")?, col("error")?, col("tolerance")?);
    let mut rows = Vec::new();
    for rec in rdr.records() {
        let rec = rec?;
        let num = |k: usize| rec.get(k).and_then(|s| s.parse::<f64>().ok());
        rows.push(Row {
            case: rec[c_case].to_string(),
            name: rec[c_name].to_string(),
            error: num(c_err),
            tolerance: num(c_tol),
        });
    }
    Ok(rows)
}
