//! A run that goes wrong stops early with a diagnosis: the step, the particle, the quantity with
//! its value, and the most likely cause with the value that would fix it.

use super::common::block_scene;
use solver::{Scene, SimError, Simulation};

fn run_until_error(text: &str, steps: usize) -> SimError {
    let scene = Scene::from_toml_str(text).expect("valid scene");
    let mut sim = match Simulation::new(&scene) {
        Ok(s) => s,
        Err(e) => return e,
    };
    for _ in 0..steps {
        if let Err(e) = sim.step(f64::INFINITY) {
            return e;
        }
    }
    panic!("the run should have stopped");
}

#[test]
fn a_flow_faster_than_the_sound_speed_allows_is_stopped_with_the_speed_it_needs() {
    // a drop thrown at 3 m/s with c = 2.5 m/s: Mach 1.2 > health.max_mach = 1.0
    let text = block_scene(6, 1e-4, "interfacial_tension = true", "")
        .replace("sound_speed = 12.0", "sound_speed = 2.5")
        + "\n";
    let text = text.replace(
        "shape = { kind = \"box\"",
        "velocity = [3.0, 0.0, 0.0]\nshape = { kind = \"box\"",
    );
    let e = run_until_error(&text, 10).to_string();
    for part in [
        "step 0",
        "particle",
        "Mach 1.20",
        "max_mach",
        "discretisation.sound_speed",
        "30.00 m/s",
    ] {
        assert!(e.contains(part), "{e:?} lacks {part:?}");
    }
}

#[test]
fn an_equation_of_state_too_soft_for_the_tension_is_stopped_with_the_sound_speed_it_needs() {
    // matte at l0 = 0.1 mm holds a cohesive pressure ~1.75σ/l0 = 7 kPa; with c = 0.3 m/s
    // (ρc² = 405 Pa) the drop collapses: compression past health.max_compression = 100 %
    // (the Mach bound is lifted: at such a low c the collapse is also supersonic, which would
    // be reported first)
    let text = block_scene(
        8,
        1e-4,
        "interfacial_tension = true",
        "[health]\nmax_mach = 1000.0\n",
    )
    .replace("sound_speed = 12.0", "sound_speed = 0.3");
    let e = run_until_error(&text, 20_000);
    let SimError::Unstable {
        step,
        quantity,
        cause,
        ..
    } = &e
    else {
        panic!("{e}")
    };
    assert!(*step > 0);
    assert!(
        quantity.contains("compressed by") && quantity.contains("max_compression"),
        "{quantity}"
    );
    assert!(
        cause.contains("sound_speed") && cause.contains("c ≥"),
        "{cause}"
    );
}

#[test]
fn a_particle_leaving_the_domain_is_an_error_not_a_crash() {
    // a body shot at 1e7 m/s leaves the neighbour grid within a step: refused at once by the
    // Mach check (the first line of defence)
    let text = block_scene(4, 1e-4, "", "").replace(
        "shape = { kind = \"box\"",
        "velocity = [1.0e7, 0.0, 0.0]\nshape = { kind = \"box\"",
    );
    let e = run_until_error(&text, 5).to_string();
    assert!(e.contains("Mach"), "{e}");
}

/// Paper B's setting (h = 2 l0, r_e = 4 l0) with water on glass (30°): a 2 mm drop at
/// l0 = 0.2 mm, landing at 0.19 m/s.
fn wetting_drop_in_paper_b_setting(health: &str) -> String {
    format!(
        r#"
[discretisation]
l0 = 2.0e-4
setting = "natsui2016"
sound_speed = 8.0
[time]
end = 4.0e-3
output_interval = 2.0e-4
[effects]
gravity = [0.0, 0.0, -9.81]
laminar_viscosity = true
artificial_viscosity = {{ alpha1 = 0.01, alpha2 = 0.01 }}
interfacial_tension = true
{health}
[[liquid]]
name = "water"
density = 997.0
viscosity = 0.89e-3
surface_tension = 0.073
[[solid]]
name = "glass"
contact_angles = {{ water = 30.0 }}
[[body]]
name = "drop"
liquid = "water"
shape = {{ kind = "sphere", center = [0.0, 0.0, 1.2e-3], radius = 1.0e-3 }}
velocity = [0.0, 0.0, -0.19]
[[wall]]
name = "plate"
solid = "glass"
shape = {{ kind = "disk", center = [0.0, 0.0, 0.0], radius = 3.2e-3 }}
"#
    )
}

#[test]
fn a_liquid_entering_a_wall_is_stopped_with_the_wall_and_the_cause() {
    // in paper B's setting the wall's pressure barrier is weak (the kernel gradient at one
    // spacing is small at h = 2 l0) and wetting water is pulled into the plate (measured at
    // this resolution: 48 particles inside after 4 ms when nothing stops it)
    let e = run_until_error(&wetting_drop_in_paper_b_setting(""), 2000);
    let SimError::Unstable {
        quantity, cause, ..
    } = &e
    else {
        panic!("{e}")
    };
    assert!(
        quantity.contains("inside wall 'plate'") && quantity.contains("max_wall_depth_over_l0"),
        "{quantity}"
    );
    assert!(
        cause.contains("h = 2.00 l0") && cause.contains("h_over_l0"),
        "{cause}"
    );
}

#[test]
fn the_wall_repulsion_keeps_the_liquid_out_of_the_wall() {
    // the run above, with the kernel-independent repulsion, goes well past the step at which
    // the liquid entered the plate (148) without any particle inside it
    let text = wetting_drop_in_paper_b_setting("").replace(
        "interfacial_tension = true",
        "interfacial_tension = true\nwall_repulsion = true",
    );
    let mut sim = Simulation::new(&Scene::from_toml_str(&text).unwrap()).unwrap();
    for _ in 0..600 {
        sim.step(f64::INFINITY)
            .expect("no liquid enters the wall with the repulsion");
    }
}

#[test]
fn the_wall_entry_check_can_be_switched_off() {
    // the same run with the bound lifted goes on past the entry (the run above stops within
    // about 150 steps)
    let text = wetting_drop_in_paper_b_setting("[health]\nmax_wall_depth_over_l0 = inf\n");
    let mut sim = Simulation::new(&Scene::from_toml_str(&text).unwrap()).unwrap();
    for _ in 0..300 {
        sim.step(f64::INFINITY)
            .expect("no wall-entry stop when switched off");
    }
}
