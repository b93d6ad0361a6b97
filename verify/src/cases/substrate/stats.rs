//! Statistics of the probe series: the settled mean and its residual oscillation, and the
//! settling time.

/// Mean and half the peak-to-peak range of the finite values of `y` at times `t ≥ from_s` [s].
pub fn tail_stats(t: &[f64], y: &[f64], from_s: f64) -> (f64, f64) {
    let v: Vec<f64> = t
        .iter()
        .zip(y)
        .filter(|(t, y)| **t >= from_s && y.is_finite())
        .map(|(_, y)| *y)
        .collect();
    if v.is_empty() {
        return (f64::NAN, f64::NAN);
    }
    let mean = v.iter().sum::<f64>() / v.len() as f64;
    let (lo, hi) = v
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
            (a.min(x), b.max(x))
        });
    (mean, 0.5 * (hi - lo))
}

/// The last time [s] at which `y` was farther than `band` from `settled`: the settling time.
/// NaN without data; 0 if `y` never left the band.
pub fn settling_time(t: &[f64], y: &[f64], settled: f64, band: f64) -> f64 {
    if t.is_empty() || !settled.is_finite() {
        return f64::NAN;
    }
    t.iter()
        .zip(y)
        .filter(|(_, y)| !y.is_finite() || (**y - settled).abs() > band)
        .map(|(t, _)| *t)
        .fold(0.0, f64::max)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tail_and_settling() {
        let t: Vec<f64> = (0..100).map(|k| k as f64 * 1e-3).collect();
        // a decaying oscillation about 2.0
        let y: Vec<f64> = t
            .iter()
            .map(|&t| 2.0 + (-t / 0.01f64).exp() * (600.0 * t).cos())
            .collect();
        let (m, half) = tail_stats(&t, &y, 0.08);
        assert!((m - 2.0).abs() < 1e-3 && half < 1e-3, "{m} {half}");
        // |y − 2| ≤ e^{−t/0.01} falls below 0.02 at t = 0.01 ln 50 = 39 ms
        let ts = settling_time(&t, &y, 2.0, 0.02);
        assert!(ts > 0.03 && ts <= 0.04, "{ts}");
        assert!(settling_time(&[], &[], 2.0, 0.1).is_nan());
    }
}
