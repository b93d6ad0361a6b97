//! The surface force with walls, on lattices where the result is known: a liquid layer on a
//! wall under a gas has no force and the energy of its two faces; a vertical liquid|gas
//! interface across a channel is pushed along the walls by Young's unbalanced tension, which
//! vanishes at 90°; the bits do not depend on the thread count.

use super::contact_line::{self, Channel};
use super::*;
use crate::periodic::PeriodicBox;
use crate::physics::surface_tension::test_cloud::{
    cloud_with_walls, colour_kernel, lattice, lattice_moment, Cloud, L0, SIGMA,
};

/// Phases: the liquid 0 (surface tension `SIGMA`), a gas 1 without one, the walls' solid 2.
const WALL: usize = 2;

/// Tensions [N/m] of the liquid with the gas (`SIGMA`) and, relative to the solid's own, of
/// each with the solid (Young: `−σ cos θ` for the liquid at contact angle `theta_deg`, zero
/// for the gas without a surface tension), as the model's table holds them.
fn tensions(theta_deg: f64) -> impl Fn(usize, usize) -> f64 + Sync {
    let young = -SIGMA * theta_deg.to_radians().cos();
    move |a, b| match (a.min(b), a.max(b)) {
        (0, 1) => SIGMA,
        (0, 2) => young,
        _ => 0.0,
    }
}

fn evaluate(c: &Cloud, theta_deg: f64) -> ForceScratch {
    let mut s = ForceScratch::default();
    s.evaluate(&c.input(), 2, tensions(theta_deg), Some(WALL));
    s
}

/// The lattice sites `(i + ½) l0` of `nx × ny` columns over the z layers `z0..z1` (in l0).
fn slab(nx: usize, ny: usize, z0: i64, z1: i64) -> Vec<Vec3> {
    lattice([nx, ny, (z1 - z0) as usize])
        .into_iter()
        .map(|p| p + Vec3::new(0.0, 0.0, z0 as f64 * L0))
        .collect()
}

#[test]
fn the_shares_of_two_liquids_on_a_wall_follow_young() {
    // σ_0 + σ_1 = σ_01 and σ_0 − σ_1 = σ_0S − σ_1S = −σ cos θ; the solid has no term
    let terms = interface_terms(2, &tensions(60.0), Some(WALL));
    let share = |k: u8| terms.iter().find(|t| t.0 == Sides::Phase(k)).unwrap().1;
    assert_eq!(terms.len(), 2, "{terms:?}");
    assert!((share(0) - 0.25 * SIGMA).abs() < 1e-15 && (share(1) - 0.75 * SIGMA).abs() < 1e-15);
    // no wall: the pair form
    assert_eq!(
        interface_terms(2, &tensions(60.0), None),
        vec![(Sides::Pair(0, 1), SIGMA)]
    );
}

#[test]
fn a_liquid_layer_on_a_wall_has_no_force_and_the_energy_of_its_faces() {
    // periodic 10 × 10 columns: the wall's five layers below z = 0, the liquid up to 10 l0, the
    // gas up to 20 l0, empty space above (no phase: no term)
    let b = PeriodicBox::new([Some([0.0, 10.0 * L0]), Some([0.0, 10.0 * L0]), None]);
    let c = cloud_with_walls(
        slab(10, 10, 0, 20),
        |x| u8::from(x.z > 10.0 * L0),
        slab(10, 10, -5, 0),
        WALL as u8,
        b,
    );
    let s = evaluate(&c, 60.0);
    // every band normal is ±z up to its lattice sum's round-off, as on a flat liquid interface
    let force_max = s.force.iter().fold(0.0f64, |m, f| m.max(f.norm()));
    assert!(force_max < 1e-12 * SIGMA * L0, "{force_max:e} N");
    // the energy: the liquid's share σ/4 on its face with the wall (the solid's share is
    // zero), σ on its face with the gas, each per area times the colour kernel's lattice
    // moment (the flat test's); round-off of ~10⁴ terms
    let area = 100.0 * L0 * L0;
    let expected = (0.25 + 1.0) * SIGMA * area * lattice_moment();
    let e = s.interface_energy_j / expected - 1.0;
    assert!(e.abs() < 1e-12, "{e:e}");
}

#[test]
fn a_contact_line_off_its_angle_is_pushed_along_the_wall_as_young_says() {
    let channel = Channel::new(&colour_kernel(), L0);
    let push = |theta: f64, factor: f64| {
        let cos = theta.to_radians().cos();
        let s = channel.evaluate(colour_kernel(), SIGMA, cos, factor);
        (channel.push_n(&s), channel.energy_push_n(SIGMA, cos), s)
    };
    // the interface is vertical (90°): at θ = 90° the liquid's and the gas's shares are equal
    // and the lattice is symmetric about the interface with the phases swapped, so the force
    // along x cancels to round-off
    let (at_90, _, s) = push(90.0, 1.0);
    let scale = s.force.iter().fold(0.0f64, |m, f| m.max(f.norm()));
    assert!(
        at_90.abs() < 1e-12 * scale * 1e3,
        "{at_90:e} N against {scale:e} N"
    );
    // at θ the energy falls by 2σ cos θ L_y M per length moved towards the gas
    // (Channel::energy_push_n); the uncalibrated force hands the fluid a share of it
    let ratio = |theta: f64, factor: f64| {
        let (fx, energy, _) = push(theta, factor);
        eprintln!("θ = {theta}°, factor {factor}: F_x {fx:e} N, energy's {energy:e} N");
        fx / energy
    };
    let (wetting, repelled) = (ratio(60.0, 1.0), ratio(120.0, 1.0));
    // 120° is 60° with the liquid and the gas swapped (shares ¾σ and ¼σ exchanged): the same
    // ratio, up to round-off
    assert!(
        (wetting / repelled - 1.0).abs() < 1e-9,
        "{wetting} {repelled}"
    );
    // the model's measurement (at another tension: the same ratio up to round-off)
    let share = contact_line::young_share(colour_kernel(), L0);
    assert!((wetting / share - 1.0).abs() < 1e-12, "{wetting} {share}");
    // measured 0.895: the share on the wall particles is lost (contact_line); the bounds hold
    // it to its sign (towards the gas below 90°) and to within 0.05 of what it is at this
    // lattice, so that a change in the force at walls shows here before it shows in the caps
    assert!((wetting - 0.895).abs() < 0.05, "{wetting}");
    // the model's calibration divides the liquid–solid tension by the share: the push is then
    // the energy's at every angle, as far as the force is linear in the shares (round-off)
    for theta in [30.0, 60.0, 120.0, 150.0] {
        let calibrated = ratio(theta, 1.0 / wetting);
        assert!((calibrated - 1.0).abs() < 1e-9, "{theta}°: {calibrated}");
    }
}

#[test]
fn with_walls_the_same_bits_for_any_thread_count() {
    let channel = Channel::new(&colour_kernel(), L0);
    super::tests::assert_same_bits_for_any_thread_count(|| {
        channel.evaluate(colour_kernel(), SIGMA, 0.5, 1.0)
    });
}
