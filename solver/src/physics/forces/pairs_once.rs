//! Each pair once: a pass over pairs `(i, j > i)` that evaluates a central pair force once and
//! adds it to `i` and its exact negative to `j` — half the pair evaluations of a gather loop,
//! which evaluates every pair from both sides.
//!
//! **Determinism.** The fluid particles are cut into chunks of consecutive indices whose length
//! depends on the particle count alone ([`chunk_len`]), never on the number of threads. A chunk
//! adds the forces on its own particles in place, in the order of its pairs, and collects those
//! on later particles (`j` beyond the chunk) in a spill buffer of its own. Chunks run in waves of
//! [`WAVE`]; after a wave its spills are added in chunk order. Every particle's force is thus a
//! sum in one fixed order — the spills of earlier waves (chunk order), its own chunk's pairs,
//! the spills of its own wave's earlier chunks — the same bits for any thread count.
//!
//! **Memory.** Particles are sorted by cell, so a chunk's pairs reach only a bounded index range
//! ahead (about two cell layers); a wave holds at most `WAVE` such spills.

use crate::state::Vec3;
use rayon::prelude::*;
use std::sync::Mutex;

/// Chunks per wave (the spills alive at once; the parallelism of a wave).
pub const WAVE: usize = 32;

/// Fluid particles per chunk for `n_fluid` particles: about 32 chunks, at least 1024 and at most
/// 32768 particles each (a function of the count alone: the partition fixes the summation order).
pub fn chunk_len(n_fluid: usize) -> usize {
    (n_fluid / 32).clamp(1024, 32768)
}

/// Spill buffers kept from one pass to the next, so that a pass allocates none (a chunk's spill
/// is tens of kB). A buffer is emptied before use, so which one a chunk gets changes nothing.
#[derive(Default)]
pub struct Spills(Mutex<Vec<Vec<Vec3>>>);

impl Spills {
    /// An empty buffer: a kept one if any.
    fn take(&self) -> Vec<Vec3> {
        let mut v = self.0.lock().expect("spill pool").pop().unwrap_or_default();
        v.clear();
        v
    }

    /// Keeps `v` for a later pass.
    fn keep(&self, v: Vec<Vec3>) {
        self.0.lock().expect("spill pool").push(v);
    }
}

impl Clone for Spills {
    /// Scratch: a clone starts with no buffers.
    fn clone(&self) -> Self {
        Spills::default()
    }
}

impl std::fmt::Debug for Spills {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("Spills")
    }
}

/// Where the reaction `−F_ij` of a pair goes: into the chunk's own particles, or its spill.
pub struct Reactions<'a> {
    own: &'a mut [Vec3],
    start: usize,
    spill: &'a mut Vec<Vec3>,
    n_fluid: usize,
}

impl Reactions<'_> {
    /// Subtracts the force `f` [N] (the force of the pair on its lower particle) from particle
    /// `j` (`j > i` of the pair, so `j ≥` the chunk's start); a wall (`j ≥ n_fluid`) is fixed
    /// and takes nothing.
    #[inline(always)]
    pub fn subtract(&mut self, j: usize, f: Vec3) {
        let k = j - self.start;
        if k < self.own.len() {
            self.own[k] -= f;
        } else if j < self.n_fluid {
            let s = k - self.own.len();
            if s >= self.spill.len() {
                grow(self.spill, s + 1);
            }
            self.spill[s] -= f;
        }
    }
}

/// Lengthens `spill` to `len` zeros: out of the hot loop, which then keeps its sums in registers.
#[cold]
#[inline(never)]
fn grow(spill: &mut Vec<Vec3>, len: usize) {
    spill.resize(len, Vec3::zeros());
}

/// Adds to `out[i]` (one per fluid particle) the pair forces [N] of every pair `(i, j > i)`:
/// `pairs(i, reactions)` returns `Σ_j F_ij` on `i` and subtracts each `F_ij` from `j` through
/// `reactions`, in the order it sums them. `spills` lends the chunks their spill buffers.
pub fn each_pair_once<P>(out: &mut [Vec3], spills: &Spills, pairs: P)
where
    P: Fn(usize, &mut Reactions) -> Vec3 + Sync,
{
    let n_fluid = out.len();
    let len = chunk_len(n_fluid);
    let n_chunks = n_fluid.div_ceil(len);
    for wave in (0..n_chunks).step_by(WAVE) {
        let lo = wave * len;
        let hi = ((wave + WAVE) * len).min(n_fluid);
        let waves_spills: Vec<(usize, Vec<Vec3>)> = out[lo..hi]
            .par_chunks_mut(len)
            .enumerate()
            .map(|(c, own)| {
                let start = lo + c * len;
                let end = start + own.len();
                let mut spill = spills.take();
                for i in start..end {
                    let mut r = Reactions {
                        own: &mut *own,
                        start,
                        spill: &mut spill,
                        n_fluid,
                    };
                    let f = pairs(i, &mut r);
                    own[i - start] += f;
                }
                (end, spill)
            })
            .collect();
        for (end, spill) in waves_spills {
            for (o, s) in out[end..].iter_mut().zip(&spill) {
                *o += s;
            }
            spills.keep(spill);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A pair force of `i` and `j` that is not symmetric in rounding-friendly ways.
    fn force(i: usize, j: usize) -> Vec3 {
        let d = (i as f64 - j as f64) * 1e-3;
        Vec3::new(d.sin() * 0.37, (d * 1.3).cos() * d, 1.0 / (1.0 + d * d))
    }

    /// Pairs `(i, j)` with `i < j ≤ i + reach` (and a few beyond the fluid: walls).
    fn run(n: usize, reach: usize, threads: usize, spills: &Spills) -> Vec<Vec3> {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        let mut out = vec![Vec3::zeros(); n];
        pool.install(|| {
            each_pair_once(&mut out, spills, |i, r| {
                let mut f = Vec3::zeros();
                for j in (i + 1)..(i + reach + 1).min(n + 3) {
                    let fij = force(i, j);
                    f += fij;
                    r.subtract(j, fij);
                }
                f
            })
        });
        out
    }

    #[test]
    fn the_same_bits_for_any_thread_count_and_the_gather_sums() {
        // 70,000 particles: chunks of 2187 (n/32), 33 of them, so two waves (32 chunks each);
        // pairs across chunk and wave boundaries
        let (n, reach) = (70_000, 3000);
        assert_eq!((chunk_len(n), n.div_ceil(chunk_len(n))), (2187, 33));
        let one = run(n, reach, 1, &Spills::default());
        // one pool of spill buffers for all: buffers kept from a pass must not leak into the next
        let kept = Spills::default();
        for threads in [2, 3, 5, 2] {
            assert!(one == run(n, reach, threads, &kept), "{threads} threads");
        }
        // against the gather over both sides: the same up to rounding of the summation order
        // the first particle, either side of a chunk boundary, either side of the wave boundary
        for i in [0usize, 2186, 2187, 69_983, 69_984, 69_999] {
            let mut g = Vec3::zeros();
            for j in i.saturating_sub(reach)..(i + reach + 1).min(n + 3) {
                if j < i {
                    g -= force(j, i);
                } else if j > i {
                    g += force(i, j);
                }
            }
            // summation of ~6000 terms of order 1 in another order: 1e-10 of their scale
            assert!(
                (g - one[i]).norm() < 1e-10 * reach as f64,
                "{i}: {g} {}",
                one[i]
            );
        }
    }
}
