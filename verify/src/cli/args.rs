//! The command line: every subcommand and its arguments (clap), and the suite's options built
//! from them.

use super::interrupt_flag;
use clap::{Parser, Subcommand};
use solver::kernel::KernelKind;
use solver::simulation::calibration::SlabDesign;
use std::path::{Path, PathBuf};
use verify::diagnostics::mode_stiffness::Continuum;
use verify::suite::overrides::SceneOverride;
use verify::suite::runner::SuiteOptions;
use verify::suite::Fidelity;

#[derive(Parser)]
#[command(
    name = "verify",
    version,
    about = "SPH droplets with pairwise-potential interfacial tension: run scenes, reproduce the papers' checks"
)]
pub(crate) struct Cli {
    #[command(subcommand)]
    pub(crate) command: Command,
}

#[derive(clap::Args, Clone)]
pub(crate) struct SuiteArgs {
    /// smoke (seconds per case), standard (default), paper (the papers' resolutions).
    #[arg(long, value_enum, default_value = "standard")]
    pub(crate) fidelity: Fidelity,
    /// Output folder (default: reports/, or reports/smoke, reports/paper).
    #[arg(long)]
    pub(crate) out: Option<PathBuf>,
    /// Re-run finished runs.
    #[arg(long)]
    pub(crate) force: bool,
    /// Worker threads per run (default: all cores).
    #[arg(long, value_name = "N")]
    pub(crate) threads: Option<usize>,
    /// Set a scene key in every run, e.g. `--set discretisation.kernel=quintic_spline`
    /// (repeatable; use with --out: the results are not the cases as written).
    #[arg(long = "set", value_name = "KEY=VALUE")]
    pub(crate) set: Vec<SceneOverride>,
    /// Simulate only the runs with these ids (e.g. `--only eps_10`); the case is measured from
    /// the runs that exist.
    #[arg(long, value_delimiter = ',')]
    pub(crate) only: Vec<String>,
    /// Refuse a run whose scene has pre-flight findings the case does not accept (unit
    /// slips, coarse bodies, a low sound speed) instead of warning.
    #[arg(long)]
    pub(crate) strict: bool,
    /// Write each run's checkpoint every M minutes of wall time; a suite stopped by Ctrl-C or
    /// SIGTERM (exit 130) resumes its stopped run when the same command runs again.
    #[arg(long, value_name = "M", default_value = "10")]
    pub(crate) checkpoint_minutes: f64,
}

impl SuiteArgs {
    pub(crate) fn options(&self) -> SuiteOptions {
        let out = self.out.clone().unwrap_or_else(|| match self.fidelity {
            Fidelity::Standard => PathBuf::from("reports"),
            f => Path::new("reports").join(f.name()),
        });
        SuiteOptions {
            fidelity: self.fidelity,
            out,
            force: self.force,
            threads: self.threads,
            progress: true,
            overrides: self.set.clone(),
            only: self.only.clone(),
            strict: self.strict,
            checkpoint_minutes: Some(self.checkpoint_minutes),
            interrupt: Some(interrupt_flag()),
        }
    }
}

#[derive(clap::Args)]
pub(crate) struct RunArgs {
    /// The scene (TOML).
    #[arg(required_unless_present = "resume")]
    pub(crate) scene: Option<PathBuf>,
    /// Output folder.
    #[arg(long, required_unless_present = "resume", conflicts_with = "resume")]
    pub(crate) out: Option<PathBuf>,
    /// Continue the run in this folder from its checkpoint (bitwise as if never stopped).
    #[arg(long, value_name = "DIR")]
    pub(crate) resume: Option<PathBuf>,
    /// Write a checkpoint every N steps.
    #[arg(long, value_name = "N")]
    pub(crate) checkpoint_steps: Option<u64>,
    /// Write a checkpoint every M minutes of wall time.
    #[arg(long, value_name = "M", default_value = "10")]
    pub(crate) checkpoint_minutes: f64,
    /// Write a particle snapshot (.vtu) every N outputs (N ≥ 1).
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..))]
    pub(crate) vtk: Option<u32>,
    /// Worker threads (default: all cores).
    #[arg(long, value_name = "N")]
    pub(crate) threads: Option<usize>,
    /// Overwrite a non-empty output folder.
    #[arg(long)]
    pub(crate) force: bool,
    /// Refuse a scene with pre-flight findings (unit slips, coarse bodies, a low sound speed)
    /// instead of warning.
    #[arg(long)]
    pub(crate) strict: bool,
}

/// Lists of discretisation settings whose every combination a diagnostic tabulates (an empty
/// list: the command's default value).
#[derive(clap::Args)]
pub(crate) struct SettingLists {
    /// Kernels.
    #[arg(long, value_enum, value_delimiter = ',')]
    pub(crate) kernel: Vec<KernelArg>,
    /// Smoothing lengths h/l0.
    #[arg(long = "h", value_delimiter = ',')]
    pub(crate) h_over_l0: Vec<f64>,
    /// Potential cut-offs r_e/l0.
    #[arg(long = "re", value_delimiter = ',')]
    pub(crate) re_over_l0: Vec<f64>,
    /// Orders m of the potential's zero at r_e (1: Kondo 2007; 2, 3: smoother).
    #[arg(long, value_delimiter = ',')]
    pub(crate) order: Vec<u8>,
}

#[derive(Subcommand)]
pub(crate) enum Command {
    /// Run one scene file (or continue a stopped run with --resume DIR).
    Run(RunArgs),
    /// List the verification cases.
    List {
        /// Show the runs at this fidelity.
        #[arg(long, value_enum, default_value = "standard")]
        fidelity: Fidelity,
    },
    /// Run some cases (missing runs are simulated, finished ones reused) and report them.
    Case {
        /// Case names (see `verify list`).
        #[arg(required = true)]
        names: Vec<String>,
        #[command(flatten)]
        suite: SuiteArgs,
        /// Compare the named cases with their rows of a baseline summary.csv; exit with code 4
        /// if any metric is worse.
        #[arg(long, value_name = "BASELINE.csv")]
        compare: Option<PathBuf>,
    },
    /// Run every case and write OUT/summary.md.
    All {
        #[command(flatten)]
        suite: SuiteArgs,
        /// Compare with a baseline summary.csv; exit with code 4 if any metric is worse.
        #[arg(long, value_name = "BASELINE.csv")]
        compare: Option<PathBuf>,
    },
    /// Studies across discretisation choices.
    Study {
        #[command(subcommand)]
        which: StudyKind,
    },
    /// The shear moduli G44 and C' [σ/l0] of the reference particle lattice (potential and
    /// pressure term) for kernels × h/l0 × r_e/l0: a liquid has both at zero.
    LatticeModuli {
        /// Kernels.
        #[arg(long, value_enum, value_delimiter = ',', default_value = "wendland-c2")]
        kernel: Vec<KernelArg>,
        /// Smoothing lengths h/l0.
        #[arg(
            long = "h",
            value_delimiter = ',',
            default_value = "1.05,1.2,1.3,1.5,2.0"
        )]
        h_over_l0: Vec<f64>,
        /// Potential cut-offs r_e/l0.
        #[arg(
            long = "re",
            value_delimiter = ',',
            default_value = "2.1,3.1,4.0,4.2,5.6"
        )]
        re_over_l0: Vec<f64>,
        /// Orders m of the potential's zero at r_e (1: Kondo 2007; 2, 3: smoother).
        #[arg(long, value_delimiter = ',', default_value = "1")]
        order: Vec<u8>,
    },
    /// The surface force's curvature on a lattice sphere (docs/model.md §4b): its mean and
    /// particle-scale spread in units of 2/R, and the inward force's total, for colour-kernel
    /// reaches r_e/l0 × sphere radii R/l0.
    Curvature {
        /// Colour-kernel supports r_e/l0.
        #[arg(long = "re", value_delimiter = ',', default_value = "4.2,6.0,8.4")]
        re_over_l0: Vec<f64>,
        /// Sphere radii R/l0.
        #[arg(long = "r", value_delimiter = ',', default_value = "10,14,20")]
        r_over_l0: Vec<f64>,
        /// Seeded jitter of the lattice, up to ± this many spacings per axis.
        #[arg(long, default_value = "0.05")]
        jitter: f64,
    },
    /// The continuum models' stiffness against a lattice sphere's l = 2 mode (static: the
    /// generalised force on a volume-preserving stretch into spheroids, over the spheroid's
    /// exact `σ d²A/dε²`, which tends to Lamb's `3.2πσR²`), per model, colour-kernel support
    /// and radius.
    Stiffness {
        /// Continuum models.
        #[arg(
            long,
            value_delimiter = ',',
            default_value = "surface_force,surface_stress"
        )]
        model: Vec<Continuum>,
        /// Colour-kernel supports r_e/l0.
        #[arg(long = "re", value_delimiter = ',', default_value = "4.2")]
        re_over_l0: Vec<f64>,
        /// Sphere radii R/l0.
        #[arg(long = "r", value_delimiter = ',', default_value = "10,14,20")]
        r_over_l0: Vec<f64>,
        /// Seeded jitter of the lattice, up to ± this many spacings per axis.
        #[arg(long, default_value = "0.05")]
        jitter: f64,
        /// The mode's amplitude ε (surface at R (1 + ε P₂)).
        #[arg(long, default_value = "0.02")]
        eps: f64,
        /// The surface force's band threshold on |∇c| r_e (default: the solver's).
        #[arg(long, default_value_t = solver::physics::surface_tension::surface_force::BAND_GRADIENT_TIMES_R_E)]
        band: f64,
    },
    /// Measure a finished run like the cases do (height, wetted radius, contact angle, shape
    /// moments per liquid against time, from its `--vtk` snapshots) → RUN_DIR/measures.csv and
    /// plots, with the Young–Laplace equilibrium where one liquid rests on one wall.
    Measure {
        /// The run's output folder.
        run_dir: PathBuf,
    },
    /// Surface energy γ and surface stress f of a flat lattice surface (f/γ: a liquid has 1),
    /// for the pairwise potential (r_e/l0, order) and the square-gradient energy (kernel, h/l0);
    /// default: the accuracy–cost study's variants; with any list, the product of the lists (a
    /// list not given: the study's default value).
    SurfaceStress {
        #[command(flatten)]
        lists: SettingLists,
    },
    /// The surface tension of each liquid of a scene as the relaxed particle liquid has it:
    /// a periodic slab relaxed under the scene's forces, σ from the pair-force virial
    /// (Kirkwood–Buff), for kernels × h/l0 × r_e/l0 × orders (default: the scene's own).
    SlabTension {
        /// The scene (its liquids, sound speed, density control and viscosities are used).
        scene: PathBuf,
        #[command(flatten)]
        lists: SettingLists,
        /// The slab's thickness over l0 (a convergence check of the measurement).
        #[arg(long, default_value_t = SlabDesign::default().thickness_over_l0)]
        thickness_over_l0: f64,
        /// Run length in sound crossings of the slab (the last quarter is averaged).
        #[arg(long, default_value_t = SlabDesign::default().crossings)]
        crossings: f64,
    },
    /// Check a scene before running it: the pre-flight findings (unit slips, coarse bodies,
    /// a low sound speed) and the time step and steps it will take. Exit 2 with --strict if
    /// there are findings.
    Check {
        /// The scene (TOML).
        scene: PathBuf,
        /// Exit 2 if there is any finding.
        #[arg(long)]
        strict: bool,
        /// Build the particles and time this many steps: particles, neighbours, and the run's
        /// estimated wall time and memory on this machine (0: findings and step only).
        #[arg(long, value_name = "N", default_value = "20")]
        sample_steps: u64,
        /// Worker threads of the sample (default: all cores).
        #[arg(long, value_name = "N")]
        threads: Option<usize>,
    },
    /// Write the suite, the study or a sweep as independent tasks with a SLURM array job:
    /// run them with `verify task` (in any order, anywhere), then `verify collect`.
    Plan {
        #[command(subcommand)]
        which: PlanKind,
    },
    /// Run task N of a plan: skipped if finished, resumed from its checkpoint if stopped.
    Task {
        /// The plan's folder.
        plan: PathBuf,
        /// The task (0-based; `$SLURM_ARRAY_TASK_ID` in an array job).
        #[arg(long)]
        index: usize,
        /// Worker threads (default: all cores).
        #[arg(long, value_name = "N")]
        threads: Option<usize>,
        /// Write the run's checkpoint every M minutes of wall time.
        #[arg(long, value_name = "M", default_value = "10")]
        checkpoint_minutes: f64,
    },
    /// Measure a plan's finished runs and write its summaries (exit 5 if some tasks are not
    /// finished: they are named and left out).
    Collect {
        /// The plan's folder.
        plan: PathBuf,
    },
    /// Run a scene over every combination of values of some keys, here and now: the plan
    /// (`verify plan sweep`), every task in order, then `sweep.csv`.
    Sweep {
        /// The scene (TOML).
        scene: PathBuf,
        /// A key and its values, e.g. `--set discretisation.l0=1e-4,7e-5` (repeatable: every
        /// combination; commas inside [..] or quotes do not split).
        #[arg(long = "set", value_name = "KEY=V1,V2", required = true)]
        set: Vec<String>,
        /// Output folder (the plan's).
        #[arg(long)]
        out: PathBuf,
        /// Worker threads per run (default: all cores).
        #[arg(long, value_name = "N")]
        threads: Option<usize>,
    },
    /// Redraw every plot and table from saved runs, without simulating.
    Report {
        /// Output folder of a previous suite run.
        #[arg(long, default_value = "reports")]
        out: PathBuf,
    },
}

/// Where a plan goes and how its SLURM array job asks for resources.
#[derive(clap::Args)]
pub(crate) struct PlanArgs {
    /// The plan's folder (tasks write their results into it).
    #[arg(long)]
    pub(crate) out: PathBuf,
    /// Write over another plan in the folder.
    #[arg(long)]
    pub(crate) force: bool,
    /// Cores per task (`#SBATCH --cpus-per-task`), the run's worker threads.
    #[arg(long, value_name = "N", default_value = "2")]
    pub(crate) cpus_per_task: usize,
    /// Time limit per task (`#SBATCH --time`); a task stopped at it resumes when submitted again.
    #[arg(long, value_name = "D-HH:MM:SS", default_value = "04:00:00")]
    pub(crate) time: String,
    /// Partition (`#SBATCH --partition`).
    #[arg(long)]
    pub(crate) partition: Option<String>,
}

#[derive(Subcommand)]
pub(crate) enum PlanKind {
    /// The suite's runs (all cases, or those named), as `verify all` / `verify case` runs them.
    Suite {
        /// Case names (default: every case).
        names: Vec<String>,
        /// smoke, standard (default), paper.
        #[arg(long, value_enum, default_value = "standard")]
        fidelity: Fidelity,
        /// Set a scene key in every run (repeatable).
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
        /// Refuse runs with pre-flight findings the case does not accept.
        #[arg(long)]
        strict: bool,
        #[command(flatten)]
        plan: PlanArgs,
    },
    /// The accuracy–cost study's points.
    Study {
        /// reduced, standard (default), full.
        #[arg(long, value_enum, default_value = "standard")]
        grid: verify::study::Grid,
        /// Leave out the points with more fluid particles than N.
        #[arg(long, value_name = "N")]
        max_particles: Option<usize>,
        #[command(flatten)]
        plan: PlanArgs,
    },
    /// A scene over every combination of values of some keys.
    Sweep {
        /// The scene (TOML).
        scene: PathBuf,
        /// A key and its values, e.g. `--set liquid.matte.surface_tension=0.3,0.4`
        /// (repeatable: every combination).
        #[arg(long = "set", value_name = "KEY=V1,V2", required = true)]
        set: Vec<String>,
        #[command(flatten)]
        plan: PlanArgs,
    },
}

/// A kernel on the command line.
#[derive(Clone, Copy, clap::ValueEnum)]
pub(crate) enum KernelArg {
    WendlandC2,
    WendlandC4,
    CubicSpline,
    QuinticSpline,
}

impl From<KernelArg> for KernelKind {
    fn from(k: KernelArg) -> KernelKind {
        match k {
            KernelArg::WendlandC2 => KernelKind::WendlandC2,
            KernelArg::WendlandC4 => KernelKind::WendlandC4,
            KernelArg::CubicSpline => KernelKind::CubicSpline,
            KernelArg::QuinticSpline => KernelKind::QuinticSpline,
        }
    }
}

#[derive(Subcommand)]
pub(crate) enum StudyKind {
    /// What accuracy costs in time: the cube drop and a sessile drop over resolution, kernel,
    /// h/l0, r_e/l0 and density scheme. Finished points are reused unless --force.
    AccuracyCost {
        /// reduced (tests), standard (each single change from the defaults), full (factorial).
        #[arg(long, value_enum, default_value = "standard")]
        grid: verify::study::Grid,
        /// Output folder.
        #[arg(long, default_value = "reports/study")]
        out: PathBuf,
        /// Re-run finished points.
        #[arg(long)]
        force: bool,
        /// Worker threads per run (default: all cores).
        #[arg(long, value_name = "N")]
        threads: Option<usize>,
        /// Leave out the points with more fluid particles than N (a shorter run; the summary
        /// lists what was left out).
        #[arg(long, value_name = "N")]
        max_particles: Option<usize>,
    },
}
