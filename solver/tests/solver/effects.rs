//! Removing an effect removes exactly its contribution.

use super::common::{advance, block_scene, sim};

#[test]
fn without_tension_a_resting_block_in_a_closed_box_stays_at_rest() {
    // A lattice block filling a closed box exactly: every particle has a full kernel support
    // (walls complete it), so the summation density is ρ0 up to the rounding of the lattice sum
    // (relative 1e-16) and the pressure is at most c²ρ0·1e-15 ≈ 1e-9 Pa. Nothing else acts.
    // After 200 steps the speed must stay below 1e-12 m/s — ten orders below the capillary
    // speeds (~0.1 m/s) that tension produces in the same box.
    let walls = |tension: bool| {
        let h = 4.0e-4;
        block_scene(
            8,
            1e-4,
            if tension {
                "interfacial_tension = true"
            } else {
                ""
            },
            &format!(
                r#"
[[solid]]
name = "steel"
contact_angles = {{ matte = 120.0 }}
[[wall]]
name = "box"
solid = "steel"
shape = {{ kind = "box", min = [{m}, {m}, {m}], max = [{h}, {h}, {h}] }}
"#,
                m = -h
            ),
        )
    };
    let mut s = sim(&walls(false));
    advance(&mut s, 200);
    let vmax = s.observe().max_speed_m_s;
    assert!(vmax < 1e-12, "block moved without tension: {vmax:e} m/s");

    // with tension the unbalanced wetting of the walls sets it moving
    let mut s = sim(&walls(true));
    advance(&mut s, 200);
    assert!(s.observe().max_speed_m_s > 1e-6);
}

#[test]
fn without_gravity_the_centroid_does_not_accelerate_and_with_it_falls_at_g() {
    let g = 9.81;
    for gravity in [false, true] {
        let eff = if gravity {
            format!("interfacial_tension = true\nartificial_viscosity = {{}}\ngravity = [0.0, 0.0, -{g}]")
        } else {
            "interfacial_tension = true\nartificial_viscosity = {}".to_string()
        };
        let mut s = sim(&block_scene(8, 1e-4, &eff, ""));
        advance(&mut s, 150);
        let o = s.observe();
        let v = o.phases[0].centroid_velocity_m_s;
        let expected = if gravity { -g * o.time_s } else { 0.0 };
        // internal forces cancel to round-off (see conservation.rs): the centroid velocity
        // departs from the free-fall value by far less than 1e-9 of the speeds inside the
        // relaxing block (~0.1 m/s)
        let scale = o.max_speed_m_s.max(g * o.time_s);
        assert!(
            v[0].abs() < 1e-9 * scale && v[1].abs() < 1e-9 * scale,
            "{v:?}"
        );
        assert!(
            (v[2] - expected).abs() < 1e-9 * scale,
            "gravity {gravity}: v_z = {} expected {expected}",
            v[2]
        );
    }
}

#[test]
fn a_zeroed_effect_is_bitwise_the_absent_effect() {
    // AV with α1 = α2 = 0 and viscosity with μ = 0 add exact zeros to every pair force: the
    // run must match the one without those effects bit for bit, which shows that building an
    // effect has no side effect on the others (time step, ordering, state).
    let base = "interfacial_tension = true";
    let mut a = sim(&block_scene(7, 1e-4, base, ""));
    let zeroed = format!(
        "{base}\nartificial_viscosity = {{ alpha1 = 0.0, alpha2 = 0.0 }}\nlaminar_viscosity = true"
    );
    let mut b =
        sim(&block_scene(7, 1e-4, &zeroed, "").replace("viscosity = 3.13e-3", "viscosity = 0.0"));
    advance(&mut a, 100);
    advance(&mut b, 100);
    let bits = |s: &solver::Simulation| -> Vec<u64> {
        s.particles
            .pos
            .iter()
            .flat_map(|v| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>())
            .collect()
    };
    assert_eq!(bits(&a), bits(&b));
}
