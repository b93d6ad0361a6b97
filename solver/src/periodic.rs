//! Periodic boundaries: the minimum-image convention along the axes a scene declares periodic.
//!
//! A periodic axis has a range `[lo, lo + L)`; a particle that leaves it re-enters at the other
//! side (positions are wrapped when the neighbour lists are rebuilt), and every pair vector
//! `x_i − x_j` is the shortest one among the periodic images. The box must be at least twice
//! the neighbour-search cut-off along each periodic axis so that this image is unique (the
//! model refuses smaller boxes).
//!
//! An open axis has `L = 0` and `1/L = 0`, so the wrap `d − L·round(d/L)` leaves the
//! difference exactly as it was: a scene without periodic axes computes the same bits as
//! before periodic boundaries existed.

use crate::state::Vec3;
use serde::{Deserialize, Serialize};

/// The periodic axes of a scene and their ranges.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct PeriodicBox {
    /// Lower end of each axis's range [m] (0 for an open axis).
    lo_m: [f64; 3],
    /// Period `L` along each axis [m] (0 for an open axis).
    len_m: [f64; 3],
    /// `1/L` [1/m] (0 for an open axis).
    inv_len_per_m: [f64; 3],
    /// Whether any axis is periodic.
    any: bool,
}

impl PeriodicBox {
    /// No periodic axis.
    pub const OPEN: PeriodicBox = PeriodicBox {
        lo_m: [0.0; 3],
        len_m: [0.0; 3],
        inv_len_per_m: [0.0; 3],
        any: false,
    };

    /// A box from the range `[lo, hi]` [m] of each periodic axis (`None`: open).
    pub fn new(ranges: [Option<[f64; 2]>; 3]) -> Self {
        let mut b = Self::OPEN;
        for (k, r) in ranges.iter().enumerate() {
            if let Some([lo, hi]) = *r {
                b.lo_m[k] = lo;
                b.len_m[k] = hi - lo;
                b.inv_len_per_m[k] = 1.0 / (hi - lo);
                b.any = true;
            }
        }
        b
    }

    /// Whether any axis is periodic.
    #[inline(always)]
    pub fn is_periodic(&self) -> bool {
        self.any
    }

    /// Whether `axis` (0, 1, 2) is periodic.
    pub fn axis_is_periodic(&self, axis: usize) -> bool {
        self.len_m[axis] > 0.0
    }

    /// Period along `axis` [m] (0 if open).
    pub fn period_m(&self, axis: usize) -> f64 {
        self.len_m[axis]
    }

    /// Lower end of the range along `axis` [m] (0 if open).
    pub fn lo_m(&self, axis: usize) -> f64 {
        self.lo_m[axis]
    }

    /// The shortest image of the difference `d` [m] (unchanged, bit for bit, along open axes).
    #[inline(always)]
    pub fn image(&self, d: Vec3) -> Vec3 {
        if !self.any {
            return d;
        }
        Vec3::new(
            d.x - self.len_m[0] * (d.x * self.inv_len_per_m[0]).round(),
            d.y - self.len_m[1] * (d.y * self.inv_len_per_m[1]).round(),
            d.z - self.len_m[2] * (d.z * self.inv_len_per_m[2]).round(),
        )
    }

    /// Replaces the differences `(dx, dy, dz)` [m] of a chunk of pairs by their shortest
    /// images (lanes of equal length; nothing to do in an open box). The pair loops gather
    /// plain differences and call this once per chunk, so an open box pays one test per chunk
    /// rather than one per pair.
    #[inline(always)]
    pub fn image_lanes(&self, dx: &mut [f64], dy: &mut [f64], dz: &mut [f64]) {
        if !self.any {
            return;
        }
        for (x, (y, z)) in dx.iter_mut().zip(dy.iter_mut().zip(dz.iter_mut())) {
            let d = self.image(Vec3::new(*x, *y, *z));
            (*x, *y, *z) = (d.x, d.y, d.z);
        }
    }

    /// `x_i − x_j` [m] under the minimum-image convention.
    #[inline(always)]
    pub fn delta(&self, xi: Vec3, xj: Vec3) -> Vec3 {
        self.image(xi - xj)
    }

    /// `x` [m] moved into the range `[lo, lo + L)` of every periodic axis.
    pub fn wrap(&self, x: Vec3) -> Vec3 {
        let mut out = x;
        for k in 0..3 {
            if self.len_m[k] > 0.0 {
                let shifted =
                    x[k] - self.len_m[k] * ((x[k] - self.lo_m[k]) * self.inv_len_per_m[k]).floor();
                // rounding can land exactly on lo + L: that is lo
                out[k] = if shifted >= self.lo_m[k] + self.len_m[k] {
                    self.lo_m[k]
                } else {
                    shifted
                };
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_open_box_leaves_differences_bit_for_bit() {
        let b = PeriodicBox::OPEN;
        for d in [
            Vec3::new(-0.0, 0.0, 1e-300),
            Vec3::new(3.3e-4, -7.1e-5, 2.0),
        ] {
            assert_eq!(b.image(d).map(f64::to_bits), d.map(f64::to_bits));
        }
        // one periodic axis: the other two are untouched to the bit as well
        let b = PeriodicBox::new([None, Some([0.0, 1.0]), None]);
        let d = Vec3::new(0.123456789, 0.75, -0.987654321);
        let i = b.image(d);
        assert_eq!(i.x.to_bits(), d.x.to_bits());
        assert_eq!(i.z.to_bits(), d.z.to_bits());
        assert!((i.y + 0.25).abs() < 1e-15);
    }

    #[test]
    fn images_are_the_shortest_and_wrapping_lands_in_range() {
        let b = PeriodicBox::new([Some([-1.0, 1.0]); 3]);
        let xi = Vec3::new(0.95, -0.95, 0.1);
        let xj = Vec3::new(-0.95, 0.95, 0.2);
        let d = b.delta(xi, xj);
        // 1e-12: rounding of differences of numbers of order 1
        assert!((d - Vec3::new(-0.1, 0.1, -0.1)).norm() < 1e-12, "{d:?}");
        for x in [-3.5, -1.0, 0.999_999_999_999_999_9, 1.0, 7.25] {
            let w = b.wrap(Vec3::new(x, 0.0, 0.0)).x;
            assert!((-1.0..1.0).contains(&w), "{x} → {w}");
            // the wrapped position is the same point modulo the period (1e-12 as above)
            let k = ((x - w) / 2.0).round();
            assert!((x - w - 2.0 * k).abs() < 1e-12);
        }
    }
}
