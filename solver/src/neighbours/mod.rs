//! Cell-list neighbour search with Verlet lists.
//!
//! One search serves both interaction radii: the kernel support (pressure, viscosity, density)
//! and the potential cut-off `r_e` (interfacial tension), which may be larger. Each particle's
//! list holds its *near* neighbours (within support + skin) first, then its *far* ones (within
//! `max(support, r_e)` + skin) of higher index only — every far pair once, in the list of its
//! lower index (walls, indexed after the fluid, are in every fluid particle's far part): kernel
//! loops gather over the near part, the potential evaluates the far pairs once and adds each to
//! both particles ([`crate::physics::surface_tension::far_pair_forces`]). Lists are rebuilt when
//! a particle has moved half the skin. Entries are stored as 16-bit differences ([`ids`]): a
//! list is read in order, through the iterator [`Ids`].
//!
//! Cells are cubes of half the far radius (plus skin) keyed by their integer coordinates on a
//! fixed global grid (x fastest), so the five cells of a row are consecutive keys and the
//! 5×5×5-cell neighbourhood is 25 contiguous ranges of the key-sorted particles. Half-size cells
//! scan (5/2)³ ≈ 15.6 cut-off cubes per particle instead of the 27 of full-size cells. Fluid particles are re-sorted by key at
//! each build (cache locality); walls are sorted once. The order of each list is fixed by the
//! particle order and positions, so results do not depend on the number of threads.

mod cells;
mod clip;
mod ids;
mod periodic;
mod table;

pub use cells::{cell_key, CellKeyError};
pub use ids::Ids;

use crate::periodic::PeriodicBox;
use crate::state::Vec3;
use clip::RowCells;
use rayon::prelude::*;
use table::CellTable;

/// Neighbour lists, stored in the segments the parallel build produced (no flattening copy:
/// it would double the lists' memory at every rebuild).
#[derive(Clone, Debug, Default)]
pub struct NeighbourLists {
    /// The segments of encoded neighbour lists ([`ids::encode`]: 16-bit differences).
    segments: Vec<Vec<u16>>,
    /// Per particle: `(segment, start, near end, end)`, in words of its segment; the near and
    /// the far part are each encoded from the particle's own index.
    loc: Vec<[u32; 4]>,
    /// The box the pairs were found in: every pair vector `x_i − x_j` of these lists is
    /// [`NeighbourLists::delta`] (the minimum image along periodic axes).
    pub periodic: PeriodicBox,
}

impl NeighbourLists {
    #[inline(always)]
    fn part(&self, i: usize, from: usize, to: usize) -> Ids<'_> {
        let l = self.loc[i];
        Ids::new(
            &self.segments[l[0] as usize][l[from] as usize..l[to] as usize],
            i as u32,
        )
    }
    /// Near neighbours of `i` (within support + skin).
    #[inline(always)]
    pub fn near(&self, i: usize) -> Ids<'_> {
        self.part(i, 1, 2)
    }
    /// The near neighbours of `i`, then its far ones of higher index (each far pair is in
    /// one list only: [`NeighbourLists::far`]).
    #[inline(always)]
    pub fn all(&self, i: usize) -> std::iter::Chain<Ids<'_>, Ids<'_>> {
        self.near(i).chain(self.far(i))
    }
    /// The far neighbours `j > i` of `i` (beyond support + skin, within the far radius + skin):
    /// each far pair once, in the list of its lower index.
    #[inline(always)]
    pub fn far(&self, i: usize) -> Ids<'_> {
        self.part(i, 2, 3)
    }
    /// `x_i − x_j` [m] of a listed pair (the minimum image along periodic axes).
    #[inline(always)]
    pub fn delta(&self, xi: Vec3, xj: Vec3) -> Vec3 {
        self.periodic.delta(xi, xj)
    }
    /// Number of particles with lists.
    pub fn len(&self) -> usize {
        self.loc.len()
    }
    /// Whether there are no lists.
    pub fn is_empty(&self) -> bool {
        self.loc.is_empty()
    }
    /// Total entries over all lists (decodes them all).
    pub fn entries(&self) -> usize {
        (0..self.len())
            .map(|i| self.near(i).count() + self.far(i).count())
            .sum()
    }
    /// 16-bit words in use (an entry takes one, an escaped one three: [`ids`]).
    pub fn words(&self) -> usize {
        self.segments.iter().map(|s| s.len()).sum()
    }
    /// Bytes held.
    pub fn memory_bytes(&self) -> usize {
        2 * self.segments.iter().map(|s| s.capacity()).sum::<usize>() + 16 * self.loc.capacity()
    }
}

/// The row ranges around a cell, from the dense table when it is built, else by galloping.
enum Rows<'a> {
    /// No particles (a scene without walls).
    Empty,
    Dense(&'a CellTable),
    Sparse(Box<RowCursor<'a>>),
}

impl<'a> Rows<'a> {
    fn new(keys: &'a [u64], table: &'a CellTable) -> Self {
        if keys.is_empty() {
            Rows::Empty
        } else if table.is_built() {
            Rows::Dense(table)
        } else {
            Rows::Sparse(Box::new(RowCursor::new(keys)))
        }
    }

    #[inline]
    fn ranges(&mut self, key: u64) -> [std::ops::Range<usize>; ROWS] {
        match self {
            Rows::Empty => Default::default(),
            Rows::Dense(t) => t.ranges(key),
            Rows::Sparse(c) => c.ranges(key),
        }
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
    /// Per segment: (near words, total words) of each particle (kept for reuse).
    counts: Vec<Vec<(u32, u32)>>,
    /// Dense cell starts of the fluid and of the walls (unused when their box is too large).
    fluid_table: CellTable,
    wall_table: CellTable,
    /// Whether dense tables may be used (tests switch them off to compare with galloping).
    dense_tables: bool,
    /// The fewest particles per occupied cell at which the scan's rows are clipped to the
    /// cells within reach ([`clip::MIN_PARTICLES_PER_CELL`]; tests set it to force either way).
    clip_min_per_cell: usize,
    /// Per fluid particle: bit `k` says whether the `k`-th entry of `lists.near(i)` interacts at
    /// the current positions (within the kernel support or `r_e`; `k < 64`, later entries are
    /// always visited). A build sets every bit; the summation density narrows them at the positions
    /// the forces are then evaluated at, so that the force loop skips the skin's entries (a
    /// third of the list at the default skin) — they would add exact zeros.
    pub active: Vec<u64>,
    /// Number of builds so far.
    pub builds: u64,
    /// Whether wall particles also list their fluid neighbours beyond the near cut-off, within
    /// the far one, in their far part (the continuum surface force reads the colour gradient
    /// at walls within `r_e`); off by default, when walls list only their near neighbours.
    pub walls_reach_far: bool,
}

/// Bits of a particle's [`NeighbourSearch::active`] mask: its first `ACTIVE_BITS` near entries.
pub const ACTIVE_BITS: usize = 64;

/// Cells per cut-off: the neighbourhood of a cell spans `REACH` cells on each side.
pub const REACH: i64 = 2;
/// Rows (along x) in a neighbourhood.
const ROWS: usize = ((2 * REACH + 1) * (2 * REACH + 1)) as usize;

impl NeighbourSearch {
    /// A search for the given radii \[m\] and skin \[m\]; the particles it builds lists for
    /// must be in [`NeighbourSearch::sort_order`] (the simulation sorts the walls once and the
    /// fluid at every rebuild).
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
            counts: Vec::new(),
            fluid_table: CellTable::default(),
            wall_table: CellTable::default(),
            dense_tables: true,
            clip_min_per_cell: clip::MIN_PARTICLES_PER_CELL,
            active: Vec::new(),
            builds: 0,
            walls_reach_far: false,
        }
    }

    /// Makes the axes of `periodic` periodic (distances by the minimum image).
    pub fn set_periodic(&mut self, periodic: PeriodicBox) {
        self.lists.periodic = periodic;
    }

    /// Cell keys of `pos` [m] into `keys` (its allocation reused).
    fn keys_into(&self, pos: &[Vec3], keys: &mut Vec<u64>) -> Result<(), CellKeyError> {
        let inv = 1.0 / self.cell_m;
        keys.resize(pos.len(), 0);
        keys.par_iter_mut()
            .zip(pos.par_iter())
            .try_for_each(|(k, p)| cell_key(p, inv).map(|c| *k = c))
    }

    /// The permutation that sorts `pos` by cell key (ties keep their order, so the result does
    /// not depend on the number of threads).
    pub fn sort_order(&self, pos: &[Vec3]) -> Result<Vec<u32>, CellKeyError> {
        let (mut keys, mut perm) = (Vec::new(), Vec::new());
        self.sort_order_into(pos, &mut keys, &mut perm)?;
        Ok(perm)
    }

    /// [`NeighbourSearch::sort_order`] into `perm`, with `keys` as scratch (both allocations
    /// reused). An in-place sort on (key, index): unique pairs, so the same order as a stable
    /// sort on the key, without the stable sort's buffer.
    pub fn sort_order_into(
        &self,
        pos: &[Vec3],
        keys: &mut Vec<u64>,
        perm: &mut Vec<u32>,
    ) -> Result<(), CellKeyError> {
        self.keys_into(pos, keys)?;
        perm.clear();
        perm.extend(0..pos.len() as u32);
        perm.par_sort_unstable_by_key(|&i| (keys[i as usize], i));
        Ok(())
    }

    /// Builds the lists for fluid positions `pos[..n_fluid]` (sorted by key) and wall positions
    /// `pos[n_fluid..]` (sorted by key). The segment buffers of the previous build are reused:
    /// no allocation churn, one set of lists in memory.
    pub fn build(&mut self, pos: &[Vec3], n_fluid: usize) -> Result<(), CellKeyError> {
        if self.lists.periodic.is_periodic() {
            self.build_periodic(pos, n_fluid);
            return Ok(());
        }
        let mut keys = std::mem::take(&mut self.fluid_keys);
        self.keys_into(&pos[..n_fluid], &mut keys)?;
        self.fluid_keys = keys;
        if self.wall_keys.len() != pos.len() - n_fluid {
            let mut keys = std::mem::take(&mut self.wall_keys);
            self.keys_into(&pos[n_fluid..], &mut keys)?;
            self.wall_keys = keys;
            let max = self.max_table_cells(self.wall_keys.len());
            self.wall_table.rebuild(&self.wall_keys, max);
        }
        let max = self.max_table_cells(n_fluid);
        self.fluid_table.rebuild(&self.fluid_keys, max);
        debug_assert!(self.fluid_keys.windows(2).all(|w| w[0] <= w[1]));
        debug_assert!(self.wall_keys.windows(2).all(|w| w[0] <= w[1]));
        let near_cut = self.near_radius_m + self.skin_m;
        let far_cut = self.far_radius_m + self.skin_m;
        let (near2, far2) = (near_cut * near_cut, far_cut * far_cut);
        let inv_cell = 1.0 / self.cell_m;
        let fk = &self.fluid_keys;
        let wk = &self.wall_keys;
        let (ft, wt) = (&self.fluid_table, &self.wall_table);
        let fluid_runs = runs_of(fk);
        let wall_runs = runs_of(wk);
        // clip the rows to the cells within reach only where cells hold enough particles to pay
        // for finding the cells' boundaries (the same lists either way)
        let clip_fluid = n_fluid >= self.clip_min_per_cell.saturating_mul(fluid_runs.len());
        let clip_walls = wk.len() >= self.clip_min_per_cell.saturating_mul(wall_runs.len());
        const RUNS_PER_SEGMENT: usize = 16;
        let n_fluid_seg = fluid_runs.len().div_ceil(RUNS_PER_SEGMENT);
        let n_seg = n_fluid_seg + wall_runs.len().div_ceil(RUNS_PER_SEGMENT);
        let lists = &mut self.lists;
        lists.segments.resize_with(n_seg, Vec::new);
        self.counts.resize_with(n_seg, Vec::new);
        let (fluid_seg, wall_seg) = lists.segments.split_at_mut(n_fluid_seg);
        let (fluid_cnt, wall_cnt) = self.counts.split_at_mut(n_fluid_seg);

        // fluid particles: fluid and wall neighbours, near then far
        fluid_seg
            .par_iter_mut()
            .zip(fluid_cnt.par_iter_mut())
            .zip(fluid_runs.par_chunks(RUNS_PER_SEGMENT))
            .for_each(|((list, counts), runs)| {
                list.clear();
                counts.clear();
                let (mut near_buf, mut far_buf): (Vec<u32>, Vec<u32>) = (Vec::new(), Vec::new());
                let (mut fc, mut wc) = (Rows::new(fk, ft), Rows::new(wk, wt));
                // without a far part (r_e ≤ support) only the near buffer is written
                type Scan = fn(
                    &[Vec3],
                    usize,
                    usize,
                    &[std::ops::Range<usize>],
                    &[std::ops::Range<usize>],
                    (f64, f64),
                    (&mut [u32], &mut [u32]),
                ) -> (usize, usize);
                let scan_fluid: Scan = if far2 > near2 {
                    scan::<true>
                } else {
                    scan::<false>
                };
                for &(s, e) in runs {
                    let f_ranges = fc.ranges(fk[s]);
                    let w_ranges = wc.ranges(fk[s]);
                    let candidates: usize = f_ranges.iter().chain(&w_ranges).map(|r| r.len()).sum();
                    if near_buf.len() < candidates {
                        near_buf.resize(candidates, 0);
                        far_buf.resize(candidates, 0);
                    }
                    let cells = clip_fluid.then(|| {
                        (
                            RowCells::new(fk, fk[s], &f_ranges),
                            RowCells::new(wk, fk[s], &w_ranges),
                        )
                    });
                    for i in s..e {
                        let (f_ranges, w_ranges) = match &cells {
                            Some((f_cells, w_cells)) => {
                                let reach = clip::window(&pos[i], inv_cell, far_cut);
                                (f_cells.clipped(&reach), w_cells.clipped(&reach))
                            }
                            None => (f_ranges.clone(), w_ranges.clone()),
                        };
                        let (nn, nf) = scan_fluid(
                            pos,
                            i,
                            n_fluid,
                            &f_ranges,
                            &w_ranges,
                            (near2, far2),
                            (&mut near_buf, &mut far_buf),
                        );
                        counts.push(push_list(list, i, &near_buf[..nn], &far_buf[..nf]));
                    }
                }
            });

        // wall particles: fluid neighbours within the kernel support (+ skin), and with
        // `walls_reach_far` those within the far cut-off in their far part
        let (wall_cut, wall_far2) = if self.walls_reach_far {
            (far_cut, far2)
        } else {
            (near_cut, near2)
        };
        wall_seg
            .par_iter_mut()
            .zip(wall_cnt.par_iter_mut())
            .zip(wall_runs.par_chunks(RUNS_PER_SEGMENT))
            .for_each(|((list, counts), runs)| {
                list.clear();
                counts.clear();
                let mut fc = Rows::new(fk, ft);
                let (mut buf, mut far_buf): (Vec<u32>, Vec<u32>) = (Vec::new(), Vec::new());
                for &(s, e) in runs {
                    let f_ranges = fc.ranges(wk[s]);
                    let candidates: usize = f_ranges.iter().map(|r| r.len()).sum();
                    if buf.len() < candidates {
                        buf.resize(candidates, 0);
                        far_buf.resize(candidates, 0);
                    }
                    let f_cells = clip_walls.then(|| RowCells::new(fk, wk[s], &f_ranges));
                    for iw in s..e {
                        let f_ranges = match &f_cells {
                            Some(f_cells) => {
                                let reach = clip::window(&pos[n_fluid + iw], inv_cell, wall_cut);
                                f_cells.clipped(&reach)
                            }
                            None => f_ranges.clone(),
                        };
                        let i = n_fluid + iw;
                        let range = (near2, wall_far2);
                        let (n, nf) = if wall_far2 > near2 {
                            scan_wall(pos, i, &f_ranges, range, (&mut buf, &mut far_buf))
                        } else {
                            scan::<false>(
                                pos,
                                i,
                                n_fluid,
                                &f_ranges,
                                &[],
                                range,
                                (&mut buf, &mut []),
                            )
                        };
                        counts.push(push_list(list, i, &buf[..n], &far_buf[..nf]));
                    }
                }
            });
        self.finish_build(pos.len(), n_fluid);
        Ok(())
    }

    /// After the lists are written: caps the segments' slack and records where each
    /// particle's list is.
    fn finish_build(&mut self, n_total: usize, n_fluid: usize) {
        let lists = &mut self.lists;
        // segments are reused from build to build and keep their largest size; cap the slack at
        // a quarter so that it cannot accumulate (measured: 2.9× the entries otherwise)
        for list in lists.segments.iter_mut() {
            if list.capacity() > list.len() + list.len() / 4 + 64 {
                list.shrink_to(list.len() + list.len() / 8);
            }
        }
        // each particle records where its list is
        lists.loc.clear();
        lists.loc.reserve(n_total);
        for (k, c) in self.counts.iter().enumerate() {
            let mut offset = 0u32;
            for &(near_words, all_words) in c {
                lists
                    .loc
                    .push([k as u32, offset, offset + near_words, offset + all_words]);
                offset += all_words;
            }
        }
        debug_assert_eq!(lists.loc.len(), n_total);
        self.active.clear();
        self.active.resize(n_fluid, u64::MAX);
        self.builds += 1;
    }

    /// The largest dense cell table kept for `n` particles: 4 cells per particle (16 bytes) — a
    /// compact drop's box holds 1.4–2.6 (cube, sphere; cells of half the cut-off hold ~1.5
    /// particles); a scattered splash gets the galloping search instead.
    fn max_table_cells(&self, n: usize) -> usize {
        if self.dense_tables {
            4 * n + 4096
        } else {
            0
        }
    }

    /// Bytes held by the search besides the lists: cell keys and dense cell tables.
    pub fn index_memory_bytes(&self) -> usize {
        8 * (self.fluid_keys.capacity() + self.wall_keys.capacity())
            + self.fluid_table.memory_bytes()
            + self.wall_table.memory_bytes()
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

/// The candidates of particle `i` (fluid `f_ranges`, then walls `w_ranges` offset by `n_fluid`)
/// within the near and far cut-offs (squared, [m²]), written to the two buffers in candidate
/// order; returns their counts. Without a far part (`FAR` false) only the near buffer is written
/// (a wall particle's list: fluid neighbours within the near cut-off).
///
/// Branch-free compaction: every candidate is written, the list grows only when it passes (a
/// quarter do, at random: a branch would mispredict).
#[inline(always)]
fn scan<const FAR: bool>(
    pos: &[Vec3],
    i: usize,
    n_fluid: usize,
    f_ranges: &[std::ops::Range<usize>],
    w_ranges: &[std::ops::Range<usize>],
    (near2, far2): (f64, f64),
    (near_buf, far_buf): (&mut [u32], &mut [u32]),
) -> (usize, usize) {
    let pi = pos[i];
    let (mut nn, mut nf) = (0usize, 0usize);
    let mut test = |j: usize| {
        let d2 = (pi - pos[j]).norm_squared();
        let is_near = (d2 < near2) & (j != i);
        near_buf[nn] = j as u32;
        nn += usize::from(is_near);
        if FAR {
            // far pairs once: in the list of the lower index (walls come after the fluid)
            let is_far = (d2 < far2) & (j > i) & !is_near;
            far_buf[nf] = j as u32;
            nf += usize::from(is_far);
        }
    };
    for r in f_ranges {
        for j in r.clone() {
            test(j);
        }
    }
    for r in w_ranges {
        for jw in r.clone() {
            test(n_fluid + jw);
        }
    }
    (nn, nf)
}

/// The fluid candidates `f_ranges` of wall particle `i` within the near cut-off and, beyond it,
/// within the far one (squared, [m²]), written to the two buffers in candidate order; returns
/// their counts ([`NeighbourSearch::walls_reach_far`]: a wall's far part holds fluid particles
/// of lower index, so such a pair is in both particles' lists).
fn scan_wall(
    pos: &[Vec3],
    i: usize,
    f_ranges: &[std::ops::Range<usize>],
    (near2, far2): (f64, f64),
    (near_buf, far_buf): (&mut [u32], &mut [u32]),
) -> (usize, usize) {
    let pi = pos[i];
    let (mut nn, mut nf) = (0usize, 0usize);
    for j in f_ranges.iter().flat_map(|r| r.clone()) {
        let d2 = (pi - pos[j]).norm_squared();
        near_buf[nn] = j as u32;
        nn += usize::from(d2 < near2);
        far_buf[nf] = j as u32;
        nf += usize::from((d2 < far2) & (d2 >= near2));
    }
    (nn, nf)
}

/// Appends particle `i`'s lists to its segment `words`: its near entries, then its far ones,
/// each part encoded from `i`; returns the words of the near part and of both.
fn push_list(words: &mut Vec<u16>, i: usize, near: &[u32], far: &[u32]) -> (u32, u32) {
    let start = words.len();
    ids::encode(words, i as u32, near);
    let near_end = words.len();
    ids::encode(words, i as u32, far);
    ((near_end - start) as u32, (words.len() - start) as u32)
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

#[cfg(test)]
mod tests;
