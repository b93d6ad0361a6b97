//! The two forms of the pressure force between liquid particles (`density.pressure_gradient`):
//! a uniform pressure loads the symmetric form's pairs, so a disordered arrangement feels a
//! force from the pressure level alone (the stiffness that held the wall normal's receding
//! contact lines, docs/findings.md), and leaves the difference form at zero; where the kernel
//! is complete the two give the same force for a pressure gradient.

use super::common::{block_scene, error_of, sim};
use super::energy_budget::{drop_on_plate, SUMMATION_CLIP};
use solver::kernel::WendlandC2;
use solver::state::Vec3;
use solver::{SimError, Simulation};

/// Spacing [m] and particles per side of the block.
const L0: f64 = 1e-4;
const N: usize = 12;

fn density(form: &str) -> String {
    format!("[density]\npressure_gradient = \"{form}\"\n")
}

/// The fluid particles' pair forces [N] of `s` as it is.
fn forces(s: &Simulation) -> Vec<Vec3> {
    let n = s.particles.n_fluid;
    let mut acc = vec![Vec3::zeros(); n];
    s.pair_forces::<WendlandC2>(&mut acc, &mut []);
    let mass = s.model.mass[0];
    acc.iter().map(|a| a * mass).collect()
}

/// A periodic block of matte, every particle moved by up to ±0.2 l0 along each axis (a fixed
/// sequence), at a uniform pressure `p_pa` [Pa]; no term but the pressure.
fn jittered(form: &str, p_pa: f64) -> Simulation {
    let half = N as f64 * L0 / 2.0;
    let range = format!("[{:e}, {:e}]", -half, half);
    let mut s = sim(&block_scene(
        N,
        L0,
        "",
        &format!(
            "{}[periodic]\nx = {range}\ny = {range}\nz = {range}\n",
            density(form)
        ),
    ));
    let mut state: u64 = 0x9e37_79b9_7f4a_7c15;
    let mut unit = || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (state >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    };
    for x in s.particles.pos.iter_mut() {
        *x += Vec3::new(unit(), unit(), unit()) * (0.4 * L0);
    }
    s.rebuild_neighbours().expect("lists");
    s.particles.pressure.iter_mut().for_each(|p| *p = p_pa);
    s
}

#[test]
fn a_uniform_pressure_pushes_disordered_particles_in_the_symmetric_form_only() {
    let p = 1000.0; // Pa: about a 1 mm matte drop's Laplace pressure
    let largest = |f: &[Vec3]| f.iter().map(|v| v.norm()).fold(0.0, f64::max);
    let symmetric = largest(&forces(&jittered("symmetric", p)));
    let difference = largest(&forces(&jittered("difference", p)));
    // the scale of one pair's force: p l0² (the pressure on a particle's face)
    let face = p * L0 * L0;
    // the symmetric form: the arrangement's disorder turns the pressure level into forces of
    // the order of a face's (measured 1.28 p l0²)
    assert!(symmetric > 0.1 * face, "symmetric {symmetric:e} N");
    // the difference form: round-off of sums of ~300 pair terms of size p l0²
    assert!(difference < 1e-12 * face, "difference {difference:e} N");
}

#[test]
fn where_the_kernel_is_complete_both_forms_give_the_same_force_for_a_gradient() {
    let g = 1.0e6; // Pa/m: a pressure gradient along z
    let mut results = Vec::new();
    for form in ["symmetric", "difference"] {
        let mut s = sim(&block_scene(N, L0, "", &density(form)));
        let z: Vec<f64> = s.particles.pos.iter().map(|x| x.z).collect();
        for (p, z) in s.particles.pressure.iter_mut().zip(&z) {
            *p = 1000.0 + g * z;
        }
        results.push((forces(&s), s));
    }
    let (sym, s) = (&results[0].0, &results[0].1);
    let dif = &results[1].0;
    let support = s.model.kernel.support_over_h() * s.model.h_m;
    let half = N as f64 * L0 / 2.0;
    let volume = L0 * L0 * L0;
    let mut inner = 0;
    let mut worst: f64 = 0.0;
    for i in 0..s.particles.n_fluid {
        let x = s.particles.pos[i];
        if x.iter().any(|c| c.abs() > half - support - L0) {
            continue;
        }
        inner += 1;
        // the same force where the kernel sum's gradient vanishes: the symmetric form's
        // uniform part (1000 Pa) cancels over the lattice's pairs to
        // 5e-8 of the gradient's force (measured; the lattice's float positions are not
        // exactly symmetric), the difference form's to 1e-16
        assert!(
            (sym[i] - dif[i]).norm() < 1e-6 * g * volume,
            "{} {}",
            sym[i],
            dif[i]
        );
        // and it is −V ∇p to the lattice's first-moment error
        let expected = Vec3::new(0.0, 0.0, -g * volume);
        worst = worst.max((dif[i] - expected).norm() / (g * volume));
    }
    assert!(inner >= 8, "{inner} interior particles");
    // the kernel gradient's first moment on the lattice, Σ_j V_j (x_j − x_i) ⊗ ∇W, is not
    // exactly the identity: measured 1.7e-3 at the scene's default kernel; 2 % leaves room
    // for another default kernel, while a wrong sign or a missing volume factor is off by
    // 100 % or more
    println!("difference form against −V ∇p: largest relative error {worst:.2e}");
    assert!(worst < 0.02, "relative error {worst:e}");
}

#[test]
fn the_difference_form_is_refused_with_the_pairwise_potential() {
    let e = error_of(&block_scene(
        4,
        L0,
        "interfacial_tension = true",
        &density("difference"),
    ));
    assert!(
        e.contains("density.pressure_gradient") && e.contains("continuum models"),
        "{e}"
    );
}

/// A 1 mm water drop thrown at 0.3 m/s onto a no-slip plate, tension off (the walls alone),
/// with the pressure force in `form`.
fn thrown_drop(form: &str) -> Simulation {
    sim(&drop_on_plate(
        "lattice",
        &format!("{SUMMATION_CLIP}\npressure_gradient = \"{form}\""),
        "no_slip",
    )
    .replace("interfacial_tension = true", "interfacial_tension = false"))
}

#[test]
fn in_the_difference_form_the_walls_let_a_thrown_drop_in_and_the_run_says_why() {
    // the symmetric form's walls hold the drop to 5 ms (its lowest particle 0.11 l0 below the
    // plate's face, measured)
    let mut s = thrown_drop("symmetric");
    while s.time_s < 5e-3 {
        s.step(f64::INFINITY).expect("the symmetric walls hold");
    }
    // the difference form's walls resist only the difference between the wall's extrapolated
    // pressure (Adami et al. 2012: a Shepard average of its liquid neighbours') and the liquid
    // particle's: at the spreading edge the first layer is compressed by the wall particles in
    // its density sum beyond its neighbours, the wall pulls it in, and a particle is 0.5 l0
    // past the face at 3.5 ms (measured; docs/findings.md; at c = 24 m/s it held, at 48 m/s
    // it entered at 3.6 ms: the sound speed is no remedy). The health check stops the run and
    // names the symmetric form as the remedy.
    let mut s = thrown_drop("difference");
    let e = loop {
        if let Err(e) = s.step(f64::INFINITY) {
            break e;
        }
        assert!(s.time_s < 5e-3, "the difference form's walls held the drop");
    };
    let SimError::Unstable {
        quantity, cause, ..
    } = &e
    else {
        panic!("{e}")
    };
    assert!(quantity.contains("inside wall 'plate'"), "{quantity}");
    assert!(
        cause.contains("difference form") && cause.contains("pressure_gradient = \"symmetric\""),
        "{cause}"
    );
}
