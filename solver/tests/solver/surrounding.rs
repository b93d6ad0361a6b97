//! The `surrounding` body: a box of one liquid filled around the scene's other bodies and
//! walls (the host or gas a continuum capillarity model needs declared as a liquid).

use super::common::{error_of, sim};

const L0: f64 = 1.0e-4;
/// Half the box's edge [m]: 24 spacings across.
const HALF: f64 = 1.2e-3;

/// Two drops of liquids `a` and `b` (radius 4e-4 m at x = ∓5e-4 m) with the surrounding
/// `host` body listed between them, and `extra` appended.
fn two_drops_in_host(extra: &str) -> String {
    format!(
        r#"
[discretisation]
l0 = {L0:e}
sound_speed = 5.0
[time]
end = 1.0e-4
output_interval = 1.0e-4
[effects]
laminar_viscosity = true
[[liquid]]
name = "a"
density = 1000.0
viscosity = 1.0e-3
surface_tension = 0.07
[[liquid]]
name = "b"
density = 1000.0
viscosity = 1.0e-3
surface_tension = 0.07
[[liquid]]
name = "host"
density = 1000.0
viscosity = 1.0e-3
surface_tension = 0.07
[[interface]]
liquids = ["a", "b"]
tension = 0.05
[[interface]]
liquids = ["a", "host"]
tension = 0.07
[[interface]]
liquids = ["b", "host"]
tension = 0.07
[[body]]
name = "drop_a"
liquid = "a"
shape = {{ kind = "sphere", center = [-5.0e-4, 0.0, 0.0], radius = 4.0e-4 }}
[[body]]
name = "host"
liquid = "host"
shape = {{ kind = "surrounding", min = [{m:e}, {m:e}, {m:e}], max = [{p:e}, {p:e}, {p:e}] }}
[[body]]
name = "drop_b"
liquid = "b"
shape = {{ kind = "sphere", center = [5.0e-4, 0.0, 0.0], radius = 4.0e-4 }}
{extra}
"#,
        m = -HALF,
        p = HALF
    )
}

/// The lattice sites `(i + ½) l0` inside a ball, counted here independently of the solver.
fn sites_in_ball(center: [f64; 3], radius: f64) -> usize {
    let n = (HALF / L0).round() as i64;
    let mut count = 0;
    for i in -n..n {
        for j in -n..n {
            for k in -n..n {
                let p = [i, j, k].map(|q| (q as f64 + 0.5) * L0);
                let d2: f64 = (0..3).map(|q| (p[q] - center[q]).powi(2)).sum();
                count += usize::from(d2 < radius * radius);
            }
        }
    }
    count
}

#[test]
fn the_host_fills_its_box_around_the_drops_once() {
    let s = sim(&two_drops_in_host(""));
    let box_sites = (2.0 * HALF / L0).round() as usize;
    let box_sites = box_sites.pow(3);
    let a = sites_in_ball([-5.0e-4, 0.0, 0.0], 4.0e-4);
    let b = sites_in_ball([5.0e-4, 0.0, 0.0], 4.0e-4);
    // the inventory keeps the scene's order, whatever the order of filling
    let names: Vec<&str> = s.inventory.bodies.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(names, ["drop_a", "host", "drop_b"]);
    let counts: Vec<usize> = s.inventory.bodies.iter().map(|b| b.1).collect();
    assert_eq!(counts, [a, box_sites - a - b, b]);
    // no site twice, and no host particle inside a drop
    let p = &s.particles;
    let mut keys: Vec<[i64; 3]> = p.pos[..p.n_fluid]
        .iter()
        .map(|x| [x.x, x.y, x.z].map(|c| (c / L0 - 0.5).round() as i64))
        .collect();
    keys.sort_unstable();
    keys.dedup();
    assert_eq!(keys.len(), box_sites);
    let host = 2u8; // liquids in scene order: a, b, host
    for (x, &ph) in p.pos[..p.n_fluid].iter().zip(&p.phase) {
        let in_drop = [-5.0e-4, 5.0e-4]
            .iter()
            .any(|&cx| (x.x - cx).powi(2) + x.y * x.y + x.z * x.z < 1.6e-7);
        assert_eq!(ph == host, !in_drop, "particle at {x:?} of phase {ph}");
    }
}

#[test]
fn the_host_leaves_a_walls_sites_to_the_wall() {
    // a plate whose top is at z = −1.0e-3 m: its top layers lie inside the host's box
    let plate = r#"
[[solid]]
name = "glass"
contact_angles = { a = 90.0, b = 90.0, host = 90.0 }
[[wall]]
name = "plate"
solid = "glass"
shape = { kind = "plate", min = [-1.2e-3, -1.2e-3], max = [1.2e-3, 1.2e-3], top = -1.0e-3 }
"#;
    let s = sim(&two_drops_in_host(plate));
    let with = s.inventory.bodies[1].1;
    let without = sim(&two_drops_in_host("")).inventory.bodies[1].1;
    // the plate's layers sit at z = −1.05, −1.15, −1.25 … mm: two of them (24 × 24 sites
    // each) are inside the box
    assert_eq!(without - with, 2 * 24 * 24);
}

#[test]
fn two_surrounding_bodies_that_overlap_are_refused() {
    let second = format!(
        r#"
[[body]]
name = "more_host"
liquid = "host"
shape = {{ kind = "surrounding", min = [0.0, 0.0, 0.0], max = [{HALF:e}, {HALF:e}, {HALF:e}] }}
"#
    );
    let e = error_of(&two_drops_in_host(&second));
    assert!(
        e.contains("body[more_host]") && e.contains("overlaps 'host'"),
        "{e}"
    );
}

#[test]
fn the_surface_force_takes_three_liquids_and_refuses_a_fourth() {
    let csf = |extra: &str| {
        two_drops_in_host(extra).replace(
            "laminar_viscosity = true",
            "laminar_viscosity = true\ninterfacial_tension = \"surface_force\"",
        )
    };
    // two drops in a host: three liquids, each pair's tension split into their shares
    sim(&csf(""));
    let fourth = r#"
[[liquid]]
name = "c"
density = 1000.0
viscosity = 1.0e-3
surface_tension = 0.07
[[interface]]
liquids = ["a", "c"]
tension = 0.05
[[interface]]
liquids = ["b", "c"]
tension = 0.05
[[interface]]
liquids = ["host", "c"]
tension = 0.07
[[body]]
name = "drop_c"
liquid = "c"
shape = { kind = "sphere", center = [0.0, 0.0, 8.0e-4], radius = 2.0e-4 }
"#;
    let e = error_of(&csf(fourth));
    assert!(
        e.contains("effects.interfacial_tension") && e.contains("4 liquids"),
        "{e}"
    );
}
