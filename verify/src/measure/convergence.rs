//! The observed order of convergence: the slope `p` of `ln|error|` against `ln l0`.

/// Least-squares order `p` of `|error| ∝ l0^p` and its R², from the points whose error is
/// finite and non-zero; `None` from fewer than two such points or a single spacing. A positive
/// order means the error falls as `l0` is refined; a negative one, that it grows.
pub fn observed_order(l0: &[f64], error: &[f64]) -> Option<(f64, f64)> {
    let xy: Vec<(f64, f64)> = l0
        .iter()
        .zip(error)
        .filter(|(h, e)| h.is_finite() && **h > 0.0 && e.is_finite() && **e != 0.0)
        .map(|(h, e)| (h.ln(), e.abs().ln()))
        .collect();
    if xy.len() < 2 {
        return None;
    }
    let n = xy.len() as f64;
    let mx = xy.iter().map(|p| p.0).sum::<f64>() / n;
    let my = xy.iter().map(|p| p.1).sum::<f64>() / n;
    let sxx: f64 = xy.iter().map(|p| (p.0 - mx).powi(2)).sum();
    let sxy: f64 = xy.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let syy: f64 = xy.iter().map(|p| (p.1 - my).powi(2)).sum();
    if sxx == 0.0 {
        return None;
    }
    let r2 = if syy > 0.0 {
        sxy * sxy / (sxx * syy)
    } else {
        1.0
    };
    Some((sxy / sxx, r2))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_power_law_gives_its_exponent_with_either_sign_of_the_error() {
        let h = [0.1, 0.07, 0.05, 0.03];
        for p in [1.0, 2.0, -0.7] {
            let e: Vec<f64> = h
                .iter()
                .enumerate()
                .map(|(k, x): (usize, &f64)| if k % 2 == 0 { 3.0 } else { -3.0 } * x.powf(p))
                .collect();
            let (q, r2) = observed_order(&h, &e).unwrap();
            assert!(
                (q - p).abs() < 1e-12 && (r2 - 1.0).abs() < 1e-12,
                "{p}: {q}, {r2}"
            );
        }
    }

    #[test]
    fn too_few_or_degenerate_points_give_none() {
        assert_eq!(observed_order(&[0.1], &[0.2]), None);
        assert_eq!(observed_order(&[0.1, 0.1], &[0.2, 0.1]), None);
        assert_eq!(observed_order(&[0.1, 0.05], &[f64::NAN, 0.1]), None);
        assert!(observed_order(&[0.1, 0.05, 0.02], &[0.0, 0.1, 0.05]).is_some());
    }
}
