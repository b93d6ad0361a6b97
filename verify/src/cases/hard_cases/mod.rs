//! Hard cases: the scenes of `scenes/hard/`, checked for the invariants of a healthy run rather
//! than for looks — the run completes (no NaN, no blow-up), no particle is lost or ends inside a
//! wall, mass is conserved exactly, momentum to round-off where no external force acts, the
//! kinetic plus interfacial energy of a zero-gravity relaxation does not grow after the first
//! transient beyond what the equation of state can give back, compression stays bounded, and a
//! drop at rest stays one body without clumping.

mod judge;
mod measure;

use super::analysis::{self, Analysis};
use super::scene::SceneBuilder;
use crate::suite::{Case, Check, DeclaredEffects, Fidelity, Metric, RunData, RunSpec};
use std::path::Path;

/// The case.
pub struct HardCases;

/// `(id, scene text, smoke l0 factor, smoke end factor, expected bodies at the end)`. A θ ≈ 0°
/// drop spreads into a film thinner than a particle, which breaks up: its bodies are reported,
/// not judged; a splash fragments by nature.
const SCENES: [(&str, &str, f64, f64, Option<usize>); 7] = [
    (
        "viscosity_ratio",
        include_str!("../../../../scenes/hard/viscosity_ratio.toml"),
        1.6,
        0.1,
        Some(1),
    ),
    (
        "iron_small",
        include_str!("../../../../scenes/hard/iron_small.toml"),
        1.6,
        0.2,
        Some(1),
    ),
    (
        "splash",
        include_str!("../../../../scenes/hard/splash.toml"),
        1.6,
        0.3,
        None,
    ),
    (
        "resting_drop",
        include_str!("../../../../scenes/hard/resting_drop.toml"),
        1.6,
        0.16,
        Some(1),
    ),
    (
        "coarse_long_cutoff",
        include_str!("../../../../scenes/hard/coarse_long_cutoff.toml"),
        1.0,
        0.3,
        Some(1),
    ),
    (
        "point_contact",
        include_str!("../../../../scenes/hard/point_contact.toml"),
        1.6,
        0.3,
        None,
    ),
    (
        "extreme_contact_angles",
        include_str!("../../../../scenes/hard/extreme_contact_angles.toml"),
        1.6,
        0.3,
        None,
    ),
];

/// The first part of a run treated as the transient [-].
const TRANSIENT: f64 = 0.2;

impl Case for HardCases {
    fn name(&self) -> &'static str {
        "hard_cases"
    }
    fn title(&self) -> &'static str {
        "Hard cases: invariants of viscosity ratio 6000, iron at small scale, splash (We 246), 1e5 resting steps, coarse long cut-off, point contact, θ ≈ 0°/180°"
    }
    fn source(&self) -> &'static str {
        "scenes/hard/*.toml (issue: hard cases stay stable)"
    }
    fn effects(&self) -> Option<DeclaredEffects> {
        // the scenes differ (gravity, walls): each run's effects are in its scene
        None
    }
    fn accepted_findings(&self, _: Fidelity) -> Vec<(Check, String)> {
        let why = "hard cases are extreme on purpose: small and thin drops, a coarse long cut-off, iron at small scale, each to show the run stays stable";
        [Check::Resolution, Check::Film, Check::CohesiveSoundSpeed]
            .into_iter()
            .map(|c| (c, why.to_string()))
            .collect()
    }
    fn resolution(&self, f: Fidelity) -> String {
        match f {
            Fidelity::Smoke => "each scene with l0 × 1.6 (the coarse case as is) and a fraction of its end time (resting drop: 1e4 steps)".into(),
            Fidelity::Standard => "the scenes of scenes/hard/ as written (resting drop: 1e5 steps)".into(),
            Fidelity::Paper => "the scenes of scenes/hard/ with l0 / 1.5".into(),
        }
    }
    fn runs(&self, f: Fidelity) -> Vec<RunSpec> {
        SCENES
            .iter()
            .map(|&(id, text, l0_factor, end_factor, _)| {
                let base = SceneBuilder::from_toml(text);
                let (l0, end) = (base.scene().discretisation.l0, base.scene().time.end);
                let (l0, end) = match f {
                    Fidelity::Smoke => (l0 * l0_factor, end * end_factor),
                    Fidelity::Standard => (l0, end),
                    Fidelity::Paper => (l0 / 1.5, end),
                };
                let output_interval = base.scene().time.output_interval.min(end / 20.0);
                let s = base.l0(l0).time(end, output_interval).build();
                RunSpec {
                    id: id.into(),
                    scene: s,
                    snapshot_times_s: vec![],
                }
            })
            .collect()
    }
    fn analyse(&self, f: Fidelity, runs: &[RunData], dir: &Path) -> anyhow::Result<Vec<Metric>> {
        analysis::analyse(self, f, runs, dir)
    }
}

impl Analysis for HardCases {
    type Measured<'r> = Vec<measure::HardRun<'r>>;

    fn measure<'r>(&self, _: Fidelity, runs: &'r [RunData]) -> anyhow::Result<Self::Measured<'r>> {
        Ok(runs.iter().map(measure::hard_run).collect())
    }

    fn judge(&self, _: Fidelity, measured: &Self::Measured<'_>) -> anyhow::Result<Vec<Metric>> {
        Ok(measured
            .iter()
            .flat_map(|m| judge::run_metrics(self.name(), m))
            .collect())
    }

    /// The invariants are tables, not plots.
    fn draw(&self, _: Fidelity, _: &Self::Measured<'_>, _: &Path) -> anyhow::Result<()> {
        Ok(())
    }
}
