//! What a run of the oscillating drop gives: its axial moment Q2 over time, the damped cosine
//! fitted to it, and the drop's equal-volume radius.

use super::{Q2, RADIUS_M};
use crate::analytic::lamb;
use crate::measure::oscillation::{self, OscillationFit};
use crate::output::timeseries::RunColumn;
use crate::suite::RunData;
use solver::scene::BodyShape;

/// One run, measured.
pub struct DropRun<'r> {
    /// The run.
    pub run: &'r RunData,
    /// The initial stretch `ε` of the spheroid along z [-].
    pub amplitude: f64,
    /// Radius of the sphere with the drop's volume (particles × l0³) [m].
    pub radius_m: f64,
    /// The oscillation of Q2.
    pub oscillation: Oscillation,
}

/// The l = 2 oscillation of Q2.
#[derive(Debug)]
pub struct Oscillation {
    /// Output times [s].
    pub t_s: Vec<f64>,
    /// Q2 at those times [-].
    pub q2: Vec<f64>,
    /// The damped cosine fitted to the whole series, or why it failed.
    pub fit: Result<OscillationFit, String>,
}

impl Oscillation {
    /// Fits `q2` at times `t_s` [s].
    pub fn of(t_s: &[f64], q2: &[f64]) -> Oscillation {
        let n = t_s.len().min(q2.len());
        Oscillation {
            t_s: t_s[..n].to_vec(),
            q2: q2[..n].to_vec(),
            fit: oscillation::fit_damped_cosine(&t_s[..n], &q2[..n]),
        }
    }

    /// Period [s] and amplitude decay rate [1/s] of the fit (NaN if it failed).
    pub fn period_and_damping(&self) -> (f64, f64) {
        self.fit
            .as_ref()
            .map_or((f64::NAN, f64::NAN), |f| (f.period_s, f.damping_rate_per_s))
    }
}

/// Measures a run from its probes and record.
pub fn drop_run(run: &RunData) -> DropRun<'_> {
    let scene = &run.info.scene;
    let amplitude = match scene.bodies.first().map(|b| &b.shape) {
        Some(BodyShape::Ellipsoid { semi_axes, .. }) => semi_axes[2] / RADIUS_M - 1.0,
        _ => f64::NAN,
    };
    let l0 = scene.discretisation.l0;
    let particles = run.info.fluid_particles as f64;
    let t = run
        .probes
        .column(&RunColumn::Time.name())
        .unwrap_or_default();
    let q2 = run.probes.column(Q2).unwrap_or_default();
    DropRun {
        run,
        amplitude,
        radius_m: lamb::sphere_radius_from_volume(particles * l0 * l0 * l0),
        oscillation: Oscillation::of(&t, &q2),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_damped_cosine_q2_gives_its_period_and_damping() {
        let (period, gamma) = (7.5e-3, 40.0);
        let t: Vec<f64> = (0..250).map(|k| k as f64 * 7.5e-5).collect();
        let q2: Vec<f64> = t
            .iter()
            .map(|&t| 1e-4 + 0.07 * (-gamma * t).exp() * (std::f64::consts::TAU * t / period).cos())
            .collect();
        let o = Oscillation::of(&t, &q2);
        let (p, g) = o.period_and_damping();
        assert!((p / period - 1.0).abs() < 1e-6, "{p}");
        assert!((g / gamma - 1.0).abs() < 1e-6, "{g}");
        assert!(Oscillation::of(&t, &vec![0.0; t.len()]).fit.is_err());
    }
}
