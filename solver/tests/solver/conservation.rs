//! Total momentum is conserved to round-off without external forces: every pair force is
//! antisymmetric (pressure, both viscosities and the potential), so only the rounding of each
//! particle's sum can change it.

use super::common::sim;
use solver::state::Vec3;

fn binary_droplet() -> String {
    r#"
[discretisation]
l0 = 1.0e-4
re_over_l0 = 3.1
sound_speed = 12.0
[time]
end = 1.0e-3
output_interval = 1.0e-4
[effects]
laminar_viscosity = true
artificial_viscosity = {}
interfacial_tension = true
[[liquid]]
name = "matte"
density = 4500.0
viscosity = 3.13e-3
surface_tension = 0.4
[[liquid]]
name = "slag"
density = 3500.0
viscosity = 0.1
surface_tension = 0.2
[[interface]]
liquids = ["matte", "slag"]
tension = 0.3
[[body]]
name = "left"
liquid = "matte"
shape = { kind = "sphere", center = [-4.0e-4, 0.0, 0.0], radius = 4.0e-4 }
velocity = [0.05, 0.02, 0.0]
[[body]]
name = "right"
liquid = "slag"
shape = { kind = "sphere", center = [4.0e-4, 0.0, 0.0], radius = 4.0e-4 }
velocity = [-0.05, 0.0, 0.01]
"#
    .to_string()
}

fn momentum(s: &solver::Simulation) -> Vec3 {
    let p = &s.particles;
    (0..p.n_fluid)
        .map(|i| p.vel[i] * s.model.mass[p.phase[i] as usize])
        .sum()
}

#[test]
fn momentum_is_conserved_to_round_off_in_a_free_binary_droplet() {
    check(&binary_droplet());
}

#[test]
fn momentum_is_conserved_with_the_continuity_density_and_mls() {
    let text = binary_droplet().replace(
        "[effects]",
        "[density]\nscheme = \"continuity\"\nreinit = \"mls\"\nreinit_every = 10\n[effects]",
    );
    check(&text);
}

fn check(text: &str) {
    let mut s = sim(text);
    let p0 = momentum(&s);
    // Σ over steps of dt Σ_i |m_i a_i|: the impulse the internal forces carry. Round-off of the
    // per-particle sums can leave a net fraction of order ε·√(neighbours) ≈ 1e-15 of it; 1e-10
    // leaves five orders of margin and still catches a single unbalanced pair term (which
    // would leave a fraction of order 1e-3 and more).
    let mut impulse = 0.0;
    for _ in 0..300 {
        let dt = s.step(f64::INFINITY).unwrap();
        let p = &s.particles;
        impulse += dt
            * (0..p.n_fluid)
                .map(|i| p.acc[i].norm() * s.model.mass[p.phase[i] as usize])
                .sum::<f64>();
    }
    let dp = (momentum(&s) - p0).norm();
    assert!(impulse > 0.0);
    assert!(
        dp < 1e-10 * impulse,
        "momentum changed by {dp:e} kg m/s; internal impulse {impulse:e}"
    );
    assert!(p0.norm() > 0.0);
}
