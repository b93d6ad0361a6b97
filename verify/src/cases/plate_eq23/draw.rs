//! The plots of the drop on a plate: the side view of each final state, the Eq. 23 maps of
//! Fig. 3 with the simulated points, θ12 along θ31 = 90°, and measured θ12 against Eq. 23
//! from the typed and from the measured Young angles.

use super::measure::{Measured, PlateRun};
use super::SIGMA12;
use crate::analytic::eq23::{self, SolidContact};
use crate::cases::views;
use crate::report::plot::{self, Heatmap, ParticleView, Plot, Series, SeriesKind};
use std::path::Path;

/// Draws every plot of the case into `dir`, the particles seen at spacing `l0_m` [m].
pub fn plots(measured: &Measured, l0_m: f64, dir: &Path) -> anyhow::Result<()> {
    let runs = &measured.binaries;
    for m in runs {
        side_view(m, l0_m, dir)?;
    }
    for s in &measured.singles {
        side_view_of(s.run, l0_m, dir)?;
    }
    // the paper's maps and sweep: the potential's runs
    let (identical, matte_slag): (Vec<&PlateRun>, Vec<&PlateRun>) = (runs.iter())
        .filter(|m| !m.surface_force)
        .partition(|m| m.run.id.starts_with("identical"));
    map("fig3a", (0.4, 0.4), &identical, dir)?;
    map("fig3b", (0.4, 0.2), &matte_slag, dir)?;
    theta12_at_theta31_90(&identical, dir)?;
    measured_against_eq23(measured, dir)
}

/// Measured θ12 against Eq. 23's, from the typed Young angles and from the angles the single
/// drops measured; the diagonal is agreement.
fn measured_against_eq23(measured: &Measured, dir: &Path) -> anyhow::Result<()> {
    let mut typed = Vec::new();
    let mut surface_force = Vec::new();
    let mut from_measured = Vec::new();
    let mut surface_force_from_measured = Vec::new();
    for m in &measured.binaries {
        let theta = measured_theta12(m);
        if !theta.is_finite() {
            continue;
        }
        let (s1, s2) = m.sigma_n_m;
        if let Ok(eq23::SolidContact::TripleLine { theta12_deg }) =
            eq23::solid_contact(s1, s2, SIGMA12, m.theta31_deg, m.theta23_deg)
        {
            let model = if m.surface_force {
                &mut surface_force
            } else {
                &mut typed
            };
            model.push((theta12_deg, theta));
        }
        let ingredients = (
            measured.ingredient(s1, m.theta31_deg, m.surface_force),
            measured.ingredient(s2, m.theta23_deg, m.surface_force),
        );
        if let (Some(t31), Some(t23)) = ingredients {
            if let Ok(c) = eq23::solid_contact(s1, s2, SIGMA12, t31, t23) {
                let model = if m.surface_force {
                    &mut surface_force_from_measured
                } else {
                    &mut from_measured
                };
                model.push((c.theta12_deg(), theta));
            }
        }
    }
    plot::draw(
        &Plot {
            title: "θ12 measured against Eq. 23 (0°/180°: Eq. 23 has no line)".into(),
            x_label: "θ12 of Eq. 23 [deg]".into(),
            y_label: "θ12 measured [deg]".into(),
            series: vec![
                Series {
                    label: "agreement".into(),
                    points: vec![(0.0, 0.0), (180.0, 180.0)],
                    kind: SeriesKind::Dashed,
                    color: 0,
                },
                Series {
                    label: "Eq. 23 at the typed Young angles".into(),
                    points: typed,
                    kind: SeriesKind::Markers,
                    color: 1,
                },
                Series {
                    label: "Eq. 23 at the angles single drops measured".into(),
                    points: from_measured,
                    kind: SeriesKind::Markers,
                    color: 2,
                },
                Series {
                    label: "surface force (wall normal): Eq. 23 at the typed Young angles".into(),
                    points: surface_force,
                    kind: SeriesKind::Markers,
                    color: 3,
                },
                Series {
                    label: "surface force (wall normal): Eq. 23 at the angles its single drops measured".into(),
                    points: surface_force_from_measured,
                    kind: SeriesKind::Markers,
                    color: 4,
                },
            ],
            x_range: Some((0.0, 180.0)),
            y_range: Some((0.0, 180.0)),
            hlines: vec![],
        },
        &dir.join("theta12_measured_vs_eq23"),
    )
}

/// What touches the plate, in a few words for a label on the map.
fn short_words(seen: &str) -> &'static str {
    match seen {
        "liquid 2 rides on liquid 1" => "2 on 1",
        "liquid 1 rides on liquid 2" => "1 on 2",
        "no liquid on the plate" => "none",
        _ => "line",
    }
}

/// The measured θ12 [deg] of a run: NaN where none was measured.
fn measured_theta12(m: &PlateRun) -> f64 {
    match &m.theta12_deg {
        Some(Ok(theta)) => *theta,
        _ => f64::NAN,
    }
}

/// The final state, slice |y| < l0 through the axis.
fn side_view(m: &PlateRun, l0_m: f64, dir: &Path) -> anyhow::Result<()> {
    side_view_of(m.run, l0_m, dir)
}

/// The final state of `run` (one or two liquids), slice |y| < l0 through the axis.
fn side_view_of(run: &crate::suite::RunData, l0_m: f64, dir: &Path) -> anyhow::Result<()> {
    let liquids = &run.info.scene.liquids;
    let mut categories: Vec<String> = liquids.iter().map(|l| l.name.clone()).collect();
    categories.push("plate".into());
    plot::draw_particles(
        &ParticleView {
            title: format!(
                "{} at t = {:.0} ms (slice |y| < l0)",
                run.id,
                run.last.time_s * 1e3
            ),
            x_label: "x [mm]".into(),
            y_label: "z [mm]".into(),
            points: views::phase_slice(&run.last, l0_m, 2.5e-3, liquids.len()),
            categories,
            rects: vec![],
            marker_px: 4,
        },
        &dir.join(format!("side_{}", run.id)),
    )
}

/// Eq. 23's θ12 over (θ31, θ23) for surface tensions `(s1, s2)` [N/m], with `runs` on it.
fn map(name: &str, (s1, s2): (f64, f64), runs: &[&PlateRun], dir: &Path) -> anyhow::Result<()> {
    let grid: Vec<f64> = (0..=90).map(|k| k as f64 * 2.0).collect();
    let map = eq23::theta12_map(s1, s2, SIGMA12, &grid, &grid).map_err(anyhow::Error::msg)?;
    let z: Vec<Vec<Option<f64>>> = (0..grid.len())
        .map(|iy| {
            (0..grid.len())
                .map(|ix| match map[ix][iy] {
                    SolidContact::TripleLine { theta12_deg } => Some(theta12_deg),
                    _ => None,
                })
                .collect()
        })
        .collect();
    let overlay = runs
        .iter()
        .map(|m| {
            let theta = measured_theta12(m);
            let angle = if theta.is_finite() {
                format!(", θ12 = {theta:.0}°")
            } else {
                String::new()
            };
            (
                m.theta31_deg,
                m.theta23_deg,
                format!("{}{angle}", short_words(m.seen)),
            )
        })
        .collect();
    plot::draw_heatmap(
        &Heatmap {
            title: format!("Eq. 23: θ12 for σ1 = {s1}, σ2 = {s2}, σ12 = {SIGMA12} N/m; runs: line or 2 on 1 (liquid 2 rides on 1)"),
            x_label: "θ31 [deg]".into(),
            y_label: "θ23 [deg]".into(),
            x: grid.clone(),
            y: grid,
            z,
            none_label: "no solid/liquid/liquid line: one liquid spreads under the other".into(),
            z_label: "θ12 [deg]".into(),
            z_range: (0.0, 180.0),
            overlay,
        },
        &dir.join(format!("theta12_map_{name}")),
    )
}

/// θ12 along θ31 = 90° for identical liquids: Eq. 23's line and the runs where it was measured.
fn theta12_at_theta31_90(identical: &[&PlateRun], dir: &Path) -> anyhow::Result<()> {
    let line: Vec<(f64, f64)> = (0..=180)
        .map(|k| k as f64)
        .map(|th| {
            (
                th,
                eq23::solid_contact(0.4, 0.4, SIGMA12, 90.0, th)
                    .map(|c| c.theta12_deg())
                    .unwrap_or(f64::NAN),
            )
        })
        .collect();
    let measured: Vec<(f64, f64)> = identical
        .iter()
        .filter(|m| m.theta12_deg.is_some() && m.theta31_deg == 90.0)
        .map(|m| (m.theta23_deg, measured_theta12(m)))
        .collect();
    plot::draw(
        &Plot {
            title: "θ12 at θ31 = 90° (identical liquids, σ12 = 0.1 N/m)".into(),
            x_label: "θ23 [deg]".into(),
            y_label: "θ12 [deg]".into(),
            series: vec![
                Series {
                    label: "Eq. 23 (0°/180°: spreading, no line)".into(),
                    points: line,
                    kind: SeriesKind::Dashed,
                    color: 0,
                },
                Series {
                    label: "this project".into(),
                    points: measured,
                    kind: SeriesKind::Markers,
                    color: 2,
                },
            ],
            x_range: Some((0.0, 180.0)),
            y_range: Some((0.0, 180.0)),
            hlines: vec![],
        },
        &dir.join("theta12_theta31_90"),
    )
}
