//! The study's outputs: `points.csv`, per problem the plots of error against wall time and of
//! convergence in l0, and `summary.md` with the tables and conclusions.

use super::analysis::{convergence_order, pareto_front, words};
use super::grid::{Problem, Variant};
use super::points::PointResult;
use crate::report::plot::{self, Plot, Series, SeriesKind};
use crate::report::summary::sig;
use std::fmt::Write as _;
use std::path::Path;

/// Writes `points.csv`, the plots and `summary.md` into `out`.
pub fn write(out: &Path, results: &[PointResult], variants: &[Variant]) -> anyhow::Result<()> {
    crate::output::atomic_write(&out.join("points.csv"), &points_csv(results)?)?;
    let mut md = String::new();
    let _ = writeln!(md, "# Accuracy–cost study\n");
    let _ = writeln!(
        md,
        "Each point is one run in its own process (wall time and peak memory are its own). Error = \
         (value − reference)/reference: the cube drop's l = 4 period and amplitude decay rate \
         (damped-cosine fit of the shape moment Q4) against Lamb's (the rate with ν + α1 h c/10), \
         the sessile matte drop's equilibrium height against the Young–Laplace solution, and the \
         static angle of zero-gravity drops on 30° and 60° plates (the spherical cap of their \
         volume and height). Data: `points.csv`. Variants are labelled `kernel h/l0 r_e/l0 \
         density` (and `mM` for a potential of order M, `wr` with the liquid–wall repulsion at the \
         plate).\n"
    );
    for problem in Problem::ALL {
        let pts: Vec<&PointResult> = results
            .iter()
            .filter(|r| r.point.problem == problem)
            .collect();
        if !pts.is_empty() {
            write_problem(&mut md, out, problem, &pts, variants)?;
        }
    }
    targets_table(&mut md, results, variants);
    cheapest_table(&mut md, results, variants);
    crate::output::atomic_write(&out.join("summary.md"), md.as_bytes())?;
    Ok(())
}

/// Per variant and problem with a target: the coarsest measured resolution from which every
/// measured resolution (it and all finer) is within the liquid model's target, and its wall
/// time — which setting reaches which target, and at what cost. A setting that meets a target
/// at a coarse resolution and misses it at a finer one has not converged to it: it does not
/// count.
fn targets_table(md: &mut String, results: &[PointResult], variants: &[Variant]) {
    let problems: Vec<Problem> = Problem::ALL
        .into_iter()
        .filter(|p| p.target().is_some())
        .collect();
    let _ = writeln!(
        md,
        "## Which setting meets which target
"
    );
    let _ = writeln!(
        md,
        "The coarsest measured resolution from which every measured resolution (it and all \
         finer) is within each target of the liquid model (README, \"Targets of the liquid \
         model\"), and its wall time; \"—\" where the finest measured point misses it (or \
         failed).\n"
    );
    let head: Vec<String> = problems
        .iter()
        .map(|p| format!("{} ({})", p.name(), p.target().map_or("", |t| t.1)))
        .collect();
    let _ = writeln!(md, "| variant | {} | all |", head.join(" | "));
    let _ = writeln!(md, "|---|{}---|", "---|".repeat(problems.len()));
    for v in variants {
        let cells: Vec<Option<&PointResult>> = problems
            .iter()
            .map(|&p| {
                let tol = p.target().map_or(0.0, |t| t.0);
                coarsest_within(results, p, v, tol)
            })
            .collect();
        let text: Vec<String> = cells
            .iter()
            .map(|c| match c {
                Some(r) => format!(
                    "n{} ({:+.1} %, {:.1} s)",
                    r.point.resolution,
                    100.0 * r.relative_error,
                    r.wall_time_s
                ),
                None => "—".into(),
            })
            .collect();
        let all = if cells.iter().all(Option::is_some) {
            "**yes**"
        } else {
            "no"
        };
        let _ = writeln!(md, "| {} | {} | {all} |", v.label(), text.join(" | "));
    }
    let _ = writeln!(md);
}

/// The coarsest measured resolution of `variant` on `problem` from which every finer measured
/// one is within `tol` (relative) too; `None` if the finest misses it (a NaN misses).
fn coarsest_within<'a>(
    results: &'a [PointResult],
    problem: Problem,
    variant: &Variant,
    tol: f64,
) -> Option<&'a PointResult> {
    let mut mine: Vec<&PointResult> = (results.iter())
        .filter(|r| r.point.problem == problem && r.point.variant == *variant)
        .collect();
    mine.sort_by_key(|r| std::cmp::Reverse(r.point.resolution));
    // finest first: the last of the unbroken run within the target
    mine.iter()
        .take_while(|r| r.relative_error.abs() <= tol)
        .last()
        .copied()
}

/// Target errors a user may ask for, per problem: `(relative tolerance, in words)`.
fn target_levels(problem: Problem) -> Vec<(f64, String)> {
    let rel = |pcts: &[f64]| {
        pcts.iter()
            .map(|&p| (p / 100.0, format!("{p} %")))
            .collect::<Vec<_>>()
    };
    let deg = |at: f64, ds: &[f64]| {
        ds.iter()
            .map(|&d| (d / at, format!("±{d}°")))
            .collect::<Vec<_>>()
    };
    match problem {
        Problem::CubeDrop | Problem::SessileDrop => rel(&[1.0, 3.0, 10.0]),
        Problem::CubeDamping => rel(&[30.0, 100.0]),
        Problem::ContactAngle30 => deg(30.0, &[2.0, 4.0, 8.0]),
        Problem::ContactAngle60 => deg(60.0, &[2.0, 5.0, 10.0]),
    }
}

/// For each problem and target error, the cheapest setting (over variants, in wall time) whose
/// resolution and every finer one measured meet it, and what it costs: per particle-step, and
/// per simulated millisecond per thousand particles (to scale to a user's scene of another
/// size at the same resolution).
fn cheapest_table(md: &mut String, results: &[PointResult], variants: &[Variant]) {
    let _ = writeln!(
        md,
        "## The cheapest setting for a target error
"
    );
    let mut machines: Vec<String> = results.iter().filter_map(|r| r.machine.clone()).collect();
    machines.sort();
    machines.dedup();
    let _ = writeln!(
        md,
        "Over every variant and resolution measured: the cheapest (wall time) whose resolution \
         and every finer one measured meet the target. Costs on {} (2 threads; they scale with \
         the machine, the ratios between settings much less).\n",
        if machines.is_empty() {
            "a machine not recorded".to_string()
        } else {
            machines.join("; ")
        }
    );
    let _ = writeln!(
        md,
        "| quantity | target | setting | resolution | error | particles | wall time [s] | µs per particle-step | s per simulated ms per 1000 particles |"
    );
    let _ = writeln!(md, "|---|---|---|---|---|---|---|---|---|");
    for p in Problem::ALL {
        for (tol, words) in target_levels(p) {
            let best = variants
                .iter()
                .filter_map(|v| coarsest_within(results, p, v, tol))
                .min_by(|a, b| a.wall_time_s.total_cmp(&b.wall_time_s));
            match best {
                Some(r) => {
                    let per_ms = r.wall_time_s / (r.simulated_time_s * 1e3).max(f64::MIN_POSITIVE);
                    // an angle's error in degrees, as its target
                    let error = match p {
                        Problem::ContactAngle30 | Problem::ContactAngle60 => {
                            format!("{:+.1}°", r.value - r.reference)
                        }
                        _ => format!("{:+.1} %", 100.0 * r.relative_error),
                    };
                    let _ = writeln!(
                        md,
                        "| {} | {words} | {} | {} | {error} | {} | {:.1} | {:.2} | {:.3} |",
                        p.name(),
                        r.point.variant.label(),
                        r.point.resolution,
                        r.particles,
                        r.wall_time_s,
                        1e6 / r.particle_steps_per_second,
                        per_ms * 1000.0 / r.particles.max(1) as f64
                    );
                }
                None => {
                    let _ = writeln!(
                        md,
                        "| {} | {words} | none measured meets it | | | | | | |",
                        p.name()
                    );
                }
            }
        }
    }
    let _ = writeln!(md);
}

/// `points.csv`: one row per point.
fn points_csv(results: &[PointResult]) -> anyhow::Result<Vec<u8>> {
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record([
        "problem",
        "variant",
        "kernel",
        "h_over_l0",
        "re_over_l0",
        "potential_order",
        "wall_repulsion",
        "density",
        "resolution",
        "l0_m",
        "particles",
        "value",
        "reference",
        "relative_error",
        "wall_time_s",
        "particle_steps_per_second",
        "mean_neighbours",
        "peak_memory_bytes",
        "status",
    ])?;
    for r in results {
        let v = &r.point.variant;
        w.write_record([
            r.point.problem.name().to_string(),
            v.label(),
            v.kernel.name().to_string(),
            v.h_over_l0.to_string(),
            v.re_over_l0.to_string(),
            v.potential_order.to_string(),
            v.wall_repulsion.to_string(),
            if v.continuity {
                "continuity+shepard"
            } else {
                "summation"
            }
            .to_string(),
            r.point.resolution.to_string(),
            format!("{:e}", r.l0_m),
            r.particles.to_string(),
            format!("{:e}", r.value),
            format!("{:e}", r.reference),
            format!("{:e}", r.relative_error),
            format!("{:.3}", r.wall_time_s),
            format!("{:.4e}", r.particle_steps_per_second),
            format!("{:.1}", r.mean_neighbours),
            r.peak_memory_bytes
                .map(|b| b.to_string())
                .unwrap_or_default(),
            r.status.clone(),
        ])?;
    }
    Ok(w.into_inner()?)
}

/// The section of one problem in `summary.md` — its points, convergence orders and conclusions
/// — and its two plots (error against wall time with the Pareto front, convergence in l0).
fn write_problem(
    md: &mut String,
    out: &Path,
    problem: Problem,
    pts: &[&PointResult],
    variants: &[Variant],
) -> anyhow::Result<()> {
    let front = pareto_front(pts);
    let _ = writeln!(
        md,
        "## {} ({}; reference {})\n",
        problem.name(),
        problem.quantity(),
        sig(pts[0].reference)
    );
    point_table(md, pts, &front);
    let _ = writeln!(
        md,
        "\nConvergence order in l0 (least squares of ln|error| on ln l0):\n"
    );
    let _ = writeln!(md, "| variant | order | R² |");
    let _ = writeln!(md, "|---|---|---|");
    let mut order_series = Vec::new();
    let mut scatter = Vec::new();
    for (k, v) in variants.iter().enumerate() {
        let vp: Vec<&PointResult> = pts
            .iter()
            .copied()
            .filter(|r| r.point.variant == *v)
            .collect();
        match convergence_order(&vp) {
            Some((p, r2)) => {
                let _ = writeln!(md, "| {} | {p:.2} | {r2:.2} |", v.label());
            }
            None => {
                let _ = writeln!(md, "| {} | — (fewer than 3 measured points) | |", v.label());
            }
        }
        let finite: Vec<&PointResult> = vp
            .into_iter()
            .filter(|r| r.relative_error.is_finite() && r.relative_error != 0.0)
            .collect();
        order_series.push(log_series(v.label(), &finite, |r| r.l0_m, k));
        scatter.push(Series {
            kind: SeriesKind::Markers,
            ..log_series(v.label(), &finite, |r| r.wall_time_s.max(1e-3), k)
        });
    }
    let on_front: Vec<&PointResult> = front.iter().map(|&i| pts[i]).collect();
    scatter.push(Series {
        kind: SeriesKind::Line,
        ..log_series(
            "Pareto front".into(),
            &on_front,
            |r| r.wall_time_s.max(1e-3),
            variants.len(),
        )
    });
    let name = problem.name();
    draw(
        out,
        format!("{name}: error against wall time (2 cores)"),
        "log10(wall time [s])",
        scatter,
        &format!("{name}_error_vs_time"),
    )?;
    draw(
        out,
        format!("{name}: convergence in l0"),
        "log10(l0 [m])",
        order_series,
        &format!("{name}_convergence"),
    )?;
    let _ = writeln!(md, "\n{}\n", words(pts, &front, variants));
    let _ = writeln!(md, "Plots: [{name}_error_vs_time.png]({name}_error_vs_time.png), [{name}_convergence.png]({name}_convergence.png)\n");
    Ok(())
}

/// The table of a problem's points: error, cost, and whether each is on the Pareto `front`.
fn point_table(md: &mut String, pts: &[&PointResult], front: &[usize]) {
    let _ = writeln!(md, "| variant | resolution | particles | error | wall time [s] | particle-steps/s | neighbours | memory [B/particle] | Pareto | status |");
    let _ = writeln!(md, "|---|---|---|---|---|---|---|---|---|---|");
    for (i, r) in pts.iter().enumerate() {
        let mem = r
            .peak_memory_bytes
            .map(|b| format!("{:.0}", b as f64 / r.particles.max(1) as f64))
            .unwrap_or_else(|| "—".into());
        let _ = writeln!(
            md,
            "| {} | {} | {} | {:+.2} % | {:.1} | {:.3e} | {:.0} | {mem} | {} | {} |",
            r.point.variant.label(),
            r.point.resolution,
            r.particles,
            100.0 * r.relative_error,
            r.wall_time_s,
            r.particle_steps_per_second,
            r.mean_neighbours,
            if front.contains(&i) { "**yes**" } else { "" },
            r.status
        );
    }
}

/// A line with markers through (log10 x(point), log10 |relative error|).
fn log_series(
    label: String,
    pts: &[&PointResult],
    x: impl Fn(&PointResult) -> f64,
    color: usize,
) -> Series {
    Series {
        label,
        points: pts
            .iter()
            .map(|r| (x(r).log10(), r.relative_error.abs().log10()))
            .collect(),
        kind: SeriesKind::LineMarkers,
        color,
    }
}

/// Draws `series` against log10 |relative error| to `out/file` (PNG and SVG).
fn draw(
    out: &Path,
    title: String,
    x_label: &str,
    series: Vec<Series>,
    file: &str,
) -> anyhow::Result<()> {
    plot::draw(
        &Plot {
            title,
            x_label: x_label.into(),
            y_label: "log10(|relative error|)".into(),
            series,
            x_range: None,
            y_range: None,
            hlines: vec![],
        },
        &out.join(file),
    )
}
