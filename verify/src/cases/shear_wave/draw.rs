//! The shear wave's plot: `A(t)/A(0)` per run beside a liquid's `exp(−ν k² t)`.

use super::judge::reference_viscosity_m2_s;
use super::measure::WaveRun;
use crate::report::plot::{self, Plot, Series, SeriesKind};
use std::path::Path;

/// Draws every plot of the case into `dir`.
pub fn plots(runs: &[WaveRun], dir: &Path) -> anyhow::Result<()> {
    let Some(first) = runs.first() else {
        return Ok(());
    };
    let mut series: Vec<Series> = runs
        .iter()
        .enumerate()
        .map(|(k, m)| {
            let a0 = m.amplitude_m_s.first().copied().unwrap_or(1.0);
            Series {
                label: m.run.id.replace('_', " "),
                points: m
                    .t_s
                    .iter()
                    .zip(&m.amplitude_m_s)
                    .map(|(t, a)| (t * 1e3, a / a0))
                    .collect(),
                kind: SeriesKind::Line,
                color: k + 1,
            }
        })
        .collect();
    let (nu, _) = reference_viscosity_m2_s(first);
    let rate = nu * first.k_per_m * first.k_per_m;
    let t_end = first.t_s.last().copied().unwrap_or(0.0);
    series.push(Series {
        label: "liquid: exp(−ν k² t), ν = μ/ρ".into(),
        points: (0..=200)
            .map(|i| {
                let t = t_end * i as f64 / 200.0;
                (t * 1e3, (-rate * t).exp())
            })
            .collect(),
        kind: SeriesKind::Dashed,
        color: 0,
    });
    let plot = |title: &str, series: Vec<Series>, y_range: Option<(f64, f64)>, name: &str| {
        plot::draw(
            &Plot {
                title: title.into(),
                x_label: "t [ms]".into(),
                y_label: "A(t) / A(0)".into(),
                series,
                x_range: None,
                y_range,
                hlines: vec![(0.0, String::new())],
            },
            &dir.join(name),
        )
    };
    plot(
        "Shear wave in a periodic box: amplitude of the sin(kz) velocity mode",
        series.clone(),
        None,
        "amplitude",
    )?;
    // the last per cent: where a liquid's wave has decayed, what is left of the others
    plot(
        "Shear wave: the last per cent of the sin(kz) mode",
        series,
        Some((-0.05, 0.05)),
        "amplitude_tail",
    )
}
