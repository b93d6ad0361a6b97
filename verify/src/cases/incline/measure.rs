//! What a run of the sliding drop gives: its side-view angles, position and speed over time,
//! and their means over the second half of the run.

use crate::cases::substrate::{tail_stats, Probe};
use crate::suite::RunData;

/// One run, measured.
pub struct InclineRun<'r> {
    /// The run.
    pub run: &'r RunData,
    /// The plate's solid.
    pub solid: &'static str,
    /// Water's equilibrium contact angle on it [deg].
    pub theta_deg: f64,
    /// Output times [s].
    pub t_s: Vec<f64>,
    /// Side-view angle on the downhill (+x) side [deg].
    pub advancing_deg: Vec<f64>,
    /// Side-view angle on the uphill (−x) side [deg].
    pub receding_deg: Vec<f64>,
    /// Centroid position along the plate [mm].
    pub centroid_x_mm: Vec<f64>,
    /// The slide over the second half of the run.
    pub slide: Slide,
}

/// The slide over the second half of a run.
#[derive(Debug)]
pub struct Slide {
    /// Start of the second half [s].
    pub from_s: f64,
    /// Mean advancing angle [deg] and half its peak-to-peak range [deg].
    pub advancing_deg: (f64, f64),
    /// Mean receding angle [deg] and half its peak-to-peak range [deg].
    pub receding_deg: (f64, f64),
    /// Mean liquid velocity along the plate [m/s].
    pub speed_m_s: f64,
    /// `(v_end − v_mid)/(t_end − t_mid)` [m/s²].
    pub acceleration_m_s2: f64,
    /// Whether the drop's front is still on the plate at the end.
    pub on_plate: bool,
}

/// Measures a run on `solid` (water's angle `theta_deg` [deg]) whose drop of `diameter_m` [m]
/// slides towards the plate's end at x = `plate_end_m` [m].
pub fn incline_run<'r>(
    run: &'r RunData,
    (solid, theta_deg): (&'static str, f64),
    diameter_m: f64,
    plate_end_m: f64,
) -> InclineRun<'r> {
    let t_s = Probe::times(run);
    let advancing_deg = Probe::ThetaRight.series(run);
    let receding_deg = Probe::ThetaLeft.series(run);
    let centroid_x_mm = Probe::CentroidX.series(run);
    let vx = Probe::VelocityX.series(run);
    let front_on_plate = centroid_x_mm
        .last()
        .is_some_and(|&xe| xe * 1e-3 + 0.5 * diameter_m < plate_end_m);
    InclineRun {
        run,
        solid,
        theta_deg,
        slide: slide(&t_s, &advancing_deg, &receding_deg, &vx, front_on_plate),
        t_s,
        advancing_deg,
        receding_deg,
        centroid_x_mm,
    }
}

/// The slide over the second half of times `t` [s], from the advancing and receding angles
/// [deg] and the velocity along the plate `vx` [m/s].
pub fn slide(t: &[f64], adv: &[f64], rec: &[f64], vx: &[f64], on_plate: bool) -> Slide {
    let from = 0.5 * t.last().copied().unwrap_or(0.0);
    let at = |t0: f64| {
        t.iter()
            .zip(vx)
            .find(|(t, _)| **t >= t0)
            .map(|(t, v)| (*t, *v))
    };
    let acceleration_m_s2 = match (at(from), t.last().zip(vx.last())) {
        (Some((t0, v0)), Some((&t1, &v1))) if t1 > t0 => (v1 - v0) / (t1 - t0),
        _ => f64::NAN,
    };
    Slide {
        from_s: from,
        advancing_deg: tail_stats(t, adv, from),
        receding_deg: tail_stats(t, rec, from),
        speed_m_s: tail_stats(t, vx, from).0,
        acceleration_m_s2,
        on_plate,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_drop_accelerating_uniformly() {
        // v = 0.01 + 0.5 t: mean over the second half of 0–40 ms is 0.01 + 0.5 · 30 ms
        let t: Vec<f64> = (0..=40).map(|k| k as f64 / 1000.0).collect();
        let vx: Vec<f64> = t.iter().map(|t| 0.01 + 0.5 * t).collect();
        let adv = vec![100.0; t.len()];
        let rec: Vec<f64> = (0..t.len()).map(|k| 60.0 + (k % 2) as f64).collect();
        let s = slide(&t, &adv, &rec, &vx, true);
        assert!((s.from_s - 0.02).abs() < 1e-15);
        assert!((s.speed_m_s - 0.025).abs() < 1e-12, "{s:?}");
        assert!((s.acceleration_m_s2 - 0.5).abs() < 1e-9, "{s:?}");
        assert_eq!(s.advancing_deg, (100.0, 0.0));
        assert!((s.receding_deg.1 - 0.5).abs() < 1e-12);
    }
}
