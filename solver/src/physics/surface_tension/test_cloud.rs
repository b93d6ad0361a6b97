//! Lattice clouds for the continuum models' unit tests: particles on a simple cubic lattice,
//! sorted by cell, with neighbour lists, and the colour kernel's lattice moment.

use super::surface_stress::StressInput;
use crate::kernel::{Kernel, WendlandC2};
use crate::neighbours::NeighbourSearch;
use crate::periodic::PeriodicBox;
use crate::state::Vec3;

pub const L0: f64 = 1e-4; // m
pub const SIGMA: f64 = 0.05; // N/m
pub const R_E: f64 = 4.2 * L0; // m: the colour kernel's support (the default cut-off)

/// The colour kernel with support `R_E` (Wendland C2: support 2h).
pub fn colour_kernel() -> WendlandC2 {
    WendlandC2::new(R_E / 2.0)
}

/// Particles, their phases and volumes [m³], and lists that reach the colour kernel's support.
pub struct Cloud {
    pub pos: Vec<Vec3>,
    pub phase: Vec<u8>,
    pub vol: Vec<f64>,
    pub search: NeighbourSearch,
    /// The fluid particles come first; walls after.
    pub n_fluid: usize,
}

impl Cloud {
    /// What the continuum models read of the cloud (all fluid, the colour kernel).
    pub fn input(&self) -> StressInput<'_, WendlandC2> {
        StressInput {
            kernel: colour_kernel(),
            pos: &self.pos,
            vol: &self.vol,
            phase: &self.phase,
            n_fluid: self.n_fluid,
            lists: &self.search.lists,
        }
    }
}

/// The cloud of `pos`, phase `phase_of(x)`, volume `l0³` each, sorted by cell, with lists built
/// (periodic along the axes in `periodic`).
pub fn cloud(pos: Vec<Vec3>, phase_of: impl Fn(Vec3) -> u8, periodic: PeriodicBox) -> Cloud {
    cloud_with_walls(pos, phase_of, Vec::new(), 0, periodic)
}

/// [`cloud`] with wall particles at `walls` of phase `wall_phase` after the fluid (each part
/// sorted by cell), their lists reaching the colour kernel's support.
pub fn cloud_with_walls(
    fluid: Vec<Vec3>,
    phase_of: impl Fn(Vec3) -> u8,
    walls: Vec<Vec3>,
    wall_phase: u8,
    periodic: PeriodicBox,
) -> Cloud {
    let mut search = NeighbourSearch::new(1.05 * L0 * 2.0, R_E, 0.3 * L0);
    search.set_periodic(periodic);
    search.walls_reach_far = true;
    let sorted = |x: &[Vec3]| -> Vec<Vec3> {
        let perm = search.sort_order(x).unwrap();
        perm.iter().map(|&i| x[i as usize]).collect()
    };
    let n_fluid = fluid.len();
    let mut pos = sorted(&fluid);
    pos.extend(sorted(&walls));
    search.build(&pos, n_fluid).unwrap();
    let phase = pos
        .iter()
        .enumerate()
        .map(|(i, &x)| if i < n_fluid { phase_of(x) } else { wall_phase })
        .collect();
    let vol = vec![L0 * L0 * L0; pos.len()];
    Cloud {
        pos,
        phase,
        vol,
        search,
        n_fluid,
    }
}

/// A sphere of phase 1, radius 4 l0, in a 12³ lattice cube of phase 0 (open).
pub fn small_sphere() -> Cloud {
    let centre = Vec3::repeat(6.0 * L0);
    cloud(
        lattice([12, 12, 12]),
        |x| u8::from((x - centre).norm() < 4.0 * L0),
        PeriodicBox::OPEN,
    )
}

/// `f()` on a pool of `threads` worker threads.
pub fn on_threads<T: Send>(threads: usize, f: impl FnOnce() -> T + Send) -> T {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap()
        .install(f)
}

/// The simple cubic lattice `(i + ½) l0` of an `nx × ny × nz` box [m].
pub fn lattice(n: [usize; 3]) -> Vec<Vec3> {
    let mut v = Vec::new();
    for k in 0..n[2] {
        for j in 0..n[1] {
            for i in 0..n[0] {
                v.push(Vec3::new(i as f64 + 0.5, j as f64 + 0.5, k as f64 + 0.5) * L0);
            }
        }
    }
    v
}

/// The colour kernel's second moment on the lattice, `M = −V Σ_{δ≠0} W′(|δ|) δ_z²/|δ|` over
/// the lattice offsets δ: 1 in the continuum (`−∫ z ∂_z W = ∫ W = 1`). A flat interface's
/// `Σ V |G|` per area is `M` (each side's pairs straddling it give `M/2`).
pub fn lattice_moment() -> f64 {
    let k = colour_kernel();
    let n = (R_E / L0).ceil() as i64 + 1;
    let mut m = 0.0;
    for i in -n..=n {
        for j in -n..=n {
            for l in -n..=n {
                let d = Vec3::new(i as f64, j as f64, l as f64) * L0;
                let r = d.norm();
                if r > 0.0 {
                    m -= L0.powi(3) * k.dw_dr(r) * d.z * d.z / r;
                }
            }
        }
    }
    m
}
