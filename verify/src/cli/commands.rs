//! What each subcommand does, once its arguments are parsed; each returns the exit code.

use super::args::{PlanKind, RunArgs, SettingLists};
use super::interrupt_flag;
use solver::kernel::KernelKind;
use solver::simulation::calibration::SlabDesign;
use std::path::Path;
use verify::cases;
use verify::diagnostics::slab_tension;
use verify::plan::{self, TaskOptions};
use verify::preflight;
use verify::report::summary;
use verify::run::{self, load_scene, run_scene, RunOptions};
use verify::study::{run_all, StudyOptions};
use verify::suite::compare::Baseline;
use verify::suite::runner::{self, SuiteOptions};
use verify::suite::Fidelity;

impl RunArgs {
    /// Runs (or resumes) the scene; the exit code. Ctrl-C finishes the current step, writes a
    /// checkpoint, flushes and exits with 130.
    pub(crate) fn run(self) -> i32 {
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

/// Prints every case: title, source, effects, and its runs and resolution at `fidelity`.
pub(crate) fn list(fidelity: Fidelity) -> i32 {
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
pub(crate) fn run_suite(
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
    let ran: Vec<&str> = cases
        .iter()
        .map(|c| c.name())
        .filter(|c| names.map_or(true, |n| n.iter().any(|x| x == c)))
        .collect();
    // every chosen case's runs as `--set` makes them, refused (exit 2) before anything is
    // written or simulated if a key is unknown or a case will not take the change
    for case in cases.iter().filter(|c| ran.contains(&c.name())) {
        runner::specs_of(case.as_ref(), opts).map_err(|e| plan::InputError(format!("{e:#}")))?;
    }
    runner::write_record(&opts.out, opts.fidelity, &ran, &opts.overrides)?;
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
    let baseline = baseline.map(|path| Baseline { path, cases: names });
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

pub(crate) fn report(out: &Path) -> anyhow::Result<i32> {
    let record = runner::read_record(out)?;
    let cases = cases::all();
    for case in &cases {
        if out.join(case.name()).exists() {
            let overrides = record.overrides(case.name())?;
            runner::analyse_case(case.as_ref(), record.fidelity, out, &overrides)?;
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
pub(crate) fn check_scene(
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
pub(crate) fn slab_tension_table(
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

/// Runs the study with this very binary for each point; the exit code.
pub(crate) fn study(opts: &StudyOptions) -> anyhow::Result<i32> {
    // Ctrl-C or SIGTERM reach the running point's own process, which checkpoints and exits
    // 130; this one waits for it instead of dying first
    let _ = interrupt_flag();
    run_all(opts, &std::env::current_exe()?)?;
    Ok(0)
}

/// `verify plan …`: writes the plan and says how to run it.
pub(crate) fn write_plan(which: PlanKind) -> anyhow::Result<i32> {
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
pub(crate) fn collect(dir: &Path) -> anyhow::Result<i32> {
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
pub(crate) fn sweep(
    scene: &Path,
    set: &[String],
    out: &Path,
    threads: Option<usize>,
) -> anyhow::Result<i32> {
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
pub(crate) fn surface_stress_settings(lists: SettingLists) -> Vec<(KernelKind, f64, f64, u8)> {
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
pub(crate) fn measure_run(dir: &Path) -> anyhow::Result<i32> {
    let m = verify::run_measures::write(dir)?;
    if let Some(last) = m.rows.last() {
        eprintln!(
            "measured {} snapshots: at t = {:.4e} s height {:.4} mm, wetted radius {:.4} mm, angle {:.1}°",
            m.rows.iter().filter(|r| r.liquid == last.liquid).count(),
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
