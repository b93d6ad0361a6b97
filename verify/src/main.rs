//! `verify`: run scenes and reproduce the papers' checks. Exit codes are listed in docs/user-guide.md.

mod cli;

use clap::Parser;
use cli::args::{Cli, Command, StudyKind};
use cli::commands::{
    check_scene, collect, list, measure_run, report, run_suite, slab_tension_table, study,
    surface_stress_settings, sweep, write_plan,
};
use cli::{exit_of, interrupt_flag};
use solver::kernel::KernelKind;
use solver::simulation::calibration::SlabDesign;
use verify::diagnostics::{curvature, lattice_moduli, mode_stiffness, surface_stress};
use verify::plan::{self, TaskOptions};
use verify::study::StudyOptions;

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

/// A command piped into a reader that stops early (`verify list | head`) ends quietly, as Unix
/// tools do, instead of panicking on the closed pipe: Rust ignores SIGPIPE by default, so every
/// `print!` after the reader has gone fails with EPIPE and panics. Restoring the default action
/// makes the write end the process (runs write their records to files, which raise no SIGPIPE).
fn end_quietly_on_a_closed_pipe() {
    #[cfg(unix)]
    // SAFETY: restores a signal's default action; called before any thread is started.
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
    }
}

fn main() {
    tune_allocator();
    end_quietly_on_a_closed_pipe();
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
        Command::Case {
            names,
            suite,
            compare,
        } => exit_of(run_suite(
            &suite.options(),
            Some(&names),
            compare.as_deref(),
        )),
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
        Command::Curvature {
            re_over_l0,
            r_over_l0,
            jitter,
        } => {
            print!("{}", curvature::table(&re_over_l0, &r_over_l0, jitter));
            0
        }
        Command::Stiffness {
            model,
            re_over_l0,
            r_over_l0,
            jitter,
            eps,
            band,
        } => {
            print!(
                "{}",
                mode_stiffness::table(&model, &re_over_l0, &r_over_l0, jitter, eps, band)
            );
            0
        }
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
