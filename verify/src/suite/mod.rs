//! The verification suite: cases (one per paper check), their runs at a fidelity, the metrics
//! they measure, and the reports.
//!
//! A case declares its runs (scenes, named from their parameters) and measures its metrics from
//! the saved outputs only, so reports can be redrawn without simulating (automan's split of
//! simulations and post-processing). Finished runs are reused unless forced.

pub mod compare;
pub mod metric;
pub mod overrides;
pub mod runner;
pub mod tally;

pub use metric::{Metric, Tolerance};

use crate::output::run_info::RunInfo;
use crate::output::timeseries::Table;
pub use crate::preflight::Check;
use serde::{Deserialize, Serialize};
use solver::{Scene, Simulation};
use std::path::{Path, PathBuf};

/// How hard the suite works.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, clap::ValueEnum)]
#[serde(rename_all = "snake_case")]
pub enum Fidelity {
    /// Each case in seconds, for the test suite.
    Smoke,
    /// The default of `verify all`: resolves the physics. A full re-run (`--force`) takes most
    /// of a day on 2 cores (the README states the committed runs' own wall times); finished runs
    /// are reused, so `all` then only re-reports, after simulating any run not made yet.
    Standard,
    /// The papers' particle counts and time steps.
    Paper,
}

impl Fidelity {
    /// Lower-case name.
    pub fn name(self) -> &'static str {
        match self {
            Fidelity::Smoke => "smoke",
            Fidelity::Standard => "standard",
            Fidelity::Paper => "paper",
        }
    }
}

/// The physical effects a case's scenes are built with (checked against every scene).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct DeclaredEffects {
    /// Gravity.
    pub gravity: bool,
    /// Laminar viscosity.
    pub laminar_viscosity: bool,
    /// Artificial viscosity.
    pub artificial_viscosity: bool,
    /// Interfacial tension (pairwise potential).
    pub interfacial_tension: bool,
    /// Walls (and wetting, with tension).
    pub walls: bool,
}

impl DeclaredEffects {
    /// A drop in zero gravity without walls: tension and both viscosities.
    pub const FREE_DROP: DeclaredEffects = DeclaredEffects {
        gravity: false,
        laminar_viscosity: true,
        artificial_viscosity: true,
        interfacial_tension: true,
        walls: false,
    };
    /// Drops on a wall under gravity: every effect.
    pub const ON_A_PLATE: DeclaredEffects = DeclaredEffects {
        gravity: true,
        laminar_viscosity: true,
        artificial_viscosity: true,
        interfacial_tension: true,
        walls: true,
    };

    /// Whether `scene` builds exactly these effects.
    pub fn matches(&self, scene: &Scene) -> bool {
        let e = &scene.effects;
        self.gravity == e.gravity.is_some()
            && self.laminar_viscosity == e.laminar_viscosity
            && self.artificial_viscosity == e.artificial_viscosity.is_some()
            && self.interfacial_tension == e.interfacial_tension.is_on()
            && self.walls != scene.walls.is_empty()
    }

    /// A case's declaration in words: its effects, or that they differ per run.
    pub fn describe_declared(e: Option<DeclaredEffects>) -> String {
        e.map_or_else(
            || "different for each run (see each run's scene)".into(),
            |e| e.describe(),
        )
    }

    /// In words, for reports.
    pub fn describe(&self) -> String {
        let on_off = |b: bool, s: &str| if b { s.to_string() } else { format!("no {s}") };
        [
            on_off(self.interfacial_tension, "interfacial tension"),
            on_off(self.laminar_viscosity, "laminar viscosity"),
            on_off(self.artificial_viscosity, "artificial viscosity"),
            on_off(self.gravity, "gravity"),
            on_off(self.walls, "walls"),
        ]
        .join(", ")
    }
}

/// One simulation of a case.
#[derive(Clone, Debug)]
pub struct RunSpec {
    /// Folder name, made from the parameters (e.g. `c2_150`).
    pub id: String,
    /// The scene.
    pub scene: Scene,
    /// Times [s] at which the particles are dumped (the final state always is).
    pub snapshot_times_s: Vec<f64>,
}

/// A finished (or failed) run, read back from its folder.
#[derive(Clone, Debug)]
pub struct RunData {
    /// The run's id.
    pub id: String,
    /// Its folder.
    pub dir: PathBuf,
    /// Its record.
    pub info: RunInfo,
    /// `timeseries.csv`.
    pub timeseries: Table,
    /// `probes.csv` (the case's extra columns per output; may be empty).
    pub probes: Table,
    /// The final particle state.
    pub last: crate::output::dump::Dump,
    /// Dumps at the requested snapshot times `(time [s], dump)`.
    pub snapshots: Vec<(f64, crate::output::dump::Dump)>,
}

impl RunData {
    /// Whether the run reached its end time.
    pub fn completed(&self) -> bool {
        self.info.status == crate::output::run_info::Status::Completed
    }

    /// `"run did not complete: {error}. "` for a run that stopped early, else empty: the
    /// prefix of every note measured on this run.
    pub fn status_note(&self) -> String {
        if self.completed() {
            String::new()
        } else {
            format!(
                "run did not complete: {}. ",
                self.info.error.clone().unwrap_or_default()
            )
        }
    }
}

/// A paper check.
pub trait Case: Sync {
    /// Short name (`cube_drop`), used for folders and `verify case NAME`.
    fn name(&self) -> &'static str;
    /// One-line title.
    fn title(&self) -> &'static str;
    /// Where it comes from (paper, section, table/figure).
    fn source(&self) -> &'static str;
    /// The effects its scenes are built with (checked against every scene), or None when its
    /// runs differ (each run's effects are then in its scene and `run_info.json`).
    fn effects(&self) -> Option<DeclaredEffects>;
    /// The resolution used at a fidelity, and why.
    fn resolution(&self, fidelity: Fidelity) -> String;
    /// The pre-flight checks ([`crate::preflight`]) the case's runs at a fidelity trip on
    /// purpose, and why; recorded in each run's record instead of warned about. By default:
    /// at smoke fidelity, the resolution.
    fn accepted_findings(&self, fidelity: Fidelity) -> Vec<(Check, String)> {
        smoke_is_coarse(fidelity)
    }
    /// The runs at a fidelity.
    fn runs(&self, fidelity: Fidelity) -> Vec<RunSpec>;
    /// Refuses the run `id` whose scene `--set` changed from `written` to `run` if the case
    /// would then name or judge it as something it is not (a model it does not declare). By
    /// default every change is accepted.
    fn check_override(&self, _id: &str, _written: &Scene, _run: &Scene) -> anyhow::Result<()> {
        Ok(())
    }
    /// Extra values recorded at every output (`probes.csv`).
    fn probe(&self, _sim: &Simulation) -> Vec<(&'static str, f64)> {
        Vec::new()
    }
    /// Measures the metrics from the saved runs and draws the case's plots into `dir`.
    fn analyse(
        &self,
        fidelity: Fidelity,
        runs: &[RunData],
        dir: &Path,
    ) -> anyhow::Result<Vec<Metric>>;
}

/// At smoke fidelity every case is coarse on purpose: the resolution check is accepted.
pub fn smoke_is_coarse(fidelity: Fidelity) -> Vec<(Check, String)> {
    if fidelity == Fidelity::Smoke {
        vec![(
            Check::Resolution,
            "smoke fidelity: a seconds-scale check that the case runs, coarse on purpose".into(),
        )]
    } else {
        Vec::new()
    }
}
