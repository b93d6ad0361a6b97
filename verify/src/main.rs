//! `verify`: run scenes and reproduce the papers' checks.

use clap::{Parser, Subcommand};
use std::path::PathBuf;
use verify::run::{load_scene, run_scene, RunOptions};

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

#[derive(Subcommand)]
enum Command {
    /// Run one scene file.
    Run {
        /// The scene (TOML).
        scene: PathBuf,
        /// Output folder.
        #[arg(long)]
        out: PathBuf,
        /// Write a particle snapshot (.vtu) every N outputs.
        #[arg(long, value_name = "N")]
        vtk: Option<u32>,
        /// Worker threads (default: all cores).
        #[arg(long, value_name = "N")]
        threads: Option<usize>,
        /// Overwrite a non-empty output folder.
        #[arg(long)]
        force: bool,
    },
}

fn main() {
    let cli = Cli::parse();
    let code = match cli.command {
        Command::Run {
            scene,
            out,
            vtk,
            threads,
            force,
        } => {
            let opts = RunOptions {
                out_dir: out,
                vtk_every: vtk,
                threads,
                force,
                progress: true,
            };
            match load_scene(&scene).and_then(|s| run_scene(&s, &scene, &opts)) {
                Ok(info) => {
                    eprintln!(
                        "done: {} steps, {:.3e} s simulated, {:.1} s wall, {:.3e} particle-steps/s",
                        info.steps,
                        info.simulated_time_s,
                        info.wall_time_s,
                        info.particle_steps_per_second
                    );
                    0
                }
                Err(e) => {
                    eprintln!("error: {e}");
                    e.exit_code()
                }
            }
        }
    };
    std::process::exit(code);
}
