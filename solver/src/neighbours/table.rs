//! A dense table of cell starts over the bounding box of a key-sorted particle array: the
//! particles of the cells `x_lo..=x_hi` of one row are one index range, found with two loads.
//!
//! It answers the same question as galloping through the sorted keys ([`super::RowCursor`]),
//! in constant time per row; the search uses it whenever the box holds few enough cells (a
//! splash whose drops fly far apart makes the box huge: the search then gallops).

use super::cells::decode;
use super::{REACH, ROWS};
use rayon::prelude::*;
use std::ops::Range;

/// Cell starts over a box of cells.
#[derive(Clone, Debug, Default)]
pub(crate) struct CellTable {
    /// Lowest cell coordinates of the box.
    lo: [i64; 3],
    /// Cells along each axis.
    dim: [i64; 3],
    /// `start[c]`: index of the first particle in dense cell `c` or after it; one entry more
    /// than there are cells.
    start: Vec<u32>,
}

impl CellTable {
    /// Rebuilds the table for the sorted `keys`; `false` (and an empty table) when the box would
    /// have more than `max_cells` cells.
    pub(crate) fn rebuild(&mut self, keys: &[u64], max_cells: usize) -> bool {
        self.start.clear();
        if keys.is_empty() {
            return false;
        }
        let (lo, hi) = keys
            .par_iter()
            .map(|&k| {
                let c = decode(k);
                (c, c)
            })
            .reduce(
                || ([i64::MAX; 3], [i64::MIN; 3]),
                |(a_lo, a_hi), (b_lo, b_hi)| {
                    (
                        std::array::from_fn(|d| a_lo[d].min(b_lo[d])),
                        std::array::from_fn(|d| a_hi[d].max(b_hi[d])),
                    )
                },
            );
        let dim: [i64; 3] = std::array::from_fn(|d| hi[d] - lo[d] + 1);
        let cells = dim
            .iter()
            .try_fold(1usize, |acc, &n| acc.checked_mul(n as usize));
        match cells {
            Some(c) if c <= max_cells => {}
            _ => return false,
        }
        self.lo = lo;
        self.dim = dim;
        let cells = (dim[0] * dim[1] * dim[2]) as usize;
        // keys sorted by (z, y, x) are sorted by dense index too (z-major, x fastest)
        self.start.reserve(cells + 1);
        let mut next = 0usize;
        for (i, &k) in keys.iter().enumerate() {
            let c = self.dense(decode(k));
            while next <= c {
                self.start.push(i as u32);
                next += 1;
            }
        }
        while next <= cells {
            self.start.push(keys.len() as u32);
            next += 1;
        }
        true
    }

    /// Whether the table is in use.
    pub(crate) fn is_built(&self) -> bool {
        !self.start.is_empty()
    }

    fn dense(&self, c: [i64; 3]) -> usize {
        let r = [c[0] - self.lo[0], c[1] - self.lo[1], c[2] - self.lo[2]];
        ((r[2] * self.dim[1] + r[1]) * self.dim[0] + r[0]) as usize
    }

    /// The index ranges of the particles in the (2·REACH + 1)³ cells around the cell `key`, one
    /// per row along x — in the order of [`super::RowCursor::ranges`].
    pub(crate) fn ranges(&self, key: u64) -> [Range<usize>; ROWS] {
        let mut out: [Range<usize>; ROWS] = Default::default();
        let c = decode(key);
        let x_lo = (c[0] - REACH).max(self.lo[0]);
        let x_hi = (c[0] + REACH).min(self.lo[0] + self.dim[0] - 1);
        if x_lo > x_hi {
            return out;
        }
        let mut n = 0;
        for dz in -REACH..=REACH {
            for dy in -REACH..=REACH {
                let (y, z) = (c[1] + dy, c[2] + dz);
                let inside = (self.lo[1]..self.lo[1] + self.dim[1]).contains(&y)
                    && (self.lo[2]..self.lo[2] + self.dim[2]).contains(&z);
                if inside {
                    let a = self.start[self.dense([x_lo, y, z])] as usize;
                    let b = self.start[self.dense([x_hi, y, z]) + 1] as usize;
                    out[n] = a..b;
                }
                n += 1;
            }
        }
        out
    }

    /// Bytes held.
    pub(crate) fn memory_bytes(&self) -> usize {
        4 * self.start.capacity()
    }
}
