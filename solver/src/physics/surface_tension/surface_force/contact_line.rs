//! The contact line on the reference lattice: the share of Young's push along a wall that the
//! surface force hands to the liquid, measured once per model so that the force can be
//! calibrated by it (docs/model.md §4b).
//!
//! At a contact line the liquid's and the other phase's terms meet, and the difference of
//! their shares, Young's `σ_aS − σ_bS = −σ_ab cos θ`, pushes the line along the wall. The force
//! of that difference is spread over the colour kernel's reach, and the part of it that lands
//! on wall particles acts on nothing. On a channel between two walls whose liquid|gas
//! interface stands at 90°, the liquid and the gas receive a fixed share of the push the
//! energy says (`2σ cos θ` per length of line, two walls): 0.895 with Wendland C2 at
//! `r_e = 4.2 l0`. A fine 2D cap typed at 60° settled at the angle whose cosine is that share
//! of the typed one (63.4°; docs/findings.md), so the model divides the liquid–solid
//! tensions by the share; with that, the same cap sits at 60.9° by its height and 59.2° by
//! its foot.

use super::wall_normal::WallNormal;
use super::{ForceScratch, Walls};
use crate::kernel::Kernel;
use crate::neighbours::NeighbourSearch;
use crate::periodic::PeriodicBox;
use crate::physics::surface_tension::lattice_cloud::{lattice_sites, LatticeCloud};
use crate::state::Vec3;

/// The channel's phases: the liquid 0, the gas 1 (no surface tension), the walls' solid 2.
const LIQUID: u8 = 0;
const GAS: u8 = 1;
const SOLID: u8 = 2;

/// A channel on the lattice of spacing `l0`, periodic along x and y, between two walls of
/// `ρ = ⌈r_e/l0⌉` layers each (the default wall's thickness); `8ρ` columns along x, `2ρ`
/// along y, `4ρ` layers high. The liquid fills `x < 4ρ l0`, the gas the rest: two vertical
/// interfaces, each meeting both walls, `4ρ l0` apart.
pub struct Channel {
    /// The channel's particles, fluid then walls.
    pub cloud: LatticeCloud,
    /// The interface at the middle [m] (the other is at the period's ends).
    middle_x_m: f64,
    /// Half the width along x over which the push is summed [m]: `2ρ l0`, twice the force's
    /// reach and clear of the other interface's.
    half_window_m: f64,
    /// The channel's width along y: the contact line's length on each wall [m].
    width_y_m: f64,
    /// The colour kernel's second moment on the lattice [-] ([`crate::physics::surface_tension::lattice_cloud::second_moment`]).
    moment: f64,
    /// The lattice spacing [m].
    l0_m: f64,
}

impl Channel {
    /// The channel for the colour kernel `colour` (support `r_e`) on the lattice of spacing
    /// `l0_m` [m].
    pub fn new<K: Kernel>(colour: &K, l0_m: f64) -> Channel {
        let reach = (colour.support_m() / l0_m - 1e-9).ceil() as usize;
        let (nx, ny, nz) = (8 * reach, 2 * reach, 4 * reach);
        let lift = |sites: Vec<Vec3>, layers: f64| -> Vec<Vec3> {
            let dz = Vec3::new(0.0, 0.0, layers * l0_m);
            sites.into_iter().map(|p| p + dz).collect()
        };
        let mut walls = lift(lattice_sites([nx, ny, reach], l0_m), -(reach as f64));
        walls.extend(lift(lattice_sites([nx, ny, reach], l0_m), nz as f64));
        let fluid = lattice_sites([nx, ny, nz], l0_m);
        let middle_x_m = (4 * reach) as f64 * l0_m;
        let r_e = colour.support_m();
        let mut search = NeighbourSearch::new(r_e, r_e, 0.0);
        search.set_periodic(PeriodicBox::new([
            Some([0.0, nx as f64 * l0_m]),
            Some([0.0, ny as f64 * l0_m]),
            None,
        ]));
        search.walls_reach_far = true;
        let phase_of = |x: Vec3| if x.x < middle_x_m { LIQUID } else { GAS };
        let cloud = LatticeCloud::new(search, fluid, phase_of, walls, SOLID, l0_m.powi(3));
        Channel {
            cloud,
            middle_x_m,
            half_window_m: (2 * reach) as f64 * l0_m,
            width_y_m: ny as f64 * l0_m,
            moment: crate::physics::surface_tension::lattice_cloud::second_moment(colour, l0_m),
            l0_m,
        }
    }

    /// The surface force on the channel: the liquid's surface tension `sigma_n_m` [N/m]
    /// against the gas, its tension against the walls' solid `−σ cos θ` times `young_factor`
    /// [-] (the model's calibration; 1 for none); the walls as a phase of the split, or, if
    /// `turn_normals`, as the wall normal's condition ([`super::wall_normal`]).
    pub fn evaluate<K: Kernel>(
        &self,
        colour: K,
        sigma_n_m: f64,
        cos_theta: f64,
        young_factor: f64,
        turn_normals: bool,
    ) -> ForceScratch {
        let young = -sigma_n_m * cos_theta * young_factor;
        let tension = move |a: usize, b: usize| match (a.min(b) as u8, a.max(b) as u8) {
            (LIQUID, GAS) => sigma_n_m,
            (LIQUID, SOLID) => young,
            _ => 0.0,
        };
        let walls = if turn_normals {
            Walls::Normal(WallNormal {
                solid: SOLID as usize,
                l0_m: self.l0_m,
            })
        } else {
            Walls::Shares(SOLID as usize)
        };
        let mut s = ForceScratch::default();
        s.evaluate(&self.cloud.stress_input(colour), 2, tension, walls);
        s
    }

    /// The force along x [N] on the fluid within the window about the middle interface.
    pub fn push_n(&self, s: &ForceScratch) -> f64 {
        (0..self.cloud.n_fluid)
            .filter(|&i| (self.cloud.pos[i].x - self.middle_x_m).abs() < self.half_window_m)
            .map(|i| s.force[i].x)
            .sum()
    }

    /// The push the interfacial energy says [N]: moving the interface by `dx` towards the gas
    /// wets `2 L_y dx` more of the walls (two walls), which lowers the energy by
    /// `2σ cos θ L_y dx`, each face's energy per area being its tension times the lattice
    /// moment `M`.
    pub fn energy_push_n(&self, sigma_n_m: f64, cos_theta: f64) -> f64 {
        2.0 * sigma_n_m * cos_theta * self.width_y_m * self.moment
    }
}

/// The share of Young's push that the uncalibrated surface force hands to the fluid at a
/// contact line [-]: the channel's push at 60° over the energy's, with the walls as a phase of
/// the split or, if `turn_normals`, as the wall normal's condition. In the split the push is
/// linear in `cos θ` (the liquid's and the gas's shares differ by `−σ cos θ`, and at 90° the
/// push cancels by symmetry), so one angle measures it; the wall normal's share varies by
/// about 2 % over 15°–150° (docs/findings.md). 1/share is the model's factor on the
/// liquid–solid tensions.
pub fn young_share<K: Kernel>(colour: K, l0_m: f64, turn_normals: bool) -> f64 {
    const COS_THETA: f64 = 0.5; // 60°: any angle off 90° gives the same ratio
    const SIGMA_N_M: f64 = 1.0; // the ratio does not depend on it
    let channel = Channel::new(&colour, l0_m);
    let s = channel.evaluate(colour, SIGMA_N_M, COS_THETA, 1.0, turn_normals);
    channel.push_n(&s) / channel.energy_push_n(SIGMA_N_M, COS_THETA)
}
