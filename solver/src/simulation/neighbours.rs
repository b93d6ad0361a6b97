//! Keeping the particle order and the neighbour lists: walls sorted once by cell, fluid
//! particles re-sorted at every list rebuild.

use super::Simulation;
use crate::error::SimError;
use rayon::prelude::*;
use std::time::Instant;

impl Simulation {
    /// Sorts the wall particles by cell (once: walls never move).
    pub(super) fn sort_walls(&mut self) -> Result<(), SimError> {
        let nf = self.particles.n_fluid;
        let perm = self
            .search
            .sort_order(&self.particles.pos[nf..])
            .map_err(|source| SimError::Escaped { step: 0, source })?;
        fn gather<T: Copy>(v: &mut [T], perm: &[u32]) {
            let old = v.to_vec();
            for (k, &p) in perm.iter().enumerate() {
                v[k] = old[p as usize];
            }
        }
        let p = &mut self.particles;
        gather(&mut p.pos[nf..], &perm);
        gather(&mut p.vel[nf..], &perm);
        gather(&mut p.rho[nf..], &perm);
        gather(&mut p.pressure[nf..], &perm);
        gather(&mut p.vol[nf..], &perm);
        gather(&mut p.phase[nf..], &perm);
        gather(&mut p.id[nf..], &perm);
        gather(&mut self.wall_no_slip, &perm);
        Ok(())
    }

    /// Re-sorts the fluid particles by cell and rebuilds the neighbour lists (the step does
    /// this when a particle has moved half the skin; public for benchmarks of the search).
    pub fn rebuild_neighbours(&mut self) -> Result<(), SimError> {
        let t0 = Instant::now();
        let nf = self.particles.n_fluid;
        let step = self.step;
        let periodic = self.model.periodic;
        if periodic.is_periodic() {
            // particles that crossed a periodic boundary re-enter at the other side
            self.particles.pos[..nf]
                .par_iter_mut()
                .for_each(|x| *x = periodic.wrap(*x));
        }
        let r = &mut self.rebuild;
        self.search
            .sort_order_into(&self.particles.pos[..nf], &mut r.keys, &mut r.perm)
            .map_err(|source| SimError::Escaped { step, source })?;
        self.particles.permute_fluid(&r.perm, &mut r.old);
        self.particles
            .x_ref
            .copy_from_slice(&self.particles.pos[..nf]);
        self.search
            .build(&self.particles.pos, nf)
            .map_err(|source| SimError::Escaped { step, source })?;
        self.timings.search_s += t0.elapsed().as_secs_f64();
        Ok(())
    }
}

/// Scratch of a rebuild (sort keys, the permutation, the old values), kept between rebuilds so
/// that a rebuild allocates nothing of the particle count's size.
#[derive(Clone, Debug, Default)]
pub(super) struct RebuildScratch {
    keys: Vec<u64>,
    perm: Vec<u32>,
    old: crate::state::PermuteScratch,
}
