//! The convergence case's figures and table: |error| against l0 (log–log, with slopes 1 and 2),
//! the drops' Q2 over time, and `table.md` (the drop's period and damping per resolution, and
//! the caps' angles of each model side by side).

use super::judge::{amplitude_sets, cap_series, drop_series, host_series};
use super::measure::{CapPoint, DropPoint, Measured};
use super::{HostModel, Series as ErrorSeries};
use crate::report::plot::{self, Plot, Series, SeriesKind};
use std::fmt::Write as _;
use std::path::Path;

/// Draws every figure of the case and writes `table.md` into `dir`.
pub fn plots(m: &Measured, dir: &Path) -> anyhow::Result<()> {
    let mut all: Vec<ErrorSeries> = drop_series(&m.drops, "drop", m.declared.drops).into();
    all.extend(cap_series(&m.caps, &m.declared));
    all.extend(host_series(m));
    error_against_spacing(&all, dir)?;
    drop_histories(
        &m.drops,
        by_resolution,
        "Free drop, l = 2: Q2 from 1 ms, per resolution",
        "t / Rayleigh period",
        &dir.join("drop_q2"),
    )?;
    let mut table = drop_table(&m.drops);
    for (h, drops) in &m.host_drops {
        let (first, rest) = h.label.split_at(1);
        drop_histories(
            drops,
            by_resolution,
            &format!(
                "{}{rest} in its host, l = 2: Q2 from 1 ms, per resolution",
                first.to_uppercase()
            ),
            "t / Lamb period in the host",
            &dir.join(format!("{}_drop_q2", h.id)),
        )?;
        table.push_str(&host_drop_table(h, drops));
    }
    for (h, others) in &m.amplitude_drops {
        for set in amplitude_sets(m, h, others) {
            let r = set[0].r_over_l0;
            drop_histories(
                set.iter().copied(),
                |d| format!("ε = {:.2}", d.amplitude),
                &format!(
                    "{}: Q2 from 1 ms, per initial stretch ε, R/l0 = {r:.0}",
                    h.label
                ),
                "t / Lamb period in the host",
                &dir.join(format!("{}_drop_r{r:.0}_eps_q2", h.id)),
            )?;
            table.push_str(&amplitude_table(h, &set));
        }
    }
    table.push_str(&cap_table(&m.caps));
    std::fs::write(dir.join("table.md"), table)?;
    Ok(())
}

/// `log10 |error|` against `log10(l0/R)`, one line per metric, and the slopes 1 and 2 through
/// the coarsest point of the first measured metric.
fn error_against_spacing(all: &[ErrorSeries], dir: &Path) -> anyhow::Result<()> {
    let log = |(h, e): (f64, f64)| (h.log10(), e.abs().log10());
    let mut series: Vec<Series> = all
        .iter()
        .enumerate()
        .map(|(k, s)| Series {
            label: match s.order() {
                Some((p, _)) => format!("{} (p = {p:.2})", s.label),
                None => s.label.clone(),
            },
            points: s.points.iter().copied().map(log).collect(),
            kind: SeriesKind::LineMarkers,
            color: k + 1,
        })
        .collect();
    let anchor = all
        .iter()
        .flat_map(|s| s.points.iter().copied())
        .find(|p| p.1.is_finite() && p.1 != 0.0);
    let spacings: Vec<f64> = all
        .iter()
        .flat_map(|s| s.points.iter().map(|p| p.0))
        .collect();
    if let Some((h0, e0)) = anchor {
        let lo = spacings.iter().copied().fold(f64::INFINITY, f64::min);
        // two colours beyond the metrics' so the slopes tell apart (dashed: a reference)
        for (k, order) in [1.0, 2.0].into_iter().enumerate() {
            series.push(Series {
                label: format!("slope {order:.0} (error ∝ l0^{order:.0})"),
                points: [lo, h0]
                    .iter()
                    .map(|&h| log((h, e0.abs() * (h / h0).powf(order))))
                    .collect(),
                kind: SeriesKind::Dashed,
                color: all.len() + 1 + k,
            });
        }
    }
    plot::draw(
        &Plot {
            title: "Convergence: |relative error| against the spacing".into(),
            x_label: "log10(l0 / R)".into(),
            y_label: "log10 |relative error|".into(),
            series,
            x_range: None,
            y_range: None,
            hlines: vec![],
        },
        &dir.join("error_vs_spacing"),
    )
}

/// Q2 over its value at 1 ms against t over the reference period, one line per drop (named
/// by `label`), into `file`.
fn drop_histories<'a, 'r: 'a>(
    drops: impl IntoIterator<Item = &'a DropPoint<'r>>,
    label: impl Fn(&DropPoint) -> String,
    title: &str,
    x_label: &str,
    file: &Path,
) -> anyhow::Result<()> {
    let series = drops
        .into_iter()
        .enumerate()
        .map(|(k, d)| {
            let (t, q) = &d.series;
            let q0 = q.first().copied().unwrap_or(1.0);
            Series {
                label: label(d),
                points: t
                    .iter()
                    .zip(q)
                    .map(|(t, q)| (t / d.reference_period_s, q / q0))
                    .collect(),
                kind: SeriesKind::Line,
                color: k + 1,
            }
        })
        .collect();
    plot::draw(
        &Plot {
            title: title.into(),
            x_label: x_label.into(),
            y_label: "Q2 / Q2(1 ms)".into(),
            series,
            x_range: None,
            y_range: None,
            hlines: vec![(0.0, "a liquid settles at 0".into())],
        },
        file,
    )
}

/// A line's label: its drop's resolution.
fn by_resolution(d: &DropPoint) -> String {
    format!("R/l0 = {:.0}", d.r_over_l0)
}

/// A model's drop at one resolution across initial stretches: per ε the fitted period against
/// the reference, the decay rate against the reference's with ν + ν_AV, Q2's offset.
fn amplitude_table(h: &HostModel, set: &[&DropPoint]) -> String {
    let mut s = format!(
        "\n## The {} drop across initial stretches ε, R/l0 = {:.0}\n\n\
         A liquid's period and damping do not depend on the amplitude; an elastic–plastic body's do. \
         References as above.\n\n\
         | ε | drop particles | period [ms] | reference [ms] | error | decay rate [1/s] | / reference(ν + ν_AV) | Q2 offset | wall time [s] |\n\
         |---|---|---|---|---|---|---|---|---|\n",
        h.name,
        set.first().map_or(f64::NAN, |d| d.r_over_l0)
    );
    for d in set {
        let ([p, g, b], _) = fitted(d);
        let t = d.reference_period_s;
        let _ = writeln!(
            s,
            "| {:.2} | {} | {:.2} | {:.2} | {:+.1} % | {:.1} | {:.1} | {:+.4} | {:.0} |",
            d.amplitude,
            d.drop_particles,
            p * 1e3,
            t * 1e3,
            100.0 * (p / t - 1.0),
            g,
            g / d.decay_with_av_per_s,
            b,
            d.run.info.wall_time_s
        );
    }
    s
}

/// A drop's fits: the period [s], decay rate [1/s] and offset [-] of Q2's, the period [s] and
/// decay rate [1/s] of the z-extent's (NaN where a fit failed).
fn fitted(d: &DropPoint) -> ([f64; 3], [f64; 2]) {
    let q2 = d.fit.as_ref().map_or([f64::NAN; 3], |f| {
        [f.period_s, f.damping_rate_per_s, f.offset]
    });
    let extent = d
        .extent_fit
        .as_ref()
        .map_or([f64::NAN; 2], |f| [f.period_s, f.damping_rate_per_s]);
    (q2, extent)
}

/// The drop's table: R/l0, particles, period, error, the elastic drop's error bracket, decay
/// rate and its ratio to Lamb's with the physical ν alone (all from Q2), the same from the
/// z-extent, wall time.
fn drop_table(drops: &[DropPoint]) -> String {
    let mut s = String::from(
        "| R/l0 | l0 [µm] | particles | period [ms] | Rayleigh [ms] | error | elastic drop: error with C′ … C44 | decay rate [1/s] | / Lamb(ν) | / Lamb(ν + ν_AV) | Q2 offset | z-extent: period [ms], error, decay [1/s] | wall time [s] |\n\
         |---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    for d in drops {
        let ([p, g, b], [pe, ge]) = fitted(d);
        let _ = writeln!(
            s,
            "| {:.1} | {:.1} | {} | {:.2} | {:.2} | {:+.1} % | {:+.1} … {:+.1} % | {:.1} | {:.1} | {:.1} | {:+.4} | {:.2}, {:+.1} %, {:.1} | {:.0} |",
            d.r_over_l0,
            d.run.info.scene.discretisation.l0 * 1e6,
            d.run.info.fluid_particles,
            p * 1e3,
            d.reference_period_s * 1e3,
            100.0 * (p / d.reference_period_s - 1.0),
            100.0 * (d.elastic_periods_s[0] / d.reference_period_s - 1.0),
            100.0 * (d.elastic_periods_s[1] / d.reference_period_s - 1.0),
            g,
            g / d.decay_physical_per_s,
            g / d.decay_with_av_per_s,
            b,
            pe * 1e3,
            100.0 * (pe / d.reference_period_s - 1.0),
            ge,
            d.run.info.wall_time_s
        );
    }
    s
}

/// A continuum model's drop table: R/l0, spacing, the drop's and all particles, period, the
/// viscous reference and Lamb's inviscid in the host with the errors against each, decay rate
/// against the reference's with ν and with ν + ν_AV, Q2 offset, the z-extent's fit, the
/// momentum's drift, wall time.
fn host_drop_table(h: &HostModel, drops: &[DropPoint]) -> String {
    let mut s = format!(
        "\n## The same drop under the continuum {}, in a host of equal density (docs/model.md {})\n\n\
         The reference is Lamb's period in the host slowed by the interface's boundary layer at the liquids' \
         physical viscosities (Miller & Scriven 1968); Lamb's inviscid period is beside it. The static \
         stiffness is the model's against the l = 2 mode of a lattice sphere of the same R/l0 (`verify stiffness`): the \
         force's share of the error, apart from the run's inertia (host, box, compressibility).\n\n\
         | R/l0 | l0 [µm] | drop particles | all particles | period [ms] | reference [ms] | error | Lamb inviscid [ms], error | static stiffness k/k_exact (its error) | decay rate [1/s] | / reference(ν) | / reference(ν + ν_AV) | Q2 offset | z-extent: period [ms], error, decay [1/s] | momentum drift / (M·|v|max) | wall time [s] |\n\
         |---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
        h.name,
        h.section
    );
    for d in drops {
        let ([p, g, b], [pe, ge]) = fitted(d);
        let (t, t0) = (d.reference_period_s, d.inviscid_period_s);
        let _ = writeln!(
            s,
            "| {:.1} | {:.1} | {} | {} | {:.2} | {:.2} | {:+.1} % | {:.2}, {:+.1} % | {:.3} ({:+.1} %) | {:.1} | {:.1} | {:.1} | {:+.4} | {:.2}, {:+.1} %, {:.1} | {:.1e} | {:.0} |",
            d.r_over_l0,
            d.run.info.scene.discretisation.l0 * 1e6,
            d.drop_particles,
            d.run.info.fluid_particles,
            p * 1e3,
            t * 1e3,
            100.0 * (p / t - 1.0),
            t0 * 1e3,
            100.0 * (p / t0 - 1.0),
            d.static_stiffness,
            100.0 * (d.static_stiffness.powf(-0.5) - 1.0),
            g,
            g / d.decay_physical_per_s,
            g / d.decay_with_av_per_s,
            b,
            pe * 1e3,
            100.0 * (pe / t - 1.0),
            ge,
            d.momentum_drift,
            d.run.info.wall_time_s
        );
    }
    s
}

/// The caps' table: per typed angle and resolution, each model's angle from the settled
/// height (its error) and from the side view, side by side.
fn cap_table(caps: &[CapPoint]) -> String {
    let models: Vec<Option<HostModel>> = {
        let mut v: Vec<Option<HostModel>> = caps.iter().map(|c| c.host_model).collect();
        v.dedup();
        v
    };
    let name = |m: &Option<HostModel>| m.map_or("potential", |h| h.name);
    let mut s = format!(
        "\n## The caps, model by model\n\n\
         The angle of the spherical cap of the drop's volume and its settled height (the last quarter's mean), \
         its error against the typed angle, and the side-view fit on the last state. The continuum model's caps sit in \
         a host without a surface tension (the gas of Young's relation) at {} Pa·s, on a plate of {} layers.\n\n| typed | n = R/l0 |",
        super::CAP_HOST.viscosity_pa_s,
        super::cap_plate_layers()
    );
    for m in &models {
        let _ = write!(
            s,
            " {}: height (error) | side view | wall time [s] |",
            name(m)
        );
    }
    s.push_str("\n|---|---|");
    s.push_str(&"---|---|---|".repeat(models.len()));
    s.push('\n');
    let mut rows: Vec<(f64, f64)> = caps.iter().map(|c| (c.typed_deg, c.n)).collect();
    rows.sort_by(|a, b| a.partial_cmp(b).expect("finite angles and resolutions"));
    rows.dedup();
    for (theta, n) in rows {
        let _ = write!(s, "| {theta:.0}° | {n:.0} |");
        for m in &models {
            let cap = caps
                .iter()
                .find(|c| c.typed_deg == theta && c.n == n && c.host_model == *m);
            match cap {
                Some(c) => {
                    let h = c.height_angle_deg.unwrap_or(f64::NAN);
                    let side = c.side_view_deg.as_ref().map_or(f64::NAN, |a| *a);
                    let _ = write!(
                        s,
                        " {h:.1}° ({:+.1}°) | {side:.1}° | {:.0} |",
                        h - theta,
                        c.run.info.wall_time_s
                    );
                }
                None => s.push_str(" – | – | – |"),
            }
        }
        s.push('\n');
    }
    s
}
