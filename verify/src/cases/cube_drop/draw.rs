//! The cube drop's plots: the period and the damping against c², and the widths over time.

use super::judge::{lamb, Lamb};
use super::measure::CubeRun;
use super::{c2_values, paper_values};
use crate::report::plot::{self, Plot, Series, SeriesKind};
use crate::suite::Fidelity;
use std::path::Path;

/// Draws every plot of the case into `dir`.
pub fn plots(f: Fidelity, runs: &[CubeRun], dir: &Path) -> anyhow::Result<()> {
    let lamb = lamb();
    let c2s = c2_values(f);
    let c2_range = (
        c2s.first().copied().unwrap_or(0.0) * 0.8,
        c2s.last().copied().unwrap_or(1.0) * 1.1,
    );
    period_vs_c2(runs, &lamb, c2_range, dir)?;
    widths(runs, &lamb, dir)?;
    damping_vs_c2(runs, &lamb, c2_range, dir)
}

/// A horizontal dashed line at `y` across `(lo, hi)`.
fn level(label: &str, (lo, hi): (f64, f64), y: f64) -> Series {
    Series {
        label: label.into(),
        points: vec![(lo, y), (hi, y)],
        kind: SeriesKind::Dashed,
        color: 0,
    }
}

fn period_vs_c2(
    runs: &[CubeRun],
    lamb: &Lamb,
    c2_range: (f64, f64),
    dir: &Path,
) -> anyhow::Result<()> {
    let paper: Vec<(f64, f64)> = paper_values::list("cube_drop", "c2_m2_s2")
        .into_iter()
        .zip(paper_values::list("cube_drop", "period_ms"))
        .collect();
    let width: Vec<(f64, f64)> = runs
        .iter()
        .map(|m| (m.c2_m2_s2, m.oscillation.width_period_and_damping().0 * 1e3))
        .collect();
    let q4: Vec<(f64, f64)> = runs
        .iter()
        .filter_map(|m| Some((m.c2_m2_s2, m.oscillation.q4_fit.as_ref()?.period_s * 1e3)))
        .collect();
    let points = |label: &str, points, kind, color| Series {
        label: String::from(label),
        points,
        kind,
        color,
    };
    plot::draw(
        &Plot {
            title: "Cube drop: l = 4 period against the sound speed".into(),
            x_label: "c² [m²/s²]".into(),
            y_label: "full period [ms]".into(),
            series: vec![
                level(
                    "Lamb (1932), equal-volume sphere",
                    c2_range,
                    lamb.period_s * 1e3,
                ),
                points("Natsui 2021, Table A-1", paper, SeriesKind::Markers, 1),
                points(
                    "this project (width fit)",
                    width,
                    SeriesKind::LineMarkers,
                    2,
                ),
                points("this project (Q4 fit)", q4, SeriesKind::Markers, 3),
            ],
            x_range: None,
            y_range: None,
            hlines: vec![],
        },
        &dir.join("period_vs_c2"),
    )
}

fn widths(runs: &[CubeRun], lamb: &Lamb, dir: &Path) -> anyhow::Result<()> {
    let series = runs
        .iter()
        .enumerate()
        .map(|(k, m)| Series {
            label: format!("c² = {:.0} m²/s²", m.c2_m2_s2),
            points: m
                .oscillation
                .t_s
                .iter()
                .zip(&m.oscillation.width_m)
                .map(|(a, b)| (a * 1e3, b * 1e3))
                .collect(),
            kind: SeriesKind::Line,
            color: k,
        })
        .collect();
    plot::draw(
        &Plot {
            title: "Cube drop: width (mean of the x, y, z extents)".into(),
            x_label: "t [ms]".into(),
            y_label: "width [mm]".into(),
            series,
            x_range: None,
            y_range: None,
            hlines: vec![(
                2.0 * lamb.radius_m * 1e3,
                "sphere diameter (equal volume)".into(),
            )],
        },
        &dir.join("width"),
    )
}

fn damping_vs_c2(
    runs: &[CubeRun],
    lamb: &Lamb,
    c2_range: (f64, f64),
    dir: &Path,
) -> anyhow::Result<()> {
    let gamma: Vec<(f64, f64)> = runs
        .iter()
        .map(|m| (m.c2_m2_s2, m.oscillation.width_period_and_damping().1))
        .collect();
    plot::draw(
        &Plot {
            title: "Cube drop: amplitude decay rate".into(),
            x_label: "c² [m²/s²]".into(),
            y_label: "γ [1/s]".into(),
            series: vec![
                level(
                    "Lamb, physical viscosity only",
                    c2_range,
                    lamb.damping_per_s,
                ),
                Series {
                    label: "this project".into(),
                    points: gamma,
                    kind: SeriesKind::LineMarkers,
                    color: 2,
                },
            ],
            x_range: None,
            y_range: None,
            hlines: vec![],
        },
        &dir.join("damping_vs_c2"),
    )
}
