//! What a hard run gives: the invariants of a healthy run, from its time series and final
//! state.

use super::TRANSIENT;
use crate::measure::invariants;
use crate::output::timeseries::{Axis, LiquidColumn, RunColumn, Table};
use crate::suite::RunData;

/// One run, measured.
pub struct HardRun<'r> {
    /// The run.
    pub run: &'r RunData,
    /// Liquid particles at every output (all liquids) [-].
    pub counts: Vec<f64>,
    /// Liquid mass at every output (all liquids) [kg].
    pub mass_kg: Vec<f64>,
    /// Liquid particles at the first output, per liquid in scene order [-].
    pub initial_counts: Vec<f64>,
    /// Liquid particles deeper than l0/2 inside a wall at the end [-].
    pub inside_walls: usize,
    /// Largest compression ρ/ρ0 − 1 after the transient [-].
    pub compression_after_transient: f64,
    /// Largest compression ρ/ρ0 − 1 over the whole run [-].
    pub compression_max: f64,
    /// Largest distance of the total momentum from its start [kg m/s].
    pub momentum_drift_kg_m_s: f64,
    /// Largest particle speed at any output [m/s].
    pub max_speed_m_s: f64,
    /// Largest rise of kinetic + interfacial energy above its value after the transient [J].
    pub energy_growth_j: f64,
    /// Bodies at the end: particles within 1.5 l0 of each other form one [-].
    pub bodies: usize,
    /// Share of particles with a neighbour closer than l0/2 at the end [-].
    pub clumped: f64,
    /// Largest distance of the first liquid's centroid from its start [m].
    pub centroid_drift_m: f64,
}

/// Measures a run.
pub fn hard_run(run: &RunData) -> HardRun<'_> {
    let (sc, ts) = (&run.info.scene, &run.timeseries);
    let l0 = sc.discretisation.l0;
    let per_liquid = |c: LiquidColumn| -> Vec<Vec<f64>> {
        sc.liquids
            .iter()
            .map(|l| ts.liquid_column(&l.name, c))
            .collect()
    };
    let liquid: Vec<[f64; 3]> = (0..run.last.pos.len())
        .filter(|&i| !run.last.wall[i])
        .map(|i| run.last.pos[i])
        .collect();
    let comp = ts.run_column(RunColumn::MaxCompression);
    let from = ((comp.len() as f64 * TRANSIENT) as usize).min(comp.len().saturating_sub(1));
    let energy: Vec<f64> = (ts.run_column(RunColumn::KineticEnergy).iter())
        .zip(&ts.run_column(RunColumn::InterfacialEnergy))
        .map(|(a, b)| a + b)
        .collect();
    let counts = per_liquid(LiquidColumn::Count);
    HardRun {
        run,
        initial_counts: counts
            .iter()
            .map(|c| c.first().copied().unwrap_or(0.0))
            .collect(),
        counts: sum(&counts),
        mass_kg: sum(&per_liquid(LiquidColumn::Mass)),
        inside_walls: invariants::inside_walls(&liquid, sc),
        compression_after_transient: largest(&comp[from..]),
        compression_max: largest(&comp),
        momentum_drift_kg_m_s: invariants::drift(
            Axis::ALL.map(|ax| ts.run_column(RunColumn::Momentum(ax))),
        ),
        max_speed_m_s: (ts.run_column(RunColumn::MaxSpeed).into_iter()).fold(0.0, f64::max),
        energy_growth_j: invariants::energy_growth(&energy, TRANSIENT),
        bodies: invariants::components(&liquid, 1.5 * l0),
        clumped: invariants::clumped_fraction(&liquid, l0),
        centroid_drift_m: sc
            .liquids
            .first()
            .map_or(0.0, |l| invariants::drift(centroids(ts, &l.name))),
    }
}

/// The centroid of liquid `l` along x, y, z [m] at every output.
fn centroids(ts: &Table, l: &str) -> [Vec<f64>; 3] {
    Axis::ALL.map(|ax| ts.liquid_column(l, LiquidColumn::Centroid(ax)))
}

/// Row-wise sum of equally long series (as long as the first).
pub fn sum(cols: &[Vec<f64>]) -> Vec<f64> {
    let n = cols.first().map_or(0, |c| c.len());
    (0..n).map(|k| cols.iter().map(|c| c[k]).sum()).collect()
}

/// The largest value (−∞ for none).
fn largest(v: &[f64]) -> f64 {
    v.iter().fold(f64::NEG_INFINITY, |a, &b| a.max(b))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sums() {
        assert_eq!(sum(&[vec![1.0, 2.0], vec![10.0, 20.0]]), vec![11.0, 22.0]);
        assert!(sum(&[]).is_empty());
    }
}
