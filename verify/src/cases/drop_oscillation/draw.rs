//! The oscillating drop's plot: Q2 over time, normalised by its initial value, per amplitude,
//! beside the liquid's response (Rayleigh's period, Lamb's damping with ν + ν_AV).

use super::judge::reference;
use super::measure::DropRun;
use crate::report::plot::{self, Plot, Series, SeriesKind};
use std::path::Path;

/// Draws every plot of the case into `dir`.
pub fn plots(runs: &[DropRun], dir: &Path) -> anyhow::Result<()> {
    let Some(first) = runs.first() else {
        return Ok(());
    };
    let r = reference(first);
    let mut series: Vec<Series> = runs
        .iter()
        .enumerate()
        .map(|(k, m)| {
            let o = &m.oscillation;
            let q0 = o.q2.first().copied().unwrap_or(1.0);
            Series {
                label: format!("ε = {:.2}", m.amplitude),
                points: o
                    .t_s
                    .iter()
                    .zip(&o.q2)
                    .map(|(t, q)| (t / r.period_s, q / q0))
                    .collect(),
                kind: SeriesKind::Line,
                color: k + 1,
            }
        })
        .collect();
    let t_end = first.oscillation.t_s.last().copied().unwrap_or(0.0);
    let omega = std::f64::consts::TAU / r.period_s;
    series.push(Series {
        label: "liquid: Rayleigh period, Lamb damping (ν + ν_AV)".into(),
        points: (0..=400)
            .map(|k| {
                let t = t_end * k as f64 / 400.0;
                (
                    t / r.period_s,
                    (-r.damping_per_s * t).exp() * (omega * t).cos(),
                )
            })
            .collect(),
        kind: SeriesKind::Dashed,
        color: 0,
    });
    plot::draw(
        &Plot {
            title: "Free drop, l = 2: axial moment Q2 over its initial value".into(),
            x_label: "t / Rayleigh period".into(),
            y_label: "Q2 / Q2(0)".into(),
            series,
            x_range: None,
            y_range: None,
            hlines: vec![],
        },
        &dir.join("q2"),
    )
}
