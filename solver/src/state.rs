//! The particle state, structure-of-arrays.
//!
//! Fluid particles come first (`0..n_fluid`), kept sorted by neighbour-search cell for cache
//! locality; wall particles follow (`n_fluid..`) and never move. Arrays marked "all" cover both.

use nalgebra::Vector3;
use serde::{Deserialize, Serialize};

/// A 3-vector of `f64`.
pub type Vec3 = Vector3<f64>;

/// Particle arrays.
#[derive(Clone, Debug, Default, Serialize, Deserialize, PartialEq)]
pub struct Particles {
    /// Number of fluid particles; they occupy indices `0..n_fluid`.
    pub n_fluid: usize,
    /// Position [m] (all).
    pub pos: Vec<Vec3>,
    /// Velocity [m/s] (all; for no-slip walls the ghost velocity of Adami 2012, else zero).
    pub vel: Vec<Vec3>,
    /// Acceleration of the last force evaluation [m/s²] (fluid).
    pub acc: Vec<Vec3>,
    /// Density [kg/m³] (all; walls: from the EOS at their extrapolated pressure).
    pub rho: Vec<f64>,
    /// Density rate `dρ/dt` of the last force evaluation [kg/(m³ s)] (fluid; continuity only).
    pub drho: Vec<f64>,
    /// Pressure [Pa] (all).
    pub pressure: Vec<f64>,
    /// Volume `V = m/ρ` [m³] (all).
    pub vol: Vec<f64>,
    /// Phase index: liquids first, then solids (all).
    pub phase: Vec<u8>,
    /// Index of the particle when the scene was built; stable across re-sorting (all).
    pub id: Vec<u32>,
    /// Position at the last neighbour-list build [m] (fluid).
    pub x_ref: Vec<Vec3>,
}

impl Particles {
    /// Total number of particles (fluid and wall).
    pub fn len(&self) -> usize {
        self.pos.len()
    }

    /// Whether there are no particles.
    pub fn is_empty(&self) -> bool {
        self.pos.is_empty()
    }

    /// Number of wall particles.
    pub fn n_wall(&self) -> usize {
        self.pos.len() - self.n_fluid
    }

    /// Reorders the fluid particles: new index `k` takes old index `perm[k]`; `scratch` holds
    /// the old values (its buffers are reused from one rebuild to the next).
    pub(crate) fn permute_fluid(&mut self, perm: &[u32], scratch: &mut PermuteScratch) {
        use rayon::prelude::*;
        fn gather<T: Copy + Send + Sync>(v: &mut [T], perm: &[u32], old: &mut Vec<T>) {
            if v.is_empty() {
                return;
            }
            old.clear();
            old.extend_from_slice(&v[..perm.len()]);
            let old = &*old;
            v[..perm.len()]
                .par_iter_mut()
                .zip(perm.par_iter())
                .for_each(|(x, &p)| *x = old[p as usize]);
        }
        let s = scratch;
        gather(&mut self.pos, perm, &mut s.vectors);
        gather(&mut self.vel, perm, &mut s.vectors);
        gather(&mut self.acc, perm, &mut s.vectors);
        gather(&mut self.rho, perm, &mut s.scalars);
        gather(&mut self.drho, perm, &mut s.scalars);
        gather(&mut self.pressure, perm, &mut s.scalars);
        gather(&mut self.vol, perm, &mut s.scalars);
        gather(&mut self.phase, perm, &mut s.bytes);
        gather(&mut self.id, perm, &mut s.ids);
        gather(&mut self.x_ref, perm, &mut s.vectors);
    }
}

/// The buffers [`Particles::permute_fluid`] copies the old values into, one per element type.
#[derive(Clone, Debug, Default)]
pub(crate) struct PermuteScratch {
    vectors: Vec<Vec3>,
    scalars: Vec<f64>,
    bytes: Vec<u8>,
    ids: Vec<u32>,
}
