//! Integer cell keys on a fixed global grid.

use crate::state::Vec3;

/// Bits per axis in a key.
const BITS: u32 = 21;
/// Offset making cell coordinates non-negative.
const OFFSET: i64 = 1 << (BITS - 1);
const MASK: u64 = (1 << BITS) - 1;

/// A position too far from the origin for the cell grid (usually a particle that has blown
/// away).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("position ({x:e}, {y:e}, {z:e}) m lies outside the neighbour-search grid (±{limit_m:e} m)")]
pub struct CellKeyError {
    /// Position [m].
    pub x: f64,
    /// Position [m].
    pub y: f64,
    /// Position [m].
    pub z: f64,
    /// Half-width of the grid [m].
    pub limit_m: f64,
}

/// Key of the cell holding `p` [m] for cells of edge `1/inv_cell_m` [m]: `(z, y, x)` packed with
/// x in the lowest bits, so the cells of a row along x are consecutive keys.
#[inline]
pub fn cell_key(p: &Vec3, inv_cell_m: f64) -> Result<u64, CellKeyError> {
    let mut key = 0u64;
    for axis in (0..3).rev() {
        let c = (p[axis] * inv_cell_m).floor();
        // keep a margin of cells at each end so that the neighbours of a cell have keys too
        let margin = super::REACH + 1;
        if !(c > (margin - OFFSET) as f64 && c < (OFFSET - margin) as f64) {
            return Err(CellKeyError {
                x: p[0],
                y: p[1],
                z: p[2],
                limit_m: (OFFSET - super::REACH - 1) as f64 / inv_cell_m,
            });
        }
        key = (key << BITS) | ((c as i64 + OFFSET) as u64 & MASK);
    }
    Ok(key)
}

/// Key of the cell displaced by `(dx, dy, dz)` cells from `key` (no overflow: keys keep a
/// margin of `REACH` cells).
#[inline]
pub(crate) fn offset_key(key: u64, dx: i64, dy: i64, dz: i64) -> u64 {
    let x = (key & MASK) as i64 + dx;
    let y = ((key >> BITS) & MASK) as i64 + dy;
    let z = ((key >> (2 * BITS)) & MASK) as i64 + dz;
    ((z as u64) << (2 * BITS)) | ((y as u64) << BITS) | x as u64
}

/// The integer cell coordinates `[x, y, z]` of `key` (offset to be non-negative).
#[inline]
pub(crate) fn decode(key: u64) -> [i64; 3] {
    [
        (key & MASK) as i64,
        ((key >> BITS) & MASK) as i64,
        ((key >> (2 * BITS)) & MASK) as i64,
    ]
}
