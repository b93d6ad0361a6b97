//! What a run of a falling drop gives: its probe histories and the state it settles in.

use crate::cases::substrate::{settling_time, tail_stats, Probe};
use crate::suite::RunData;

/// One run, measured.
pub struct ImpactRun<'r> {
    /// The run.
    pub run: &'r RunData,
    /// The plate's solid.
    pub solid: &'static str,
    /// The liquid's equilibrium contact angle on it [deg].
    pub theta_deg: f64,
    /// The drop's volume: liquid particles × l0³ (physical particle mass, ρ0 l0³ each) [m³].
    pub volume_m3: f64,
    /// The probes over time.
    pub history: History,
    /// The state it settles in.
    pub settled: Settled,
}

/// The probes of a drop over time.
pub struct History {
    /// Output times [s].
    pub t_s: Vec<f64>,
    /// Height [mm].
    pub height_mm: Vec<f64>,
    /// Wetted radius [mm].
    pub contact_radius_mm: Vec<f64>,
    /// Mean of the left and right side-view angles [deg].
    pub theta_mean_deg: Vec<f64>,
    /// Left side-view angle [deg].
    pub theta_left_deg: Vec<f64>,
    /// Right side-view angle [deg].
    pub theta_right_deg: Vec<f64>,
    /// Sphere-fit angle of the whole rim [deg].
    pub theta_sphere_deg: Vec<f64>,
}

impl History {
    /// A run's probes.
    pub fn of(run: &RunData) -> History {
        History {
            t_s: Probe::times(run),
            height_mm: Probe::Height.series(run),
            contact_radius_mm: Probe::ContactRadius.series(run),
            theta_mean_deg: Probe::ThetaSideMean.series(run),
            theta_left_deg: Probe::ThetaLeft.series(run),
            theta_right_deg: Probe::ThetaRight.series(run),
            theta_sphere_deg: Probe::ThetaSphere.series(run),
        }
    }
}

/// The settled drop: means over the last fifth of the run, and how it got there.
#[derive(Debug)]
pub struct Settled {
    /// Start of the last fifth [s].
    pub from_s: f64,
    /// Mean height [mm].
    pub height_mm: f64,
    /// Half the peak-to-peak range of the height: the residual oscillation [mm].
    pub height_osc_mm: f64,
    /// Mean of the side-view angles [deg].
    pub theta_deg: f64,
    /// Half the peak-to-peak range of the angle [deg].
    pub theta_osc_deg: f64,
    /// Mean wetted radius [mm].
    pub contact_radius_mm: f64,
    /// The largest wetted radius [mm].
    pub largest_radius_mm: f64,
    /// Band around the mean height the settled drop stays in: 2 % or l0/2, the larger [mm].
    pub band_mm: f64,
    /// The last time the height left the band [s].
    pub settling_time_s: f64,
    /// Lowest and highest angle after the first 2 ms [deg].
    pub theta_range_deg: (f64, f64),
    /// Lowest and highest height after the first 2 ms [mm].
    pub height_range_mm: (f64, f64),
}

/// Measures a run on `solid` (contact angle `theta_deg` [deg]) at spacing `l0_m` [m].
pub fn impact_run<'r>(
    run: &'r RunData,
    solid: &'static str,
    theta_deg: f64,
    l0_m: f64,
) -> ImpactRun<'r> {
    let history = History::of(run);
    let fluid = run.last.wall.iter().filter(|w| !**w).count();
    ImpactRun {
        run,
        solid,
        theta_deg,
        volume_m3: fluid as f64 * l0_m.powi(3),
        settled: settled(&history, l0_m),
        history,
    }
}

/// The settled state of a drop's `history` measured at spacing `l0_m` [m].
pub fn settled(h: &History, l0_m: f64) -> Settled {
    let t = &h.t_s;
    let end = t.last().copied().unwrap_or(0.0);
    // equilibrium: the mean over the last fifth of the run
    let from = 0.8 * end;
    let (height, height_osc) = tail_stats(t, &h.height_mm, from);
    let (theta, theta_osc) = tail_stats(t, &h.theta_mean_deg, from);
    let (radius, _) = tail_stats(t, &h.contact_radius_mm, from);
    // settling: the height stays within 2 % of its final value (or l0/2, if larger)
    let band = (0.02 * height).max(0.5 * l0_m * 1e3);
    let after_2_ms = |y: &[f64]| -> Vec<f64> {
        t.iter()
            .zip(y)
            .filter(|(t, y)| **t > 0.002 && y.is_finite())
            .map(|(_, y)| *y)
            .collect()
    };
    Settled {
        from_s: from,
        height_mm: height,
        height_osc_mm: height_osc,
        theta_deg: theta,
        theta_osc_deg: theta_osc,
        contact_radius_mm: radius,
        largest_radius_mm: (h.contact_radius_mm.iter().copied())
            .filter(|x| x.is_finite())
            .fold(f64::NAN, f64::max),
        band_mm: band,
        settling_time_s: settling_time(t, &h.height_mm, height, band),
        theta_range_deg: range(&after_2_ms(&h.theta_mean_deg)),
        height_range_mm: range(&after_2_ms(&h.height_mm)),
    }
}

/// Smallest and largest value (NaN for none).
fn range(v: &[f64]) -> (f64, f64) {
    (
        v.iter().copied().fold(f64::NAN, f64::min),
        v.iter().copied().fold(f64::NAN, f64::max),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_drop_settling_to_2_mm() {
        let t: Vec<f64> = (0..100).map(|k| k as f64 * 1e-3).collect();
        // the height oscillates about 2 mm with an envelope e^{−t/10 ms}; the wetted radius
        // grows to 3 mm; the angle is 90° ± 10° · e^{−t/10 ms}
        let wave = |t: f64| (-t / 0.01f64).exp() * (600.0 * t).cos();
        let h = History {
            height_mm: t.iter().map(|&t| 2.0 + wave(t)).collect(),
            contact_radius_mm: t
                .iter()
                .map(|&t| 3.0 * (1.0 - (-t / 0.005f64).exp()))
                .collect(),
            theta_mean_deg: t.iter().map(|&t| 90.0 + 10.0 * wave(t)).collect(),
            theta_left_deg: vec![],
            theta_right_deg: vec![],
            theta_sphere_deg: vec![],
            t_s: t,
        };
        let s = settled(&h, 2e-5);
        assert!((s.from_s - 0.0792).abs() < 1e-12);
        assert!(
            (s.height_mm - 2.0).abs() < 1e-3 && s.height_osc_mm < 1e-3,
            "{s:?}"
        );
        assert!((s.theta_deg - 90.0).abs() < 1e-2, "{s:?}");
        assert!((s.contact_radius_mm - 3.0).abs() < 1e-6);
        assert!(s.largest_radius_mm < 3.0 && s.largest_radius_mm > 3.0 - 1e-6);
        // band 2 % of 2 mm = 0.04 mm (l0/2 = 0.01 mm is smaller): the envelope falls below it
        // at t = 10 ms · ln 25 = 32.2 ms
        assert!((s.band_mm - 0.04).abs() < 1e-4, "{s:?}");
        assert!(
            s.settling_time_s > 0.03 && s.settling_time_s < 0.0322,
            "{s:?}"
        );
        // after 2 ms the height swings between 2 ± e^{−0.2}… at most
        let (lo, hi) = s.height_range_mm;
        assert!(
            lo > 2.0 - 0.82 && hi < 2.0 + 0.82 && lo < 2.0 && hi > 2.0,
            "{lo} {hi}"
        );
    }
}
