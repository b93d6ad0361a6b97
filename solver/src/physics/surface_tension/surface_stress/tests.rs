//! The surface stress on lattices where its result is known: a flat interface carries the
//! typed tension (up to the colour kernel's lattice moment, computed here), no net force, and
//! a bulk carries nothing; any cloud conserves linear momentum.

use super::*;
use crate::periodic::PeriodicBox;
use crate::physics::surface_tension::test_cloud::{
    cloud, lattice, lattice_moment, on_threads, small_sphere, Cloud, L0, R_E, SIGMA,
};

fn evaluate(c: &Cloud, sigma: f64) -> StressScratch {
    let mut s = StressScratch::default();
    s.evaluate(&c.input(), 2, |a, b| if a != b { sigma } else { 0.0 });
    s
}

#[test]
fn a_flat_interface_carries_the_typed_tension_and_no_force() {
    // 10 × 10 × 20 periodic box: phase 0 below z = 10 l0, phase 1 above (two interfaces)
    let n = [10, 10, 20];
    let b = PeriodicBox::new([
        Some([0.0, 10.0 * L0]),
        Some([0.0, 10.0 * L0]),
        Some([0.0, 20.0 * L0]),
    ]);
    let c = cloud(lattice(n), |x| u8::from(x.z > 10.0 * L0), b);
    let s = evaluate(&c, SIGMA);
    // the mechanical tension Σ V (T_xx − T_zz) per area of the two interfaces
    let area = 100.0 * L0 * L0;
    let tension: f64 = (0..c.pos.len())
        .map(|i| c.vol[i] * (s.stress[i][0] - s.stress[i][2]))
        .sum::<f64>()
        / (2.0 * area);
    let m = lattice_moment();
    // the same lattice sum in another order: round-off of ~10⁴ terms
    assert!(
        (tension / (SIGMA * m) - 1.0).abs() < 1e-12,
        "tension {tension} N/m against σM = {} N/m",
        SIGMA * m
    );
    // the lattice's quadrature error of the colour kernel's moment at h_c = 2.1 l0 is 4e-4
    // (this sum: 1.0004), so the flat lattice interface carries the typed σ to that
    assert!((m - 1.0).abs() < 1e-3, "M = {m}");
    // xx and yy alike, no shear: the stress of a flat interface
    for t in &s.stress {
        assert!((t[0] - t[1]).abs() <= 1e-12 * t[0].abs());
        assert!(t[2].abs() + t[3].abs() + t[4].abs() + t[5].abs() <= 1e-9 * SIGMA / L0);
    }
    // the energy estimate: σ per area of interface, up to the same moment
    assert!((s.interface_energy_j / (2.0 * area * SIGMA * m) - 1.0).abs() < 1e-12);
    // no force on a flat interface (by the lattice's symmetry; round-off of sums of σ l0 terms)
    let scale = SIGMA * L0;
    for f in &s.force {
        assert!(f.norm() < 1e-10 * scale, "{f}");
    }
}

#[test]
fn a_bulk_carries_no_stress_however_its_particles_sit() {
    // a sheared lattice (x += 0.3 z) of phase 0 around a block of phase 1: particles farther
    // than the colour kernel's support from phase 1 have no stress and no force
    let pos: Vec<Vec3> = lattice([16, 16, 16])
        .into_iter()
        .map(|x| Vec3::new(x.x + 0.3 * x.z, x.y, x.z))
        .collect();
    let in_block = |x: Vec3| x.z < 3.0 * L0;
    let c = cloud(pos, |x| u8::from(in_block(x)), PeriodicBox::OPEN);
    let s = evaluate(&c, SIGMA);
    let far = |x: Vec3| x.z > 3.0 * L0 + 2.0 * R_E; // the stress's and the force's reach
    let mut checked = 0;
    for (i, x) in c.pos.iter().enumerate() {
        if far(*x) {
            assert_eq!(s.stress[i], [0.0; 6]);
            assert_eq!(s.force[i], Vec3::zeros());
            checked += 1;
        }
    }
    assert!(checked > 1000, "{checked}");
}

#[test]
fn linear_momentum_is_conserved_on_a_disordered_two_phase_cloud() {
    // a jittered lattice with a sphere of phase 1: every pair force has its exact opposite
    let pos =
        crate::physics::surface_tension::lattice_cloud::jittered_sites([14, 14, 14], L0, 0.4 * L0);
    let centre = Vec3::repeat(7.0 * L0);
    let c = cloud(
        pos,
        |x| u8::from((x - centre).norm() < 4.5 * L0),
        PeriodicBox::OPEN,
    );
    let s = evaluate(&c, SIGMA);
    let total: Vec3 = s.force.iter().sum();
    let magnitude: f64 = s.force.iter().map(|f| f.norm()).sum();
    assert!(magnitude > 0.0);
    // the pairs are added in another order on each side: round-off only
    assert!(total.norm() < 1e-13 * magnitude, "{total} of {magnitude}");
    // the tension pulls the sphere's surface inward: the radial force on phase 1 is negative
    let radial: f64 = (0..c.pos.len())
        .filter(|&i| c.phase[i] == 1)
        .map(|i| s.force[i].dot(&(c.pos[i] - centre).normalize()))
        .sum();
    assert!(radial < 0.0, "{radial}");
}

#[test]
fn the_same_bits_for_any_thread_count() {
    let c = small_sphere();
    let run = |threads| on_threads(threads, || evaluate(&c, SIGMA));
    let one = run(1);
    for threads in [2, 3] {
        let other = run(threads);
        assert!(one.force == other.force && one.stress == other.stress);
        assert_eq!(
            one.interface_energy_j.to_bits(),
            other.interface_energy_j.to_bits()
        );
    }
}
