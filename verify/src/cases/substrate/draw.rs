//! Paper B's plots: time histories of the probes and views of particle dumps.

use crate::output::dump::Dump;
use crate::report::plot::{self, ParticleView, Plot, Series, SeriesKind};
use crate::suite::RunData;
use std::path::Path;

/// Draws time histories `(values, label)` against `t_s` [s] (shown in ms), with horizontal
/// reference lines `(y, label)`, into `stem`.svg/png.
pub fn draw_history(
    t_s: &[f64],
    series: &[(&[f64], &str)],
    title: String,
    y_label: &str,
    hlines: Vec<(f64, String)>,
    y_range: Option<(f64, f64)>,
    stem: &Path,
) -> anyhow::Result<()> {
    let series = series
        .iter()
        .enumerate()
        .map(|(k, (y, label))| Series {
            label: label.to_string(),
            points: t_s.iter().map(|t| t * 1e3).zip(y.iter().copied()).collect(),
            kind: SeriesKind::Line,
            color: k,
        })
        .collect();
    plot::draw(
        &Plot {
            title,
            x_label: "t [ms]".into(),
            y_label: y_label.into(),
            series,
            hlines,
            y_range,
            ..Default::default()
        },
        stem,
    )
}

/// Speed classes of the snapshots [m/s] (upper bounds).
const SPEED_BINS_M_S: [f64; 2] = [0.02, 0.1];

/// Draws a particle dump as a side view (slice |y − y_c| < l0 through the liquid's centroid,
/// x horizontal) or, with `top`, as a bird's-eye view (all liquid particles projected on the
/// plate, x horizontal, y vertical), coloured by speed; the plate within `plate_x_mm` [mm].
pub fn draw_view(
    dump: &Dump,
    l0_m: f64,
    title: String,
    plate_x_mm: (f64, f64),
    top: bool,
    stem: &Path,
) -> anyhow::Result<()> {
    let fluid: Vec<usize> = (0..dump.pos.len()).filter(|&i| !dump.wall[i]).collect();
    let yc = fluid.iter().map(|&i| dump.pos[i][1]).sum::<f64>() / fluid.len().max(1) as f64;
    let class = |i: usize| {
        if dump.wall[i] {
            return 3;
        }
        let v = dump.vel[i];
        let s = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        SPEED_BINS_M_S.iter().filter(|&&b| s >= b).count()
    };
    let points: Vec<(f64, f64, usize)> = (0..dump.pos.len())
        .filter(|&i| {
            let x = dump.pos[i];
            if top {
                !dump.wall[i]
            } else {
                (x[1] - yc).abs() < l0_m
                    && (!dump.wall[i] || (x[0] * 1e3 >= plate_x_mm.0 && x[0] * 1e3 <= plate_x_mm.1))
            }
        })
        .map(|i| {
            let x = dump.pos[i];
            let v = if top { x[1] } else { x[2] };
            (x[0] * 1e3, v * 1e3, class(i))
        })
        .collect();
    let [a, b] = SPEED_BINS_M_S;
    plot::draw_particles(
        &ParticleView {
            title,
            x_label: "x [mm]".into(),
            y_label: if top { "y [mm]" } else { "z [mm]" }.into(),
            points,
            categories: vec![
                format!("|v| < {a} m/s"),
                format!("{a}–{b} m/s"),
                format!("> {b} m/s"),
                "plate".into(),
            ],
            rects: vec![],
            marker_px: if top { 2 } else { 4 },
        },
        stem,
    )
}

/// A run's snapshots and its final state, `(time [s], dump)`, in time order.
pub fn states(run: &RunData) -> impl Iterator<Item = (f64, &Dump)> {
    (run.snapshots.iter().map(|(t, d)| (*t, d)))
        .chain(std::iter::once((run.last.time_s, &run.last)))
}
