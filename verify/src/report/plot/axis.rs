//! Axes: a linear range with ticks at 1, 2 or 5 × 10ⁿ, minor grid positions and compact tick
//! labels; the axis serves as plotters' coordinate itself.

use std::ops::Range;

use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint, Ranged};

use super::range::widen;

/// One axis: its range, the labelled ticks and the minor grid positions.
#[derive(Debug, Clone)]
pub(super) struct Axis {
    /// Lower end of the range.
    pub(super) lo: f64,
    /// Upper end of the range.
    pub(super) hi: f64,
    /// Labelled tick positions (bold mesh lines).
    pub(super) ticks: Vec<f64>,
    /// Minor grid positions (light mesh lines).
    minor: Vec<f64>,
    /// Distance between ticks.
    step: f64,
    /// Largest tick magnitude (it decides between fixed-point and exponent labels).
    max_abs: f64,
}

impl Axis {
    /// Ticks at multiples of 1, 2 or 5 × 10ⁿ, about `target` of them over `[lo, hi]`.
    pub(super) fn new((lo, hi): (f64, f64), target: usize) -> Self {
        let (lo, hi) = widen(lo, hi);
        let span = hi - lo;
        let raw = span / target.max(1) as f64;
        let mag = 10f64.powf(raw.log10().floor());
        let norm = raw / mag;
        let (nice, minor_div) = if norm <= 1.0 {
            (1.0, 5.0)
        } else if norm <= 2.0 {
            (2.0, 4.0)
        } else if norm <= 5.0 {
            (5.0, 5.0)
        } else {
            (10.0, 5.0)
        };
        let step = nice * mag;
        let ticks = multiples(lo, hi, step);
        let minor = multiples(lo, hi, step / minor_div);
        let (ticks, step) = match ticks {
            Some(t) if !t.is_empty() => (t, step),
            _ => (vec![lo, hi], span),
        };
        let minor = minor.unwrap_or_default();
        let max_abs = ticks.iter().fold(0f64, |m, t| m.max(t.abs()));
        Self {
            lo,
            hi,
            ticks,
            minor,
            step,
            max_abs,
        }
    }

    /// The tick label of value `v`.
    pub(super) fn label(&self, v: f64) -> String {
        format_tick(v, self.step, self.max_abs)
    }

    /// The middle of the range.
    pub(super) fn mid(&self) -> f64 {
        0.5 * (self.lo + self.hi)
    }
}

/// The axis is its own coordinate: linear, with the module's ticks as bold mesh lines and
/// labels and the minor positions as light mesh lines.
impl Ranged for Axis {
    type FormatOption = DefaultFormatting;
    type ValueType = f64;

    fn map(&self, value: &f64, limit: (i32, i32)) -> i32 {
        let t = (value - self.lo) / (self.hi - self.lo);
        let p = f64::from(limit.0) + f64::from(limit.1 - limit.0) * t;
        if p.is_nan() {
            limit.0
        } else {
            // Far outside the area (only reachable for unclipped elements): keep i32 safe.
            p.clamp(-1e7, 1e7).round() as i32
        }
    }

    fn key_points<H: KeyPointHint>(&self, hint: H) -> Vec<f64> {
        if hint.weight().allow_light_points() {
            self.minor.clone()
        } else {
            self.ticks.clone()
        }
    }

    fn range(&self) -> Range<f64> {
        self.lo..self.hi
    }
}

/// The multiples of `step` within `[lo, hi]`, `None` if the step is unusable or gives too many.
fn multiples(lo: f64, hi: f64, step: f64) -> Option<Vec<f64>> {
    if !(step.is_finite() && step > 0.0) {
        return None;
    }
    let first = (lo / step - 1e-9).ceil();
    let last = (hi / step + 1e-9).floor();
    if !(first.is_finite() && last.is_finite()) || last - first > 1000.0 {
        return None;
    }
    let mut out = Vec::new();
    let mut k = first;
    while k <= last {
        let v = k * step;
        out.push(if v.abs() < step * 1e-9 { 0.0 } else { v });
        k += 1.0;
    }
    Some(out)
}

/// A compact tick label: fixed-point with the decimals the step needs, or `1.5e-3` style
/// when the largest tick magnitude is below 1e-2 or at least 1e5.
fn format_tick(v: f64, step: f64, max_abs: f64) -> String {
    if !v.is_finite() {
        return String::new();
    }
    if v == 0.0 || (step > 0.0 && v.abs() < step * 1e-6) {
        return "0".to_string();
    }
    let step_exp = if step > 0.0 && step.is_finite() {
        (step.log10() + 1e-9).floor() as i32
    } else {
        v.abs().log10().floor() as i32 - 2
    };
    if !(1e-2..1e5).contains(&max_abs) {
        let exp = (v.abs().log10() + 1e-9).floor() as i32;
        let digits = (exp - step_exp).clamp(0, 10) as usize;
        let s = format!("{v:.digits$e}");
        match s.split_once('e') {
            Some((mantissa, e)) if mantissa.contains('.') => {
                format!(
                    "{}e{e}",
                    mantissa.trim_end_matches('0').trim_end_matches('.')
                )
            }
            _ => s,
        }
    } else {
        let digits = (-step_exp).clamp(0, 10) as usize;
        format!("{v:.digits$}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tick_labels_are_compact() {
        let a = Axis::new((0.0, 1.0e-3), 5);
        let labels: Vec<String> = a.ticks.iter().map(|&t| a.label(t)).collect();
        assert_eq!(labels, ["0", "2e-4", "4e-4", "6e-4", "8e-4", "1e-3"]);
        let a = Axis::new((1.0e-3, 2.0e-3), 4);
        assert_eq!(a.label(1.5e-3), "1.5e-3");
        let a = Axis::new((0.0, 1.0), 5);
        assert_eq!(a.label(0.4), "0.4");
        assert_eq!(a.label(1.0), "1.0");
        let a = Axis::new((0.0, 500.0), 5);
        assert_eq!(a.label(300.0), "300");
        let a = Axis::new((0.0, 3.0e6), 3);
        assert_eq!(a.label(2.0e6), "2e6");
        assert_eq!(format_tick(-0.0, 0.1, 1.0), "0");
        assert_eq!(format_tick(f64::NAN, 0.1, 1.0), "");
    }

    #[test]
    fn ticks_survive_degenerate_ranges() {
        for (lo, hi) in [
            (0.0, 1e-300),
            (1.0, 1.0 + 1e-15),
            (-1e300, 1e300),
            (5.0, 5.0),
        ] {
            let a = Axis::new((lo, hi), 7);
            assert!(!a.ticks.is_empty() && a.ticks.len() < 1000);
            assert!(a.lo < a.hi);
        }
    }
}
