//! What a run of the cube drop gives: its width over time and the damped cosines fitted to the
//! width and to the l = 4 shape moment Q4.

use super::FIT_FROM_S;
use crate::cases::scene::MATTE;
use crate::measure::oscillation::{self, OscillationFit};
use crate::output::timeseries::{Axis, LiquidColumn, RunColumn};
use crate::suite::RunData;

/// One run, measured.
pub struct CubeRun<'r> {
    /// The run.
    pub run: &'r RunData,
    /// Its squared sound speed c² [m²/s²].
    pub c2_m2_s2: f64,
    /// Its oscillation.
    pub oscillation: Oscillation,
}

/// The l = 4 oscillation of a relaxing cube.
#[derive(Debug)]
pub struct Oscillation {
    /// Output times [s].
    pub t_s: Vec<f64>,
    /// Width: the mean of the x, y and z extents [m].
    pub width_m: Vec<f64>,
    /// The damped cosine fitted to the width after [`FIT_FROM_S`], or why it failed.
    pub width_fit: Result<OscillationFit, String>,
    /// The damped cosine fitted to Q4 after [`FIT_FROM_S`] (none without a Q4 series of the
    /// times' length, or if the fit failed).
    pub q4_fit: Option<OscillationFit>,
    /// Natsui 2021's "period": minimum to next maximum of the fitted width [s].
    pub paper_half_period_s: Option<f64>,
    /// Natsui 2021's damping: fall of the fitted width's (max − min) per half-period, over the
    /// half-period [m/s].
    pub paper_damping_m_s: Option<f64>,
}

impl Oscillation {
    /// Period [s] and amplitude decay rate [1/s] of the width's fit (NaN if it failed).
    pub fn width_period_and_damping(&self) -> (f64, f64) {
        self.width_fit
            .as_ref()
            .map_or((f64::NAN, f64::NAN), |f| (f.period_s, f.damping_rate_per_s))
    }
}

/// Measures a run from its time series.
pub fn cube_run(run: &RunData) -> CubeRun<'_> {
    let ts = &run.timeseries;
    let extents = Axis::ALL.map(|ax| ts.liquid_column(MATTE.name, LiquidColumn::Extent(ax)));
    CubeRun {
        run,
        c2_m2_s2: run.info.scene.discretisation.sound_speed.powi(2),
        oscillation: oscillation(
            &ts.run_column(RunColumn::Time),
            [&extents[0], &extents[1], &extents[2]],
            &ts.liquid_column(MATTE.name, LiquidColumn::Q4),
        ),
    }
}

/// The oscillation of the extents along x, y, z [m] and of Q4 [-] at times `t_s` [s].
pub fn oscillation(t_s: &[f64], extents_m: [&[f64]; 3], q4: &[f64]) -> Oscillation {
    // the l = 4 mode of a cube moves its three widths in phase: their mean is the paper's width
    // with √3 less particle noise
    let [wx, wy, wz] = extents_m;
    let width_m: Vec<f64> = (0..wx.len().min(wy.len()).min(wz.len()))
        .map(|k| (wx[k] + wy[k] + wz[k]) / 3.0)
        .collect();
    let from = t_s.iter().position(|&x| x >= FIT_FROM_S).unwrap_or(0);
    let width_fit = oscillation::fit_damped_cosine(&t_s[from..], &width_m[from..]);
    let q4_fit = if q4.len() == t_s.len() {
        oscillation::fit_damped_cosine(&t_s[from..], &q4[from..]).ok()
    } else {
        None
    };
    // the paper's own definitions, on the turning points of the fitted curve (sampled extrema of
    // a particle extent are too noisy at these resolutions)
    let turning = width_fit
        .as_ref()
        .ok()
        .map(|fit| fit.model_extrema(FIT_FROM_S, t_s.last().copied().unwrap_or(0.0)));
    Oscillation {
        paper_half_period_s: turning
            .as_ref()
            .and_then(|ex| oscillation::paper_half_period(ex, 0)),
        paper_damping_m_s: turning
            .as_ref()
            .and_then(|ex| oscillation::paper_damping_rate(ex)),
        t_s: t_s.to_vec(),
        width_m,
        width_fit,
        q4_fit,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_damped_cosine_width_gives_its_period_damping_and_half_period() {
        let (period, gamma) = (1.2e-3, 300.0);
        let t: Vec<f64> = (0..500).map(|k| k as f64 * 1e-5).collect();
        let wave = |t: f64| (-gamma * t).exp() * (std::f64::consts::TAU * t / period).cos();
        // three extents oscillating in phase about different means
        let ext = |mean: f64| -> Vec<f64> { t.iter().map(|&t| mean + 1e-4 * wave(t)).collect() };
        let (x, y, z) = (ext(1.1e-3), ext(1.2e-3), ext(1.3e-3));
        let q4: Vec<f64> = t.iter().map(|&t| 0.1 * wave(t)).collect();
        let o = oscillation(&t, [&x, &y, &z], &q4);
        assert!((o.width_m[0] - 1.3e-3).abs() < 1e-12, "mean of the extents");
        let fit = o.width_fit.as_ref().unwrap();
        assert!(
            (fit.period_s / period - 1.0).abs() < 1e-6,
            "{}",
            fit.period_s
        );
        assert!((fit.damping_rate_per_s / gamma - 1.0).abs() < 1e-6);
        let q4_fit = o.q4_fit.as_ref().unwrap();
        assert!((q4_fit.period_s / period - 1.0).abs() < 1e-6);
        // turning points of a damped cosine are exactly half a period apart
        let half = o.paper_half_period_s.unwrap();
        assert!((half / (0.5 * period) - 1.0).abs() < 1e-6, "{half}");
        assert!(o.paper_damping_m_s.unwrap() > 0.0);
    }

    #[test]
    fn a_q4_series_of_another_length_is_not_fitted() {
        let t: Vec<f64> = (0..100).map(|k| k as f64 * 1e-5).collect();
        let w = vec![1e-3; 100];
        let o = oscillation(&t, [&w, &w, &w], &[0.0; 3]);
        assert!(o.q4_fit.is_none());
        assert!(o.width_fit.is_err(), "a constant width has no oscillation");
    }
}
