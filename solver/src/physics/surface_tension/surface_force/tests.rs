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

/// The surface force on a lattice of `nz` layers of 10 × 10 sites, periodic along x, y and z,
/// with phase 1 where `z` is in `layer` [m] and phase 0 elsewhere (two flat interfaces).
fn flat_layer(nz: usize, layer: [f64; 2]) -> ForceScratch {
    let b = PeriodicBox::new([
        Some([0.0, 10.0 * L0]),
        Some([0.0, 10.0 * L0]),
        Some([0.0, nz as f64 * L0]),
    ]);
    let c = cloud(
        lattice([10, 10, nz]),
        |x| u8::from(x.z > layer[0] && x.z < layer[1]),
        b,
    );
    evaluate(&c)
}

/// Asserts that every curvature and force of `s` is round-off: every band particle's normal
/// is ±z up to the round-off of its gradient's lattice sum (~10² terms of unit size), so
/// `n_j − n_i`, the curvature and the force are round-off.
fn assert_flat(s: &ForceScratch, what: &str) {
    let kappa_max = s.curvature.iter().fold(0.0f64, |m, k| m.max(k.abs()));
    assert!(kappa_max * L0 < 1e-12, "{what}: κ l0 = {kappa_max:e}");
    let force_max = s.force.iter().fold(0.0f64, |m, f| m.max(f.norm()));
    assert!(force_max < 1e-12 * SIGMA * L0, "{what}: {force_max:e} N");
}

#[test]
fn a_flat_interface_has_no_curvature_and_no_force() {
    // 10 × 10 × 20 periodic box: phase 0 below z = 10 l0, phase 1 above (two interfaces)
    let s = flat_layer(20, [10.0 * L0, 20.0 * L0]);
    assert_flat(&s, "flat");
    // the energy estimate: σ per area of interface, up to the colour kernel's lattice moment
    // (the surface stress's flat test: 1.0004 at h_c = 2.1 l0); round-off of ~10⁴ terms
    let area = 100.0 * L0 * L0;
    let m = lattice_moment();
    assert!((s.interface_energy_j / (2.0 * area * SIGMA * m) - 1.0).abs() < 1e-12);
}

#[test]
fn a_film_thinner_than_the_colour_kernel_has_no_curvature_and_no_force() {
    // slabs of phase 1, 2 to 8 l0 thick, in a periodic 10 × 10 × 24 box of phase 0: both faces of
    // the film are within the colour kernel's support (R_E = 4.2 l0) of its middle, where the
    // two faces' gradients meet with opposite normals. A flat film has zero curvature; counted
    // as neighbours, the opposite normals made its middle a fold (κ ~ 1/l0), which the shear
    // wave's 8 l0 slabs showed as every layer kicked along z, alternately (docs/findings.md).
    // The curvature's sums leave out neighbours whose normals are more than 120° apart; the
    // rest share the normal ±z up to round-off (as in the flat test above)
    for thickness in [2.0, 4.0, 6.0, 8.0] {
        let s = flat_layer(24, [8.0 * L0, (8.0 + thickness) * L0]);
        assert_flat(&s, &format!("{thickness} l0"));
    }
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

/// The forces [N] per fluid particle on a lattice Janus sphere in a periodic box: radius
/// `rho` l0, liquid 0 at x < 0 and liquid 1 at x > 0, in a gas (2), with tensions `t` [N/m]
/// and the split's momentum correction as `corrected`.
fn janus_sphere_forces(
    rho: f64,
    t: impl Fn(usize, usize) -> f64 + Sync,
    corrected: bool,
) -> Vec<Vec3> {
    let half = (rho + 7.0).ceil() as usize;
    let len = 2.0 * half as f64 * L0;
    let b = PeriodicBox::new([Some([0.0, len]); 3]);
    let centre = Vec3::repeat(half as f64 * L0);
    let c = cloud(
        lattice([2 * half; 3]),
        move |x| {
            let d = x - centre;
            if d.norm() < rho * L0 {
                u8::from(d.x > 0.0)
            } else {
                2
            }
        },
        b,
    );
    let mut s = ForceScratch {
        split_momentum_correction: corrected,
        ..ForceScratch::default()
    };
    s.evaluate(&c.input(), 3, t, Walls::Absent);
    s.force
}

#[test]
fn a_fold_in_an_interface_pulls_a_twentieth_more_than_its_line_force() {
    // A square column of liquid (side 2a, periodic along y) in another: each 90° fold of its
    // interface is a line force σ(t_1 + t_2) per length in the continuum, t the faces'
    // tangents away from the fold. The force summed over the quadrant of one fold, per σ and
    // length, measured −1.0504 along x and z at a = 8, 12, 16 and 24 l0 alike: the colour
    // kernel rounds the fold over its reach, and the rounding does not shrink with the fold's
    // distance from the others. A sphere's face pulls 0.99 of its Laplace force (the test
    // above), so where the split's folds do not cancel (off Neumann's balance) a drop is
    // pushed: the split's momentum correction (next test). Bounds ±0.01 around the measured
    // 1.050: the fold's error, 0.05, is five times that
    let (a, ny) = (12usize, 6usize);
    let n = 2 * a + 16;
    let side = n as f64 * L0;
    let b = PeriodicBox::new([
        Some([0.0, side]),
        Some([0.0, ny as f64 * L0]),
        Some([0.0, side]),
    ]);
    let mid = side / 2.0;
    let inside =
        move |x: Vec3| (x.x - mid).abs() < a as f64 * L0 && (x.z - mid).abs() < a as f64 * L0;
    let c = cloud(lattice([n, ny, n]), move |x| u8::from(!inside(x)), b);
    let s = evaluate(&c);
    let fold: Vec3 = (0..c.n_fluid)
        .filter(|&i| c.pos[i].x > mid && c.pos[i].z > mid)
        .map(|i| s.force[i])
        .sum::<Vec3>()
        / (SIGMA * ny as f64 * L0);
    eprintln!("one fold's force per σ and length: {fold:?}");
    for component in [-fold.x, -fold.z] {
        assert!((component - 1.05).abs() < 0.01, "{fold:?}");
    }
    assert!(fold.y.abs() < 1e-12, "{fold:?}");
}

#[test]
fn the_split_conserves_momentum_off_neumann_s_balance() {
    // Matte/slag's tensions (σ01 = 0.1, σ02 = 0.4, σ12 = 0.2 N/m; σ02 > σ01 + σ12, no
    // Neumann triangle) on a Janus sphere: the liquids' folds at their line with the gas do
    // not cancel and, uncorrected, push the drop along x (measured −7.4e-6 N at ρ = 8 l0 and
    // −3.0e-5 N at 12 l0: 0.74 % and 1.96 % of the two liquids' difference in line force
    // 2πR (σ02 − σ12); bound 0.3 %, so that the test fails if the push it removes vanishes).
    // With the correction the net force is round-off (~1e5 terms of up to 1e-6 N; 1e-18 N
    // measured, bound 1e-15 N). Each share is corrected on its own (its closed interface's
    // force vanishes whatever the others do), so identical liquids (0.4, 0.4), whose net
    // vanishes by symmetry, are corrected too: no particle's force changes by more than 1 %
    // of the largest (a small uniform traction per share, not a reshaping of the force)
    let ms = |a: usize, b: usize| match (a.min(b), a.max(b)) {
        (0, 1) => 0.1,
        (0, 2) => 0.4,
        (1, 2) => 0.2,
        _ => 0.0,
    };
    for rho in [8.0, 12.0] {
        let raw: Vec3 = janus_sphere_forces(rho, ms, false).iter().sum();
        let net: Vec3 = janus_sphere_forces(rho, ms, true).iter().sum();
        let line = 2.0 * std::f64::consts::PI * rho * L0 * 0.2;
        eprintln!(
            "ρ = {rho} l0: net {raw:?} N uncorrected ({:.4} of 2πR(σ02 − σ12)), {net:?} N corrected",
            raw.x / line
        );
        assert!(
            raw.x.abs() > 0.003 * line,
            "the uncorrected push vanished: {raw:?}"
        );
        assert!(net.norm() < 1e-15, "{net:?}");
    }
    let identical = |a: usize, b: usize| match (a.min(b), a.max(b)) {
        (0, 1) => 0.1,
        (0, 2) | (1, 2) => 0.4,
        _ => 0.0,
    };
    let before = janus_sphere_forces(8.0, identical, false);
    let after = janus_sphere_forces(8.0, identical, true);
    let largest = before.iter().fold(0.0f64, |m, b| m.max(b.norm()));
    let change = before
        .iter()
        .zip(&after)
        .fold(0.0f64, |m, (b, a)| m.max((a - b).norm()));
    eprintln!("identical liquids: largest change {change:e} of {largest:e} N");
    assert!(change < 0.01 * largest, "{change:e} of {largest:e} N");
}

#[test]
fn the_corrected_split_has_the_same_bits_for_any_thread_count() {
    // the correction's sums run in particle order
    let centre = Vec3::repeat(6.0 * L0);
    let c = cloud(
        lattice([12, 12, 12]),
        move |x| {
            let d = x - centre;
            if d.norm() < 4.0 * L0 {
                u8::from(d.x > 0.0)
            } else {
                2
            }
        },
        PeriodicBox::OPEN,
    );
    assert_same_bits_for_any_thread_count(|| {
        let mut s = ForceScratch::default();
        s.evaluate(&c.input(), 3, three(0.1, 0.4, 0.2), Walls::Absent);
        s
    });
}
