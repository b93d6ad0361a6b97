//! The list build for scenes with periodic axes: a grid of cells no smaller than the cut-off
//! that wraps around the periodic axes, distances by the minimum image.
//!
//! Periodic scenes are small verification boxes (a shear wave, a slab), so this build favours
//! plainness over the open search's tuning: full-size cells, 27 of them per particle, found
//! through a counting sort. The lists it writes have the open search's layout (near entries
//! first, then far — each far pair once, in the lower index's list; fluid candidates before
//! wall candidates) and an order fixed by the
//! particle order alone, so results do not depend on the number of threads.

use super::NeighbourSearch;
use crate::periodic::PeriodicBox;
use crate::state::Vec3;
use rayon::prelude::*;

/// Particles per list segment (the unit of parallel work).
const SEGMENT: usize = 256;

/// A grid of cells over the periodic ranges and the bounding box of the open axes.
struct Grid {
    /// Lower corner [m].
    lo_m: [f64; 3],
    /// Cell edge per axis [m] (at least the cut-off).
    cell_m: [f64; 3],
    /// Cells per axis.
    n: [i64; 3],
    /// Whether each axis wraps.
    wraps: [bool; 3],
}

impl Grid {
    fn new(pbc: &PeriodicBox, pos: &[Vec3], cut_m: f64) -> Self {
        let mut g = Grid {
            lo_m: [0.0; 3],
            cell_m: [cut_m; 3],
            n: [1; 3],
            wraps: [false; 3],
        };
        for k in 0..3 {
            if pbc.axis_is_periodic(k) {
                let len = pbc.period_m(k);
                g.n[k] = ((len / cut_m).floor() as i64).max(1);
                g.cell_m[k] = len / g.n[k] as f64;
                g.lo_m[k] = pbc.lo_m(k);
                g.wraps[k] = true;
            } else {
                let (lo, hi) = pos
                    .iter()
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
                        (a.min(p[k]), b.max(p[k]))
                    });
                g.lo_m[k] = lo;
                // open axes: cells of the cut-off, coarser if the box would be huge (the
                // particles have spread far apart; a larger cell is still correct)
                let extent = (hi - lo).max(0.0);
                while extent / g.cell_m[k] > (4 * pos.len() + 4096) as f64 {
                    g.cell_m[k] *= 2.0;
                }
                g.n[k] = (extent / g.cell_m[k]).floor() as i64 + 1;
            }
        }
        g
    }

    /// Cell coordinates of `p` [m].
    fn coords(&self, p: &Vec3) -> [i64; 3] {
        std::array::from_fn(|k| {
            let c = ((p[k] - self.lo_m[k]) / self.cell_m[k]).floor() as i64;
            if self.wraps[k] {
                c.rem_euclid(self.n[k])
            } else {
                c.clamp(0, self.n[k] - 1)
            }
        })
    }

    fn index(&self, c: [i64; 3]) -> usize {
        ((c[2] * self.n[1] + c[1]) * self.n[0] + c[0]) as usize
    }

    fn cells(&self) -> usize {
        (self.n[0] * self.n[1] * self.n[2]) as usize
    }

    /// The distinct neighbouring coordinates of `c` along `axis` (itself and ±1, wrapped).
    fn around(&self, c: i64, axis: usize) -> ([i64; 3], usize) {
        let mut out = [0i64; 3];
        let mut len = 0;
        for d in -1..=1 {
            let mut x = c + d;
            if self.wraps[axis] {
                x = x.rem_euclid(self.n[axis]);
            } else if !(0..self.n[axis]).contains(&x) {
                continue;
            }
            if !out[..len].contains(&x) {
                out[len] = x;
                len += 1;
            }
        }
        (out, len)
    }
}

/// Particles grouped by cell (a counting sort: within a cell, in particle order).
struct Binned {
    /// `start[c]..start[c + 1]` indexes `members` for cell `c`.
    start: Vec<u32>,
    members: Vec<u32>,
}

impl Binned {
    fn new(grid: &Grid, pos: &[Vec3]) -> Self {
        let cells: Vec<usize> = pos.iter().map(|p| grid.index(grid.coords(p))).collect();
        let mut start = vec![0u32; grid.cells() + 1];
        for &c in &cells {
            start[c + 1] += 1;
        }
        for c in 0..grid.cells() {
            start[c + 1] += start[c];
        }
        let mut fill = start.clone();
        let mut members = vec![0u32; pos.len()];
        for (i, &c) in cells.iter().enumerate() {
            members[fill[c] as usize] = i as u32;
            fill[c] += 1;
        }
        Binned { start, members }
    }

    fn of(&self, c: usize) -> &[u32] {
        &self.members[self.start[c] as usize..self.start[c + 1] as usize]
    }
}

impl NeighbourSearch {
    /// Builds the lists of [`NeighbourSearch::build`] in a box with periodic axes.
    pub(super) fn build_periodic(&mut self, pos: &[Vec3], n_fluid: usize) {
        let pbc = self.lists.periodic;
        let walls_reach_far = self.walls_reach_far;
        let near_cut = self.near_radius_m + self.skin_m;
        let far_cut = self.far_radius_m + self.skin_m;
        let (near2, far2) = (near_cut * near_cut, far_cut * far_cut);
        let grid = Grid::new(&pbc, pos, far_cut);
        let fluid = Binned::new(&grid, &pos[..n_fluid]);
        let walls = Binned::new(&grid, &pos[n_fluid..]);
        let n_seg = n_fluid.div_ceil(SEGMENT) + (pos.len() - n_fluid).div_ceil(SEGMENT);
        let lists = &mut self.lists;
        lists.segments.resize_with(n_seg, Vec::new);
        self.counts.resize_with(n_seg, Vec::new);
        lists
            .segments
            .par_iter_mut()
            .zip(self.counts.par_iter_mut())
            .enumerate()
            .for_each(|(s, (list, counts))| {
                list.clear();
                counts.clear();
                let n_fluid_seg = n_fluid.div_ceil(SEGMENT);
                // fluid particles list fluid and wall neighbours (near, then far); wall
                // particles list fluid neighbours within the near cut-off (with
                // `walls_reach_far`, then those within the far one: of lower index)
                let (first, last, far2_i) = if s < n_fluid_seg {
                    (s * SEGMENT, ((s + 1) * SEGMENT).min(n_fluid), far2)
                } else {
                    let w = (s - n_fluid_seg) * SEGMENT;
                    let far2_w = if walls_reach_far { far2 } else { near2 };
                    (n_fluid + w, (n_fluid + w + SEGMENT).min(pos.len()), far2_w)
                };
                let (mut near, mut far) = (Vec::new(), Vec::new());
                for i in first..last {
                    near.clear();
                    far.clear();
                    let mut test = |j: usize| {
                        if j == i {
                            return;
                        }
                        let d2 = pbc.delta(pos[i], pos[j]).norm_squared();
                        if d2 < near2 {
                            near.push(j as u32);
                        } else if d2 < far2_i && (j > i || i >= n_fluid) {
                            // far pairs once: in the list of the lower index (a wall's far
                            // part, if any, repeats its fluid pairs)
                            far.push(j as u32);
                        }
                    };
                    let c = grid.coords(&pos[i]);
                    let (cells, n_cells) = neighbour_cells(&grid, c);
                    let cells = &cells[..n_cells];
                    for &cell in cells {
                        fluid.of(cell).iter().for_each(|&j| test(j as usize));
                    }
                    if i < n_fluid {
                        for &cell in cells {
                            walls
                                .of(cell)
                                .iter()
                                .for_each(|&j| test(n_fluid + j as usize));
                        }
                    }
                    counts.push(super::push_list(list, i, &near, &far));
                }
            });
        self.finish_build(pos.len(), n_fluid);
    }
}

/// The distinct cells around cell coordinates `c`, z slowest, x fastest, and their number.
fn neighbour_cells(grid: &Grid, c: [i64; 3]) -> ([usize; 27], usize) {
    let (xs, nx) = grid.around(c[0], 0);
    let (ys, ny) = grid.around(c[1], 1);
    let (zs, nz) = grid.around(c[2], 2);
    let mut out = [0usize; 27];
    let mut n = 0;
    for &z in &zs[..nz] {
        for &y in &ys[..ny] {
            for &x in &xs[..nx] {
                out[n] = grid.index([x, y, z]);
                n += 1;
            }
        }
    }
    (out, n)
}
