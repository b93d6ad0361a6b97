//! Cube drop vs sound speed (Natsui 2021, Appendix, Table A-1).
//!
//! A 1 mm cube of matte relaxes to a sphere in zero gravity and oscillates in the l = 4 mode.
//! Measured from the width (the paper's quantity; here the mean of the x, y and z extents) by a
//! damped-cosine fit after the first 0.2 ms (the corners' collapse): the full period and the amplitude decay rate, against
//! Lamb's values for the sphere of equal volume, and the period against the paper's Table A-1.
//! The l = 4 shape moment Q4 (`measure::shape`, recorded in every time series) gives a second,
//! less noisy period.

mod draw;
mod judge;
mod measure;

use super::analysis::{self, Analysis};
use super::paper_values;
use super::scene::SceneBuilder;
use crate::suite::{
    smoke_is_coarse, Case, Check, DeclaredEffects, Fidelity, Metric, RunData, RunSpec,
};
use std::path::Path;

/// The case.
pub struct CubeDrop;

const SCENE: &str = include_str!("../../../../scenes/cube_drop.toml");
/// Side of the cube [m].
const SIDE_M: f64 = 1e-3;

fn side_particles(f: Fidelity) -> usize {
    match f {
        Fidelity::Smoke => 10,
        Fidelity::Standard => 18,
        Fidelity::Paper => 27,
    }
}

/// The squared sound speeds [m²/s²] run at a fidelity.
fn c2_values(f: Fidelity) -> Vec<f64> {
    match f {
        Fidelity::Smoke => vec![150.0],
        _ => paper_values::list("cube_drop", "c2_m2_s2"),
    }
}

/// Fit window start [s]: the corners collapse first (higher modes), then l = 4 dominates.
const FIT_FROM_S: f64 = 2e-4;

impl Case for CubeDrop {
    fn name(&self) -> &'static str {
        "cube_drop"
    }
    fn title(&self) -> &'static str {
        "Cube drop: l = 4 oscillation period and damping against the sound speed"
    }
    fn source(&self) -> &'static str {
        "Natsui et al. 2021, Appendix, Fig. A-1 and Table A-1; Lamb (1932) §275"
    }
    fn effects(&self) -> Option<DeclaredEffects> {
        Some(DeclaredEffects::FREE_DROP)
    }
    fn accepted_findings(&self, f: Fidelity) -> Vec<(Check, String)> {
        let mut out = smoke_is_coarse(f);
        let why = "the check is Table A-1's sweep of c² = 60 … 600 m²/s²: its low sound speeds are the point";
        out.push((Check::CohesiveSoundSpeed, why.into()));
        out.push((Check::FlowSoundSpeed, why.into()));
        out
    }
    fn resolution(&self, f: Fidelity) -> String {
        let n = side_particles(f);
        let why = match f {
            Fidelity::Smoke => "R/l0 = 6.2; seconds per run, c² = 150 only",
            Fidelity::Standard => "R/l0 = 11: the period error has converged to a few per cent (15³: +1 %, 20³: similar)",
            Fidelity::Paper => "the paper's 27³ = 19,683 particles and dt = 2e-7 s",
        };
        format!(
            "{n}³ = {} particles (l0 = {:.4} mm); {why}.",
            n * n * n,
            SIDE_M / n as f64 * 1e3
        )
    }
    fn runs(&self, f: Fidelity) -> Vec<RunSpec> {
        let n = side_particles(f);
        c2_values(f)
            .into_iter()
            .map(|c2| {
                let end_s = if f == Fidelity::Smoke { 3.0e-3 } else { 5.0e-3 };
                let scene = SceneBuilder::from_toml(SCENE)
                    .l0(SIDE_M / n as f64)
                    .sound_speed(c2.sqrt())
                    .time(end_s, 1.0e-5)
                    .fixed_dt((f == Fidelity::Paper).then_some(2.0e-7))
                    .build();
                RunSpec {
                    id: format!("c2_{c2:.0}"),
                    scene,
                    snapshot_times_s: vec![],
                }
            })
            .collect()
    }
    fn analyse(&self, f: Fidelity, runs: &[RunData], dir: &Path) -> anyhow::Result<Vec<Metric>> {
        analysis::analyse(self, f, runs, dir)
    }
}

impl Analysis for CubeDrop {
    type Measured<'r> = Vec<measure::CubeRun<'r>>;

    fn measure<'r>(&self, _: Fidelity, runs: &'r [RunData]) -> anyhow::Result<Self::Measured<'r>> {
        Ok(runs.iter().map(measure::cube_run).collect())
    }

    fn judge(&self, _: Fidelity, measured: &Self::Measured<'_>) -> anyhow::Result<Vec<Metric>> {
        Ok(measured
            .iter()
            .flat_map(|m| judge::run_metrics(self.name(), m))
            .collect())
    }

    fn draw(&self, f: Fidelity, measured: &Self::Measured<'_>, dir: &Path) -> anyhow::Result<()> {
        draw::plots(f, measured, dir)
    }
}
