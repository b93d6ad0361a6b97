//! Cell-list neighbour search with Verlet lists.
//!
//! One search serves both interaction radii: the kernel support (pressure, viscosity, density)
//! and the potential cut-off `r_e` (interfacial tension), which may be larger. Each particle's
//! list holds its *near* neighbours (within support + skin) first, then its *far* ones (within
//! `max(support, r_e)` + skin): kernel loops stop at the end of the near part, the
//! potential loop runs on. Lists are rebuilt when a particle has moved half the skin.
//!
//! Cells are cubes of half the far radius (plus skin) keyed by their integer coordinates on a
//! fixed global grid (x fastest), so the five cells of a row are consecutive keys and the
//! 5×5×5-cell neighbourhood is 25 contiguous ranges of the key-sorted particles. Half-size cells
//! scan (5/2)³ ≈ 15.6 cut-off cubes per particle instead of the 27 of full-size cells. Fluid particles are re-sorted by key at
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
    /// Cell edge [m] (= (far radius + skin) / [`REACH`]).
    pub cell_m: f64,
    fluid_keys: Vec<u64>,
    wall_keys: Vec<u64>,
    /// Current lists (fluid particles, then walls: walls list only fluid neighbours).
    pub lists: NeighbourLists,
    /// Number of builds so far.
    pub builds: u64,
}

/// Cells per cut-off: the neighbourhood of a cell spans `REACH` cells on each side.
pub const REACH: i64 = 2;
/// Rows (along x) in a neighbourhood.
const ROWS: usize = ((2 * REACH + 1) * (2 * REACH + 1)) as usize;

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
            cell_m: (far + skin_m) / REACH as f64,
            fluid_keys: Vec::new(),
            wall_keys: Vec::new(),
            lists: NeighbourLists::default(),
            builds: 0,
        }
    }

    /// Cell keys of `pos` [m].
    pub fn keys(&self, pos: &[Vec3]) -> Result<Vec<u64>, CellKeyError> {
        let inv = 1.0 / self.cell_m;
        pos.par_iter().map(|p| cell_key(p, inv)).collect()
    }

    /// The permutation that sorts `pos` by cell key (stable: ties keep their order, so the
    /// result does not depend on the number of threads).
    pub fn sort_order(&self, pos: &[Vec3]) -> Result<Vec<u32>, CellKeyError> {
        let inv = 1.0 / self.cell_m;
        let keys: Vec<u64> = pos
            .par_iter()
            .map(|p| cell_key(p, inv))
            .collect::<Result<_, _>>()?;
        let mut perm: Vec<u32> = (0..pos.len() as u32).collect();
        perm.par_sort_by_key(|&i| keys[i as usize]);
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
                let (mut near_buf, mut far_buf): (Vec<u32>, Vec<u32>) = (Vec::new(), Vec::new());
                let (mut fc, mut wc) = (RowCursor::new(fk), RowCursor::new(wk));
                for &(s, e) in runs {
                    let f_ranges = fc.ranges(fk[s]);
                    let w_ranges = wc.ranges(fk[s]);
                    let candidates: usize = f_ranges.iter().chain(&w_ranges).map(|r| r.len()).sum();
                    if near_buf.len() < candidates {
                        near_buf.resize(candidates, 0);
                        far_buf.resize(candidates, 0);
                    }
                    for i in s..e {
                        let pi = pos[i];
                        let (mut nn, mut nf) = (0usize, 0usize);
                        // branch-free compaction: every candidate is written, the list grows only
                        // when it passes (a quarter do, at random: a branch would mispredict)
                        let mut scan = |j: usize| {
                            let d2 = (pi - pos[j]).norm_squared();
                            let is_near = (d2 < near2) & (j != i);
                            let is_far = (d2 < far2) & (j != i) & !is_near;
                            near_buf[nn] = j as u32;
                            nn += usize::from(is_near);
                            far_buf[nf] = j as u32;
                            nf += usize::from(is_far);
                        };
                        for r in &f_ranges {
                            for j in r.clone() {
                                scan(j);
                            }
                        }
                        for r in &w_ranges {
                            for jw in r.clone() {
                                scan(n_fluid + jw);
                            }
                        }
                        out.list.extend_from_slice(&near_buf[..nn]);
                        out.list.extend_from_slice(&far_buf[..nf]);
                        out.counts.push((nn as u32, (nn + nf) as u32));
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
                let mut fc = RowCursor::new(fk);
                for &(s, e) in runs {
                    let f_ranges = fc.ranges(wk[s]);
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

        // flatten: offsets by a prefix sum over the chunks, then every chunk copied in parallel
        // into its own disjoint part of the arrays
        let chunks: Vec<&Chunk> = fluid_chunks.iter().chain(&wall_chunks).collect();
        let mut list_at = Vec::with_capacity(chunks.len() + 1);
        let mut particle_at = Vec::with_capacity(chunks.len() + 1);
        let (mut nl, mut np) = (0usize, 0usize);
        for c in &chunks {
            list_at.push(nl);
            particle_at.push(np);
            nl += c.list.len();
            np += c.counts.len();
        }
        let lists = &mut self.lists;
        lists.list.resize(nl, 0);
        lists.start.resize(np + 1, 0);
        lists.near_end.resize(np, 0);
        lists.start[np] = nl as u32;
        let mut list_parts = Vec::with_capacity(chunks.len());
        let mut start_parts = Vec::with_capacity(chunks.len());
        let mut near_parts = Vec::with_capacity(chunks.len());
        let (mut rest_l, mut rest_s, mut rest_n) = (
            &mut lists.list[..],
            &mut lists.start[..np],
            &mut lists.near_end[..],
        );
        for c in &chunks {
            let (a, b) = std::mem::take(&mut rest_l).split_at_mut(c.list.len());
            list_parts.push(a);
            rest_l = b;
            let (a, b) = std::mem::take(&mut rest_s).split_at_mut(c.counts.len());
            start_parts.push(a);
            rest_s = b;
            let (a, b) = std::mem::take(&mut rest_n).split_at_mut(c.counts.len());
            near_parts.push(a);
            rest_n = b;
        }
        chunks
            .par_iter()
            .zip(list_parts.into_par_iter())
            .zip(start_parts.into_par_iter().zip(near_parts.into_par_iter()))
            .zip(list_at.par_iter())
            .for_each(|(((c, l), (st, ne)), &base)| {
                l.copy_from_slice(&c.list);
                let mut offset = base as u32;
                for (k, &(n_near, n_all)) in c.counts.iter().enumerate() {
                    st[k] = offset;
                    ne[k] = offset + n_near;
                    offset += n_all;
                }
            });
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

/// First index `i ≥ start` with `!below(keys[i])`, for a `below` that holds on a prefix of
/// `keys` (sorted): an exponential (galloping) search from `start`, O(log d) for an answer `d`
/// places ahead — cells visited in key order find their neighbours' ranges a few places on.
fn gallop(keys: &[u64], start: usize, below: impl Fn(u64) -> bool) -> usize {
    let n = keys.len();
    if start >= n || !below(keys[start]) {
        return start;
    }
    let (mut lo, mut step) = (start, 1);
    loop {
        let probe = lo + step;
        if probe >= n || !below(keys[probe]) {
            let hi = probe.min(n);
            return lo + 1 + keys[lo + 1..hi].partition_point(|&k| below(k));
        }
        lo = probe;
        step *= 2;
    }
}

/// The index ranges of one sorted key array covering the (2·REACH + 1)³ cells around a cell,
/// one per row along x, for cells visited in increasing key order: each row's range only moves
/// forward, so it is found by galloping from where it was.
struct RowCursor<'a> {
    keys: &'a [u64],
    at: [(usize, usize); ROWS],
}

impl<'a> RowCursor<'a> {
    fn new(keys: &'a [u64]) -> Self {
        Self {
            keys,
            at: [(0, 0); ROWS],
        }
    }

    /// The ranges around the cell `key` (not smaller than the previous `key`).
    fn ranges(&mut self, key: u64) -> [std::ops::Range<usize>; ROWS] {
        let mut out: [std::ops::Range<usize>; ROWS] = Default::default();
        let mut n = 0;
        for dz in -REACH..=REACH {
            for dy in -REACH..=REACH {
                let centre = cells::offset_key(key, 0, dy, dz);
                let lo = centre - REACH as u64;
                let hi = centre + REACH as u64;
                let a = gallop(self.keys, self.at[n].0, |k| k < lo);
                let b = gallop(self.keys, self.at[n].1.max(a), |k| k <= hi);
                self.at[n] = (a, b);
                out[n] = a..b;
                n += 1;
            }
        }
        out
    }
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
