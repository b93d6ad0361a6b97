//! Lattice clouds for the continuum models' calibrations (and their tests): particles on a
//! simple cubic lattice, fluid then walls, each part sorted by cell, with neighbour lists that
//! reach the colour kernel's support.

use super::surface_stress::StressInput;
use crate::kernel::Kernel;
use crate::neighbours::NeighbourSearch;
use crate::state::Vec3;

/// Particles, their phases and volumes [m³], and their lists.
pub struct LatticeCloud {
    /// Positions [m]: the fluid first, the walls after.
    pub pos: Vec<Vec3>,
    /// Phase per particle.
    pub phase: Vec<u8>,
    /// Volume per particle [m³].
    pub vol: Vec<f64>,
    /// The search with the built lists.
    pub search: NeighbourSearch,
    /// Number of fluid particles.
    pub n_fluid: usize,
}

impl LatticeCloud {
    /// The cloud of fluid particles at `fluid` [m], of phase `phase_of(x)`, and wall particles
    /// at `walls` [m] of phase `wall_phase`, each of volume `vol_m3`, with lists built by
    /// `search` (its radii and periodic axes set by the caller; its far radius must cover the
    /// colour kernel's support, and `walls_reach_far` must be on if walls take part).
    ///
    /// # Panics
    /// If a position is not finite or beyond the cell keys' range (a lattice never is).
    pub fn new(
        mut search: NeighbourSearch,
        fluid: Vec<Vec3>,
        phase_of: impl Fn(Vec3) -> u8,
        walls: Vec<Vec3>,
        wall_phase: u8,
        vol_m3: f64,
    ) -> LatticeCloud {
        let sorted = |x: &[Vec3]| -> Vec<Vec3> {
            let perm = search.sort_order(x).expect("lattice sites have cell keys");
            perm.iter().map(|&i| x[i as usize]).collect()
        };
        let n_fluid = fluid.len();
        let mut pos = sorted(&fluid);
        pos.extend(sorted(&walls));
        search
            .build(&pos, n_fluid)
            .expect("lattice sites have cell keys");
        let phase = pos
            .iter()
            .enumerate()
            .map(|(i, &x)| if i < n_fluid { phase_of(x) } else { wall_phase })
            .collect();
        let vol = vec![vol_m3; pos.len()];
        LatticeCloud {
            pos,
            phase,
            vol,
            search,
            n_fluid,
        }
    }

    /// What the continuum models read of the cloud, with the colour kernel `kernel`.
    pub fn stress_input<K: Kernel>(&self, kernel: K) -> StressInput<'_, K> {
        StressInput {
            kernel,
            pos: &self.pos,
            vol: &self.vol,
            phase: &self.phase,
            n_fluid: self.n_fluid,
            lists: &self.search.lists,
        }
    }
}

/// The simple cubic lattice sites `(i + ½, j + ½, k + ½) l0` [m] of an `n[0] × n[1] × n[2]`
/// box, x fastest.
pub fn lattice_sites(n: [usize; 3], l0_m: f64) -> Vec<Vec3> {
    let mut v = Vec::with_capacity(n[0] * n[1] * n[2]);
    for k in 0..n[2] {
        for j in 0..n[1] {
            for i in 0..n[0] {
                v.push(Vec3::new(i as f64 + 0.5, j as f64 + 0.5, k as f64 + 0.5) * l0_m);
            }
        }
    }
    v
}

/// The lattice sites of [`lattice_sites`], each moved by up to `±amplitude_m/2` [m] per axis
/// by a fixed pseudo-random sequence (a 64-bit LCG from seed 12345): a disordered cloud that
/// is the same on every machine, for tests.
#[cfg(test)]
pub fn jittered_sites(n: [usize; 3], l0_m: f64, amplitude_m: f64) -> Vec<Vec3> {
    let mut state = 12345u64;
    let mut rnd = || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (state >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    };
    lattice_sites(n, l0_m)
        .into_iter()
        .map(|x| x + Vec3::new(rnd(), rnd(), rnd()) * amplitude_m)
        .collect()
}

/// The kernel's second moment on the lattice, `M = −l0³ Σ_{δ≠0} W′(|δ|) δ_z²/|δ|` over the
/// lattice offsets δ [-]: 1 in the continuum (`−∫ z ∂_z W = ∫ W = 1`). With the colour kernel,
/// a flat (001) interface's `Σ V |∇c|` per area is `M` (the pairs straddling it give `M/2`
/// on each side): the continuum models' interfacial energy per tension and area on the lattice.
pub fn second_moment<K: Kernel>(kernel: &K, l0: f64) -> f64 {
    let n = (kernel.support_m() / l0).ceil() as i64 + 1;
    let mut m = 0.0;
    for k in -n..=n {
        for j in -n..=n {
            for i in -n..=n {
                let r = l0 * ((i * i + j * j + k * k) as f64).sqrt();
                if r > 0.0 {
                    let dz = k as f64 * l0;
                    m -= l0 * l0 * l0 * kernel.dw_dr(r) * dz * dz / r;
                }
            }
        }
    }
    m
}
