//! A case's analysis in three stages: **measure** the runs (pure functions of their saved data
//! into the case's own measurement types), **judge** the measurements (metrics against computed
//! references, each with the source of its tolerance), and **draw** them (plots only).

use crate::suite::{Fidelity, Metric, RunData};
use std::path::Path;

/// The three stages of a case's analysis; [`analyse`] composes them into
/// [`crate::suite::Case::analyse`].
pub trait Analysis {
    /// What the case measures on its runs (may borrow the runs).
    type Measured<'r>;

    /// Measures the saved runs.
    fn measure<'r>(&self, f: Fidelity, runs: &'r [RunData]) -> anyhow::Result<Self::Measured<'r>>;

    /// The metrics: the measurements against their references.
    fn judge(&self, f: Fidelity, measured: &Self::Measured<'_>) -> anyhow::Result<Vec<Metric>>;

    /// Draws the case's plots into `dir`.
    fn draw(&self, f: Fidelity, measured: &Self::Measured<'_>, dir: &Path) -> anyhow::Result<()>;
}

/// Measures `runs`, judges the measurements and draws them into `dir`; the metrics.
pub fn analyse<A: Analysis>(
    case: &A,
    f: Fidelity,
    runs: &[RunData],
    dir: &Path,
) -> anyhow::Result<Vec<Metric>> {
    let measured = case.measure(f, runs)?;
    let metrics = case.judge(f, &measured)?;
    case.draw(f, &measured, dir)?;
    Ok(metrics)
}
