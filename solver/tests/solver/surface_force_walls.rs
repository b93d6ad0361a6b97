//! The surface force with walls (docs/model.md §4b): a liquid cap on a plate in a gas declared
//! as a liquid spreads below its contact angle of 90° and draws back above it (under the wall
//! normal, a cap at 90° holds its foot), the same bits
//! for any thread count; the scenes the split of the tensions cannot take are refused with the
//! reason.

use super::common::{error_of, scene};
use solver::physics::surface_tension::surface_force::wall_normal::WallNormal;
use solver::physics::surface_tension::surface_force::Walls;
use solver::state::Vec3;
use solver::Simulation;

const L0: f64 = 1.0e-4;
/// The cap's radius [m]: a hemisphere of 6 spacings.
const R: f64 = 6.0 * L0;

/// A hemisphere of liquid `a` (σ 0.05 N/m, contact angle `theta_deg` on the plate) on a plate
/// whose top is z = 0, in a gas `g` (no surface tension) filling a box periodic along x and y
/// (24 spacings) up to z = 12 l0, under the surface force, with `extra` appended. The box is
/// periodic along z too, the gas at its top meeting the plate's underside: no free surface.
pub fn cap(theta_deg: f64, extra: &str) -> String {
    let half = 12.0 * L0;
    format!(
        r#"
[discretisation]
l0 = {L0:e}
h_over_l0 = 1.3
re_over_l0 = 4.2
sound_speed = 5.0
[time]
end = 1.0e-3
output_interval = 1.0e-4
[effects]
interfacial_tension = "surface_force"
artificial_viscosity = {{ alpha1 = 0.05, alpha2 = 0.0 }}
[periodic]
x = [{m:e}, {p:e}]
y = [{m:e}, {p:e}]
z = [{b:e}, {p:e}]
[[liquid]]
name = "a"
density = 1000.0
viscosity = 1.0e-3
surface_tension = 0.05
[[liquid]]
name = "g"
density = 1000.0
viscosity = 1.0e-3
[[interface]]
liquids = ["a", "g"]
tension = 0.05
[[solid]]
name = "plate"
contact_angles = {{ a = {theta_deg:?} }}
[[body]]
name = "cap"
liquid = "a"
shape = {{ kind = "hemisphere", center = [0.0, 0.0, 0.0], radius = {R:e}, pole = [0.0, 0.0, 1.0] }}
[[body]]
name = "gas"
liquid = "g"
shape = {{ kind = "surrounding", min = [{m:e}, {m:e}, 0.0], max = [{p:e}, {p:e}, {p:e}] }}
[[wall]]
name = "plate"
solid = "plate"
shape = {{ kind = "plate", min = [{m:e}, {m:e}], max = [{p:e}, {p:e}], top = 0.0 }}
{extra}
"#,
        m = -half,
        p = half,
        b = -5.0 * L0
    )
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

/// The mean outward velocity [m/s] of the cap's particles at its foot: the two layers on the
/// plate, within two spacings of the contact line.
fn foot_velocity(s: &Simulation) -> f64 {
    let p = &s.particles;
    let foot: Vec<f64> = (0..p.n_fluid)
        .filter(|&i| p.phase[i] == 0)
        .filter(|&i| p.pos[i].z < 2.0 * L0)
        .filter_map(|i| {
            let r = Vec3::new(p.pos[i].x, p.pos[i].y, 0.0);
            (r.norm() > R - 2.0 * L0).then(|| p.vel[i].dot(&r.normalize()))
        })
        .collect();
    assert!(foot.len() > 50, "{} foot particles", foot.len());
    foot.iter().sum::<f64>() / foot.len() as f64
}

#[test]
fn a_cap_spreads_below_90_degrees_and_draws_back_above() {
    // 100 steps (0.65 ms, a third of the capillary time √(ρR³/σ) = 2.1 ms): the hemisphere
    // is the equilibrium at 90° only; the foot's mean outward speed is the contact line's
    let speed = |theta| foot_velocity(&run(&cap(theta, ""), 2, 100));
    let (wet, neutral, dry) = (speed(60.0), speed(90.0), speed(120.0));
    eprintln!("foot speed [m/s]: 60° {wet:e}, 90° {neutral:e}, 120° {dry:e}");
    // the foot moves out even at 90° (measured +0.034 m/s; +0.068 m/s after 300 steps): this
    // cap of 1.4 r_e spreads at its typed angle (docs/model.md §4b); the contact angle adds
    // to that motion with the sign of cos θ
    assert!(wet > neutral && neutral > dry, "{wet} {neutral} {dry}");
    // at one shape the wall's term is linear in cos θ (the liquid's and the gas's shares
    // differ by −σ cos θ): 60° and 120° move the foot by equal and opposite amounts, up to
    // the shapes' own divergence over the 100 steps (measured: +0.048 and −0.048 m/s)
    let (up, down) = (wet - neutral, neutral - dry);
    assert!((up / down - 1.0).abs() < 0.1, "{up} {down}");
}

#[test]
fn with_walls_the_same_bits_for_any_thread_count() {
    let text = cap(60.0, "");
    let one = run(&text, 1, 150);
    let two = run(&text, 2, 150);
    let flat = |s: &Simulation| -> Vec<u64> {
        let p = &s.particles;
        p.pos
            .iter()
            .chain(&p.vel)
            .chain(&p.acc)
            .flat_map(|v| v.iter().map(|x| x.to_bits()))
            .collect()
    };
    assert!(one.search.builds > 1, "the run must cover list rebuilds");
    assert!(
        flat(&one) == flat(&two),
        "states differ between 1 and 2 threads"
    );
}

#[test]
fn the_liquid_solid_tension_carries_the_contact_line_calibration() {
    use solver::kernel::{Kernel, WendlandC2};
    use solver::model::Model;
    use solver::physics::surface_tension::surface_force::contact_line::young_share;
    let model = Model::from_scene(&scene(&cap(60.0, ""))).unwrap();
    // the channel measured with the run's colour kernel: Wendland C2 of support r_e = 4.2 l0
    let colour = WendlandC2::new(4.2 * L0 / WendlandC2::new(1.0).support_m());
    let share = young_share(colour, L0, false);
    // the same function on the same inputs, but compiled twice (here, with L0 a constant, and
    // in the model): the optimiser's folding differs between the two and between builds (CI's
    // non-incremental build once gave 1.1169275103562597 against the model's …593, 2 ulp),
    // so the factor is compared to a few ulp, far below anything the calibration measures
    let same = |a: f64, b: f64| (a / b - 1.0).abs() < 1e-14;
    assert!(same(model.contact_line_factor, 1.0 / share), "{share}");
    // the phases: a 0, g 1, the plate's solid 2; Young's −σ cos θ divided by the share, the
    // gas (no σ) none, the pair's tension as typed
    let young = -0.05 * 60f64.to_radians().cos() / share;
    assert!(same(model.surface_stress_sigma(0, 2), young));
    assert_eq!(model.surface_stress_sigma(1, 2), 0.0);
    assert_eq!(model.surface_stress_sigma(0, 1), 0.05);
    // no walls: no calibration
    let free = cap(60.0, "")
        .split("[[wall]]")
        .next()
        .unwrap()
        .replace("z = [-5e-4", "z = [0e0");
    let model = Model::from_scene(&scene(&free)).unwrap();
    assert_eq!(model.contact_line_factor, 1.0);
    // the wall normal's treatment: its own channel's share, and the walls' solid with it
    let model = Model::from_scene(&scene(&normal(&cap(60.0, "")))).unwrap();
    let share = young_share(colour, L0, true);
    assert!(same(model.contact_line_factor, 1.0 / share), "{share}");
    assert!(matches!(
        model.surface_force_walls,
        Walls::Normal(WallNormal { solid: 2, .. })
    ));
}

/// `text` with the walls as the wall normal's condition (`effects.surface_force_walls`).
fn normal(text: &str) -> String {
    text.replace(
        "[effects]\n",
        "[effects]\nsurface_force_walls = \"normal\"\n",
    )
}

#[test]
fn with_the_wall_normal_a_cap_spreads_below_90_degrees_and_draws_back_above() {
    // the shares' test above, with the wall normal's walls (docs/model.md §4b)
    let speed = |theta| foot_velocity(&run(&normal(&cap(theta, "")), 2, 100));
    let (wet, neutral, dry) = (speed(60.0), speed(90.0), speed(120.0));
    eprintln!("foot speed [m/s]: 60° {wet:e}, 90° {neutral:e}, 120° {dry:e}");
    assert!(wet > neutral && neutral > dry, "{wet} {neutral} {dry}");
    // at its typed 90° this hemisphere holds its foot: measured +0.0007 m/s (+0.030 before the
    // wall's side of the colour's jump, the shares' +0.034), against ±0.05 m/s at 60° and
    // 120° (+0.054, −0.042); bounded at a tenth of those
    assert!(neutral.abs() < 0.005, "{neutral}");
}

#[test]
fn with_the_wall_normal_the_same_bits_for_any_thread_count() {
    let text = normal(&cap(120.0, ""));
    let flat = |s: &Simulation| -> Vec<u64> {
        let p = &s.particles;
        p.pos
            .iter()
            .chain(&p.vel)
            .flat_map(|v| v.iter().map(|x| x.to_bits()))
            .collect()
    };
    assert!(flat(&run(&text, 1, 60)) == flat(&run(&text, 2, 60)));
}

#[test]
fn the_wall_normal_needs_the_surface_force() {
    let text = normal(&cap(60.0, "")).replace("\"surface_force\"", "\"surface_stress\"");
    let e = error_of(&text);
    assert!(e.contains("effects.surface_force_walls"), "{e}");
}

#[test]
fn what_the_split_cannot_take_is_refused_with_the_reason() {
    // a second solid: the walls are one phase of the split
    let second = r#"
[[solid]]
name = "steel"
contact_angles = { a = 60.0 }
[[wall]]
name = "lid"
solid = "steel"
shape = { kind = "plate", min = [-1.2e-3, -1.2e-3], max = [1.2e-3, 1.2e-3], top = 2.0e-3 }
"#;
    let e = error_of(&cap(60.0, second));
    assert!(
        e.contains("wall[lid].solid") && e.contains("one solid"),
        "{e}"
    );
    // a third liquid: four phases with the solid
    let third = r#"
[[liquid]]
name = "c"
density = 1000.0
viscosity = 1.0e-3
[[interface]]
liquids = ["a", "c"]
tension = 0.05
[[interface]]
liquids = ["g", "c"]
tension = 0.05
[[body]]
name = "drop_c"
liquid = "c"
shape = { kind = "sphere", center = [0.0, 0.0, 9.0e-4], radius = 2.0e-4 }
"#;
    let e = error_of(&cap(60.0, third));
    assert!(e.contains("3 liquids and walls"), "{e}");
    // with the wall normal's walls, which are no phase of the split, three liquids are fine
    let scene = solver::Scene::from_toml_str(&normal(&cap(60.0, third))).expect("a valid scene");
    solver::Simulation::new(&scene).expect("three liquids on the wall normal's walls");
    // the gas has no surface tension: an angle of its would take no part
    let e = error_of(&cap(60.0, "").replace("{ a = 60.0 }", "{ a = 60.0, g = 90.0 }"));
    assert!(
        e.contains("contact_angles.g") && e.contains("no surface tension"),
        "{e}"
    );
    // the liquid has one: its angle is needed
    let e = error_of(&cap(60.0, "").replace("{ a = 60.0 }", "{}"));
    assert!(
        e.contains("contact_angles.a") && e.contains("missing"),
        "{e}"
    );
}
