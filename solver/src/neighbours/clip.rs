//! Per particle, the cells of each neighbourhood row that can hold a neighbour.
//!
//! A cell's neighbourhood is (2·REACH + 1)² rows of 2·REACH + 1 cells; the sphere of the cut-off
//! around a particle misses whole rows and the ends of others (a third of the 125 cells on
//! average, for cells of half the cut-off). The rows' cell boundaries are found once per cell
//! ([`RowCells`]), the cells within reach once per particle ([`window`]); the scan then tests
//! only their particles. Clipping only removes candidates beyond the cut-off, in the order the
//! rows are visited, so a list is the same, entry for entry, as without it.

use super::cells::offset_key;
use super::{REACH, ROWS};
use crate::state::Vec3;
use std::ops::Range;

/// The fewest particles per occupied cell at which clipping pays: the cells' boundaries are
/// found once per cell by a walk over all its neighbourhood's candidates, the window once per
/// particle; with few particles per cell the scan of whole rows is cheaper. Measured on the
/// 20 k cube (search time, clipped against whole rows, interleaved): r_e = 2.1 l0 (~1.5 per
/// cell) 7.0 → 4.1 s without clipping; 3.1 l0 (~4.5) 3.6–3.9 → 3.5–3.8 s; 4.2 l0 (~10.6)
/// 4.3–4.7 s clipped against 4.9–5.2 s without (`reports/performance.md`).
pub(super) const MIN_PARTICLES_PER_CELL: usize = 7;

/// Cells in a row of a neighbourhood.
const CELLS: usize = (2 * REACH + 1) as usize;

/// Margin [cell edges] by which a window is widened: the rounding of a particle's position
/// within its cell (keys hold 21 bits: at most 2²⁰ · 2⁻⁵² ≈ 2.3e-10 cell edges), so that no
/// candidate within the cut-off is ever clipped.
const SLACK: f64 = 1e-7;

/// Per row of a cell's neighbourhood, the index where each of its cells starts, and the row's
/// end (`starts[row][k]..starts[row][k + 1]`: the particles of cell `k`).
pub(super) struct RowCells {
    starts: [[usize; CELLS + 1]; ROWS],
}

impl RowCells {
    /// The cell boundaries of the rows `ranges` (as [`super::Rows::ranges`] gives them for the
    /// cell `key`) in the sorted `keys`.
    pub(super) fn new(keys: &[u64], key: u64, ranges: &[Range<usize>; ROWS]) -> Self {
        let mut starts = [[0usize; CELLS + 1]; ROWS];
        let mut n = 0;
        for dz in -REACH..=REACH {
            for dy in -REACH..=REACH {
                let first = offset_key(key, -REACH, dy, dz);
                let r = &ranges[n];
                let s = &mut starts[n];
                s[0] = r.start;
                let mut k = 0;
                for (idx, &key_j) in keys[r.clone()].iter().enumerate() {
                    let cell = (key_j - first) as usize;
                    debug_assert!(cell < CELLS);
                    while k < cell {
                        k += 1;
                        s[k] = r.start + idx;
                    }
                }
                while k < CELLS {
                    k += 1;
                    s[k] = r.end;
                }
                n += 1;
            }
        }
        RowCells { starts }
    }

    /// The index ranges of the cells `window` keeps, one per row (empty for a row it drops).
    #[inline]
    pub(super) fn clipped(&self, window: &Window) -> [Range<usize>; ROWS] {
        std::array::from_fn(|n| {
            let (lo, hi) = window.cells[n];
            if lo > hi {
                0..0
            } else {
                self.starts[n][lo as usize]..self.starts[n][hi as usize + 1]
            }
        })
    }
}

/// Per row, the first and last cell (`0..CELLS`) within reach of a particle; first > last when
/// the row is out of reach.
pub(super) struct Window {
    cells: [(u8, u8); ROWS],
}

/// The cells within `cut_m` [m] of the particle at `p` [m], for cells of edge `1/inv_cell_m` [m]
/// (the particle's cell is `floor(p · inv_cell_m)`, as its key says).
#[inline]
pub(super) fn window(p: &Vec3, inv_cell_m: f64, cut_m: f64) -> Window {
    let frac = |x: f64| {
        let s = x * inv_cell_m;
        s - s.floor()
    };
    let (fx, fy, fz) = (frac(p.x), frac(p.y), frac(p.z));
    let reach = cut_m * inv_cell_m;
    let reach2 = reach * reach;
    // distance [cell edges] from the particle to the cells `d` rows away along an axis, at a
    // fraction `f` across its own cell
    let gap = |d: i64, f: f64| {
        let g = match d.signum() {
            1 => d as f64 - f,
            -1 => f - (d + 1) as f64,
            _ => 0.0,
        };
        (g - SLACK).max(0.0)
    };
    let mut cells = [(1u8, 0u8); ROWS];
    let mut n = 0;
    for dz in -REACH..=REACH {
        let gz = gap(dz, fz);
        for dy in -REACH..=REACH {
            let gy = gap(dy, fy);
            let g2 = gy * gy + gz * gz;
            if g2 < reach2 {
                let ext = (reach2 - g2).sqrt() + SLACK;
                let lo = ((fx - ext).floor() as i64).max(-REACH) + REACH;
                let hi = ((fx + ext).floor() as i64).min(REACH) + REACH;
                cells[n] = (lo as u8, hi as u8);
            }
            n += 1;
        }
    }
    Window { cells }
}
