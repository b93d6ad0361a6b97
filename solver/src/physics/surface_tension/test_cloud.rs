//! Lattice clouds for the continuum models' unit tests: particles on a simple cubic lattice,
//! sorted by cell, with neighbour lists, and the colour kernel's lattice moment.

use super::lattice_cloud::{lattice_sites, LatticeCloud};
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

/// The unit tests' lattice clouds (volume `l0³` each).
pub type Cloud = LatticeCloud;

impl Cloud {
    /// What the continuum models read of the cloud, with the colour kernel.
    pub fn input(&self) -> StressInput<'_, WendlandC2> {
        self.stress_input(colour_kernel())
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
    LatticeCloud::new(search, fluid, phase_of, walls, wall_phase, L0 * L0 * L0)
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
    lattice_sites(n, L0)
}

/// The colour kernel's second moment on the lattice ([`crate::physics::surface_tension::lattice_cloud::second_moment`]): a
/// flat interface's `Σ V |G|` per area.
pub fn lattice_moment() -> f64 {
    crate::physics::surface_tension::lattice_cloud::second_moment(&colour_kernel(), L0)
}
