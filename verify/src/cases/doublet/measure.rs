//! What a run of a doublet gives: the centroid distance G1G2(t)/R0, its equilibrium and
//! oscillation, and the final state's regime and triple-line angles.

use super::{Pair, Start, R0_M};
use crate::analytic::neumann::{self, Regime};
use crate::measure::geometry::{self, DoubletAngles};
use crate::measure::oscillation::{self, OscillationFit};
use crate::measure::surface::{self, Classes, Cloud};
use crate::output::timeseries::{Axis, LiquidColumn, RunColumn, Table};
use crate::suite::RunData;

/// One run, measured.
pub struct DoubletRun<'r> {
    /// The run.
    pub run: &'r RunData,
    /// Its position among the case's runs (a run keeps its colour when another is missing).
    pub index: usize,
    /// Its interfacial tension σ12 [N/m].
    pub sigma12_n_m: f64,
    /// How it started.
    pub start: Start,
    /// Under the continuum surface force, in a host liquid (else the paper's potential).
    pub surface_force: bool,
    /// Its particle spacing [m].
    pub l0_m: f64,
    /// The liquid-1 particles closer than 1.5 l0 to a liquid-2 particle at the end: the
    /// contact between the drops (none when apart; a few at a point contact).
    pub contact_particles: usize,
    /// G1G2/R0 over time.
    pub separation: Separation,
    /// The regime of the final state, in words.
    pub regime_seen: &'static str,
    /// The triple-line angles of the final state, where the tensions make a lens (matte–slag
    /// only), or why they could not be measured.
    pub angles: Option<Result<DoubletAngles, String>>,
}

/// The distance between the liquids' centroids over the initial radius, G1G2/R0 [-].
#[derive(Debug)]
pub struct Separation {
    /// Output times [s].
    pub t_s: Vec<f64>,
    /// G1G2/R0 at each output [-].
    pub g1g2_r0: Vec<f64>,
    /// Mean over the last quarter of the run [-].
    pub equilibrium: f64,
    /// Standard deviation over the last quarter: the residual oscillation [-].
    pub residual: f64,
    /// A damped cosine fitted to the whole series.
    pub fit: Option<OscillationFit>,
    /// Extrema skipped before the paper's half-period is taken.
    pub paper_skip: usize,
    /// Natsui 2021's "period": minimum to next maximum after `paper_skip` extrema [s].
    pub paper_half_period_s: Option<f64>,
    /// Natsui 2021's damping: fall of (max − min) per half-period over the half-period [1/s].
    pub paper_damping_per_s: Option<f64>,
}

/// Measures the runs of a pair of liquids `(a, b)` with tensions `sigma_n_m` [N/m], each at
/// its own spacing; runs without a G1G2 series are left out.
pub fn doublet_runs<'r>(
    pair: Pair,
    liquids: (&str, &str),
    sigma_n_m: (f64, f64),
    runs: &'r [RunData],
) -> anyhow::Result<Vec<DoubletRun<'r>>> {
    let mut out = Vec::new();
    for (index, run) in runs.iter().enumerate() {
        let l0_m = run.info.scene.discretisation.l0;
        let centroids = |l: &str| centroids_of(&run.timeseries, l);
        let t = run.timeseries.run_column(RunColumn::Time);
        let separation = separation(&t, centroids(liquids.0), centroids(liquids.1), l0_m);
        if separation.g1g2_r0.is_empty() {
            continue;
        }
        let s12 = run.info.scene.interfaces[0].tension;
        let surface_force =
            run.info.scene.effects.interfacial_tension == solver::scene::TensionModel::SurfaceForce;
        let mut cloud = run.last.cloud(l0_m);
        if surface_force {
            // the host is the gas: the drops' surfaces against it are their free surfaces
            let own: Vec<bool> = run
                .info
                .scene
                .liquids
                .iter()
                .map(|l| l.name == liquids.0 || l.name == liquids.1)
                .collect();
            cloud.retain_phases(|p| own[p as usize]);
        }
        let classes = surface::classify(&cloud);
        let g_final = separation.g1g2_r0.last().copied().unwrap_or(f64::NAN);
        let lens = neumann::regime(sigma_n_m.0, sigma_n_m.1, s12).map_err(anyhow::Error::msg)?
            == Regime::Lens;
        let contact_particles = match surface::unlike_pairs(&cloud, &classes, 0, 1) {
            Ok(pairs) => {
                let mut firsts: Vec<u32> = pairs.iter().map(|p| p[0]).collect();
                firsts.sort_unstable();
                firsts.dedup();
                firsts.len()
            }
            Err(_) => 0,
        };
        out.push(DoubletRun {
            run,
            index,
            sigma12_n_m: s12,
            start: start_of(run),
            surface_force,
            l0_m,
            contact_particles,
            regime_seen: regime_seen(&cloud, &classes, g_final, l0_m),
            angles: (lens && pair == Pair::MatteSlag).then(|| {
                geometry::doublet_angles(&cloud, &classes, [sigma_n_m.0, sigma_n_m.1, s12])
            }),
            separation,
        });
    }
    Ok(out)
}

/// How a run starts: a shell body is an engulfed start, one body a merged one; a `fine_` run
/// is a touching start at the paper's spacing inside the standard suite.
fn start_of(run: &RunData) -> Start {
    let scene = &run.info.scene;
    let shell = |b: &solver::scene::Body| matches!(b.shape, solver::scene::BodyShape::Shell { .. });
    if scene.bodies.iter().any(shell) {
        Start::Engulfed
    } else if run.id.starts_with("fine_") {
        Start::Fine
    } else if scene.bodies.len() == 1 {
        Start::Merged
    } else {
        Start::Touching
    }
}

/// The centroid of liquid `l` along x, y, z [m] at each output.
fn centroids_of(ts: &Table, l: &str) -> [Vec<f64>; 3] {
    Axis::ALL.map(|ax| ts.liquid_column(l, LiquidColumn::Centroid(ax)))
}

/// G1G2/R0 from the centroids `a` and `b` [m] of the two liquids at times `t_s` [s], measured
/// at spacing `l0_m` [m] (extrema of the paper's definitions must stand out by 0.2 l0).
pub fn separation(t_s: &[f64], a: [Vec<f64>; 3], b: [Vec<f64>; 3], l0_m: f64) -> Separation {
    let n = t_s.len().min(a[0].len()).min(b[0].len());
    let g: Vec<f64> = (0..n)
        .map(|k| {
            ((a[0][k] - b[0][k]).powi(2)
                + (a[1][k] - b[1][k]).powi(2)
                + (a[2][k] - b[2][k]).powi(2))
            .sqrt()
                / R0_M
        })
        .collect();
    let t = &t_s[..n];
    let (equilibrium, residual) = last_quarter(&g);
    let ex = oscillation::extrema(t, &g, 0.2 * l0_m / R0_M);
    let paper_skip = 6.min(ex.len().saturating_sub(2));
    Separation {
        fit: oscillation::fit_damped_cosine(t, &g).ok(),
        paper_half_period_s: oscillation::paper_half_period(&ex, paper_skip),
        paper_damping_per_s: oscillation::paper_damping_rate(&ex),
        paper_skip,
        t_s: t.to_vec(),
        g1g2_r0: g,
        equilibrium,
        residual,
    }
}

/// Mean and standard deviation of the last quarter of a series.
fn last_quarter(y: &[f64]) -> (f64, f64) {
    let tail = &y[y.len() * 3 / 4..];
    if tail.is_empty() {
        return (f64::NAN, f64::NAN);
    }
    let n = tail.len() as f64;
    let mean = tail.iter().sum::<f64>() / n;
    let sd = (tail.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / n).sqrt();
    (mean, sd)
}

/// The regime seen in a final state: complete engulfing if liquid 1 has (almost) no free
/// surface, point contact if the drops' centroids are (nearly) 2 R0 apart, else a lens.
pub fn regime_seen(cloud: &Cloud, classes: &Classes, g1g2_r0: f64, l0_m: f64) -> &'static str {
    let fs = |ph: u8| {
        (0..cloud.pos.len())
            .filter(|&i| cloud.phase[i] == ph && classes.free_surface[i])
            .count()
    };
    let (f1, f2) = (fs(0), fs(1));
    // engulfed: under 5 % of the free surface is liquid 1 (a few stray particles may show)
    if (f1 as f64) < 0.05 * (f1 + f2) as f64 {
        "complete engulfing (slag covers matte)"
    } else if (f2 as f64) < 0.05 * (f1 + f2) as f64 {
        "complete engulfing (matte covers slag)"
    } else if g1g2_r0 > 2.0 - l0_m / R0_M {
        // within one particle spacing of touching spheres
        "point contact or apart"
    } else {
        "lens"
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn separation_of_two_centroids_oscillating_about_1_5_r0() {
        let (period, gamma) = (3e-3, 200.0);
        let t: Vec<f64> = (0..300).map(|k| k as f64 * 1e-4).collect();
        let d: Vec<f64> = t
            .iter()
            .map(|&t| {
                R0_M * (1.5 + 0.1 * (-gamma * t).exp() * (std::f64::consts::TAU * t / period).cos())
            })
            .collect();
        // along a tilted axis (3, 4, 0)/5, symmetric about a point off the origin
        let at = |sign: f64| -> [Vec<f64>; 3] {
            [0.6, 0.8, 0.0].map(|u| d.iter().map(|d| 1e-3 + sign * 0.5 * u * d).collect())
        };
        let s = separation(&t, at(-1.0), at(1.0), 1e-4);
        assert_eq!(s.g1g2_r0.len(), t.len());
        for (g, d) in s.g1g2_r0.iter().zip(&d) {
            assert!((g - d / R0_M).abs() < 1e-12);
        }
        // the last quarter (t ≥ 22.5 ms) has decayed to e^{−4.5}·0.1 ≈ 1e-3
        assert!(
            (s.equilibrium - 1.5).abs() < 2e-3 && s.residual < 2e-3,
            "{s:?}"
        );
        let fit = s.fit.as_ref().unwrap();
        assert!((fit.period_s / period - 1.0).abs() < 1e-6);
        assert!((fit.damping_rate_per_s / gamma - 1.0).abs() < 1e-6);
    }

    #[test]
    fn regime_from_who_has_free_surface() {
        let cloud = Cloud {
            pos: vec![[0.0; 3]; 40],
            phase: (0..40).map(|i| u8::from(i >= 20)).collect(),
            walls: vec![],
            l0_m: 1e-4,
        };
        // free surface: `n1` particles of liquid 1 and all 20 of liquid 2
        let classes = |n1: usize| Classes {
            neighbours: vec![0; 40],
            free_surface: (0..40).map(|i| i >= 20 || i < n1).collect(),
            interface: vec![false; 40],
        };
        let seen = |n1, g| regime_seen(&cloud, &classes(n1), g, 1e-4);
        assert_eq!(seen(0, 1.5), "complete engulfing (slag covers matte)");
        assert_eq!(seen(10, 1.5), "lens");
        // within one spacing (0.1 R0) of touching spheres
        assert_eq!(seen(10, 1.95), "point contact or apart");
    }
}
