//! `verify`: run scenes and reproduce the papers' checks. Exit codes are listed in docs/user-guide.md.

use clap::{Parser, Subcommand};
use solver::kernel::KernelKind;
use solver::simulation::calibration::SlabDesign;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use verify::cases;
use verify::diagnostics::{lattice_moduli, slab_tension, surface_stress};
use verify::plan::{self, TaskOptions};
use verify::preflight;
use verify::report::summary;
use verify::run::{self, load_scene, run_scene, RunOptions};
use verify::study::{run_all, StudyOptions};
use verify::suite::overrides::SceneOverride;
use verify::suite::runner::{self, SuiteOptions};
use verify::suite::Fidelity;

/// glibc's allocator raises its mmap threshold each time a large block is freed, after which
/// large transient buffers come from the heap and its high-water mark stays resident. A fixed
/// threshold keeps blocks of 32 KiB and more mapped and returned on release; a trim threshold
/// returns the heap's freed top. At 256 KiB the heap still crept over a run (20 k cube at the
/// default, 431 steps: live data ~15 MB, resident 33.9 MB); at 32 KiB the run peaks at 24.9 MB,
/// at the same speed.
fn tune_allocator() {
    #[cfg(all(target_os = "linux", target_env = "gnu"))]
    // SAFETY: mallopt only sets allocator parameters; called before any thread is started.
    unsafe {
        libc::mallopt(libc::M_MMAP_THRESHOLD, 32 * 1024);
        libc::mallopt(libc::M_TRIM_THRESHOLD, 1024 * 1024);
    }
}

#[derive(Parser)]
#[command(
    name = "verify",
    version,
    about = "SPH droplets with pairwise-potential interfacial tension: run scenes, reproduce the papers' checks"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(clap::Args, Clone)]
struct SuiteArgs {
    /// smoke (seconds per case), standard (default), paper (the papers' resolutions).
    #[arg(long, value_enum, default_value = "standard")]
    fidelity: Fidelity,
    /// Output folder (default: reports/, or reports/smoke, reports/paper).
    #[arg(long)]
    out: Option<PathBuf>,
    /// Re-run finished runs.
    #[arg(long)]
    force: bool,
    /// Worker threads per run (default: all cores).
    #[arg(long, value_name = "N")]
    threads: Option<usize>,
    /// Set a scene key in every run, e.g. `--set discretisation.kernel=quintic_spline`
    /// (repeatable; use with --out: the results are not the cases as written).
    #[arg(long = "set", value_name = "KEY=VALUE")]
    set: Vec<SceneOverride>,
    /// Simulate only the runs with these ids (e.g. `--only eps_10`); the case is measured from
    /// the runs that exist.
    #[arg(long, value_delimiter = ',')]
    only: Vec<String>,
    /// Refuse a run whose scene has pre-flight findings the case does not accept (unit
    /// slips, coarse bodies, a low sound speed) instead of warning.
    #[arg(long)]
    strict: bool,
    /// Write each run's checkpoint every M minutes of wall time; a suite stopped by Ctrl-C or
    /// SIGTERM (exit 130) resumes its stopped run when the same command runs again.
    #[arg(long, value_name = "M", default_value = "10")]
    checkpoint_minutes: f64,
}

impl SuiteArgs {
    fn options(&self) -> SuiteOptions {
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
struct RunArgs {
    /// The scene (TOML).
    #[arg(required_unless_present = "resume")]
    scene: Option<PathBuf>,
    /// Output folder.
    #[arg(long, required_unless_present = "resume", conflicts_with = "resume")]
    out: Option<PathBuf>,
    /// Continue the run in this folder from its checkpoint (bitwise as if never stopped).
    #[arg(long, value_name = "DIR")]
    resume: Option<PathBuf>,
    /// Write a checkpoint every N steps.
    #[arg(long, value_name = "N")]
    checkpoint_steps: Option<u64>,
    /// Write a checkpoint every M minutes of wall time.
    #[arg(long, value_name = "M", default_value = "10")]
    checkpoint_minutes: f64,
    /// Write a particle snapshot (.vtu) every N outputs (N ≥ 1).
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..))]
    vtk: Option<u32>,
    /// Worker threads (default: all cores).
    #[arg(long, value_name = "N")]
    threads: Option<usize>,
    /// Overwrite a non-empty output folder.
    #[arg(long)]
    force: bool,
    /// Refuse a scene with pre-flight findings (unit slips, coarse bodies, a low sound speed)
    /// instead of warning.
    #[arg(long)]
    strict: bool,
}

impl RunArgs {
    /// Runs (or resumes) the scene; the exit code. Ctrl-C finishes the current step, writes a
    /// checkpoint, flushes and exits with 130.
    fn run(self) -> i32 {
        let interrupt = interrupt_flag();
        let opts = RunOptions {
            out_dir: self.resume.clone().or(self.out).unwrap_or_default(),
            vtk_every: self.vtk,
            threads: self.threads,
            force: self.force,
            progress: true,
            checkpoint_steps: self.checkpoint_steps,
            checkpoint_minutes: Some(self.checkpoint_minutes),
            interrupt: Some(interrupt),
            strict: self.strict,
            accepted: Vec::new(),
        };
        let result = match (&self.resume, &self.scene) {
            (Some(_), _) => run::resume(&opts),
            (None, Some(scene)) => load_scene(scene).and_then(|s| run_scene(&s, scene, &opts)),
            (None, None) => unreachable!("clap requires a scene or --resume"),
        };
        match result {
            Ok(info) => {
                eprintln!(
                    "done: {} steps, {:.3e} s simulated, {:.1} s wall, {:.3e} particle-steps/s",
                    info.steps,
                    info.simulated_time_s,
                    info.wall_time_s,
                    info.particle_steps_per_second
                );
                // with snapshots, the run is measured as `verify measure` would (a measurement
                // that fails is said, not an error of the run)
                if self.vtk.is_some() {
                    if let Err(e) = measure_run(&opts.out_dir) {
                        eprintln!("measure: {e:#}");
                    }
                }
                0
            }
            Err(e) => {
                if matches!(e, verify::output::RunError::Simulation(_)) {
                    // a finding flagged before step 1 is the likely cause: named first
                    let info = verify::output::run_info::RunInfo::read(&opts.out_dir);
                    let flagged = info
                        .ok()
                        .and_then(|i| i.warnings.into_iter().find(|w| !w.starts_with("accepted")));
                    if let Some(w) = flagged {
                        let what = w.split(". Likely cause").next().unwrap_or(&w);
                        eprintln!("error: flagged before step 1, the likely cause: {what}");
                    }
                }
                eprintln!("error: {e}");
                e.exit_code()
            }
        }
    }
}

/// Lists of discretisation settings whose every combination a diagnostic tabulates (an empty
/// list: the command's default value).
#[derive(clap::Args)]
struct SettingLists {
    /// Kernels.
    #[arg(long, value_enum, value_delimiter = ',')]
    kernel: Vec<KernelArg>,
    /// Smoothing lengths h/l0.
    #[arg(long = "h", value_delimiter = ',')]
    h_over_l0: Vec<f64>,
    /// Potential cut-offs r_e/l0.
    #[arg(long = "re", value_delimiter = ',')]
    re_over_l0: Vec<f64>,
    /// Orders m of the potential's zero at r_e (1: Kondo 2007; 2, 3: smoother).
    #[arg(long, value_delimiter = ',')]
    order: Vec<u8>,
}

#[derive(Subcommand)]
enum Command {
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
struct PlanArgs {
    /// The plan's folder (tasks write their results into it).
    #[arg(long)]
    out: PathBuf,
    /// Write over another plan in the folder.
    #[arg(long)]
    force: bool,
    /// Cores per task (`#SBATCH --cpus-per-task`), the run's worker threads.
    #[arg(long, value_name = "N", default_value = "2")]
    cpus_per_task: usize,
    /// Time limit per task (`#SBATCH --time`); a task stopped at it resumes when submitted again.
    #[arg(long, value_name = "D-HH:MM:SS", default_value = "04:00:00")]
    time: String,
    /// Partition (`#SBATCH --partition`).
    #[arg(long)]
    partition: Option<String>,
}

#[derive(Subcommand)]
enum PlanKind {
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
enum KernelArg {
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
enum StudyKind {
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

fn main() {
    tune_allocator();
    let cli = Cli::parse();
    let code = match cli.command {
        Command::Run(args) => args.run(),
        Command::List { fidelity } => list(fidelity),
        Command::Check {
            scene,
            strict,
            sample_steps,
            threads,
        } => exit_of(check_scene(&scene, strict, sample_steps, threads)),
        Command::Case { names, suite } => exit_of(run_suite(&suite.options(), Some(&names), None)),
        Command::All { suite, compare } => {
            exit_of(run_suite(&suite.options(), None, compare.as_deref()))
        }
        Command::Report { out } => exit_of(report(&out)),
        Command::Plan { which } => exit_of(write_plan(which)),
        Command::Task {
            plan,
            index,
            threads,
            checkpoint_minutes,
        } => {
            let opts = TaskOptions {
                threads,
                checkpoint_minutes: Some(checkpoint_minutes),
                interrupt: Some(interrupt_flag()),
                progress: true,
            };
            exit_of(plan::run_task(&plan, index, &opts).map(|()| 0))
        }
        Command::Collect { plan } => exit_of(collect(&plan)),
        Command::Sweep {
            scene,
            set,
            out,
            threads,
        } => exit_of(sweep(&scene, &set, &out, threads)),
        Command::LatticeModuli {
            kernel,
            h_over_l0,
            re_over_l0,
            order,
        } => {
            let kernels: Vec<KernelKind> = kernel.into_iter().map(KernelKind::from).collect();
            print!(
                "{}",
                lattice_moduli::table(&kernels, &h_over_l0, &re_over_l0, &order)
            );
            0
        }
        Command::Measure { run_dir } => exit_of(measure_run(&run_dir)),
        Command::SurfaceStress { lists } => {
            let settings = surface_stress_settings(lists);
            print!("{}", surface_stress::table(&settings));
            0
        }
        Command::SlabTension {
            scene,
            lists,
            thickness_over_l0,
            crossings,
        } => {
            let design = SlabDesign {
                thickness_over_l0,
                crossings,
                averaged_crossings: crossings / 4.0,
                ..SlabDesign::default()
            };
            exit_of(slab_tension_table(&scene, design, lists))
        }
        Command::Study {
            which:
                StudyKind::AccuracyCost {
                    grid,
                    out,
                    force,
                    threads,
                    max_particles,
                },
        } => {
            let opts = StudyOptions {
                grid,
                out,
                force,
                threads,
                max_particles,
            };
            exit_of(study(&opts))
        }
    };
    std::process::exit(code);
}

/// Prints every case: title, source, effects, and its runs and resolution at `fidelity`.
fn list(fidelity: Fidelity) -> i32 {
    for case in cases::all() {
        println!("{:<24} {}", case.name(), case.title());
        println!("{:<24} source: {}", "", case.source());
        println!(
            "{:<24} effects: {}",
            "",
            verify::suite::DeclaredEffects::describe_declared(case.effects())
        );
        let runs: Vec<String> = case.runs(fidelity).iter().map(|r| r.id.clone()).collect();
        println!("{:<24} {} runs: {}", "", fidelity.name(), runs.join(" "));
        println!("{:<24} resolution: {}", "", case.resolution(fidelity));
    }
    0
}

/// Runs the named cases (or all) and writes the summaries; the exit code.
fn run_suite(
    opts: &SuiteOptions,
    names: Option<&[String]>,
    baseline: Option<&Path>,
) -> anyhow::Result<i32> {
    let cases = cases::all();
    if let Some(names) = names {
        for n in names {
            if !cases.iter().any(|c| c.name() == n) {
                let known: Vec<&str> = cases.iter().map(|c| c.name()).collect();
                eprintln!("error: no case named {n:?}; cases: {}", known.join(", "));
                return Ok(2);
            }
        }
    }
    runner::write_record(&opts.out, opts.fidelity)?;
    let mut tally = verify::suite::tally::RunTally::default();
    for case in &cases {
        if names.is_some_and(|n| !n.iter().any(|x| x == case.name())) {
            continue;
        }
        let specs = runner::specs_of(case.as_ref(), opts)?;
        let finished: Vec<bool> = specs
            .iter()
            .map(|s| !opts.force && runner::is_finished(&opts.out, case.as_ref(), s))
            .collect();
        let metrics = runner::run_case(case.as_ref(), opts)?;
        for (spec, reused) in specs.iter().zip(finished) {
            tally.add(&runner::run_dir(&opts.out, case.as_ref(), spec), reused);
        }
        let judged = metrics.iter().filter(|m| m.pass().is_some()).count();
        let passed = metrics.iter().filter(|m| m.pass() == Some(true)).count();
        eprintln!(
            "{}: {passed}/{judged} judged metrics within tolerance",
            case.name()
        );
    }
    let regressions = summary::write_all(&opts.out, opts.fidelity, &cases, baseline)?;
    eprintln!("{}", tally.describe());
    eprintln!(
        "summary: {} (written by revision {})",
        opts.out.join("summary.md").display(),
        env!("GIT_REVISION")
    );
    if let Some(r) = regressions {
        if !r.is_empty() {
            eprintln!("{} metric(s) worse than the baseline:", r.len());
            for x in &r {
                eprintln!("  {} / {}: {}", x.case, x.name, x.message);
            }
            return Ok(4);
        }
        eprintln!("no metric worse than the baseline");
    }
    Ok(0)
}

fn report(out: &Path) -> anyhow::Result<i32> {
    let record = runner::read_record(out)?;
    let cases = cases::all();
    for case in &cases {
        if out.join(case.name()).exists() {
            runner::analyse_case(case.as_ref(), record.fidelity, out)?;
        }
    }
    summary::write_all(out, record.fidelity, &cases, None)?;
    eprintln!("summary: {}", out.join("summary.md").display());
    Ok(0)
}

/// `verify check`: the findings, the step estimate and a timed sample of `sample_steps` steps.
/// Exit as `run` would: 2 when the scene cannot be built (e.g. overlapping bodies) and under
/// `strict` with findings, else 1 when the sample stops on an error; the first finding is named
/// with a failing sample, as its likely cause.
fn check_scene(
    path: &Path,
    strict: bool,
    sample_steps: u64,
    threads: Option<usize>,
) -> anyhow::Result<i32> {
    let scene = match load_scene(path) {
        Ok(s) => s,
        Err(e) => {
            eprintln!("error: {e}");
            return Ok(e.exit_code());
        }
    };
    let d = &scene.discretisation;
    println!(
        "{}: l0 = {:e} m, h = {:e} m, r_e = {:e} m, c = {} m/s, {} liquid(s), {} body(ies), {} wall(s)",
        path.display(),
        d.l0,
        scene.h(),
        scene.r_e(),
        d.sound_speed,
        scene.liquids.len(),
        scene.bodies.len(),
        scene.walls.len()
    );
    match preflight::step_estimate(&scene) {
        Ok(e) => println!(
            "time step: {:.3e} s ({}), {:.3e} steps to t = {:e} s",
            e.dt_s, e.limited_by, e.steps, scene.time.end
        ),
        Err(e) => println!("time step: not estimated ({e})"),
    }
    let findings = preflight::check(&scene);
    if findings.is_empty() {
        println!("no findings");
    }
    for f in &findings {
        println!("warning: {f}");
    }
    if sample_steps > 0 {
        let mut pool = rayon::ThreadPoolBuilder::new();
        if let Some(n) = threads {
            pool = pool.num_threads(n);
        }
        // a sample that fails is what the run would do: the check fails as the run would
        match pool.build()?.install(|| sample(&scene, sample_steps)) {
            Ok(()) => {}
            Err(e) => {
                let built = e.downcast_ref::<SampleStepError>().is_some();
                // the finding's first sentence: what was flagged, before its cause and fix
                let findings_first = findings.first().map_or(String::new(), |f| {
                    let text = f.to_string();
                    let what = text.split(". Likely cause").next().unwrap_or(&text);
                    format!(" — flagged before step 1: {what}")
                });
                if built {
                    println!("sample: the run fails{findings_first}: {e:#}");
                    // `--strict` refuses the scene before any step, as `run --strict` does
                    return Ok(if strict && !findings.is_empty() { 2 } else { 1 });
                }
                println!("the scene cannot be built: {e:#}");
                return Ok(2);
            }
        }
    }
    Ok(if strict && !findings.is_empty() { 2 } else { 0 })
}

/// A sampled step stopped on an error (the scene was built).
#[derive(Debug)]
struct SampleStepError(String);

impl std::fmt::Display for SampleStepError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for SampleStepError {}

/// Builds `scene`'s particles, times `steps` steps on the current thread pool, and prints the
/// particles, neighbours, the rate, the whole run's estimated wall time, and the sample's memory.
fn sample(scene: &solver::Scene, steps: u64) -> anyhow::Result<()> {
    let before = verify::output::run_info::peak_memory_bytes();
    let mut sim = solver::Simulation::new(scene)?;
    let n = sim.particles.n_fluid;
    println!("machine: {}", verify::output::machine::describe());
    println!(
        "particles: {n} fluid, {} wall; {} threads",
        sim.particles.n_wall(),
        rayon::current_num_threads()
    );
    let t0 = std::time::Instant::now();
    let mut taken = 0;
    while taken < steps && sim.time_s < scene.time.end {
        sim.step(scene.time.end - sim.time_s)
            .map_err(|e| SampleStepError(e.to_string()))?;
        taken += 1;
    }
    let wall = t0.elapsed().as_secs_f64();
    let rate = (taken as f64 * n as f64) / wall.max(1e-9);
    let total_steps = scene.time.end / sim.next_dt();
    println!(
        "sample: {taken} steps in {wall:.2} s, {rate:.3e} particle-steps/s, {:.0} neighbours per particle; the whole run: about {total_steps:.3e} steps, {:.3e} s wall on this machine",
        sim.mean_neighbours(),
        total_steps * n as f64 / rate
    );
    if let (Some(b), Some(a)) = (before, verify::output::run_info::peak_memory_bytes()) {
        println!(
            "memory: {:.0} MB peak over the sample, {:.0} B per particle (fluid and wall) above the {:.0} MB the program holds before the scene; a whole run peaks higher, as the allocator's heap grows over it (measured in reports/performance.md)",
            a as f64 / 1e6,
            a.saturating_sub(b) as f64 / (n + sim.particles.n_wall()).max(1) as f64,
            b as f64 / 1e6
        );
    }
    Ok(())
}

/// `verify slab-tension`: the settings are the scene's own unless given.
fn slab_tension_table(
    scene: &Path,
    design: SlabDesign,
    lists: SettingLists,
) -> anyhow::Result<i32> {
    let sc = load_scene(scene)?;
    let d = &sc.discretisation;
    let defaults = (d.kernel, d.h_over_l0, d.re_over_l0, d.potential_order);
    let settings: Vec<slab_tension::Setting> = settings_product(lists, defaults)
        .into_iter()
        .map(|(kernel, h, re, order)| slab_tension::Setting {
            kernel,
            h_over_l0: h,
            re_over_l0: re,
            order,
        })
        .collect();
    print!("{}", slab_tension::table(&sc, &settings, design)?);
    Ok(0)
}

/// A flag set by Ctrl-C, SIGTERM or SIGHUP (the handler is installed once per process).
fn interrupt_flag() -> Arc<AtomicBool> {
    static FLAG: std::sync::OnceLock<Arc<AtomicBool>> = std::sync::OnceLock::new();
    FLAG.get_or_init(|| {
        let flag = Arc::new(AtomicBool::new(false));
        let f = flag.clone();
        let _ = ctrlc::set_handler(move || f.store(true, Ordering::SeqCst));
        flag
    })
    .clone()
}

fn exit_of(r: anyhow::Result<i32>) -> i32 {
    match r {
        Ok(code) => code,
        Err(e) if e.downcast_ref::<plan::InputError>().is_some() => {
            eprintln!("error: {e}");
            2
        }
        Err(e) if e.downcast_ref::<runner::Interrupted>().is_some() => {
            eprintln!("{e}");
            130
        }
        Err(e) => {
            eprintln!("error: {e:#}");
            3
        }
    }
}

/// Runs the study with this very binary for each point; the exit code.
fn study(opts: &StudyOptions) -> anyhow::Result<i32> {
    // Ctrl-C or SIGTERM reach the running point's own process, which checkpoints and exits
    // 130; this one waits for it instead of dying first
    let _ = interrupt_flag();
    run_all(opts, &std::env::current_exe()?)?;
    Ok(0)
}

/// `verify plan …`: writes the plan and says how to run it.
fn write_plan(which: PlanKind) -> anyhow::Result<i32> {
    let (kind, tasks, args) = match which {
        PlanKind::Suite {
            names,
            fidelity,
            set,
            strict,
            plan: args,
        } => {
            let (k, t) = plan::suite_tasks(fidelity, &names, &set, strict)?;
            (k, t, args)
        }
        PlanKind::Study {
            grid,
            max_particles,
            plan: args,
        } => {
            let (k, t) = plan::study_tasks(grid, max_particles);
            (k, t, args)
        }
        PlanKind::Sweep {
            scene,
            set,
            plan: args,
        } => {
            let base = load_scene(&scene).map_err(|e| plan::InputError(e.to_string()))?;
            let (k, t) = plan::sweep_tasks(&base, &scene.to_string_lossy(), &set)?;
            (k, t, args)
        }
    };
    let slurm = plan::SlurmOptions {
        exe: std::env::current_exe()?,
        cpus_per_task: args.cpus_per_task,
        time: args.time,
        partition: args.partition,
    };
    let p = plan::write_plan(&args.out, kind, tasks, &slurm, args.force)?;
    let d = args.out.display();
    println!("{d}: {} task(s)", p.tasks.len());
    println!(
        "  one task:   verify task {d} --index N   (N = 0 … {})",
        p.tasks.len() - 1
    );
    println!("  on SLURM:   bash {d}/submit.sh");
    println!("  then:       verify collect {d}");
    Ok(0)
}

/// `verify collect PLAN`: the summaries; exit 5 if some tasks are not finished.
fn collect(dir: &Path) -> anyhow::Result<i32> {
    let c = plan::collect(dir)?;
    eprintln!("summary: {}", c.summary.display());
    if c.unfinished.is_empty() {
        return Ok(0);
    }
    eprintln!(
        "{} task(s) not finished, left out: {}",
        c.unfinished.len(),
        c.unfinished.join(", ")
    );
    Ok(5)
}

/// `verify sweep`: the plan, every task in order, the collection.
fn sweep(scene: &Path, set: &[String], out: &Path, threads: Option<usize>) -> anyhow::Result<i32> {
    let base = load_scene(scene).map_err(|e| plan::InputError(e.to_string()))?;
    let (kind, tasks) = plan::sweep_tasks(&base, &scene.to_string_lossy(), set)?;
    let slurm = plan::SlurmOptions {
        exe: std::env::current_exe()?,
        cpus_per_task: threads.unwrap_or(2),
        time: "04:00:00".into(),
        partition: None,
    };
    let p = plan::write_plan(out, kind, tasks, &slurm, false)?;
    let opts = TaskOptions {
        threads,
        checkpoint_minutes: Some(10.0),
        interrupt: Some(interrupt_flag()),
        progress: true,
    };
    for (k, t) in p.tasks.iter().enumerate() {
        eprintln!("[{}/{}] {}", k + 1, p.tasks.len(), t.label);
        plan::run_task(out, k, &opts)?;
    }
    collect(out)
}

/// The settings of `surface-stress`: with no list given, the study's variants; else the
/// product of the lists given, each defaulting to the study's default.
fn surface_stress_settings(lists: SettingLists) -> Vec<(KernelKind, f64, f64, u8)> {
    let l = &lists;
    if l.kernel.is_empty()
        && l.h_over_l0.is_empty()
        && l.re_over_l0.is_empty()
        && l.order.is_empty()
    {
        let mut v: Vec<(KernelKind, f64, f64, u8)> = verify::study::Grid::Standard
            .variants()
            .iter()
            .map(|v| (v.kernel, v.h_over_l0, v.re_over_l0, v.potential_order))
            .collect();
        v.dedup();
        return v;
    }
    let d = verify::study::Variant::DEFAULT;
    let defaults = (d.kernel, d.h_over_l0, d.re_over_l0, d.potential_order);
    settings_product(lists, defaults)
}

/// Every combination (kernel, h/l0, r_e/l0, order) of the lists given; an empty list stands
/// for its value in `defaults`.
fn settings_product(
    lists: SettingLists,
    defaults: (KernelKind, f64, f64, u8),
) -> Vec<(KernelKind, f64, f64, u8)> {
    let SettingLists {
        kernel,
        h_over_l0,
        re_over_l0,
        order,
    } = lists;
    let or = |v: Vec<f64>, x: f64| if v.is_empty() { vec![x] } else { v };
    let kernels: Vec<KernelKind> = if kernel.is_empty() {
        vec![defaults.0]
    } else {
        kernel.into_iter().map(KernelKind::from).collect()
    };
    let (hs, res) = (or(h_over_l0, defaults.1), or(re_over_l0, defaults.2));
    let orders = if order.is_empty() {
        vec![defaults.3]
    } else {
        order
    };
    let mut out = Vec::new();
    for &k in &kernels {
        for &h in &hs {
            for &re in &res {
                for &m in &orders {
                    out.push((k, h, re, m));
                }
            }
        }
    }
    out
}

/// `verify measure`: the measures of a user's run, and where they went.
fn measure_run(dir: &Path) -> anyhow::Result<i32> {
    let m = verify::run_measures::write(dir)?;
    if let Some(last) = m.rows.last() {
        eprintln!(
            "measured {} snapshots: at t = {:.4e} s height {:.4} mm, wetted radius {:.4} mm, angle {:.1}°",
            m.rows.len() / m.liquids.len().max(1),
            last.time_s,
            last.height_m * 1e3,
            last.wetted_radius_m * 1e3,
            last.angle_deg
        );
    }
    if let Some((h, a, theta)) = m.equilibrium {
        eprintln!(
            "Young–Laplace for the scene's volume: height {:.4} mm, wetted radius {:.4} mm at {theta}°",
            h * 1e3,
            a * 1e3
        );
    }
    eprintln!(
        "wrote {}, {} and {}",
        dir.join("measures.csv").display(),
        dir.join("measures_size.png").display(),
        dir.join("measures_angle.png").display()
    );
    Ok(0)
}
