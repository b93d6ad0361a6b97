//! The continuum models between liquids in whole runs (docs/model.md §4a, §4b), the surface
//! stress and the surface force: chosen by name, refused where they have no meaning, the same
//! bits for any thread count, pulling a drop round without pairing; the stress conserving
//! linear momentum exactly; their force's booked work closing the energy budget.

use super::common::{block_scene, error_of, scene, sim, ALUMINA_PLATE};
use solver::{Observables, Simulation};

/// The continuum models' names.
const MODELS: [&str; 2] = ["surface_stress", "surface_force"];

/// A drop of liquid `a` (an ellipsoid, semi-axes `R (1 − e/2), R (1 − e/2), R (1 + e)` [m]
/// about R = n l0/3) in a periodic box of liquid `b` of side `n l0`, both of density 1000 kg/m³,
/// σ_ab = 0.05 N/m, at h = 1.3 l0 and r_e = 4.2 l0, under the tension model `model`, with
/// `effects` appended.
fn drop_in_host(model: &str, n: usize, e: f64, effects: &str) -> String {
    let l0 = 1e-4;
    let half = n as f64 * l0 / 2.0;
    let r = n as f64 / 3.0 * l0;
    let axes = format!(
        "[{:e}, {:e}, {:e}]",
        r * (1.0 - e / 2.0),
        r * (1.0 - e / 2.0),
        r * (1.0 + e)
    );
    format!(
        r#"
[discretisation]
l0 = {l0:e}
h_over_l0 = 1.3
re_over_l0 = 4.2
sound_speed = 5.0
[time]
end = 1.0e-3
output_interval = 1.0e-4
[effects]
interfacial_tension = "{model}"
{effects}
[[liquid]]
name = "a"
density = 1000.0
viscosity = 1.0e-3
[[liquid]]
name = "b"
density = 1000.0
viscosity = 1.0e-3
[[interface]]
liquids = ["a", "b"]
tension = 0.05
[[body]]
name = "drop"
liquid = "a"
shape = {{ kind = "ellipsoid", center = [0.0, 0.0, 0.0], semi_axes = {axes} }}
[[body]]
name = "host"
liquid = "b"
shape = {{ kind = "box_around_ellipsoid", min = [{m:e}, {m:e}, {m:e}], max = [{p:e}, {p:e}, {p:e}], center = [0.0, 0.0, 0.0], semi_axes = {axes} }}
[periodic]
x = [{m:e}, {p:e}]
y = [{m:e}, {p:e}]
z = [{m:e}, {p:e}]
"#,
        m = -half,
        p = half
    )
}

#[test]
fn the_models_are_chosen_by_name_and_true_still_means_the_potential() {
    let css = scene(&drop_in_host("surface_stress", 12, 0.2, ""));
    assert!(css.effects.interfacial_tension.is_surface_stress());
    let csf = scene(&drop_in_host("surface_force", 12, 0.2, ""));
    assert!(csf.effects.interfacial_tension.is_continuum());
    assert!(!csf.effects.interfacial_tension.is_surface_stress());
    let potential = |v: &str| block_scene(6, 1e-4, &format!("interfacial_tension = {v}"), "");
    assert_eq!(
        scene(&potential("true")).effects,
        scene(&potential("\"potential\"")).effects
    );
    // run records and checkpoints store the scene: the name survives a round trip
    for (model, s) in MODELS.iter().zip([&css, &csf]) {
        let text = toml::to_string(s).unwrap();
        assert!(
            text.contains(&format!("interfacial_tension = \"{model}\"")),
            "{text}"
        );
        assert_eq!(&scene(&text), s);
    }
    let old = toml::to_string(&scene(&potential("true"))).unwrap();
    assert!(old.contains("interfacial_tension = true"), "{old}");
    let msg = error_of(&drop_in_host("surface", 12, 0.2, ""));
    assert!(
        MODELS.iter().all(|m| msg.contains(m)) && msg.contains("potential"),
        "{msg}"
    );
}

#[test]
fn one_liquid_or_a_wall_is_refused_with_the_reason() {
    for model in MODELS {
        // one liquid: a free surface against empty space would carry no tension
        let one = block_scene(6, 1e-4, &format!("interfacial_tension = \"{model}\""), "");
        let msg = error_of(&one);
        assert!(
            msg.contains("effects.interfacial_tension")
                && msg.contains("second liquid")
                && msg.contains(model),
            "{msg}"
        );
        // walls: no contact angles in the surface stress (the surface force's walls:
        // surface_force_walls.rs)
        let open_box = drop_in_host(model, 12, 0.2, "");
        let open_box = &open_box[..open_box.find("[periodic]").unwrap()];
        let two_with_wall = format!(
            "{open_box}{}",
            ALUMINA_PLATE
                .replace("{ matte = 60.0 }", "{ a = 60.0, b = 60.0 }")
                .replace("-6.0e-4", "-7.0e-4")
        );
        if model == "surface_force" {
            // walls are taken, but these liquids have no σ for Young's relation
            let msg = error_of(&two_with_wall);
            assert!(msg.contains("no surface tension"), "{msg}");
            continue;
        }
        let msg = error_of(&two_with_wall);
        assert!(
            msg.contains("wall[plate]") && msg.contains("contact angles") && msg.contains(model),
            "{msg}"
        );
    }
}

/// Runs `text` for `steps` steps on `threads` threads.
fn run(text: &str, threads: usize, steps: usize) -> Simulation {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap()
        .install(|| {
            let mut s = Simulation::new(&scene(text)).unwrap();
            for _ in 0..steps {
                s.step(f64::INFINITY).unwrap();
            }
            s
        })
}

#[test]
fn under_the_stress_a_stretched_drop_is_pulled_round_conserving_momentum_and_bits() {
    stretched_drop("surface_stress");
}

#[test]
fn under_the_force_a_stretched_drop_is_pulled_round_keeping_its_bits() {
    stretched_drop("surface_force");
}

fn stretched_drop(model: &str) {
    // R = 6 l0, stretched 20 % along z, in an 18³ periodic box (5832 particles): at R = 4 l0,
    // within the colour kernel's support, the surface force's curvature is smoothed over the
    // whole drop and it barely moved in 2 ms (aspect 1.333 to 1.311; the stress's to 0.985)
    let text = drop_in_host(
        model,
        18,
        0.2,
        "artificial_viscosity = { alpha1 = 0.05, alpha2 = 0.0 }",
    );
    let one = run(&text, 1, 300);
    let two = run(&text, 2, 300);
    let flat = |s: &Simulation| -> Vec<u64> {
        let p = &s.particles;
        p.pos
            .iter()
            .chain(&p.vel)
            .chain(&p.acc)
            .flat_map(|v| v.iter().map(|x| x.to_bits()))
            .collect()
    };
    assert_eq!(one.particles.id, two.particles.id);
    assert!(
        flat(&one) == flat(&two),
        "states differ between 1 and 2 threads"
    );
    assert!(one.search.builds > 1, "the run must cover list rebuilds");

    let o = one.observe();
    let p = &one.particles;
    if model == "surface_stress" {
        // linear momentum: every pair force has its exact opposite; what is left is the
        // rounding of sums of pair forces in two orders, against the momentum scale Σ m |v|
        // (the surface force is not a pair form: docs/model.md §4b measures its drift)
        let scale: f64 = (0..p.n_fluid)
            .map(|i| one.model.mass[p.phase[i] as usize] * p.vel[i].norm())
            .sum();
        let momentum = solver::state::Vec3::from(o.momentum_kg_m_s).norm();
        assert!(
            scale > 0.0 && momentum < 1e-12 * scale,
            "{momentum} of {scale}"
        );
    }
    // the tension pulls the stretched drop towards a sphere: its z extent shrinks, x grows
    let drop = &o.phases[0];
    let start = scene(&text);
    let solver::scene::BodyShape::Ellipsoid { semi_axes, .. } = start.bodies[0].shape else {
        unreachable!()
    };
    let aspect0 = semi_axes[2] / semi_axes[0];
    let aspect = drop.extent_m[2] / drop.extent_m[0];
    assert!(
        aspect < aspect0 - 0.05,
        "{model}: aspect {aspect} from {aspect0}"
    );
    // stable at the particle level: no pair closer than a third of the spacing
    let l0 = one.model.l0_m;
    let mut closest = f64::INFINITY;
    for i in 0..p.n_fluid {
        for j in one.search.lists.near(i) {
            let d = one.search.lists.delta(p.pos[i], p.pos[j]).norm();
            closest = closest.min(d);
        }
    }
    assert!(
        closest > l0 / 3.0,
        "{model}: closest pair {:.3} l0",
        closest / l0
    );
}

#[test]
fn the_force_work_counter_closes_the_budget_that_the_estimate_leaves_open() {
    // the stretched drop of `stretched_drop` with the lattice particle mass, the one setting
    // in which the pressure force is the gradient of the compression energy
    // (energy_budget.rs): the rest of the budget then holds, and the continuum force's
    // booked work closes it where its interfacial estimate does not
    for model in MODELS {
        let text = drop_in_host(model, 18, 0.2, "laminar_viscosity = true").replace(
            "sound_speed = 5.0",
            "sound_speed = 5.0\nparticle_mass = \"lattice\"",
        );
        let mut s = sim(&text);
        let o0 = s.observe();
        assert_eq!(o0.interfacial_force_work_j, 0.0);
        // the budget without the estimate, with the force's work in its place
        let rest = |o: &Observables| {
            o.energy_balance_j - o.interfacial_energy_j - o.interfacial_force_work_j
        };
        // what the force put in that the estimate does not hold
        let created = |o: &Observables| {
            o.interfacial_force_work_j + o.interfacial_energy_j - o0.interfacial_energy_j
        };
        let (mut drift_j, mut max_kinetic_j, mut max_created_j) = (0.0f64, 0.0f64, 0.0f64);
        let mut last = o0.clone();
        for _ in 0..300 {
            s.step(f64::INFINITY).unwrap();
            last = s.observe();
            drift_j = drift_j.max((rest(&last) - rest(&o0)).abs());
            max_kinetic_j = max_kinetic_j.max(last.kinetic_energy_j);
            max_created_j = max_created_j.max(created(&last).abs());
        }
        // the rest holds to the budget's own bound, 1 % of the largest kinetic energy
        // (energy_budget.rs: kick–drift–kick's error; measured 0.08 % and 0.11 %)
        assert!(
            drift_j <= 0.01 * max_kinetic_j,
            "{model}: drift {drift_j:e} J, largest kinetic energy {max_kinetic_j:e} J"
        );
        // the force did the work that moved the drop (measured 1.4 and 1.6 times the largest
        // kinetic energy; the rest went into compression and heat)
        assert!(
            last.interfacial_force_work_j > 0.5 * max_kinetic_j,
            "{model}: work {:e} J",
            last.interfacial_force_work_j
        );
        // and the counter is what closes the budget: without it the drift is `W + ΔE`,
        // measured 18 % and 39 % of the largest kinetic energy, 150–350 times the rest's (a
        // force that derives from its estimate would fail here: the counter would then be
        // redundant)
        assert!(
            max_created_j > 0.05 * max_kinetic_j,
            "{model}: W + ΔE {max_created_j:e} J"
        );
    }
}
