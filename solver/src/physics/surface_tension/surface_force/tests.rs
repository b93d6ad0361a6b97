//! The surface force on lattices where its result is known: a flat interface has no curvature
//! and no force; a sphere of either phase is pulled inward by `σ·2/R` over its area, more
//! closely the finer it is; the bits do not depend on the thread count.

use super::*;
use crate::periodic::PeriodicBox;
use crate::physics::surface_tension::test_cloud::{
    cloud, lattice, lattice_moment, on_threads, small_sphere, Cloud, L0, SIGMA,
};

fn evaluate(c: &Cloud) -> ForceScratch {
    let mut s = ForceScratch::default();
    s.evaluate(
        &c.input(),
        2,
        |a, b| if a != b { SIGMA } else { 0.0 },
        Walls::Absent,
    );
    s
}

#[test]
fn a_flat_interface_has_no_curvature_and_no_force() {
    // 10 × 10 × 20 periodic box: phase 0 below z = 10 l0, phase 1 above (two interfaces)
    let b = PeriodicBox::new([
        Some([0.0, 10.0 * L0]),
        Some([0.0, 10.0 * L0]),
        Some([0.0, 20.0 * L0]),
    ]);
    let c = cloud(lattice([10, 10, 20]), |x| u8::from(x.z > 10.0 * L0), b);
    let s = evaluate(&c);
    // every band particle's normal is +z up to the round-off of its gradient's lattice sum
    // (~10² terms of unit size), so n_j − n_i, the curvature and the force are round-off
    let kappa_max = s.curvature.iter().fold(0.0f64, |m, k| m.max(k.abs()));
    assert!(kappa_max * L0 < 1e-12, "κ l0 = {kappa_max:e}");
    let force_max = s.force.iter().fold(0.0f64, |m, f| m.max(f.norm()));
    assert!(force_max < 1e-12 * SIGMA * L0, "{force_max:e} N");
    // the energy estimate: σ per area of interface, up to the colour kernel's lattice moment
    // (the surface stress's flat test: 1.0004 at h_c = 2.1 l0); round-off of ~10⁴ terms
    let area = 100.0 * L0 * L0;
    let m = lattice_moment();
    assert!((s.interface_energy_j / (2.0 * area * SIGMA * m) - 1.0).abs() < 1e-12);
}

/// A lattice sphere of radius `r_over_l0` spacings, of phase `inside`, in a cube of the other
/// phase; returns the inward force's total over `8πσR` (the Laplace jump `2σ/R` on the area
/// `4πR²`) and the net force over `Σ|F|`.
fn sphere(r_over_l0: f64, inside: u8) -> (f64, f64) {
    let n = (2.0 * r_over_l0 + 12.0).ceil() as usize;
    let centre = Vec3::repeat(0.5 * n as f64 * L0);
    let r = r_over_l0 * L0;
    let c = cloud(
        lattice([n, n, n]),
        |x| {
            if (x - centre).norm() < r {
                inside
            } else {
                1 - inside
            }
        },
        PeriodicBox::OPEN,
    );
    let s = evaluate(&c);
    let inward: f64 = (0..c.pos.len())
        .map(|i| -s.force[i].dot(&(c.pos[i] - centre).normalize()))
        .sum();
    let net: Vec3 = s.force.iter().sum();
    let magnitude: f64 = s.force.iter().map(|f| f.norm()).sum();
    (
        inward / (8.0 * std::f64::consts::PI * SIGMA * r),
        net.norm() / magnitude,
    )
}

#[test]
fn a_sphere_of_either_phase_is_pulled_inward_by_its_laplace_jump() {
    let (coarse, net) = sphere(6.0, 1);
    let (fine, net_fine) = sphere(10.0, 1);
    let (swapped, _) = sphere(6.0, 0);
    eprintln!(
        "inward/8πσR: R = 6 l0 {coarse}, 10 l0 {fine}, swapped {swapped}; net {net} {net_fine}"
    );
    // the lattice sphere is symmetric under the cube's reflections about its centre: the net
    // force is round-off of sums of ~10⁴ terms
    assert!(net < 1e-12 && net_fine < 1e-12, "{net} {net_fine}");
    // the orientation: inward for a sphere of the higher phase and of the lower one alike, and
    // the same up to round-off (swapping the phases flips both κ's sign convention and ∇c)
    assert!(coarse > 0.0 && swapped > 0.0);
    assert!((swapped / coarse - 1.0).abs() < 1e-10, "{swapped} {coarse}");
    // the inward total approaches 8πσR as the sphere is refined
    assert!((fine - 1.0).abs() < (coarse - 1.0).abs(), "{coarse} {fine}");
}

/// Asserts that `evaluate` gives the same forces, curvatures and energy bits on 1, 2 and 3
/// threads.
pub(super) fn assert_same_bits_for_any_thread_count(evaluate: impl Fn() -> ForceScratch + Sync) {
    let run = |threads| on_threads(threads, &evaluate);
    let one = run(1);
    for threads in [2, 3] {
        let other = run(threads);
        assert!(one.force == other.force && one.curvature == other.curvature);
        assert_eq!(
            one.interface_energy_j.to_bits(),
            other.interface_energy_j.to_bits()
        );
    }
}

#[test]
fn the_same_bits_for_any_thread_count() {
    let c = small_sphere();
    assert_same_bits_for_any_thread_count(|| evaluate(&c));
}

/// Tensions [N/m] of three liquids: 0|1, 0|2 and 1|2.
fn three(s01: f64, s02: f64, s12: f64) -> impl Fn(usize, usize) -> f64 {
    move |a, b| match (a.min(b), a.max(b)) {
        (0, 1) => s01,
        (0, 2) => s02,
        (1, 2) => s12,
        _ => 0.0,
    }
}

#[test]
fn three_liquids_split_each_pairs_tension_into_the_liquids_shares() {
    // one pair with a tension (a third liquid declared without any): that pair as it is
    let one = interface_terms(3, &|a, b| if a + b == 1 { 0.3 } else { 0.0 }, None);
    assert_eq!(one, vec![(Sides::Pair(0, 1), 0.3)]);
    // three: σ_a + σ_b = σ_ab on every interface, exactly for these binary fractions
    let terms = interface_terms(3, &three(0.5, 0.75, 0.625), None);
    let share = |k: u8| {
        terms
            .iter()
            .find(|t| t.0 == Sides::Phase(k))
            .map_or(0.0, |t| t.1)
    };
    assert_eq!(terms.len(), 3);
    assert_eq!(share(0) + share(1), 0.5);
    assert_eq!(share(0) + share(2), 0.75);
    assert_eq!(share(1) + share(2), 0.625);
    // a share of zero is no term: σ12 = σ01 + σ02 leaves liquid 0 none
    let terms = interface_terms(3, &three(0.25, 0.5, 0.75), None);
    assert!(terms.iter().all(|t| t.0 != Sides::Phase(0)), "{terms:?}");
}

#[test]
fn the_liquids_shares_give_the_pairs_force_where_two_liquids_meet() {
    // a sphere of liquid 0 in liquid 1; liquid 2, declared with tensions, has no particle:
    // the shares σ_0 + σ_1 = σ_01 must give the pair form's force, up to round-off
    let n = 24;
    let centre = Vec3::repeat(0.5 * n as f64 * L0);
    let c = cloud(
        lattice([n, n, n]),
        |x| u8::from((x - centre).norm() >= 6.0 * L0),
        PeriodicBox::OPEN,
    );
    let mut pair = ForceScratch::default();
    pair.evaluate(
        &c.input(),
        2,
        |a, b| if a != b { SIGMA } else { 0.0 },
        Walls::Absent,
    );
    let mut shares = ForceScratch::default();
    shares.evaluate(
        &c.input(),
        3,
        three(SIGMA, 0.7 * SIGMA, 0.9 * SIGMA),
        Walls::Absent,
    );
    let scale = pair.force.iter().fold(0.0f64, |m, f| m.max(f.norm()));
    assert!(scale > 0.0);
    let worst = pair
        .force
        .iter()
        .zip(&shares.force)
        .fold(0.0f64, |m, (a, b)| m.max((a - b).norm()));
    // round-off of the two halves' sums (~10³ terms each) against the force's largest value
    assert!(worst < 1e-12 * scale, "{worst:e} N against {scale:e} N");
    let e = (shares.interface_energy_j / pair.interface_energy_j - 1.0).abs();
    assert!(e < 1e-12, "{e:e}");
}

#[test]
fn three_flat_layers_have_no_curvature_and_no_force() {
    // a periodic column of three layers, 0 | 1 | 2 along z: three flat interfaces
    let b = PeriodicBox::new([
        Some([0.0, 10.0 * L0]),
        Some([0.0, 10.0 * L0]),
        Some([0.0, 30.0 * L0]),
    ]);
    let c = cloud(lattice([10, 10, 30]), |x| (x.z / (10.0 * L0)) as u8, b);
    let mut s = ForceScratch::default();
    s.evaluate(
        &c.input(),
        3,
        three(SIGMA, 0.7 * SIGMA, 0.9 * SIGMA),
        Walls::Absent,
    );
    // as the two-liquid flat test: every normal is ±z up to its lattice sum's round-off
    let force_max = s.force.iter().fold(0.0f64, |m, f| m.max(f.norm()));
    assert!(force_max < 1e-12 * SIGMA * L0, "{force_max:e} N");
    // the energy estimate is Σ σ_ab A_ab over the three interfaces (each 100 l0²), up to the
    // colour kernel's lattice moment, as in the two-liquid test
    let area = 100.0 * L0 * L0;
    let expected = (1.0 + 0.7 + 0.9) * SIGMA * area * lattice_moment();
    assert!(
        (s.interface_energy_j / expected - 1.0).abs() < 1e-12,
        "{} {expected}",
        s.interface_energy_j
    );
}
