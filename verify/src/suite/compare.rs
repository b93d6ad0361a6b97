//! Regression check against a baseline `summary.csv`.
//!
//! A metric regresses when its error against the reference grows by more than a quarter of its
//! acceptance tolerance: `|e_now| > |e_base| + tol/4`. Runs are bitwise deterministic, so on the
//! same build any change is real; the quarter-tolerance margin absorbs compiler and platform
//! differences in the last bits, which move these metrics by far less. Metrics without a
//! reference, and metrics the baseline could not measure, are not judged. A metric of the
//! baseline that is no longer produced regresses too. `verify case NAMES --compare` judges the
//! named cases' rows only.

pub mod summary_csv;

use super::Metric;
use std::path::Path;
use summary_csv::Row;

/// Why a metric regressed.
#[derive(Clone, Debug, PartialEq)]
pub struct Regression {
    /// Case.
    pub case: String,
    /// Metric.
    pub name: String,
    /// What happened.
    pub message: String,
}

/// A baseline `summary.csv` and the cases it is compared on.
#[derive(Clone, Copy, Debug)]
pub struct Baseline<'a> {
    /// The file.
    pub path: &'a Path,
    /// The cases whose rows are judged (`None`: every row).
    pub cases: Option<&'a [String]>,
}

/// Compares `metrics` with the baseline's rows of its cases; returns the regressions.
pub fn compare(metrics: &[Metric], baseline: Baseline) -> anyhow::Result<Vec<Regression>> {
    let mut rows = summary_csv::read(baseline.path)?;
    if let Some(cases) = baseline.cases {
        rows.retain(|r| cases.contains(&r.case));
    }
    Ok(compare_rows(metrics, &rows))
}

fn compare_rows(metrics: &[Metric], rows: &[Row]) -> Vec<Regression> {
    let mut out = Vec::new();
    for row in rows {
        // a metric the baseline could not measure (NaN) cannot get worse than it
        let (Some(e_base), Some(tol)) = (row.error.filter(|e| e.is_finite()), row.tolerance) else {
            continue;
        };
        let Some(m) = metrics
            .iter()
            .find(|m| m.case == row.case && m.name == row.name)
        else {
            out.push(Regression {
                case: row.case.clone(),
                name: row.name.clone(),
                message: "no longer measured".into(),
            });
            continue;
        };
        let e_now = m.error().unwrap_or(f64::NAN);
        let within = e_now.abs() <= e_base.abs() + 0.25 * tol; // false for NaN
        if !within {
            out.push(Regression {
                case: row.case.clone(),
                name: row.name.clone(),
                message: format!(
                    "error {e_now:+.4e} {u} vs baseline {e_base:+.4e} {u} (allowed growth {:.3e} {u})",
                    0.25 * tol,
                    u = m.unit
                ),
            });
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::suite::Tolerance;

    fn metric(value: f64) -> Metric {
        Metric::new("c", "m", "ms", value).against(
            1.0,
            Tolerance {
                abs: 0.1,
                source: "test".into(),
            },
        )
    }

    fn row(error: f64) -> Row {
        Row {
            case: "c".into(),
            name: "m".into(),
            error: Some(error),
            tolerance: Some(0.1),
        }
    }

    #[test]
    fn growth_beyond_a_quarter_tolerance_regresses() {
        // baseline error 0.02; allowed up to 0.02 + 0.025
        assert!(compare_rows(&[metric(1.04)], &[row(0.02)]).is_empty());
        assert!(
            compare_rows(&[metric(0.96)], &[row(0.02)]).is_empty(),
            "sign does not matter"
        );
        assert_eq!(compare_rows(&[metric(1.05)], &[row(0.02)]).len(), 1);
        // an improvement is never a regression
        assert!(compare_rows(&[metric(1.0)], &[row(0.05)]).is_empty());
        // a NaN value (measurement failed) regresses
        assert_eq!(compare_rows(&[metric(f64::NAN)], &[row(0.02)]).len(), 1);
        // a metric that disappeared regresses
        assert_eq!(compare_rows(&[], &[row(0.02)]).len(), 1);
        // a metric the baseline could not measure is not judged
        assert!(compare_rows(&[metric(f64::NAN)], &[row(f64::NAN)]).is_empty());
    }

    #[test]
    fn a_baseline_limited_to_some_cases_judges_their_rows_only() {
        let dir = std::env::temp_dir().join(format!("compare-cases-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("baseline.csv");
        let other = Metric::new("d", "m", "ms", 1.0).against(
            1.0,
            Tolerance {
                abs: 0.1,
                source: "test".into(),
            },
        );
        summary_csv::write(&path, &[metric(1.0), other]).unwrap();
        // case d did not run: its row is "no longer measured" unless only c is compared
        let all = compare(
            &[metric(1.0)],
            Baseline {
                path: &path,
                cases: None,
            },
        )
        .unwrap();
        assert_eq!(all.len(), 1);
        assert_eq!(all[0].case, "d");
        let cases = ["c".to_string()];
        let only_c = Baseline {
            path: &path,
            cases: Some(&cases),
        };
        assert!(compare(&[metric(1.0)], only_c).unwrap().is_empty());
        // and c's own row is still judged
        assert_eq!(compare(&[metric(1.05)], only_c).unwrap().len(), 1);
        let _ = std::fs::remove_dir_all(&dir);
    }
}
