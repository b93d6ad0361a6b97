//! Shared scene builders.

use solver::{Scene, Simulation};

/// An alumina disk 6e-4 m below the block of [`block_scene`] (θ = 60° for matte), to append to it.
pub const ALUMINA_PLATE: &str = r#"
[[solid]]
name = "alumina"
contact_angles = { matte = 60.0 }
[[wall]]
name = "plate"
solid = "alumina"
shape = { kind = "disk", center = [0.0, 0.0, -6.0e-4], radius = 1.2e-3 }
"#;

/// A matte-like liquid block of `n`³ particles at spacing `l0` [m] centred at the origin, with
/// the given extra TOML appended (effects etc.).
pub fn block_scene(n: usize, l0: f64, effects: &str, extra: &str) -> String {
    let half = n as f64 * l0 / 2.0;
    let shape = format!(
        "{{ kind = \"box\", min = [{m:e}, {m:e}, {m:e}], max = [{p:e}, {p:e}, {p:e}] }}",
        m = -half,
        p = half
    );
    matte_scene(l0, effects, "block", &shape, extra)
}

/// One matte body (density 4500 kg/m³, viscosity 3.13e-3 Pa·s, σ 0.4 N/m) named `name` of
/// the given TOML `shape`, at spacing `l0` [m] and c = 12 m/s, with `effects` and `extra`
/// appended.
pub fn matte_scene(l0: f64, effects: &str, name: &str, shape: &str, extra: &str) -> String {
    format!(
        r#"
[discretisation]
l0 = {l0:e}
sound_speed = 12.0
[time]
end = 1.0e-3
output_interval = 1.0e-4
[effects]
{effects}
[[liquid]]
name = "matte"
density = 4500.0
viscosity = 3.13e-3
surface_tension = 0.4
[[body]]
name = "{name}"
liquid = "matte"
shape = {shape}
{extra}
"#
    )
}

/// Parses a scene that must be valid.
pub fn scene(text: &str) -> Scene {
    Scene::from_toml_str(text).unwrap_or_else(|e| panic!("scene should be valid: {e}\n{text}"))
}

/// Builds a simulation of a valid scene.
pub fn sim(text: &str) -> Simulation {
    Simulation::new(&scene(text)).unwrap_or_else(|e| panic!("simulation should build: {e}"))
}

/// Advances `steps` steps.
pub fn advance(sim: &mut Simulation, steps: usize) {
    for _ in 0..steps {
        sim.step(f64::INFINITY).expect("step");
    }
}

/// The error message of building `text`, which must fail (at parsing, validation or setup).
pub fn error_of(text: &str) -> String {
    match Scene::from_toml_str(text) {
        Err(e) => e.to_string(),
        Ok(scene) => match Simulation::new(&scene) {
            Err(e) => e.to_string(),
            Ok(_) => panic!("scene should have been refused:\n{text}"),
        },
    }
}
