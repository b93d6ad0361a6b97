//! The energy budget closes: kinetic + interfacial + compression + gravity energy + everything
//! the dissipative terms and the walls' own pressure took out (booked at every kick) is
//! constant to the time integration's error, for the configuration whose forces are exact
//! gradients of those energies — summation density with the lattice particle mass
//! (`m = ρ0/Σ_lattice W`, physics notes in `observables/energy.rs`).
//!
//! The scale: these drops start at (or near) rest, and their initial total energy is mostly
//! the interfacial energy of a surface that largely stays (a cube releases about a fifth of it
//! on becoming round). The energy that actually moves through the budget is the kinetic
//! energy, so the drift is measured against its largest value over the run — 7 to 12 times
//! stricter than against the initial total energy here.
//!
//! Three runs: a cube turning round (no walls), a drop hitting a no-slip plate (the walls' own
//! pressure and the viscous coupling to the wall booked), and a drop thrown into the
//! liquid–wall repulsion (its potential energy in the budget).
//!
//! The configurations that do not close (physical mass, continuity density) are measured in
//! the ignored `closure_table` test below, with the numbers in its doc comment.

use super::common::sim;
use solver::Observables;

/// A water cube of 10³ particles (l0 = 0.1 mm) at rest in zero gravity, with tension,
/// laminar and artificial viscosity; `density` is the `[density]` table.
pub fn cube(mass: &str, density: &str) -> String {
    format!(
        r#"
[discretisation]
l0 = 1.0e-4
sound_speed = 12.0
particle_mass = "{mass}"
[time]
end = 1.0
output_interval = 1.0e-4
[effects]
interfacial_tension = true
laminar_viscosity = true
artificial_viscosity = {{ alpha1 = 0.05, alpha2 = 0.05 }}
[density]
{density}
[[liquid]]
name = "water"
density = 997.0
viscosity = 0.89e-3
surface_tension = 0.073
[[body]]
name = "cube"
liquid = "water"
shape = {{ kind = "box", min = [-5.0e-4, -5.0e-4, -5.0e-4], max = [5.0e-4, 5.0e-4, 5.0e-4] }}
"#
    )
}

/// A 1 mm water drop thrown at 0.3 m/s onto a Teflon plate (θ = 110°) under gravity.
pub fn drop_on_plate(mass: &str, density: &str, boundary: &str) -> String {
    cube(mass, density)
        .replace("[effects]", "[effects]\ngravity = [0.0, 0.0, -9.81]")
        .replace(
            "[[body]]",
            r#"[[solid]]
name = "teflon"
contact_angles = { water = 110.0 }
[[wall]]
name = "plate"
solid = "teflon"
shape = { kind = "disk", center = [0.0, 0.0, 0.0], radius = 1.5e-3 }
boundary = "BOUNDARY"
[[body]]"#,
        )
        .replace("BOUNDARY", boundary)
        .replace(
            r#"shape = { kind = "box", min = [-5.0e-4, -5.0e-4, -5.0e-4], max = [5.0e-4, 5.0e-4, 5.0e-4] }"#,
            "shape = { kind = \"sphere\", center = [0.0, 0.0, 5.5e-4], radius = 5.0e-4 }\nvelocity = [0.0, 0.0, -0.3]",
        )
}

/// `[density]` tables.
pub const SUMMATION_CLIP: &str = "scheme = \"summation\"\nnegative_pressure = \"clip\"";
pub const SUMMATION_KEEP: &str = "scheme = \"summation\"\nnegative_pressure = \"keep\"";

/// The budget of a run.
pub struct Closure {
    /// The observables at the start.
    pub first: Observables,
    /// The observables at the end.
    pub last: Observables,
    /// Largest kinetic energy [J].
    pub max_kinetic_j: f64,
    /// Largest energy of the liquid–wall repulsion [J].
    pub max_repulsion_j: f64,
    /// Largest `|B(t) − B(0)|` of the energy balance [J].
    pub drift_j: f64,
    /// The same with the compression energy scaled by `l0³ Σ_lattice W` (the factor by which
    /// the pressure force exceeds the gradient of the compression energy with the physical
    /// mass) [J].
    pub scaled_drift_j: f64,
    /// Steps taken.
    pub steps: usize,
}

/// Runs a scene to `t_end_s` [s], observing the budget after every step.
pub fn closure(text: &str, t_end_s: f64) -> Closure {
    let mut s = sim(text);
    let first = s.observe();
    let scale = s.model.lattice_kernel_sum * s.model.l0_m.powi(3) - 1.0;
    let scaled = |o: &Observables| o.energy_balance_j + scale * o.compression_energy_j;
    let (mut drift_j, mut scaled_drift_j) = (0.0f64, 0.0f64);
    let (mut max_kinetic_j, mut max_repulsion_j) = (0.0f64, 0.0f64);
    let mut last = first.clone();
    let mut steps = 0;
    while s.time_s < t_end_s {
        s.step(f64::INFINITY).expect("step");
        steps += 1;
        last = s.observe();
        drift_j = drift_j.max((last.energy_balance_j - first.energy_balance_j).abs());
        scaled_drift_j = scaled_drift_j.max((scaled(&last) - scaled(&first)).abs());
        max_kinetic_j = max_kinetic_j.max(last.kinetic_energy_j);
        max_repulsion_j = max_repulsion_j.max(last.wall_repulsion_energy_j);
    }
    Closure {
        first,
        last,
        max_kinetic_j,
        max_repulsion_j,
        drift_j,
        scaled_drift_j,
        steps,
    }
}

/// The budget drifted by at most 1 % of the largest kinetic energy (module doc).
fn assert_closes(c: &Closure) {
    assert!(
        c.drift_j <= 0.01 * c.max_kinetic_j,
        "drift {:e} J, largest kinetic energy {:e} J",
        c.drift_j,
        c.max_kinetic_j
    );
}

#[test]
fn a_cube_turning_round_closes_its_energy_budget() {
    let c = closure(&cube("lattice", SUMMATION_CLIP), 2.0e-3);
    let (o0, o) = (&c.first, &c.last);
    // something happened: the cube released interfacial energy into motion and heat
    assert!(
        c.max_kinetic_j > 0.05 * o0.energy_balance_j,
        "{}",
        c.max_kinetic_j
    );
    assert!(o.interfacial_energy_j < 0.9 * o0.interfacial_energy_j);
    assert!(o.dissipated_laminar_j > 0.0 && o.dissipated_artificial_j > 0.0);
    // no walls: nothing booked on their channels
    assert_eq!(o.dissipated_laminar_walls_j, 0.0);
    assert_eq!(o.dissipated_wall_pressure_j, 0.0);
    // measured 0.19 %, the kick–drift–kick error of the conservative forces (it falls with
    // dt², see `closure_table`)
    assert_closes(&c);
}

#[test]
fn a_drop_hitting_a_no_slip_plate_closes_its_energy_budget() {
    let c = closure(&drop_on_plate("lattice", SUMMATION_CLIP, "no_slip"), 2.0e-3);
    let o = &c.last;
    // the plate took part: the walls' pressure and viscous coupling did work
    assert!(o.dissipated_laminar_walls_j > 0.0);
    assert!(o.dissipated_wall_pressure_j != 0.0);
    // measured 0.11 % (without booking the walls' own pressure, 23 %)
    assert_closes(&c);
}

#[test]
fn a_drop_thrown_into_the_wall_repulsion_closes_its_energy_budget() {
    // paper B's wide kernel (h = 2 l0), for which the repulsion is meant, and an impact at
    // 2 m/s (c = 30 m/s) that drives the first liquid layer well inside its range r0 = 0.8 l0
    let text = drop_on_plate("lattice", SUMMATION_CLIP, "free_slip")
        .replace("[effects]", "[effects]\nwall_repulsion = true")
        .replace(
            "sound_speed = 12.0",
            "sound_speed = 30.0\nsetting = \"natsui2016\"",
        )
        .replace("velocity = [0.0, 0.0, -0.3]", "velocity = [0.0, 0.0, -2.0]");
    let c = closure(&text, 1.0e-3);
    // measured 0.06 %, while the repulsion held up to 2 % of the largest kinetic energy:
    // leaving its energy out (or getting it wrong by a tenth) would show
    assert!(
        c.max_repulsion_j > 0.01 * c.max_kinetic_j,
        "{:e}",
        c.max_repulsion_j
    );
    assert!(c.drift_j <= 0.1 * c.max_repulsion_j);
    assert_closes(&c);
}

/// The closure of every configuration, printed: run with
/// `cargo test -p solver --test solver closure_table -- --ignored --nocapture` (90 s).
///
/// Measured (2 ms, drift = max |B(t) − B(0)| over every step, relative to the largest kinetic
/// energy; "scaled": with the compression energy times `l0³ Σ_lattice W` = 1.028):
///
/// | run                                   | lattice mass | physical mass | physical, scaled |
/// |---------------------------------------|--------------|---------------|------------------|
/// | cube, summation, clipped              | 0.19 %       | 0.82 %        | 0.24 %           |
/// | cube, summation, unclipped            | 1.6 %        | 2.7 %         | 1.7 %            |
/// | cube, summation, unclipped, dt/2      | 0.40 %       | 3.6 %         | 0.41 %           |
/// | cube, continuity, clipped             | 590 %        | 740 %         |                  |
/// | cube, continuity, unclipped           | 400 %        | 430 %         |                  |
/// | cube, continuity, unclipped, dt/4     | 44 %         | 46 %          |                  |
/// | plate free-slip, summation, clipped   | 0.14 %       | 0.43 %        | 0.15 %           |
/// | plate no-slip, summation, clipped     | 0.11 %       | 0.43 %        | 0.13 %           |
/// | plate no-slip, summation, unclipped   | 1.2 %        | 2.3 %         | 1.2 %            |
/// | plate no-slip, continuity, clipped    | 370 %        | 340 %         |                  |
///
/// - Summation with the lattice mass is conservative in space: what is left is the
///   kick–drift–kick error, second order (unclipped: 1.6 % → 0.40 % at half the step; the
///   unclipped cube contracts violently, Tait's tension at its deficient surface acting as an
///   extra surface tension, and its largest kinetic energy is 20 times the clipped one's).
///   Clipping costs nothing: the energy of the clipped pressure is a function of ρ too.
/// - The physical mass: the pressure force is 1.028 times the gradient of the compression
///   energy; scaling that energy by 1.028 recovers the lattice-mass closure.
/// - Walls close once the walls' own pressure `p_w V_w²` is booked (without it: 23 %).
/// - The continuity density does not close, and the energy grows. At one state the pressure
///   power and `dE_c/dt = Σ m p/ρ² dρ/dt` differ by about 1 % of the power, always as a gain
///   (the rate `ρ_i Σ V_j v_ij·∇W` is the force's conjugate only for equal densities); the
///   rest is the time integration, and it falls far faster than dt²: 2100 % of the initial
///   energy at the default step, 83 % at dt/2, 1.8 % at dt/4 (unclipped) — consistent with
///   the density's predictor–corrector, Heun's method, whose amplification exceeds one for
///   oscillations (an energy gain of order (ω dt)⁴ per step). MLS re-initialisation every 10
///   steps takes out compression energy (booked in `dissipated_density_reinit_J`) but does
///   not stop the gain (230 %).
#[test]
#[ignore]
fn closure_table() {
    let cont = |clip: &str, reinit: &str| {
        format!("scheme = \"continuity\"\nnegative_pressure = \"{clip}\"\n{reinit}")
    };
    // the step factors (CFL, viscous, capillary, force) times `f`
    let dt = |text: String, f: f64| {
        text.replace(
            "output_interval = 1.0e-4",
            &format!(
                "output_interval = 1.0e-4\nfactors = {{ cfl = {}, viscous = {}, capillary = {}, force = {} }}",
                0.25 * f, 0.125 * f, 0.25 * f, 0.25 * f
            ),
        )
    };
    let mut rows: Vec<(String, String)> = Vec::new();
    for mass in ["lattice", "physical"] {
        rows.push((
            format!("cube {mass} summation clip"),
            cube(mass, SUMMATION_CLIP),
        ));
        rows.push((
            format!("cube {mass} summation keep"),
            cube(mass, SUMMATION_KEEP),
        ));
        rows.push((
            format!("cube {mass} summation keep dt/2"),
            dt(cube(mass, SUMMATION_KEEP), 0.5),
        ));
        rows.push((
            format!("cube {mass} continuity clip"),
            cube(mass, &cont("clip", "")),
        ));
        rows.push((
            format!("cube {mass} continuity keep"),
            cube(mass, &cont("keep", "")),
        ));
        rows.push((
            format!("cube {mass} continuity keep dt/2"),
            dt(cube(mass, &cont("keep", "")), 0.5),
        ));
        rows.push((
            format!("cube {mass} continuity keep dt/4"),
            dt(cube(mass, &cont("keep", "")), 0.25),
        ));
        rows.push((
            format!("cube {mass} continuity keep mls/10"),
            cube(mass, &cont("keep", "reinit = \"mls\"\nreinit_every = 10")),
        ));
        for b in ["free_slip", "no_slip"] {
            rows.push((
                format!("plate {mass} {b} summation clip"),
                drop_on_plate(mass, SUMMATION_CLIP, b),
            ));
            rows.push((
                format!("plate {mass} {b} summation keep"),
                drop_on_plate(mass, SUMMATION_KEEP, b),
            ));
            rows.push((
                format!("plate {mass} {b} continuity clip"),
                drop_on_plate(mass, &cont("clip", ""), b),
            ));
        }
    }
    println!(
        "{:42} {:>6} {:>10} {:>10} {:>10} {:>10} {:>10}",
        "run (2 ms)", "steps", "E0 [J]", "maxKE [J]", "drift/maxKE", "drift/E0", "scaled/maxKE"
    );
    for (name, text) in rows {
        let c = closure(&text, 2.0e-3);
        let e0 = c.first.energy_balance_j;
        println!(
            "{name:42} {:6} {e0:10.3e} {:10.3e} {:10.2e} {:10.2e} {:10.2e}",
            c.steps,
            c.max_kinetic_j,
            c.drift_j / c.max_kinetic_j,
            c.drift_j / e0,
            c.scaled_drift_j / c.max_kinetic_j
        );
    }
}
