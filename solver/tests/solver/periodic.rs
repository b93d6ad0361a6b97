//! Periodic boundaries: a box of liquid that fills its periodic range is an infinite lattice —
//! every particle has exactly the reference density and no net force — and a flow through the
//! boundaries keeps the momentum it started with.

use super::common::{advance, scene, sim};
use solver::{Scene, Simulation};

/// A `n`³ block of water at spacing `l0` = 0.1 mm filling the periodic range `[0, n l0)` of
/// every axis, with tension and both viscosities, and `velocity_wave` appended to the body.
fn periodic_block(n: usize, wave: &str) -> String {
    let l0 = 1e-4;
    let len = format!("{n}.0e-4");
    format!(
        r#"
[discretisation]
l0 = {l0:e}
sound_speed = 12.0
[time]
end = 1.0e-3
output_interval = 1.0e-4
[effects]
interfacial_tension = true
laminar_viscosity = true
artificial_viscosity = {{}}
[[liquid]]
name = "water"
density = 1000.0
viscosity = 1.0e-3
surface_tension = 0.0728
[[body]]
name = "block"
liquid = "water"
shape = {{ kind = "box", min = [0.0, 0.0, 0.0], max = [{len}, {len}, {len}] }}
{wave}
[periodic]
x = [0.0, {len}]
y = [0.0, {len}]
z = [0.0, {len}]
"#
    )
}

#[test]
fn a_periodic_lattice_has_the_reference_density_and_no_force() {
    let s = sim(&periodic_block(12, ""));
    let p = &s.particles;
    assert_eq!(p.n_fluid, 12 * 12 * 12);
    // every particle sees the infinite lattice: ρ = ρ0 to rounding (1e-12 relative: sums of
    // ~250 kernel values of order 1)
    for &rho in &p.rho[..p.n_fluid] {
        assert!((rho / 1000.0 - 1.0).abs() < 1e-12, "ρ = {rho}");
    }
    // the pair forces cancel by symmetry. Scale: the cohesive pressure p_b ≈ 1.75 σ/l0 acting
    // on a particle's face, p_b l0²/m ≈ σ/(ρ l0²) = 7.3e3 m/s²; rounding of ~600 terms of that
    // size leaves ~1e-13 of it, 1e-11 allows for cancellation
    let scale = 0.0728 / (1000.0 * 1e-8);
    let worst = p.acc.iter().map(|a| a.norm()).fold(0.0, f64::max);
    assert!(worst < 1e-11 * scale, "largest |a| = {worst} m/s²");
}

#[test]
fn a_flow_through_the_boundaries_conserves_momentum_and_density() {
    // a shear wave on top of a uniform drift that carries particles across every boundary
    let wave = "velocity = [1.0, 0.6, 0.3]\nvelocity_wave = { amplitude = [0.0, 0.05, 0.0], along = \"x\", wavelength = 1.2e-3 }";
    let mut s = sim(&periodic_block(12, wave));
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
            x.iter().all(|&c| (-1e-4..1.3e-3).contains(&c)),
            "{x:?} left the box"
        );
    }
    // pair forces are antisymmetric to the last bit, so momentum changes only by rounding of
    // the sums (1e-12 of the initial momentum ~1.6e-6 kg m/s)
    assert!(
        (momentum(&s) - m0).norm() < 1e-12 * m0.norm(),
        "{m0} → {}",
        momentum(&s)
    );
    // the density stays that of a uniform liquid (1 %: the wave's compression is nil; a lost
    // image would show as a particle with a tenth of its neighbours missing)
    for &rho in &p.rho[..p.n_fluid] {
        assert!((rho / 1000.0 - 1.0).abs() < 0.01, "ρ = {rho}");
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
    let ok = periodic_block(12, "");
    let _ = scene(&ok);
    // a period of 8 l0 < 2 (r_e + skin)
    let short = ok
        .replace(
            "max = [12.0e-4, 12.0e-4, 12.0e-4]",
            "max = [8e-4, 12.0e-4, 12.0e-4]",
        )
        .replace("x = [0.0, 12.0e-4]", "x = [0.0, 8e-4]");
    assert!(err(short).contains("twice the neighbour cut-off"));
    // an end off the lattice planes
    let off = ok.replace("x = [0.0, 12.0e-4]", "x = [0.0, 12.5e-4]");
    assert!(err(off).contains("multiples of l0"));
    // a body reaching past the range would overlap its own image
    let past = ok.replace("x = [0.0, 12.0e-4]", "x = [1e-4, 12.0e-4]");
    assert!(err(past).contains("within the periodic range"));
}
