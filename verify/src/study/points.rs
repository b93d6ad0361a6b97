//! Running and measuring the study's points.

use super::grid::{Point, Problem};
use crate::analytic::young_laplace;
use crate::measure::oscillation;
use crate::output::run_info::{RunInfo, Status};
use crate::output::timeseries::{Axis, LiquidColumn, RunColumn, Table};
use crate::run::{RunError, RunOptions, Saved};
use crate::suite::runner::Interrupted;
use anyhow::Context;
use serde::{Deserialize, Serialize};
use std::path::Path;
use std::process::{Command, Stdio};

/// What one point measured and cost.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct PointResult {
    /// The point.
    pub point: Point,
    /// `l0` [m].
    pub l0_m: f64,
    /// Fluid particles.
    pub particles: usize,
    /// Measured period [s] or height [m].
    pub value: f64,
    /// Analytic value (Lamb period [s] or Young–Laplace height [m]).
    pub reference: f64,
    /// `(value − reference)/reference` [-].
    pub relative_error: f64,
    /// Wall time of the time loop [s].
    pub wall_time_s: f64,
    /// Particle-steps per second [1/s].
    pub particle_steps_per_second: f64,
    /// Mean neighbours per particle within the largest cut-off, max(2h, r_e) (skin excluded).
    pub mean_neighbours: f64,
    /// Peak resident memory of the run's process [bytes].
    pub peak_memory_bytes: Option<u64>,
    /// The machine the run started on (CPU model, cores, vector extensions), if recorded.
    #[serde(default)]
    pub machine: Option<String>,
    /// Simulated time of the run [s].
    #[serde(default)]
    pub simulated_time_s: f64,
    /// `completed`, `failed: …` or `not measurable: …`.
    pub status: String,
}

/// Runs `point` in its own `verify run` process (unless a finished run of the same scene is in
/// its folder and `force` is off; a stopped one with a checkpoint is resumed), then measures
/// it. A point stopped by Ctrl-C or SIGTERM (exit 130) stops the study: the same command
/// resumes it.
pub fn run_point(
    point: &Point,
    out: &Path,
    exe: &Path,
    threads: Option<usize>,
    force: bool,
) -> anyhow::Result<PointResult> {
    let dir = out.join(point.id());
    let scene = point.scene();
    let saved = crate::run::saved(&dir, &scene);
    let resumable = saved == Saved::Stopped;
    if force || saved != Saved::Finished {
        let mut cmd = Command::new(exe);
        cmd.arg("run");
        if resumable && !force {
            cmd.arg("--resume").arg(&dir);
        } else {
            std::fs::create_dir_all(&dir)?;
            let scene_file = dir.with_extension("toml");
            std::fs::write(&scene_file, toml::to_string(&scene)?)?;
            cmd.arg(&scene_file).arg("--out").arg(&dir).arg("--force");
        }
        if let Some(n) = threads {
            cmd.arg("--threads").arg(n.to_string());
        }
        // a point that blows up is a result (status failed), not an error of the study
        let status = cmd
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .status()
            .with_context(|| format!("running {}", exe.display()))?;
        if status.code() == Some(130) {
            return Err(anyhow::Error::new(Interrupted(format!(
                "study point {}",
                point.id()
            ))));
        }
    }
    measure(point, &dir)
}

/// Runs `point` in this process into `OUT/ID` with `opts` (its `out_dir` is set here): skipped
/// if finished, resumed if stopped with a checkpoint — the way a plan's task runs it, so that a
/// scheduler's signal reaches the run itself. Returns whether it simulated.
pub fn run_point_here(point: &Point, out: &Path, opts: &RunOptions) -> anyhow::Result<bool> {
    let dir = out.join(point.id());
    std::fs::create_dir_all(&dir)?;
    let scene_file = dir.with_extension("toml");
    crate::output::atomic_write(&scene_file, toml::to_string(&point.scene())?.as_bytes())?;
    let opts = RunOptions {
        out_dir: dir,
        ..opts.clone()
    };
    match crate::run::ensure(&point.scene(), &scene_file, &opts) {
        Ok(ran) => Ok(ran.is_some()),
        Err(RunError::Interrupted(_)) => Err(anyhow::Error::new(Interrupted(format!(
            "study point {}",
            point.id()
        )))),
        // a point that blows up is a result (status failed), not an error of the study
        Err(RunError::Simulation(_)) => Ok(true),
        Err(e) => Err(anyhow::anyhow!("study point {}: {e}", point.id())),
    }
}

/// The settled height of a drop on the plate [m]: its highest particle centre + l0/2 (the wall
/// surface at z = 0), mean over the last quarter of the run; `None` without output.
fn settled_top(ts: &Table, l0: f64) -> Option<f64> {
    let top = ts.liquid_column("matte", LiquidColumn::Max(Axis::Z));
    let tail = &top[top.len() * 3 / 4..];
    (!tail.is_empty()).then(|| tail.iter().sum::<f64>() / tail.len() as f64 + 0.5 * l0)
}

/// Measures a finished point from its folder.
pub fn measure(point: &Point, dir: &Path) -> anyhow::Result<PointResult> {
    let info = RunInfo::read(dir)?;
    let ts = Table::read(&dir.join("timeseries.csv"))?;
    let reference = point.reference();
    let l0 = point.l0();
    let t = ts.run_column(RunColumn::Time);
    let (value, why) = match point.problem {
        Problem::CubeDrop | Problem::CubeDamping => {
            let q4 = ts.liquid_column("matte", LiquidColumn::Q4);
            // skip the corners' collapse (0.2 ms), as the cube_drop case does
            let from = t.iter().position(|&x| x >= 2e-4).unwrap_or(0);
            match oscillation::fit_damped_cosine(&t[from..], &q4[from..]) {
                Ok(f) if point.problem == Problem::CubeDrop => (f.period_s, None),
                Ok(f) => (f.damping_rate_per_s, None),
                Err(e) => (f64::NAN, Some(e)),
            }
        }
        Problem::SessileDrop => match settled_top(&ts, l0) {
            Some(top) => (top, None),
            None => (f64::NAN, Some("no output".to_string())),
        },
        Problem::ContactAngle30 | Problem::ContactAngle60 => {
            // the drop's volume: its particles' rest volume l0³ (physical mass); the angle of
            // the spherical cap of that volume and the settled height
            let volume = info.fluid_particles as f64 * l0 * l0 * l0;
            match settled_top(&ts, l0)
                .and_then(|top| young_laplace::spherical_cap_angle_from_height(volume, top))
            {
                Some(theta) => (theta, None),
                None => (
                    f64::NAN,
                    Some("no spherical cap of that height".to_string()),
                ),
            }
        }
    };
    // a run that stopped has no measurement: its last state is not the answer
    let value = if info.status == Status::Completed {
        value
    } else {
        f64::NAN
    };
    let status = match (&info.status, why) {
        (Status::Completed, None) => "completed".to_string(),
        (Status::Completed, Some(e)) => format!("not measurable: {e}"),
        (s, _) => format!("{s:?}: {}", info.error.clone().unwrap_or_default()).to_lowercase(),
    };
    Ok(PointResult {
        point: *point,
        l0_m: l0,
        particles: info.fluid_particles,
        value,
        reference,
        relative_error: value / reference - 1.0,
        wall_time_s: info.wall_time_s,
        particle_steps_per_second: info.particle_steps_per_second,
        mean_neighbours: info.mean_neighbours,
        peak_memory_bytes: info.peak_memory_bytes,
        machine: info.machine.clone(),
        simulated_time_s: info.simulated_time_s,
        status,
    })
}
