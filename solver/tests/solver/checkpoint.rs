//! A run resumed from a checkpoint continues bit for bit as if it had never stopped — with
//! walls, the continuity density (its rate is state), and neighbour rebuilds in between —
//! and so does its energy budget (the energy dissipated so far and the booked power are state).

use super::common::{advance, block_scene, sim};
use solver::Simulation;

fn bits(s: &Simulation) -> Vec<u64> {
    let p = &s.particles;
    p.pos
        .iter()
        .chain(&p.vel)
        .chain(&p.acc)
        .flat_map(|v| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>())
        .chain(
            p.rho
                .iter()
                .chain(&p.drho)
                .chain(&p.pressure)
                .map(|x| x.to_bits()),
        )
        .chain([s.time_s.to_bits(), s.last_dt_s.to_bits()])
        .chain(dissipation_bits(s))
        .collect()
}

fn dissipation_bits(s: &Simulation) -> Vec<u64> {
    let d = &s.dissipation;
    d.dissipated_j
        .iter()
        .chain(&d.power.velocity_w)
        .chain(&d.power.acceleration_w_s)
        .chain([&d.density_reinit_j])
        .map(|x| x.to_bits())
        .collect()
}

#[test]
fn resumed_run_is_bitwise_the_uninterrupted_one() {
    let text = block_scene(
        8,
        1e-4,
        "interfacial_tension = true\nlaminar_viscosity = true\nartificial_viscosity = {}\ngravity = [0.0, 0.0, -9.81]",
        r#"
[density]
scheme = "continuity"
reinit = "shepard"
reinit_every = 7
[[solid]]
name = "alumina"
contact_angles = { matte = 70.0 }
[[wall]]
name = "plate"
solid = "alumina"
shape = { kind = "disk", center = [0.0, 0.0, -5.0e-4], radius = 1.2e-3 }
"#,
    );
    let mut a = sim(&text);
    advance(&mut a, 130);
    let saved = a.checkpoint();
    advance(&mut a, 170);

    let mut b = Simulation::resume(saved.clone()).expect("resumes");
    assert_eq!(b.step, 130);
    advance(&mut b, 170);
    assert!(
        a.search.builds > saved.builds,
        "rebuilds happened after the checkpoint"
    );
    assert_eq!(a.step, b.step);
    assert_eq!(bits(&a), bits(&b), "resumed state differs");
    // the budget is not trivially equal: every ledger of this scene has booked something
    // (laminar and artificial viscosity, the walls' pressure, the Shepard filter)
    let d = &a.dissipation;
    assert!(
        d.dissipated_j.iter().filter(|x| **x != 0.0).count() >= 3,
        "{d:?}"
    );
    assert!(d.density_reinit_j != 0.0);

    // a checkpoint of a different scene is refused with a message
    let mut wrong = saved;
    wrong.particles.pos.pop();
    assert!(Simulation::resume(wrong).is_err());
}
