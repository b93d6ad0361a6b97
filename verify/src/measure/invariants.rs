//! Invariants of a healthy run, measured on its outputs: one connected body, no clumping, no
//! particle inside a wall, conserved counts, mass and momentum, bounded energy.

use nalgebra::{DMatrix, DVector};
use solver::model::WallSolid;
use solver::neighbours::NeighbourSearch;
use solver::scene::Scene;
use solver::state::Vec3;

/// Number of connected bodies: particles closer than `link_m` [m] belong to the same body.
pub fn components(points: &[[f64; 3]], link_m: f64) -> usize {
    if points.is_empty() {
        return 0;
    }
    let mut search = NeighbourSearch::new(link_m, link_m, 0.0);
    let pos: Vec<Vec3> = points.iter().map(|p| Vec3::from(*p)).collect();
    let Ok(order) = search.sort_order(&pos) else {
        return usize::MAX; // a particle outside the grid: certainly not one body
    };
    let sorted: Vec<Vec3> = order.iter().map(|&i| pos[i as usize]).collect();
    if search.build(&sorted, sorted.len()).is_err() {
        return usize::MAX;
    }
    // union–find over the sorted indices
    let mut parent: Vec<usize> = (0..sorted.len()).collect();
    fn root(parent: &mut [usize], mut i: usize) -> usize {
        while parent[i] != i {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }
        i
    }
    for i in 0..sorted.len() {
        for j in search.lists.near(i) {
            let (a, b) = (root(&mut parent, i), root(&mut parent, j));
            if a != b {
                parent[a.max(b)] = a.min(b);
            }
        }
    }
    (0..sorted.len())
        .filter(|&i| root(&mut parent, i) == i)
        .count()
}

/// Fraction of particles whose nearest neighbour is closer than half a spacing `l0_m` [m]:
/// a sign of particles clumping into clusters (the pairing instability).
pub fn clumped_fraction(points: &[[f64; 3]], l0_m: f64) -> f64 {
    if points.len() < 2 {
        return 0.0;
    }
    let r = 0.5 * l0_m;
    let mut search = NeighbourSearch::new(r, r, 0.0);
    let pos: Vec<Vec3> = points.iter().map(|p| Vec3::from(*p)).collect();
    let Ok(order) = search.sort_order(&pos) else {
        return 1.0;
    };
    let sorted: Vec<Vec3> = order.iter().map(|&i| pos[i as usize]).collect();
    if search.build(&sorted, sorted.len()).is_err() {
        return 1.0;
    }
    let clumped = (0..sorted.len())
        .filter(|&i| !search.lists.near(i).is_empty())
        .count();
    clumped as f64 / points.len() as f64
}

/// Liquid particles inside a wall of `scene`: deeper than half a spacing past a face, and more
/// than one spacing inside a disk's rim — the rule of the solver's wall-entry health check
/// ([`WallSolid`]).
pub fn inside_walls(points: &[[f64; 3]], scene: &Scene) -> usize {
    let half = 0.5 * scene.discretisation.l0;
    let walls = WallSolid::of(scene);
    points
        .iter()
        .filter(|p| walls.iter().any(|w| w.holds(**p, half)))
        .count()
}

/// The largest growth of `energy` [J] after the first `skip` fraction of the series, above its
/// value there.
pub fn energy_growth(energy: &[f64], skip: f64) -> f64 {
    let from = ((energy.len() as f64 * skip) as usize).min(energy.len().saturating_sub(1));
    let Some(&e0) = energy.get(from) else {
        return f64::NAN;
    };
    energy[from..].iter().fold(0.0f64, |g, &e| g.max(e - e0))
}

/// The secular trend of `value` over `time_s` [value's unit per s] from `from_s` [s] on, through
/// an oscillation of period `period_s` [s]: the slope `b` of the least-squares fit
/// `a + b t + c cos(2πt/P) + d sin(2πt/P)`. An oscillating drop's energies swing at half its
/// mode's period, and a plain line fitted over a period or two would lean with that swing's
/// phase. A swing that decays within the samples leaks into the slope (tests: at most 15 % of
/// its amplitude per period when it decays by 0.8 per period, where a plain line leans by up to
/// 38 %). NaN with fewer than 5 samples from `from_s` on, unequal lengths, a period that is not
/// positive and finite, or a singular fit (the samples span no time).
pub fn secular_trend(time_s: &[f64], value: &[f64], from_s: f64, period_s: f64) -> f64 {
    if time_s.len() != value.len() || !(period_s > 0.0 && period_s.is_finite()) {
        return f64::NAN;
    }
    let rows: Vec<(f64, f64)> = (time_s.iter().zip(value))
        .filter(|(t, _)| **t >= from_s)
        .map(|(t, v)| (*t, *v))
        .collect();
    if rows.len() < 5 {
        return f64::NAN;
    }
    // times from the first sample, in periods, for conditioning
    let t0 = rows[0].0;
    let w = 2.0 * std::f64::consts::PI;
    let design = DMatrix::from_fn(rows.len(), 4, |r, c| {
        let x = (rows[r].0 - t0) / period_s;
        match c {
            0 => 1.0,
            1 => x,
            2 => (w * x).cos(),
            _ => (w * x).sin(),
        }
    });
    let rhs = DVector::from_iterator(rows.len(), rows.iter().map(|r| r.1));
    match design.svd(true, true).solve(&rhs, 1e-12) {
        Ok(c) if c[1].is_finite() => c[1] / period_s,
        _ => f64::NAN,
    }
}

/// The largest distance of the vector with components `xyz` from its first value (in their
/// unit).
pub fn drift([x, y, z]: [Vec<f64>; 3]) -> f64 {
    (0..x.len())
        .map(|k| ((x[k] - x[0]).powi(2) + (y[k] - y[0]).powi(2) + (z[k] - z[0]).powi(2)).sqrt())
        .fold(0.0, f64::max)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lattice(n: i32, offset: f64) -> Vec<[f64; 3]> {
        let mut v = Vec::new();
        for k in 0..n {
            for j in 0..n {
                for i in 0..n {
                    v.push([i as f64 + offset, j as f64, k as f64]);
                }
            }
        }
        v
    }

    #[test]
    fn a_secular_trend_is_read_through_an_oscillation() {
        use std::f64::consts::PI;
        // e = 1 + 0.3 t + 0.5 sin(2π t/1.1 + 0.7) over 1.3 periods: the fit holds the
        // oscillation exactly, so the slope is 0.3 to round-off (1e-9); a line alone would
        // lean by about the swing's amplitude per period.
        let t: Vec<f64> = (0..=143).map(|k| 5.0 + k as f64 * 0.01).collect();
        let swing = |x: f64| 0.5 * (2.0 * PI * x / 1.1 + 0.7).sin();
        let e: Vec<f64> = t.iter().map(|&x| 1.0 + 0.3 * x + swing(x)).collect();
        let s = secular_trend(&t, &e, 0.0, 1.1);
        assert!((s - 0.3).abs() < 1e-9, "{s}");
        // A swing that decays leaks into the slope. Decaying by 0.8 per period (e^{−0.2 t}),
        // over 13 phases: measured worst 0.068 off the trend of 0.3 (15 % of the swing's
        // amplitude per period; a plain line leaks up to 0.17, measured in a scratch
        // script); asserted within 0.08.
        let decaying = |ph: f64| -> Vec<f64> {
            (t.iter())
                .map(|&x| {
                    1.0 + 0.3 * x + 0.5 * (-0.2 * (x - 5.0)).exp() * (2.0 * PI * x / 1.1 + ph).sin()
                })
                .collect()
        };
        let worst = (0..13)
            .map(|k| (secular_trend(&t, &decaying(k as f64 * PI / 6.0), 0.0, 1.1) - 0.3).abs())
            .fold(0.0, f64::max);
        println!("decaying swing: worst leak {worst}");
        assert!(worst < 0.08, "{worst}");
        // from_s cuts the start (the steady swing, exact over any window); a constant has no
        // trend; bad input gives NaN
        let e: Vec<f64> = t.iter().map(|&x| 1.0 + 0.3 * x + swing(x)).collect();
        assert!((secular_trend(&t, &e, 5.5, 1.1) - 0.3).abs() < 1e-9);
        assert!(secular_trend(&t, &vec![2.0; t.len()], 0.0, 1.1).abs() < 1e-12);
        assert!(secular_trend(&t[..4], &e[..4], 0.0, 1.1).is_nan());
        assert!(secular_trend(&t, &e[..10], 0.0, 1.1).is_nan());
        assert!(secular_trend(&t, &e, 0.0, 0.0).is_nan());
        assert!(secular_trend(&t, &e, 100.0, 1.1).is_nan());
    }

    #[test]
    fn two_separate_blocks_are_two_bodies_and_one_block_is_one() {
        // spacing 1, link 1.5: a block is connected; a second block 3 spacings away is not
        let mut pts = lattice(4, 0.0);
        assert_eq!(components(&pts, 1.5), 1);
        pts.extend(lattice(4, 7.0));
        assert_eq!(components(&pts, 1.5), 2);
        pts.push([100.0, 100.0, 100.0]);
        assert_eq!(components(&pts, 1.5), 3);
        assert_eq!(components(&[], 1.5), 0);
    }

    #[test]
    fn clumping_counts_pairs_closer_than_half_a_spacing() {
        let mut pts = lattice(5, 0.0);
        assert_eq!(clumped_fraction(&pts, 1.0), 0.0);
        // move the particle at (0, j, k) to (0.8, j, k), 0.2 from (1, j, k), for 10 rows:
        // 20 particles are clumped
        for k in 0..2 {
            for j in 0..5 {
                pts[(k * 25 + j * 5) as usize][0] = 0.8;
            }
        }
        let f = clumped_fraction(&pts, 1.0);
        assert!((f - 20.0 / 125.0).abs() < 1e-12, "{f}");
    }

    #[test]
    fn energy_growth_after_the_transient() {
        let e = [5.0, 9.0, 3.0, 3.5, 3.2, 3.4];
        // from index 2 (skip 1/3): growth above 3.0 is 0.5
        assert!((energy_growth(&e, 0.34) - 0.5).abs() < 1e-12);
        assert_eq!(energy_growth(&[1.0, 0.5, 0.2], 0.0), 0.0);
    }

    #[test]
    fn drift_is_the_largest_distance_from_the_start() {
        // a point moving from the origin to (3, 4, 0) and back halfway: 5 from its start
        let d = drift([vec![0.0, 3.0, 1.5], vec![0.0, 4.0, 2.0], vec![0.0; 3]]);
        assert_eq!(d, 5.0);
        assert_eq!(drift([vec![], vec![], vec![]]), 0.0);
    }
}
