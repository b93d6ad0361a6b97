//! The whole study: every point of a grid (up to a particle count) run in its own process and
//! measured, then its outputs written.

use super::points::PointResult;
use super::{points, summary, Grid, Point};
use std::io::Write as _;
use std::path::{Path, PathBuf};

/// Options of a study.
#[derive(Clone, Debug)]
pub struct StudyOptions {
    /// The points to run.
    pub grid: Grid,
    /// Output folder.
    pub out: PathBuf,
    /// Re-run finished points.
    pub force: bool,
    /// Worker threads per run (default: all cores).
    pub threads: Option<usize>,
    /// Leave out the points with more fluid particles than this (`summary.md` lists them).
    pub max_particles: Option<usize>,
}

/// The points of `grid` run (those up to `max_particles` fluid particles) and those left out.
pub fn selected(grid: Grid, max_particles: Option<usize>) -> (Vec<Point>, Vec<Point>) {
    grid.points()
        .into_iter()
        .partition(|p| max_particles.map_or(true, |m| p.estimated_particles() <= m))
}

/// Runs (or reuses) and measures every point with `exe`, the `verify` binary, reporting each
/// on stderr; writes `points.csv`, the plots and `summary.md` into `opts.out`.
pub fn run_all(opts: &StudyOptions, exe: &Path) -> anyhow::Result<()> {
    let out = &opts.out;
    std::fs::create_dir_all(out)?;
    let (all, left_out) = selected(opts.grid, opts.max_particles);
    let mut results = Vec::new();
    for (k, p) in all.iter().enumerate() {
        let r = points::run_point(p, out, exe, opts.threads, opts.force)?;
        eprintln!(
            "[{}/{}] {}: error {:+.2} %, {:.1} s, {:.3e} particle-steps/s ({})",
            k + 1,
            all.len(),
            p.id(),
            100.0 * r.relative_error,
            r.wall_time_s,
            r.particle_steps_per_second,
            r.status
        );
        results.push(r);
    }
    write_outputs(out, opts.grid, opts.max_particles, &results, &left_out)
}

/// Writes `points.csv`, the plots and `summary.md` of measured `results` into `out`, listing
/// the points `left_out` by `max_particles`.
pub fn write_outputs(
    out: &Path,
    grid: Grid,
    max_particles: Option<usize>,
    results: &[PointResult],
    left_out: &[Point],
) -> anyhow::Result<()> {
    summary::write(out, results, &grid.variants())?;
    if !left_out.is_empty() {
        // problems that share runs (the cube's period and damping) share their ids: once each
        let mut ids: Vec<String> = Vec::new();
        for p in left_out {
            let id = format!("`{}`", p.id());
            if !ids.contains(&id) {
                ids.push(id);
            }
        }
        let mut f = std::fs::OpenOptions::new()
            .append(true)
            .open(out.join("summary.md"))?;
        writeln!(
            f,
            "\n**Left out of this run** (`--max-particles {}`): {} run(s) — {}.",
            max_particles.unwrap_or(0),
            ids.len(),
            ids.join(", ")
        )?;
    }
    eprintln!("study: {}", out.join("summary.md").display());
    Ok(())
}
