//! The doublets' plots: G1G2(t), and its equilibrium, period and damping against σ12.

use super::measure::DoubletRun;
use super::{drop_volume_m3, Start, R0_M};
use crate::analytic::neumann;
use crate::report::plot::{self, Plot, Series, SeriesKind};
use std::path::Path;

/// Draws every plot of a doublet case titled `title` with surface tensions `sigma_n_m` [N/m]
/// into `dir`.
pub fn plots(
    title: &str,
    sigma_n_m: (f64, f64),
    all: &[DoubletRun],
    dir: &Path,
) -> anyhow::Result<()> {
    // the runs from touching drops: the merged starts are judged only on parting
    let touching = |csf: bool| -> Vec<&DoubletRun> {
        all.iter()
            .filter(|m| m.start == Start::Touching && m.surface_force == csf)
            .collect()
    };
    let (runs, csf) = (touching(false), touching(true));
    let runs = &runs[..];
    histories(title, runs, dir)?;
    equilibrium(sigma_n_m, runs, &csf, dir)?;
    let fitted = |y: fn(&DoubletRun) -> Option<f64>| -> Vec<(f64, f64)> {
        runs.iter()
            .filter_map(|m| Some((m.sigma12_n_m, y(m)?)))
            .collect()
    };
    against_sigma12(
        "G1G2 oscillation period against σ12",
        "full period [ms]",
        fitted(|m| Some(m.separation.fit.as_ref()?.period_s * 1e3)),
        &dir.join("period"),
    )?;
    against_sigma12(
        "G1G2 damping rate against σ12",
        "γ [1/s]",
        fitted(|m| Some(m.separation.fit.as_ref()?.damping_rate_per_s)),
        &dir.join("damping"),
    )
}

fn histories(title: &str, runs: &[&DoubletRun], dir: &Path) -> anyhow::Result<()> {
    let curves = runs
        .iter()
        .map(|m| Series {
            label: format!("σ12 = {:.1} N/m", m.sigma12_n_m),
            points: (m.separation.t_s.iter())
                .zip(&m.separation.g1g2_r0)
                .map(|(x, y)| (x * 1e3, *y))
                .collect(),
            kind: SeriesKind::Line,
            color: m.index,
        })
        .collect();
    plot::draw(
        &Plot {
            title: format!("{title}: G1G2(t)"),
            x_label: "t [ms]".into(),
            y_label: "G1G2 / R0 [-]".into(),
            series: curves,
            x_range: None,
            y_range: None,
            hlines: vec![],
        },
        &dir.join("g1g2_t"),
    )
}

/// The equilibrium against σ12: the analytic doublet, the potential's `runs` and the surface
/// force's `csf` runs (drops in a host).
fn equilibrium(
    (s1, s2): (f64, f64),
    runs: &[&DoubletRun],
    csf: &[&DoubletRun],
    dir: &Path,
) -> anyhow::Result<()> {
    let v0 = drop_volume_m3();
    let analytic_curve: Vec<(f64, f64)> = (1..=79)
        .map(|k| k as f64 * 0.01)
        .filter(|&s| s > (s1 - s2).abs() + 1e-9 && s < s1 + s2)
        .filter_map(|s| {
            neumann::doublet(s1, s2, s, v0, v0)
                .ok()
                .map(|d| (s, d.g1g2_m / R0_M))
        })
        .collect();
    let measured = |runs: &[&DoubletRun]| -> Vec<(f64, f64)> {
        runs.iter()
            .map(|m| (m.sigma12_n_m, m.separation.equilibrium))
            .collect()
    };
    let mut series = vec![
        Series {
            label: "analytic doublet (Neumann)".into(),
            points: analytic_curve,
            kind: SeriesKind::Dashed,
            color: 0,
        },
        Series {
            label: "this project (mean of last quarter)".into(),
            points: measured(runs),
            kind: SeriesKind::Markers,
            color: 2,
        },
    ];
    if !csf.is_empty() {
        series.push(Series {
            label: "surface force, in a host (mean of last quarter)".into(),
            points: measured(csf),
            kind: SeriesKind::Markers,
            color: 3,
        });
    }
    plot::draw(
        &Plot {
            title: "Equilibrium centroid distance against σ12".into(),
            x_label: "σ12 [N/m]".into(),
            y_label: "G1G2 / R0 [-]".into(),
            series,
            x_range: None,
            y_range: None,
            hlines: vec![(2.0, "touching spheres".into())],
        },
        &dir.join("g1g2_equilibrium"),
    )
}

/// This project's `points` against σ12, into `stem`.svg/png.
fn against_sigma12(
    title: &str,
    y_label: &str,
    points: Vec<(f64, f64)>,
    stem: &Path,
) -> anyhow::Result<()> {
    plot::draw(
        &Plot {
            title: title.into(),
            x_label: "σ12 [N/m]".into(),
            y_label: y_label.into(),
            series: vec![Series {
                label: "this project".into(),
                points,
                kind: SeriesKind::LineMarkers,
                color: 2,
            }],
            x_range: None,
            y_range: None,
            hlines: vec![],
        },
        stem,
    )
}
