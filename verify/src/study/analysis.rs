//! The study's analysis: Pareto fronts, convergence orders and the written conclusions.

use super::grid::Variant;
use super::points::PointResult;
use crate::measure::convergence::observed_order;
use std::fmt::Write as _;

/// Indices of the points on the Pareto front of |error| against wall time (no other point is
/// both faster and more accurate), fastest first.
pub fn pareto_front(points: &[&PointResult]) -> Vec<usize> {
    let mut idx: Vec<usize> = (0..points.len())
        .filter(|&i| points[i].relative_error.is_finite())
        .collect();
    idx.sort_by(|&a, &b| points[a].wall_time_s.total_cmp(&points[b].wall_time_s));
    let mut best = f64::INFINITY;
    let mut front = Vec::new();
    for i in idx {
        let e = points[i].relative_error.abs();
        if e < best {
            best = e;
            front.push(i);
        }
    }
    front
}

/// Least-squares order `p` of `|error| ∝ l0^p` and its R², from at least three points
/// ([`observed_order`]).
pub fn convergence_order(points: &[&PointResult]) -> Option<(f64, f64)> {
    let (l0, err): (Vec<f64>, Vec<f64>) = points
        .iter()
        .filter(|p| p.relative_error.is_finite() && p.relative_error != 0.0)
        .map(|p| (p.l0_m, p.relative_error))
        .unzip();
    if l0.len() < 3 {
        return None;
    }
    observed_order(&l0, &err)
}

/// Conclusions in words, drawn from the data: the front, the cheapest point at 5 % and 2 %, and
/// the variants that never pay.
pub(super) fn words(pts: &[&PointResult], front: &[usize], variants: &[Variant]) -> String {
    let mut s = String::new();
    let on_front: Vec<String> = front
        .iter()
        .map(|&i| {
            format!(
                "{} at resolution {} ({:+.1} %, {:.1} s)",
                pts[i].point.variant.label(),
                pts[i].point.resolution,
                100.0 * pts[i].relative_error,
                pts[i].wall_time_s
            )
        })
        .collect();
    let _ = write!(
        s,
        "**Worth it** (the Pareto front, fastest first): {}. ",
        on_front.join("; ")
    );
    for limit in [0.05, 0.02] {
        let cheapest = pts
            .iter()
            .filter(|r| r.relative_error.abs() <= limit)
            .min_by(|a, b| a.wall_time_s.total_cmp(&b.wall_time_s));
        match cheapest {
            Some(r) => {
                let _ = write!(
                    s,
                    "The cheapest point within {:.0} % is {} at resolution {} ({:.1} s). ",
                    limit * 100.0,
                    r.point.variant.label(),
                    r.point.resolution,
                    r.wall_time_s
                );
            }
            None => {
                let _ = write!(s, "No point reaches {:.0} %. ", limit * 100.0);
            }
        }
    }
    let never: Vec<String> = variants
        .iter()
        .filter(|v| !front.iter().any(|&i| pts[i].point.variant == **v))
        .map(|v| v.label())
        .collect();
    if !never.is_empty() {
        let _ = write!(s, "**Not worth it here** (never on the front: another setting is both faster and more accurate): {}.", never.join(", "));
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::study::grid::{Point, Problem, Variant};

    fn result(l0: f64, err: f64, time: f64) -> PointResult {
        PointResult {
            point: Point {
                problem: Problem::CubeDrop,
                variant: Variant::DEFAULT,
                resolution: 10,
            },
            l0_m: l0,
            particles: 1000,
            value: 1.0 + err,
            reference: 1.0,
            relative_error: err,
            wall_time_s: time,
            particle_steps_per_second: 1e6,
            mean_neighbours: 30.0,
            peak_memory_bytes: None,
            machine: None,
            simulated_time_s: 1e-3,
            status: "completed".into(),
        }
    }

    #[test]
    fn order_of_a_second_order_series_is_two() {
        let pts: Vec<PointResult> = [1.0, 0.5, 0.25]
            .iter()
            .map(|&l| result(l, 0.3 * l * l, 1.0 / l))
            .collect();
        let refs: Vec<&PointResult> = pts.iter().collect();
        let (p, r2) = convergence_order(&refs).unwrap();
        assert!((p - 2.0).abs() < 1e-12 && (r2 - 1.0).abs() < 1e-12);
    }

    #[test]
    fn pareto_keeps_only_points_no_other_beats() {
        let pts = [
            result(1.0, 0.10, 1.0),
            result(1.0, 0.20, 2.0),
            result(1.0, -0.05, 3.0),
            result(1.0, f64::NAN, 0.5),
        ];
        let refs: Vec<&PointResult> = pts.iter().collect();
        assert_eq!(pareto_front(&refs), vec![0, 2]);
    }
}
