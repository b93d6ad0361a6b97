//! Data ranges: fitted to the finite values with a margin, taken from the caller when usable,
//! and widened when they have (nearly) zero width.

/// Widens a range of (nearly) zero width around its centre.
pub(super) fn widen(lo: f64, hi: f64) -> (f64, f64) {
    let (lo, hi) = if lo <= hi { (lo, hi) } else { (hi, lo) };
    let mag = lo.abs().max(hi.abs());
    if hi - lo > mag * 1e-9 && hi - lo > 0.0 {
        return (lo, hi);
    }
    let c = 0.5 * (lo + hi);
    let half = if mag > 0.0 { 0.05 * mag } else { 1.0 };
    (c - half, c + half)
}

/// A caller-given range if it is usable: both ends finite (put in order and widened).
pub(super) fn given_range(r: Option<(f64, f64)>) -> Option<(f64, f64)> {
    match r {
        Some((a, b)) if a.is_finite() && b.is_finite() => Some(widen(a, b)),
        _ => None,
    }
}

/// The range of the finite values with a 5 % margin on each side, `None` if there is none.
pub(super) fn auto_range(values: impl IntoIterator<Item = f64>) -> Option<(f64, f64)> {
    let (lo, hi) = finite_extent(values)?;
    let (lo, hi) = widen(lo, hi);
    let pad = 0.05 * (hi - lo);
    let (plo, phi) = (lo - pad, hi + pad);
    if plo.is_finite() && phi.is_finite() {
        Some((plo, phi))
    } else {
        Some((lo, hi))
    }
}

/// The smallest and largest finite value, `None` if there is none.
pub(super) fn finite_extent(values: impl IntoIterator<Item = f64>) -> Option<(f64, f64)> {
    values
        .into_iter()
        .filter(|v| v.is_finite())
        .fold(None, |acc, v| match acc {
            None => Some((v, v)),
            Some((lo, hi)) => Some((lo.min(v), hi.max(v))),
        })
}

/// The extent of the finite values without margin (widened if of zero width), `(0, 1)` if
/// there is none.
pub(super) fn tight_range(values: impl IntoIterator<Item = f64>) -> (f64, f64) {
    finite_extent(values)
        .map(|(a, b)| widen(a, b))
        .unwrap_or((0.0, 1.0))
}

/// Whether both coordinates of the point are finite.
pub(super) fn is_finite_point(&(x, y): &(f64, f64)) -> bool {
    x.is_finite() && y.is_finite()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_survive_degenerate_input() {
        assert_eq!(widen(2.0, 2.0), (1.9, 2.1));
        assert_eq!(widen(0.0, 0.0), (-1.0, 1.0));
        assert_eq!(widen(3.0, 1.0), (1.0, 3.0));
        assert_eq!(auto_range([f64::NAN, f64::INFINITY]), None);
        let (lo, hi) = auto_range([0.0, 10.0, f64::NAN]).unwrap();
        assert!((lo + 0.5).abs() < 1e-12 && (hi - 10.5).abs() < 1e-12);
        assert_eq!(given_range(Some((f64::NAN, 1.0))), None);
    }
}
