//! The surface force with walls, on lattices where the result is known: a liquid layer on a
//! wall under a gas has no force and the energy of its two faces; a vertical liquid|gas
//! interface across a channel is pushed along the walls by Young's unbalanced tension, which
//! vanishes at 90°; a circular contact line is pushed outwards as by a negative line tension
//! under the shares, drawn in as by a positive one under the wall normal (the caps' known
//! errors); the bits do not depend on the thread count.

use super::contact_line::{self, Channel};
use super::wall_normal::WallNormal;
use super::*;
use crate::periodic::PeriodicBox;
use crate::physics::surface_tension::test_cloud::{
    cloud_with_walls, colour_kernel, lattice, lattice_moment, Cloud, L0, R_E, SIGMA,
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
    evaluate_with(c, theta_deg, Walls::Shares(WALL))
}

/// The walls as the wall normal's condition.
const NORMAL: Walls = Walls::Normal(WallNormal {
    solid: WALL,
    l0_m: L0,
});

fn evaluate_with(c: &Cloud, theta_deg: f64, walls: Walls) -> ForceScratch {
    let mut s = ForceScratch::default();
    s.evaluate(&c.input(), 2, tensions(theta_deg), walls);
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

/// Periodic 10 × 10 columns: the wall's five layers below z = 0, the liquid up to 10 l0, the
/// gas up to 20 l0, empty space above (no phase: no term).
fn liquid_layer_on_wall() -> Cloud {
    let b = PeriodicBox::new([Some([0.0, 10.0 * L0]), Some([0.0, 10.0 * L0]), None]);
    cloud_with_walls(
        slab(10, 10, 0, 20),
        |x| u8::from(x.z > 10.0 * L0),
        slab(10, 10, -5, 0),
        WALL as u8,
        b,
    )
}

#[test]
fn a_liquid_layer_on_a_wall_has_no_force_and_the_energy_of_its_faces() {
    let c = liquid_layer_on_wall();
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
        let s = channel.evaluate(colour_kernel(), SIGMA, cos, factor, false);
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
    let share = contact_line::young_share(colour_kernel(), L0, false);
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
        channel.evaluate(colour_kernel(), SIGMA, 0.5, 1.0, false)
    });
}

/// The outward push per length of contact line [N/m] at the feet of a vertical liquid column of
/// radius `a_over_re` colour-kernel reaches, typed at 90° (no Young part), standing between two
/// walls (five layers each) 30 l0 apart in a gas, periodic along x and y: the radial force on
/// the ten layers next to the lower wall beyond ten times the middle layer's (the column's
/// Laplace pull), over the foot's circumference.
fn column_foot_push(a_over_re: f64, treatment: Walls) -> f64 {
    let a = a_over_re * R_E;
    let n = (2.0 * a / L0).ceil() as usize + 20;
    let n = n + n % 2;
    let (nz, near) = (30usize, 10usize);
    let centre = Vec3::new(n as f64 * L0 / 2.0, n as f64 * L0 / 2.0, 0.0);
    let side = Some([0.0, n as f64 * L0]);
    let mut walls = slab(n, n, -5, 0);
    walls.extend(slab(n, n, nz as i64, nz as i64 + 5));
    let c = cloud_with_walls(
        slab(n, n, 0, nz as i64),
        |x| u8::from((x - centre).xy().norm() >= a),
        walls,
        WALL as u8,
        PeriodicBox::new([side, side, None]),
    );
    let s = evaluate_with(&c, 90.0, treatment);
    let mut per_layer = vec![0.0; nz];
    for i in 0..c.n_fluid {
        let r = (c.pos[i] - centre).xy();
        if r.norm() > 0.0 {
            per_layer[(c.pos[i].z / L0) as usize] += s.force[i].xy().dot(&r.normalize());
        }
    }
    let middle = per_layer[nz / 2];
    let foot: f64 = per_layer[..near].iter().map(|f| f - middle).sum();
    foot / (2.0 * std::f64::consts::PI * a)
}

#[test]
fn a_contact_line_has_a_negative_line_tension_of_the_colour_kernels_reach() {
    // at 90° the exact push is zero; the smeared corners of the liquid's and the gas's faces
    // with the wall lower the energy by a line tension τ < 0, which pushes a circular line of
    // radius a outwards by −τ/a: the push times a/r_e is the same at every radius (measured
    // 0.3406 and 0.3380 at 2 and 4 r_e, and 0.3376 at 6 r_e: a higher-order part of 0.8 %,
    // bounded at 2 %)
    let scaled: Vec<f64> = [2.0, 4.0]
        .iter()
        .map(|&a| column_foot_push(a, Walls::Shares(WALL)) * a / SIGMA)
        .collect();
    eprintln!("push × a/(σ r_e): {scaled:?}");
    assert!((scaled[0] / scaled[1] - 1.0).abs() < 0.02, "{scaled:?}");
    // measured −τ/(σ r_e) = 0.34 (docs/findings.md): a regression guard on the error the caps
    // show (cos θ = cos θ_Y + 0.34 r_e/a), within 0.02 of what it is at this lattice
    assert!((scaled[1] - 0.34).abs() < 0.02, "{scaled:?}");
}

#[test]
fn with_the_wall_normal_a_liquid_layer_on_a_wall_has_no_force_and_only_its_free_face() {
    // as the shares' layer test: every normal is ±z, parallel to the wall's, so none is turned;
    // the walls are no phase, so the liquid's face on them has no term
    let c = liquid_layer_on_wall();
    let s = evaluate_with(&c, 60.0, NORMAL);
    let force_max = s.force.iter().fold(0.0f64, |m, f| m.max(f.norm()));
    assert!(force_max < 1e-12 * SIGMA * L0, "{force_max:e} N");
    let expected = SIGMA * 100.0 * L0 * L0 * lattice_moment();
    let e = s.interface_energy_j / expected - 1.0;
    assert!(e.abs() < 1e-12, "{e:e}"); // round-off of ~10⁴ terms
}

#[test]
fn with_the_wall_normal_a_contact_line_off_its_angle_is_pushed_along_the_wall() {
    let channel = Channel::new(&colour_kernel(), L0);
    let ratio = |theta: f64, factor: f64| {
        let cos = theta.to_radians().cos();
        let s = channel.evaluate(colour_kernel(), SIGMA, cos, factor, true);
        channel.push_n(&s) / channel.energy_push_n(SIGMA, cos)
    };
    let share = contact_line::young_share(colour_kernel(), L0, true);
    let thetas = [5.0, 15.0, 30.0, 45.0, 60.0, 80.0, 120.0, 150.0, 175.0];
    let calibrated: Vec<(f64, f64, f64)> = thetas
        .iter()
        .map(|&t| (t, ratio(t, 1.0), ratio(t, 1.0 / share)))
        .collect();
    eprintln!("share {share}; (θ, uncalibrated, calibrated): {calibrated:?}");
    // measured 1.055: the wall's side of the colour's jump hands the fluid a little more than
    // Young's push (0.885 without it); bounded to within 0.05 of it, as a regression guard
    assert!((share - 1.055).abs() < 0.05, "{share}");
    // 120° is 60° with the sides swapped: the same share (round-off)
    assert!((ratio(120.0, 1.0) / share - 1.0).abs() < 1e-9);
    // the push is not exactly linear in cos θ (the normal is turned, not the tension split):
    // calibrated by the share at 60°, it is within 2 % of the energy's at every angle
    // (measured 0.990–1.008 from 5° to 175°); the calibrated cos θ stays below 1 (0.948 cos θ),
    // so no angle is clipped
    for (theta, _, c) in calibrated {
        assert!((c - 1.0).abs() < 0.02, "{theta}°: {c}");
    }
}

#[test]
fn with_the_wall_normal_the_line_tension_is_a_quarter_of_the_shares_and_draws_the_line_in() {
    // the same column as the shares' line tension test: no liquid face meets a wall face, so
    // the corners that give the shares' −0.34 σ r_e are not there. What is left comes from the
    // colour extrapolated into the wall, a smeared image of the fluid's: measured push × a/(σ
    // r_e) −0.0817, −0.0803 at 2 and 4 r_e, a positive line tension (it draws the line in;
    // +0.033 before the wall's colour, from the gradients truncated at the wall). Bounded at
    // 0.12 (a third of the shares') and the same at both radii within 5 % (a line tension's
    // 1/a)
    let scaled: Vec<f64> = [2.0, 4.0]
        .iter()
        .map(|&a| column_foot_push(a, NORMAL) * a / SIGMA)
        .collect();
    eprintln!("push × a/(σ r_e): {scaled:?}");
    assert!(scaled[1] < 0.0 && scaled[1].abs() < 0.12, "{scaled:?}");
    assert!((scaled[0] / scaled[1] - 1.0).abs() < 0.05, "{scaled:?}");
}

#[test]
fn with_the_wall_normal_three_liquids_meet_the_wall_as_their_pair() {
    // the channel's two fluids as liquids A (0) and B (1) of a three-liquid scene whose third
    // liquid C (2, a gas) is elsewhere, the walls' solid then phase 3: the split's terms of A
    // and B, each turned at its own angle from the split's common level
    // (σ_A = ½(σ_AB + σ_AC − σ_BC) = 0.25 N/m, σ_B = 0.05 N/m, σ_C = 0.15 N/m; level C = 0,
    // so cos φ_A = (C − σ_AS)/σ_A = 0.8 and cos φ_B = 0), must push the line along the walls
    // as the pair does, `σ_A cos φ_A − σ_B cos φ_B = σ_AB cos θ_AB` with cos θ_AB = 2/3 (A at
    // 60°, B at 90°). Measured: 0.996 of the pair's push. Bound: 2 %, the spread of the
    // channel's push over Young's from 5° to 175° (1.043–1.063), by which a push turned at
    // another angle may differ
    let (s_ab, s_ac, s_bc) = (0.3, 0.4, 0.2);
    let young_a = -s_ac * 60f64.to_radians().cos(); // −σ_A cos θ_A against the gas C
    let pair = Channel::new(&colour_kernel(), L0);
    let pair_tension = move |a: usize, b: usize| match (a.min(b), a.max(b)) {
        (0, 1) => s_ab,
        (0, 2) => young_a, // the solid is phase 2 here
        _ => 0.0,
    };
    let mut split = Channel::new(&colour_kernel(), L0);
    let n = split.cloud.n_fluid;
    split.cloud.phase[n..].iter_mut().for_each(|p| *p = 3);
    let split_tension = move |a: usize, b: usize| match (a.min(b), a.max(b)) {
        (0, 1) => s_ab,
        (0, 2) => s_ac,
        (1, 2) => s_bc,
        (0, 3) => young_a,
        _ => 0.0, // B at 90° and the gas: no tension against the solid
    };
    let walls = |solid| Walls::Normal(WallNormal { solid, l0_m: L0 });
    let mut by_pair = ForceScratch::default();
    by_pair.evaluate(
        &pair.cloud.stress_input(colour_kernel()),
        2,
        pair_tension,
        walls(2),
    );
    let mut by_split = ForceScratch::default();
    let input = split.cloud.stress_input(colour_kernel());
    by_split.evaluate(&input, 3, split_tension, walls(3));
    assert_eq!(interface_terms(3, &split_tension, None).len(), 3);
    let (split_push, pair_push) = (pair.push_n(&by_split), pair.push_n(&by_pair));
    eprintln!(
        "the split's push along the walls over the pair's: {}",
        split_push / pair_push
    );
    assert!(
        (split_push / pair_push - 1.0).abs() < 0.02,
        "{split_push:e} {pair_push:e}"
    );
    // and the pair's push along the walls is Young's for the pair, as the channel's own test
    // measures it (its calibration share 1.055 ± 0.05 at the wall normal, uncalibrated here)
    let cos_ab = (0.0 - young_a) / s_ab;
    let ratio = pair.push_n(&by_split) / pair.energy_push_n(s_ab, cos_ab);
    assert!((ratio - 1.055).abs() < 0.06, "{ratio}");
}

#[test]
fn with_the_wall_normal_the_same_bits_for_any_thread_count() {
    let channel = Channel::new(&colour_kernel(), L0);
    super::tests::assert_same_bits_for_any_thread_count(|| {
        channel.evaluate(colour_kernel(), SIGMA, 0.5, 1.0, true)
    });
}

/// The pressure force [N] on each fluid particle of `c` (positions on the lattice `(k + ½) l0`,
/// periodic along x and y over `n` sites) when the liquid (phase 0) holds the pressure `dp_pa`
/// [Pa] and the gas none: the model's pair term `−V_i V_j (p_i + p_j) ∇_i W` with its SPH kernel
/// (Wendland C2, h = 1.3 l0) over fluid and wall neighbours, the walls' pressure extrapolated
/// from the fluid as the model does (Adami et al. 2012: `Σ_f p_f W_wf / Σ_f W_wf`; no gravity).
fn laplace_pressure_force(c: &Cloud, n: usize, dp_pa: f64) -> Vec<Vec3> {
    use crate::kernel::WendlandC2;
    use std::collections::HashMap;
    let k = WendlandC2::new(1.3 * L0);
    let reach = (k.support_m() / L0).ceil() as i64;
    let key = |x: Vec3| (x / L0).map(|v| v.floor() as i64);
    let at: HashMap<_, usize> = c
        .pos
        .iter()
        .enumerate()
        .map(|(i, &x)| (key(x), i))
        .collect();
    let wrap = |v: i64| v.rem_euclid(n as i64);
    let neighbours = |i: usize| {
        let ki = key(c.pos[i]);
        let mut out = Vec::new();
        for dx in -reach..=reach {
            for dy in -reach..=reach {
                for dz in -reach..=reach {
                    let kj = nalgebra::Vector3::new(wrap(ki.x + dx), wrap(ki.y + dy), ki.z + dz);
                    let d = Vec3::new(dx as f64, dy as f64, dz as f64) * -L0; // x_i − x_j
                    if let Some(&j) = at.get(&kj) {
                        if j != i && d.norm() < k.support_m() {
                            out.push((j, d));
                        }
                    }
                }
            }
        }
        out
    };
    let mut p: Vec<f64> = (0..c.pos.len())
        .map(|i| {
            if i < c.n_fluid && c.phase[i] == 0 {
                dp_pa
            } else {
                0.0
            }
        })
        .collect();
    for w in c.n_fluid..c.pos.len() {
        let (mut num, mut den) = (0.0, 0.0);
        for (j, d) in neighbours(w).into_iter().filter(|&(j, _)| j < c.n_fluid) {
            num += p[j] * k.w(d.norm());
            den += k.w(d.norm());
        }
        p[w] = if den > 0.0 { num / den } else { 0.0 };
    }
    (0..c.n_fluid)
        .map(|i| {
            let mut f = Vec3::zeros();
            for (j, d) in neighbours(i) {
                let r = d.norm();
                f -= d * (k.dw_dr(r) / r * c.vol[i] * c.vol[j] * (p[i] + p[j]));
            }
            f
        })
        .collect()
}

/// The radial push at the foot of a static spherical cap of radius `rho_l0` spacings meeting a
/// wall at its typed angle `theta_deg`, beyond the same sphere's without the wall, per length of
/// contact line over σ [-]: the force along the wall's plane away from the axis on the fluid
/// within 2 r_e of the wall (the wall normal's treatment, calibrated as the model is, and, if
/// `with_pressure`, the liquid's Laplace pressure `2σ/ρ` through the fluid and the wall), less
/// that of the full sphere (fluid below the plane instead of the wall, no walls) on the same
/// sites. A treatment without errors at the wall gives zero: the cap is Young's equilibrium.
fn static_cap_push(theta_deg: f64, rho_l0: f64, with_pressure: bool) -> f64 {
    static_cap_push_off(theta_deg, theta_deg, rho_l0, with_pressure)
}

/// [`static_cap_push`] of a cap built at `theta_deg` on a wall whose typed angle is `typed_deg`
/// (the push off Young's equilibrium is then `σ(cos θ_typed − cos θ)` per length).
fn static_cap_push_off(theta_deg: f64, typed_deg: f64, rho_l0: f64, with_pressure: bool) -> f64 {
    let rho = rho_l0 * L0;
    let zc = -rho * theta_deg.to_radians().cos();
    let n = (2.0 * (rho + R_E) / L0).ceil() as usize + 6;
    let n = n + n % 2;
    let nz = ((zc + rho + R_E) / L0).ceil() as i64 + 4;
    let centre = Vec3::new(n as f64 * L0 / 2.0, n as f64 * L0 / 2.0, zc);
    let side = Some([0.0, n as f64 * L0]);
    let outside = move |x: Vec3| u8::from((x - centre).norm() >= rho);
    let periodic = PeriodicBox::new([side, side, None]);
    let on_wall = cloud_with_walls(slab(n, n, 0, nz), outside, slab(n, n, -5, 0), 2, periodic);
    let factor = 1.0 / contact_line::young_share(colour_kernel(), L0, true);
    let tension = tensions(typed_deg);
    let calibrated =
        move |a: usize, b: usize| tension(a, b) * if a.max(b) == WALL { factor } else { 1.0 };
    let mut s = ForceScratch::default();
    s.evaluate(&on_wall.input(), 2, calibrated, NORMAL);
    let depth = ((rho - zc) / L0).ceil() as i64 + 6;
    let sphere = cloud_with_walls(slab(n, n, -depth, nz), outside, Vec::new(), 2, periodic);
    let mut t = ForceScratch::default();
    t.evaluate(&sphere.input(), 2, tensions(90.0), Walls::Absent);
    let foot = |c: &Cloud, force: &[Vec3]| -> f64 {
        (0..c.n_fluid)
            .filter(|&i| c.pos[i].z > 0.0 && c.pos[i].z < 2.0 * R_E)
            .map(|i| {
                let d = (c.pos[i] - centre).xy();
                force[i].xy().dot(&d) / d.norm()
            })
            .sum()
    };
    let dp = if with_pressure {
        2.0 * SIGMA / rho
    } else {
        0.0
    };
    let with = |c: &Cloud, force: &[Vec3]| -> Vec<Vec3> {
        let pressure = laplace_pressure_force(c, n, dp);
        force.iter().zip(&pressure).map(|(f, p)| f + p).collect()
    };
    let a = rho * theta_deg.to_radians().sin();
    let (cap, full) = (with(&on_wall, &s.force), with(&sphere, &t.force));
    (foot(&on_wall, &cap) - foot(&sphere, &full)) / (2.0 * std::f64::consts::PI * a * SIGMA)
}

#[test]
fn with_the_wall_normal_a_static_cap_at_its_angle_is_drawn_in_below_120_degrees() {
    // a cap of radius 10 l0 (its foot a = 2.1, 2.4, 2.1 r_e at 60°, 90°, 120°). Measured, with
    // the Laplace pressure: 60° −0.073, 90° −0.064, 120° −0.017; the surface force alone
    // −0.069, −0.064, −0.020: the pressure through the wall (extrapolated from the fluid) acts
    // as the full sphere's fluid below the plane does. Before the wall's side of the colour's
    // jump (docs/findings.md) the surface force alone gave +0.062, +0.022, +0.001, and the
    // shares give +0.178, +0.137, +0.133 (their line tension). A treatment without errors at
    // the wall gives 0. Bounds: the pressure's share below 0.01 (a tenth of the shares' line
    // tension); 0.03 at 120°, and −0.07 ± 0.02 at 60° and 90°, regression guards on the known
    // error (a cap drawn back to `cos θ_Y − 0.07`, 64° for 60°)
    let push: Vec<f64> = [60.0, 90.0, 120.0]
        .iter()
        .map(|&t| static_cap_push(t, 10.0, true))
        .collect();
    let alone: Vec<f64> = [60.0, 90.0, 120.0]
        .iter()
        .map(|&t| static_cap_push(t, 10.0, false))
        .collect();
    eprintln!("push/(σ per length) at 60°, 90°, 120°: {push:?}; the surface force alone {alone:?}");
    for (p, a) in push.iter().zip(&alone) {
        assert!((p - a).abs() < 0.01, "{push:?} {alone:?}");
    }
    assert!(push[2].abs() < 0.03, "{push:?}");
    assert!(
        (push[0] + 0.07).abs() < 0.02 && (push[1] + 0.07).abs() < 0.02,
        "{push:?}"
    );
}

#[test]
fn with_the_wall_normal_a_cap_off_its_angle_is_pushed_towards_it_as_young_says() {
    // caps of radius 10 l0 built either side of their typed angle: the change of the push at
    // the foot between the two, over the change of Young's unbalance σ(cos θ_Y − cos θ), is 1
    // for a treatment that hands the line Young's push whatever the interface's angle (the
    // channel calibrates it at 90° only). Measured 1.025 at 120° (built at 111.5° and 130°:
    // −0.161 and +0.122 against Young's −0.134 and +0.143) and 0.834 at 60° (built at 50° and
    // 70°). Bounds: 1 ± 0.25, the 60° cap's shortfall with a margin of its size again; a
    // treatment that pinned the line (no push off the angle) gives 0
    let slope = |typed: f64, below: f64, above: f64| {
        let young = |g: f64| typed.to_radians().cos() - g.to_radians().cos();
        let push = |g: f64| static_cap_push_off(g, typed, 10.0, true);
        (push(above) - push(below)) / (young(above) - young(below))
    };
    let s120 = slope(120.0, 111.5, 130.0);
    let s60 = slope(60.0, 50.0, 70.0);
    eprintln!("push over Young's unbalance: {s120} at 120°, {s60} at 60°");
    for s in [s120, s60] {
        assert!((s - 1.0).abs() < 0.25, "{s120} {s60}");
    }
}

/// The static cap's push at its foot against its size: a line tension `τ` pushes a circular
/// line of radius `a` by `−τ/a` per length, an error in the angle's force by a constant. Caps
/// of radius 10, 14, 20 l0 (feet of 2.1–4.8 r_e) at 60°, 90°, 120°, the surface force alone,
/// each fitted as `push = A + B r_e/a`. Measured (docs/findings.md): 90° A = −0.003,
/// B = −0.145 (a positive line tension, τ = 0.15 σ r_e); 60° A = −0.019, B = −0.104; 120°
/// A = +0.007, B = −0.056. Bounds: at 90° the three radii's `push·a` within 10 % of their
/// mean (a line tension alone; measured within 5 %), and at every angle |A| ≤ 0.03, a quarter of
/// the 60° cap's push at 10 l0 (the part that would not fall with `l0`). About a minute in a
/// release build: run with
/// `cargo test --release -p solver --lib static_cap_push_by_radius -- --ignored --nocapture`.
#[test]
#[ignore]
fn static_cap_push_by_radius() {
    for theta in [60.0_f64, 90.0, 120.0] {
        let fits: Vec<(f64, f64)> = [10.0, 14.0, 20.0]
            .iter()
            .map(|&rho| {
                let x = R_E / (rho * L0 * theta.to_radians().sin());
                (x, static_cap_push(theta, rho, false))
            })
            .collect();
        let (x0, p0) = fits[0];
        let (x2, p2) = fits[2];
        let b = (p0 - p2) / (x0 - x2);
        let a = p0 - b * x0;
        eprintln!("{theta}°: (r_e/a, push) {fits:?}; A = {a:.4}, B = {b:.4}");
        assert!(a.abs() <= 0.03, "{theta}°: A = {a}");
        if theta == 90.0 {
            let line: Vec<f64> = fits.iter().map(|(x, p)| p / x).collect();
            let mean = line.iter().sum::<f64>() / 3.0;
            for l in &line {
                assert!((l / mean - 1.0).abs() < 0.1, "{line:?}");
            }
        }
    }
}

/// The net force [N] on a static lattice Janus hemisphere under the wall normal, without the
/// split's momentum correction: radius `rho` l0, liquid 0 at x < 0 and liquid 1 at x > 0
/// (surface tension 0.4 N/m each, 0.1 N/m between them, contact angles 90° and `theta1_deg`),
/// in a gas (2) on a wall whose solid is phase 3, periodic along x and y.
fn janus_hemisphere_net_force_n(rho: f64, theta1_deg: f64) -> Vec3 {
    janus_hemisphere(rho, [0.4, 0.4], theta1_deg, false, 0.0).0
}

/// A deterministic offset in `[−1, 1]³` for site `i` (splitmix64's mixing).
fn scatter(i: usize) -> Vec3 {
    let unit = |k: u64| {
        let mut z = (i as u64)
            .wrapping_mul(3)
            .wrapping_add(k)
            .wrapping_add(0x9E37_79B9_7F4A_7C15);
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        2.0 * (z >> 11) as f64 / (1u64 << 53) as f64 - 1.0
    };
    Vec3::new(unit(0), unit(1), unit(2))
}

/// [`janus_hemisphere_net_force_n`] with the liquids' surface tensions `sigma` [N/m], the
/// correction as `corrected`, and each fluid site moved by up to `jitter` l0 along each axis:
/// the net force [N] and the forces per fluid particle [N].
fn janus_hemisphere(
    rho: f64,
    sigma: [f64; 2],
    theta1_deg: f64,
    corrected: bool,
    jitter: f64,
) -> (Vec3, Vec<Vec3>) {
    let half = (rho + 7.0).ceil() as usize;
    let n = 2 * half;
    let b = PeriodicBox::new([Some([0.0, n as f64 * L0]), Some([0.0, n as f64 * L0]), None]);
    let centre = Vec3::new(half as f64 * L0, half as f64 * L0, 0.0);
    let sites = slab(n, n, 0, half as i64).into_iter().enumerate();
    let c = cloud_with_walls(
        sites.map(|(i, x)| x + scatter(i) * (jitter * L0)).collect(),
        move |x| {
            let d = x - centre;
            if d.norm() < rho * L0 {
                u8::from(d.x > 0.0)
            } else {
                2
            }
        },
        slab(n, n, -6, 0),
        3,
        b,
    );
    let young1 = -sigma[1] * theta1_deg.to_radians().cos(); // liquid 0 at 90°: none
    let t = move |a: usize, b: usize| match (a.min(b), a.max(b)) {
        (0, 1) => 0.1,
        (0, 2) => sigma[0],
        (1, 2) => sigma[1],
        (1, 3) => young1,
        _ => 0.0,
    };
    let mut s = ForceScratch {
        split_momentum_correction: corrected,
        ..ForceScratch::default()
    };
    s.evaluate(
        &c.input(),
        3,
        t,
        Walls::Normal(WallNormal { solid: 3, l0_m: L0 }),
    );
    let force = s.force[..c.n_fluid].to_vec();
    (force.iter().sum(), force)
}

#[test]
fn with_the_wall_normal_a_janus_drop_is_not_pushed_along_the_wall() {
    // Whatever a drop's shape, a uniform solid pulls each wetted region's closed boundary with
    // its tension, and those pulls sum to zero: no net force along a free-slip wall (Eq. 23's
    // three line forces balance for the same reason). The wall normal hands each line its
    // Young push through the interface's bend, each share of the three-liquid split at one
    // angle along its whole boundary (`σ_k cos φ_k = C − σ_kS`), so that each share's pushes
    // cancel around its own boundary. Measured on plate_eq23's scene (θ1 = 80°, Eq. 23's
    // θ12 = 134°): per four-phase point 0.0030 and 0.0005 σ r_e at ρ = 8 and 16 l0, −0.0030
    // at θ1 = 100°. Turned at each particle's pair angle instead (a particle of the share's
    // own liquid at the mean of its pairs' angles weighted by their colours), the pushes left
    // +0.059 and +0.062 σ r_e per point, the same at both radii, and set plate_eq23's binary
    // drops moving at 4–57 mm/s (docs/findings.md). Measured without the split's momentum
    // correction, which would remove any net along the wall; the chord's own push σ12 cos θ12 is
    // 0.21 σ r_e per l0 of line here. Bound: 0.01 σ r_e per point, a sixth of that error
    // and three times the coarse hemisphere's residue
    let per_point =
        |rho: f64, theta1: f64| janus_hemisphere_net_force_n(rho, theta1).x / (2.0 * 0.4 * R_E);
    let pushes = [
        per_point(8.0, 80.0),
        per_point(16.0, 80.0),
        per_point(8.0, 100.0),
    ];
    eprintln!("net force along x per four-phase point / (σ r_e): {pushes:?} (ρ = 8, 16 l0 at θ1 = 80°; 8 l0 at 100°)");
    for p in pushes {
        assert!(p.abs() < 0.01, "{pushes:?}");
    }
}

#[test]
fn with_the_wall_normal_the_split_s_correction_removes_its_push_along_the_wall_only() {
    // Matte/slag's tensions (σ01 = 0.1, σ02 = 0.4, σ12 = 0.2 N/m: off Neumann's balance, the
    // shares 0.15, −0.05, 0.25 N/m) on plate_eq23's Janus hemisphere at θ1 = 75°, on the
    // lattice and with each fluid site moved by up to 0.2 l0 (the discrete wall normal then
    // leans, as in a run: a first version, which took any lean above 1e-9 as a wall facing
    // that way, corrected nothing in a run). Without the correction the split leaves a net
    // force along the wall (on the lattice +6.9e-7 N at ρ = 8 l0, −2.17e-5 N at 16 l0, and
    // +1.1e-5 N moved at 8 l0); with it, the split
    // conserves momentum along the plate to round-off (~1e4 terms of ~1e-6 N: ~1e-18 N
    // measured; bound 1e-12 of the force across the wall), the force across the wall, which
    // the wall takes, is unchanged (to the eigenvectors' round-off), and no particle's force
    // changes by more than 1 % of the largest (a small uniform traction, not a reshaping of
    // the force)
    for (rho, jitter) in [(8.0, 0.0), (16.0, 0.0), (8.0, 0.2)] {
        let (raw, before) = janus_hemisphere(rho, [0.4, 0.2], 75.0, false, jitter);
        let (net, after) = janus_hemisphere(rho, [0.4, 0.2], 75.0, true, jitter);
        let change = before
            .iter()
            .zip(&after)
            .fold(0.0f64, |m, (b, a)| m.max((a - b).norm()));
        let largest = before.iter().fold(0.0f64, |m, b| m.max(b.norm()));
        eprintln!(
            "ρ = {rho} l0, jitter {jitter} l0: net force {raw:?} N without the correction, \
             {net:?} N with it; largest change {:.2e} of the largest force",
            change / largest
        );
        if jitter == 0.0 {
            assert!(net.xy().norm() < 1e-12 * net.z.abs(), "{net:?}");
            assert!(
                (net.z - raw.z).abs() < 1e-12 * raw.z.abs(),
                "{net:?} {raw:?}"
            );
        } else {
            // the plane kept leans with the moved particles' wall normals (by ~1e-6 rad here),
            // letting that much of the force across the wall through: the push along the
            // plate falls 5,000-fold (1.1e-5 → 2.2e-9 N); bound 1,000-fold
            assert!(net.xy().norm() < 1e-3 * raw.xy().norm(), "{net:?} {raw:?}");
        }
        assert!(change < 0.01 * largest, "{change:e} of {largest:e} N");
    }
}

#[test]
fn the_split_s_wall_level_gives_every_pair_young_s_push_within_the_shares_reach() {
    // Eq. 23's binary drops in a gas (liquids 0, 1, gas 2, solid 3) over the angles plate_eq23
    // runs, and a share at zero (σ01 + σ02 = σ12): every share's cosine within [−1, 1]
    // unclipped, and each pair's shares adding to Young's `σ_lS − σ_kS` to round-off
    let cases: [(f64, f64, f64, f64, f64); 7] = [
        (0.1, 0.4, 0.4, 90.0, 80.0),
        (0.1, 0.4, 0.2, 90.0, 75.0),
        (0.1, 0.4, 0.2, 90.0, 105.0),
        (0.1, 0.4, 0.2, 120.0, 130.0),
        (0.1, 0.4, 0.2, 60.0, 45.0),
        (0.1, 0.4, 0.4, 60.0, 52.0),
        (0.2, 0.1, 0.3, 90.0, 120.0),
    ];
    for (s01, s0, s1, th0, th1) in cases {
        let young = [
            -s0 * f64::cos(th0.to_radians()),
            -s1 * f64::cos(th1.to_radians()),
            0.0,
        ];
        let t = move |a: usize, b: usize| match (a.min(b), a.max(b)) {
            (0, 1) => s01,
            (0, 2) => s0,
            (1, 2) => s1,
            (k, 3) => young[k],
            _ => 0.0,
        };
        let level = split_wall_level(3, &t, 3).expect("three liquids");
        let share = |k: usize| {
            let (l, m) = ((k + 1) % 3, (k + 2) % 3);
            0.5 * (t(k, l) + t(k, m) - t(l, m))
        };
        // σ_k cos φ_k, unclipped
        let push = |k: usize| level - t(k, 3);
        for k in 0..3 {
            assert!(
                push(k).abs() <= share(k).abs() + 1e-15,
                "{k}: {} of {}",
                push(k),
                share(k)
            );
            // the model's own cosines: the shares' pushes add to Young's for every pair
            for l in 0..3 {
                let turned = |k: usize| {
                    let cos = turn_cosine(Sides::Phase(k as u8), &t, 3, share(k), Some(level));
                    share(k) * cos.unwrap_or(f64::NAN)
                };
                if share(k) == 0.0 || share(l) == 0.0 {
                    continue; // a zero share is no term
                }
                let young_push = t(l, 3) - t(k, 3);
                assert!(
                    (turned(k) - turned(l) - young_push).abs() < 1e-15,
                    "{k} {l}"
                );
            }
        }
    }
    // not three liquids: no level
    assert_eq!(split_wall_level(2, &tensions(60.0), 2), None);
}
