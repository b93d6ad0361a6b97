//! Periodic boundaries: a box of liquid that fills its periodic range is an infinite lattice —
//! every particle has exactly the reference density and no net force — and a flow through the
//! boundaries keeps the momentum it started with.

use super::common::{advance, block_scene, scene, sim};
use solver::{Scene, Simulation};

/// Spacing [m] of the test blocks.
const L0: f64 = 1e-4;

/// The periodic ranges `[−n l0/2, n l0/2]` of every axis, written as the block's shape is.
fn full_range(n: usize) -> String {
    let half = n as f64 * L0 / 2.0;
    format!("[{:e}, {:e}]", -half, half)
}

/// The common `n`³ matte block (tension and both viscosities), `body` appended to its body
/// table, periodic along x over `x_range` and along y and z over the block.
fn periodic_block(n: usize, body: &str, x_range: &str) -> String {
    let full = full_range(n);
    block_scene(
        n,
        L0,
        "interfacial_tension = true\nlaminar_viscosity = true\nartificial_viscosity = {}",
        &format!("{body}\n[periodic]\nx = {x_range}\ny = {full}\nz = {full}\n"),
    )
}

#[test]
fn a_periodic_lattice_has_the_reference_density_and_no_force() {
    let s = sim(&periodic_block(12, "", &full_range(12)));
    let p = &s.particles;
    assert_eq!(p.n_fluid, 12 * 12 * 12);
    // every particle sees the infinite lattice: ρ = ρ0 to rounding (1e-12 relative: sums of
    // ~250 kernel values of order 1)
    for &rho in &p.rho[..p.n_fluid] {
        assert!((rho / 4500.0 - 1.0).abs() < 1e-12, "ρ = {rho}");
    }
    // the pair forces cancel by symmetry. Scale: the cohesive pressure p_b ≈ 1.75 σ/l0 acting
    // on a particle's face, p_b l0²/m ≈ σ/(ρ l0²) = 8.9e3 m/s²; rounding of ~600 terms of that
    // size leaves ~1e-13 of it, 1e-11 allows for cancellation
    let scale = 0.4 / (4500.0 * 1e-8);
    let worst = p.acc.iter().map(|a| a.norm()).fold(0.0, f64::max);
    assert!(worst < 1e-11 * scale, "largest |a| = {worst} m/s²");
}

#[test]
fn a_flow_through_the_boundaries_conserves_momentum_and_density() {
    // a shear wave on top of a uniform drift that carries particles across every boundary
    let wave = "velocity = [1.0, 0.6, 0.3]\nvelocity_wave = { amplitude = [0.0, 0.05, 0.0], along = \"x\", wavelength = 1.2e-3 }";
    let mut s = sim(&periodic_block(12, wave, &full_range(12)));
    let momentum = |s: &Simulation| {
        let p = &s.particles;
        p.vel[..p.n_fluid]
            .iter()
            .fold(nalgebra::Vector3::zeros(), |a, v| a + v)
            * 1e-9
    };
    let m0 = momentum(&s);
    advance(&mut s, 200);
    let p = &s.particles;
    // 200 steps of ~2 µs at 1 m/s: 0.4 mm, four spacings — particles have crossed
    assert!(s.time_s * 1.0 > 3e-4, "t = {} s", s.time_s);
    assert!(s.search.builds > 1);
    for x in &p.pos[..p.n_fluid] {
        assert!(
            x.iter().all(|&c| (-7e-4..7e-4).contains(&c)),
            "{x:?} left the box"
        );
    }
    // pair forces are antisymmetric to the last bit, so momentum changes only by rounding of
    // the sums (1e-12 of the initial momentum, ~9e-6 kg m/s)
    assert!(
        (momentum(&s) - m0).norm() < 1e-12 * m0.norm(),
        "{m0} → {}",
        momentum(&s)
    );
    // the density stays that of a uniform liquid (1 %: the wave's compression is nil; a lost
    // image would show as a particle with a tenth of its neighbours missing)
    for &rho in &p.rho[..p.n_fluid] {
        assert!((rho / 4500.0 - 1.0).abs() < 0.01, "ρ = {rho}");
    }
}

#[test]
fn periodic_ranges_are_checked() {
    let err = |text: String| match Scene::from_toml_str(&text) {
        Err(e) => e.to_string(),
        Ok(sc) => match Simulation::new(&sc) {
            Err(e) => e.to_string(),
            Ok(_) => panic!("should be refused:\n{text}"),
        },
    };
    let _ = scene(&periodic_block(12, "", &full_range(12)));
    // a period of 8 l0 < 2 (r_e + skin) = 8.8 l0
    assert!(err(periodic_block(8, "", &full_range(8))).contains("twice the neighbour cut-off"));
    // an end off the lattice planes
    assert!(err(periodic_block(12, "", "[-6.05e-4, 6e-4]")).contains("multiples of l0"));
    // a body reaching past the range would overlap its own image
    assert!(err(periodic_block(12, "", "[-5e-4, 5e-4]")).contains("within the periodic range"));
}

#[test]
fn a_background_pressure_is_uniform_in_a_periodic_box_and_refused_elsewhere() {
    // the lattice at ρ0 carries exactly the background pressure, and still no net force
    let text = periodic_block(10, "", &full_range(10)).replace(
        "[periodic]",
        "[density]\nbackground_pressure = 3.0e4\n[periodic]",
    );
    let s = sim(&text);
    let p = &s.particles;
    for &pr in &p.pressure[..p.n_fluid] {
        // Tait's pressure at ρ0 ± 1e-12 is below 1e-6 Pa; the sum keeps 3e4 to rounding
        assert!((pr - 3.0e4).abs() < 1e-6, "p = {pr} Pa");
    }
    // the pressure's pair forces cancel by symmetry like the potential's (scale as in
    // a_periodic_lattice_has_the_reference_density_and_no_force, plus p V² ∇W ~ p l0²/m =
    // 3e4 · 1e-8 / 4.5e-9 = 6.7e4 m/s²)
    let scale = 0.4 / (4500.0 * 1e-8) + 3.0e4 * 1e-8 / (4500.0 * 1e-12);
    let worst = p.acc.iter().map(|a| a.norm()).fold(0.0, f64::max);
    assert!(worst < 1e-11 * scale, "largest |a| = {worst} m/s²");
    // a box open along z would feel it at its faces: refused
    let open = text.replace(&format!("z = {}\n", full_range(10)), "");
    assert!(open.len() < text.len());
    let err = Scene::from_toml_str(&open).expect_err("refused");
    assert!(
        err.to_string().contains("density.background_pressure"),
        "{err}"
    );
}
