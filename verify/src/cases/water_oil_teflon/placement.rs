//! Where the liquids ended on the plate.
//!
//! On a wall made of particles the liquids' sideways momentum is not conserved (the pressure and
//! potential pairs with wall particles act along pair directions that have tangential parts), and
//! the water–oil pair breaks its axial symmetry: these numbers say how far it went, whether the
//! oil reached the plate's edge (where the run stops being the paper's open plate), and whether
//! any oil stayed over the water as in the paper's picture.

use crate::output::dump::Dump;
use crate::output::timeseries::{Axis, LiquidColumn, RunColumn, Table};

/// How far the liquids' common centre of mass moved off the plate's axis over a run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Drift {
    /// The largest horizontal distance of the centre of mass from the axis [m].
    pub largest_m: f64,
    /// When it was largest [s].
    pub at_s: f64,
    /// The distance at the run's end [m].
    pub last_m: f64,
}

/// The drift of the liquids' common centre of mass from the axis `x = y = 0`, from the mass and
/// the horizontal centroid of each liquid in the run's time series; `None` if the series has
/// no rows or lacks a liquid's columns.
pub fn drift(ts: &Table, liquids: &[&str]) -> Option<Drift> {
    let time = ts.run_column(RunColumn::Time);
    let columns: Vec<[Vec<f64>; 3]> = liquids
        .iter()
        .map(|l| {
            [
                ts.liquid_column(l, LiquidColumn::Mass),
                ts.liquid_column(l, LiquidColumn::Centroid(Axis::X)),
                ts.liquid_column(l, LiquidColumn::Centroid(Axis::Y)),
            ]
        })
        .collect();
    if time.is_empty() || columns.iter().flatten().any(|c| c.len() != time.len()) {
        return None;
    }
    let offset = |k: usize| {
        let (mut m, mut mx, mut my) = (0.0, 0.0, 0.0);
        for [mass, x, y] in &columns {
            m += mass[k];
            mx += mass[k] * x[k];
            my += mass[k] * y[k];
        }
        (mx / m).hypot(my / m)
    };
    let mut out = Drift {
        largest_m: f64::NEG_INFINITY,
        at_s: f64::NAN,
        last_m: offset(time.len() - 1),
    };
    for (k, &t) in time.iter().enumerate() {
        let d = offset(k);
        if d > out.largest_m {
            out.largest_m = d;
            out.at_s = t;
        }
    }
    Some(out)
}

/// Where a final state's liquids lie on a plate whose top is `z = 0` and whose axis is
/// `x = y = 0`.
///
/// What went over the edge is counted by the horizontal distance, not by `z < 0`: a film of
/// oil on the Teflon sits up to ~0.15 l0 below the plate's nominal top (pressed between the
/// wall particles' layer and the liquid above it) without leaving the plate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ending {
    /// The largest horizontal distance of a particle of the liquid `reach_phase` from the
    /// axis [m].
    pub reach_m: f64,
    /// Liquid particles farther from the axis than the plate's radius (gone over its edge) [-].
    pub off_plate: usize,
    /// The share of the particles of liquid `over` that lie higher than every particle of
    /// liquid `under` [-] (0 if none does, NaN if either has no particles).
    pub share_over: f64,
}

/// The [`Ending`] of `dump` on a plate of radius `plate_radius_m` [m]: the reach of phase
/// `reach_phase`, what went over the edge, and the share of phase `over` above the highest
/// particle of phase `under`.
pub fn ending(dump: &Dump, plate_radius_m: f64, reach_phase: u8, over: u8, under: u8) -> Ending {
    let liquid = || {
        dump.pos
            .iter()
            .zip(dump.phase.iter().zip(&dump.wall))
            .filter(|(_, (_, &wall))| !wall)
            .map(|(p, (&ph, _))| (p, ph))
    };
    let reach_m = liquid()
        .filter(|&(_, ph)| ph == reach_phase)
        .map(|(p, _)| p[0].hypot(p[1]))
        .fold(f64::NAN, f64::max);
    let off_plate = liquid()
        .filter(|(p, _)| p[0].hypot(p[1]) > plate_radius_m)
        .count();
    let top_under = liquid()
        .filter(|&(_, ph)| ph == under)
        .map(|(p, _)| p[2])
        .fold(f64::NAN, f64::max);
    let (n_over, n_above) = liquid()
        .filter(|&(_, ph)| ph == over)
        .fold((0usize, 0usize), |(n, a), (p, _)| {
            (n + 1, a + usize::from(p[2] > top_under))
        });
    let share_over = if n_over == 0 || top_under.is_nan() {
        f64::NAN
    } else {
        n_above as f64 / n_over as f64
    };
    Ending {
        reach_m,
        off_plate,
        share_over,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn table(columns: &[&str], rows: Vec<Vec<f64>>) -> Table {
        Table {
            columns: columns.iter().map(|c| c.to_string()).collect(),
            rows,
        }
    }

    #[test]
    fn drift_weighs_the_liquids_by_mass_and_finds_the_largest_offset() {
        let cols = [
            "time_s",
            "a_mass_kg",
            "a_centroid_x_m",
            "a_centroid_y_m",
            "b_mass_kg",
            "b_centroid_x_m",
            "b_centroid_y_m",
        ];
        let ts = table(
            &cols,
            vec![
                // a on the axis, b (3 times lighter) 4 m out: centre of mass 1 m out
                vec![0.0, 3.0, 0.0, 0.0, 1.0, 4.0, 0.0],
                // a at (3, 0), b at (3, 8): centre (3, 2), sqrt(13) m out
                vec![1.0, 3.0, 3.0, 0.0, 1.0, 3.0, 8.0],
                // back towards the axis: (0, 0) and (0, -4): 1 m out
                vec![2.0, 3.0, 0.0, 0.0, 1.0, 0.0, -4.0],
            ],
        );
        let d = drift(&ts, &["a", "b"]).unwrap();
        assert!((d.largest_m - 13f64.sqrt()).abs() < 1e-12);
        assert_eq!(d.at_s, 1.0);
        assert!((d.last_m - 1.0).abs() < 1e-12);
        // a liquid the series does not have
        assert!(drift(&ts, &["a", "c"]).is_none());
        assert!(drift(&table(&cols, vec![]), &["a", "b"]).is_none());
    }

    #[test]
    fn ending_finds_the_reach_what_fell_off_and_what_lies_over() {
        let dump = Dump {
            time_s: 1.0,
            pos: vec![
                [0.0, 0.0, 2.0],  // water, its top at z = 2
                [1.0, 0.0, 1.0],  // water
                [0.0, 3.0, 2.5],  // oil above the water's top
                [4.0, 3.0, 1.0],  // oil, 5 from the axis
                [0.0, -2.0, 0.5], // oil
                [6.0, 0.0, -0.5], // water over the edge (plate radius 5.5), below its top
                [0.0, 1.0, -0.1], // water pressed below the top on the plate: not off it
                [9.0, 9.0, -1.0], // a wall particle: ignored
            ],
            vel: vec![[0.0; 3]; 8],
            phase: vec![0, 0, 1, 1, 1, 0, 0, 2],
            wall: vec![false, false, false, false, false, false, false, true],
        };
        let e = ending(&dump, 5.5, 1, 1, 0);
        assert_eq!(e.reach_m, 5.0);
        assert_eq!(e.off_plate, 1);
        assert!((e.share_over - 1.0 / 3.0).abs() < 1e-15);
        // a plate wide enough for every particle: nothing off it
        assert_eq!(ending(&dump, 7.0, 1, 1, 0).off_plate, 0);
        // no particle of the phase below: no share
        assert!(ending(&dump, 5.5, 1, 1, 5).share_over.is_nan());
    }
}
