//! A lattice sphere of one liquid in a cube of another, the common input of the continuum
//! models' diagnostics ([`super::curvature`], [`super::mode_stiffness`]): lattice units
//! (l0 = 1 m, unit volumes), the simple cubic lattice jittered by a seeded uniform
//! displacement of up to `±jitter l0` per axis (a lattice is a special input), then
//! optionally deformed.

use solver::kernel::{Kernel, WendlandC2};
use solver::neighbours::NeighbourSearch;
use solver::periodic::PeriodicBox;
use solver::physics::surface_tension::surface_stress::StressInput;
use solver::state::Vec3;

/// The particles of a sphere of phase 1 in a cube of phase 0, in neighbour-search order.
pub struct SphereCloud {
    /// Positions after the deformation [l0].
    pub pos: Vec<Vec3>,
    /// Positions before it, relative to the sphere's centre [l0].
    pub reference: Vec<Vec3>,
    /// Phase per particle: 1 inside the undeformed sphere, 0 outside.
    pub phase: Vec<u8>,
    vol: Vec<f64>,
    search: NeighbourSearch,
    re_over_l0: f64,
}

/// The particles at `moved` [l0] in neighbour-search order with their lists built (near radius
/// 2 l0, far `re_over_l0`, skin 0.3 l0, periodic as `periodic` says), and `reference` (one
/// entry per particle) in the same order: `(positions, references, search)`.
pub(super) fn searched(
    moved: &[Vec3],
    reference: &[Vec3],
    re_over_l0: f64,
    periodic: PeriodicBox,
) -> (Vec<Vec3>, Vec<Vec3>, NeighbourSearch) {
    let mut search = NeighbourSearch::new(2.0, re_over_l0, 0.3);
    search.set_periodic(periodic);
    let order = search
        .sort_order(moved)
        .expect("the cloud fits the cell grid");
    let pos: Vec<Vec3> = order.iter().map(|&i| moved[i as usize]).collect();
    let reference = order.iter().map(|&i| reference[i as usize]).collect();
    search
        .build(&pos, pos.len())
        .expect("the cloud fits the cell grid");
    (pos, reference, search)
}

impl SphereCloud {
    /// The sphere of `r_over_l0` spacings, in a cube that reaches the colour kernel's support
    /// `re_over_l0` beyond it and two spacings more, jittered by up to `±jitter_over_l0`
    /// spacings; each particle then moves by `displacement(x − centre)` [l0] (the phases are
    /// those of the undeformed sphere).
    pub fn new(
        r_over_l0: f64,
        re_over_l0: f64,
        jitter_over_l0: f64,
        displacement: impl Fn(Vec3) -> Vec3,
    ) -> Self {
        let n = (2.0 * (r_over_l0 + re_over_l0) + 4.0).ceil() as usize;
        let centre = Vec3::repeat(0.5 * n as f64);
        let mut seed = 0x5eed_c0de_u64;
        let mut uniform = move || {
            seed = seed
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            2.0 * (seed >> 11) as f64 / (1u64 << 53) as f64 - 1.0
        };
        let sites = (0..n * n * n)
            .map(|k| Vec3::new((k % n) as f64, (k / n % n) as f64, (k / (n * n)) as f64));
        let reference: Vec<Vec3> = sites
            .map(|x| {
                x + Vec3::repeat(0.5) - centre
                    + Vec3::new(uniform(), uniform(), uniform()) * jitter_over_l0
            })
            .collect();
        let moved: Vec<Vec3> = reference
            .iter()
            .map(|&x| centre + x + displacement(x))
            .collect();
        let (pos, reference, search) = searched(&moved, &reference, re_over_l0, PeriodicBox::OPEN);
        let phase = reference
            .iter()
            .map(|x| u8::from(x.norm() < r_over_l0))
            .collect();
        SphereCloud {
            vol: vec![1.0; pos.len()],
            pos,
            reference,
            phase,
            search,
            re_over_l0,
        }
    }

    /// The continuum models' input: the Wendland C2 colour kernel with support `r_e`.
    pub fn input(&self) -> StressInput<'_, WendlandC2> {
        StressInput {
            kernel: WendlandC2::new(self.re_over_l0 / 2.0),
            pos: &self.pos,
            vol: &self.vol,
            phase: &self.phase,
            n_fluid: self.pos.len(),
            lists: &self.search.lists,
        }
    }
}
