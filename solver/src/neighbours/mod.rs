//! Cell-list neighbour search with Verlet lists.
//!
//! One search serves both interaction radii: the kernel support (pressure, viscosity, density)
//! and the potential cut-off `r_e` (interfacial tension), which may be larger. Each particle's
//! list holds its *near* neighbours (within support + skin) first, then its *far* ones (within
//! `max(support, r_e)` + skin): kernel loops stop at the end of the near part, the
//! potential loop runs on. Lists are rebuilt when a particle has moved half the skin.
//!
//! Cells are cubes of the far radius keyed by their integer coordinates on a fixed global grid
//! (x fastest), so the three cells of a row are consecutive keys and the 27-cell neighbourhood
//! is nine contiguous ranges of the key-sorted particles. Fluid particles are re-sorted by key at
//! each build (cache locality); walls are sorted once. The order of each list is fixed by the
//! particle order and positions, so results do not depend on the number of threads.

mod cells;

pub use cells::{cell_key, CellKeyError};

use crate::state::Vec3;
use rayon::prelude::*;

/// Neighbour lists in compressed-row form.
#[derive(Clone, Debug, Default)]
pub struct NeighbourLists {
    /// `start[i]..start[i+1]` is particle `i`'s slice of `list` (len n + 1).
    pub start: Vec<u32>,
    /// End of the near part of particle `i`'s slice.
    pub near_end: Vec<u32>,
    /// Neighbour indices.
    pub list: Vec<u32>,
}

impl NeighbourLists {
    /// Near neighbours of `i` (within support + skin).
    #[inline(always)]
    pub fn near(&self, i: usize) -> &[u32] {
        &self.list[self.start[i] as usize..self.near_end[i] as usize]
    }
    /// All neighbours of `i` (within the far radius + skin), near ones first.
    #[inline(always)]
    pub fn all(&self, i: usize) -> &[u32] {
        &self.list[self.start[i] as usize..self.start[i + 1] as usize]
    }
    /// Far-only neighbours of `i`.
    #[inline(always)]
    pub fn far(&self, i: usize) -> &[u32] {
        &self.list[self.near_end[i] as usize..self.start[i + 1] as usize]
    }
    /// Bytes held.
    pub fn memory_bytes(&self) -> usize {
        4 * (self.start.capacity() + self.near_end.capacity() + self.list.capacity())
    }
}

/// The search: radii, cell keys and the current lists.
#[derive(Clone, Debug)]
pub struct NeighbourSearch {
    /// Kernel support radius [m].
    pub near_radius_m: f64,
    /// `max(support, r_e)` [m].
    pub far_radius_m: f64,
    /// Verlet skin [m].
    pub skin_m: f64,
    /// Cell edge [m] (= far radius + skin).
    pub cell_m: f64,
    fluid_keys: Vec<u64>,
    wall_keys: Vec<u64>,
    /// Current lists (fluid particles, then walls: walls list only fluid neighbours).
    pub lists: NeighbourLists,
    /// Number of builds so far.
    pub builds: u64,
}

/// Output of one chunk of cells.
#[derive(Default)]
struct Chunk {
    list: Vec<u32>,
    /// (near count, total count) per particle.
    counts: Vec<(u32, u32)>,
}

impl NeighbourSearch {
    /// A search for the given radii [m] and skin [m]; `wall_pos` must already be sorted with
    /// [`NeighbourSearch::sort_walls`] order (see [`crate::setup`]).
    pub fn new(near_radius_m: f64, far_radius_m: f64, skin_m: f64) -> Self {
        let far = far_radius_m.max(near_radius_m);
        Self {
            near_radius_m,
            far_radius_m: far,
            skin_m,
            cell_m: far + skin_m,
            fluid_keys: Vec::new(),
            wall_keys: Vec::new(),
            lists: NeighbourLists::default(),
            builds: 0,
        }
    }

    /// Cell keys of `pos` [m].
    pub fn keys(&self, pos: &[Vec3]) -> Result<Vec<u64>, CellKeyError> {
        let inv = 1.0 / self.cell_m;
        pos.iter().map(|p| cell_key(p, inv)).collect()
    }

    /// The permutation that sorts `pos` by cell key (stable: ties keep their order).
    pub fn sort_order(&self, pos: &[Vec3]) -> Result<Vec<u32>, CellKeyError> {
        let keys = self.keys(pos)?;
        let mut perm: Vec<u32> = (0..pos.len() as u32).collect();
        perm.sort_by_key(|&i| keys[i as usize]);
        Ok(perm)
    }

    /// Builds the lists for fluid positions `pos[..n_fluid]` (sorted by key) and wall positions
    /// `pos[n_fluid..]` (sorted by key).
    pub fn build(&mut self, pos: &[Vec3], n_fluid: usize) -> Result<(), CellKeyError> {
        self.fluid_keys = self.keys(&pos[..n_fluid])?;
        if self.wall_keys.len() != pos.len() - n_fluid {
            self.wall_keys = self.keys(&pos[n_fluid..])?;
        }
        debug_assert!(self.fluid_keys.windows(2).all(|w| w[0] <= w[1]));
        debug_assert!(self.wall_keys.windows(2).all(|w| w[0] <= w[1]));
        let near_cut = self.near_radius_m + self.skin_m;
        let far_cut = self.far_radius_m + self.skin_m;
        let (near2, far2) = (near_cut * near_cut, far_cut * far_cut);
        let fk = &self.fluid_keys;
        let wk = &self.wall_keys;

        // fluid particles: fluid and wall neighbours, near then far
        let runs = runs_of(fk);
        let fluid_chunks: Vec<Chunk> = runs
            .par_chunks(16)
            .map(|runs| {
                let mut out = Chunk::default();
                let mut far = Vec::new();
                for &(s, e) in runs {
                    let f_ranges = row_ranges(fk, fk[s]);
                    let w_ranges = row_ranges(wk, fk[s]);
                    for i in s..e {
                        let pi = pos[i];
                        let before = out.list.len();
                        far.clear();
                        for r in &f_ranges {
                            for j in r.clone() {
                                let d2 = (pi - pos[j]).norm_squared();
                                if j != i && d2 < far2 {
                                    if d2 < near2 {
                                        out.list.push(j as u32);
                                    } else {
                                        far.push(j as u32);
                                    }
                                }
                            }
                        }
                        for r in &w_ranges {
                            for jw in r.clone() {
                                let j = n_fluid + jw;
                                let d2 = (pi - pos[j]).norm_squared();
                                if d2 < far2 {
                                    if d2 < near2 {
                                        out.list.push(j as u32);
                                    } else {
                                        far.push(j as u32);
                                    }
                                }
                            }
                        }
                        let n_near = (out.list.len() - before) as u32;
                        out.list.extend_from_slice(&far);
                        out.counts.push((n_near, (out.list.len() - before) as u32));
                    }
                }
                out
            })
            .collect();

        // wall particles: fluid neighbours within the kernel support (+ skin)
        let wall_runs = runs_of(wk);
        let wall_chunks: Vec<Chunk> = wall_runs
            .par_chunks(16)
            .map(|runs| {
                let mut out = Chunk::default();
                for &(s, e) in runs {
                    let f_ranges = row_ranges(fk, wk[s]);
                    let any_fluid = f_ranges.iter().any(|r| !r.is_empty());
                    for iw in s..e {
                        let before = out.list.len();
                        if any_fluid {
                            let pi = pos[n_fluid + iw];
                            for r in &f_ranges {
                                for j in r.clone() {
                                    if (pi - pos[j]).norm_squared() < near2 {
                                        out.list.push(j as u32);
                                    }
                                }
                            }
                        }
                        let n = (out.list.len() - before) as u32;
                        out.counts.push((n, n));
                    }
                }
                out
            })
            .collect();

        let lists = &mut self.lists;
        let total: usize = fluid_chunks
            .iter()
            .chain(&wall_chunks)
            .map(|c| c.list.len())
            .sum();
        lists.start.clear();
        lists.near_end.clear();
        lists.list.clear();
        lists.list.reserve(total);
        lists.start.push(0);
        for c in fluid_chunks.iter().chain(&wall_chunks) {
            let mut offset = *lists.start.last().expect("non-empty");
            for &(n_near, n_all) in &c.counts {
                lists.near_end.push(offset + n_near);
                offset += n_all;
                lists.start.push(offset);
            }
            lists.list.extend_from_slice(&c.list);
        }
        debug_assert_eq!(lists.near_end.len(), pos.len());
        self.builds += 1;
        Ok(())
    }

    /// Whether a fluid particle has moved more than half the skin since the last build.
    pub fn needs_rebuild(&self, pos: &[Vec3], x_ref: &[Vec3]) -> bool {
        let limit = 0.5 * self.skin_m;
        let limit2 = limit * limit;
        pos.par_iter()
            .zip(x_ref.par_iter())
            .any(|(p, r)| (p - r).norm_squared() >= limit2)
    }
}

/// Runs `(start, end)` of equal keys in a sorted key array.
fn runs_of(keys: &[u64]) -> Vec<(usize, usize)> {
    let mut runs = Vec::new();
    let mut s = 0;
    for i in 1..=keys.len() {
        if i == keys.len() || keys[i] != keys[s] {
            runs.push((s, i));
            s = i;
        }
    }
    runs
}

/// The nine index ranges of `keys` (sorted) covering the 27 cells around the cell `key`.
fn row_ranges(keys: &[u64], key: u64) -> [std::ops::Range<usize>; 9] {
    let mut out: [std::ops::Range<usize>; 9] = Default::default();
    let mut n = 0;
    for dz in [-1i64, 0, 1] {
        for dy in [-1i64, 0, 1] {
            let centre = cells::offset_key(key, 0, dy, dz);
            let lo = centre - 1;
            let hi = centre + 1;
            let a = keys.partition_point(|&k| k < lo);
            let b = a + keys[a..].partition_point(|&k| k <= hi);
            out[n] = a..b;
            n += 1;
        }
    }
    out
}

/// All pairs `(i, j)`, `i ≠ j`, with `|x_i − x_j| < radius` by brute force (for tests).
pub fn brute_force_pairs(pos: &[Vec3], radius_m: f64) -> Vec<(u32, u32)> {
    let r2 = radius_m * radius_m;
    let mut pairs = Vec::new();
    for i in 0..pos.len() {
        for j in 0..pos.len() {
            if i != j && (pos[i] - pos[j]).norm_squared() < r2 {
                pairs.push((i as u32, j as u32));
            }
        }
    }
    pairs
}

#[cfg(test)]
mod tests;
