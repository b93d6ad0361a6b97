//! Each kind of invalid scene is refused with a message that names the field and the value —
//! never a panic, never a silent default.

use super::common::{block_scene, error_of};
use solver::{Scene, SimError, Simulation};

fn assert_names(text: &str, parts: &[&str]) {
    let msg = error_of(text);
    for p in parts {
        assert!(msg.contains(p), "message {msg:?} should contain {p:?}");
    }
}

const BASE_EFFECTS: &str = "interfacial_tension = true";

fn base() -> String {
    block_scene(6, 1e-4, BASE_EFFECTS, "")
}

#[test]
fn non_positive_density() {
    assert_names(
        &base().replace("density = 4500.0", "density = -4500.0"),
        &["liquid[matte].density", "-4500"],
    );
    assert_names(
        &base().replace("density = 4500.0", "density = 0.0"),
        &["liquid[matte].density", "positive"],
    );
}

#[test]
fn negative_viscosity() {
    assert_names(
        &base().replace("viscosity = 3.13e-3", "viscosity = -1e-3"),
        &["liquid[matte].viscosity", "-0.001"],
    );
}

#[test]
fn non_positive_surface_tension_and_missing_one() {
    assert_names(
        &base().replace("surface_tension = 0.4", "surface_tension = 0.0"),
        &["liquid[matte].surface_tension", "0"],
    );
    assert_names(
        &base().replace("surface_tension = 0.4", ""),
        &["liquid[matte].surface_tension", "missing"],
    );
}

fn with_plate(angle: &str) -> String {
    block_scene(
        6,
        1e-4,
        BASE_EFFECTS,
        &format!(
            r#"
[[solid]]
name = "alumina"
contact_angles = {{ matte = {angle} }}
[[wall]]
name = "plate"
solid = "alumina"
shape = {{ kind = "disk", center = [0.0, 0.0, -6.0e-4], radius = 1.0e-3 }}
"#
        ),
    )
}

#[test]
fn contact_angle_outside_open_interval() {
    for bad in ["0.0", "180.0", "200.0", "-10.0"] {
        assert_names(
            &with_plate(bad),
            &["solid[alumina].contact_angles.matte", "between 0 and 180"],
        );
    }
    // a valid one builds
    Simulation::new(&Scene::from_toml_str(&with_plate("90.0")).unwrap()).unwrap();
}

#[test]
fn missing_contact_angle_for_a_wall_liquid_pair() {
    let text = with_plate("90.0").replace("contact_angles = { matte = 90.0 }", "");
    assert_names(&text, &["solid[alumina].contact_angles.matte", "missing"]);
}

#[test]
fn touching_liquids_without_interfacial_tension() {
    let text = base()
        + r#"
[[liquid]]
name = "slag"
density = 3500.0
viscosity = 0.1
surface_tension = 0.2
[[body]]
name = "drop2"
liquid = "slag"
shape = { kind = "sphere", center = [0.0, 0.0, 9.0e-4], radius = 3.0e-4 }
"#;
    assert_names(&text, &["interface", "matte", "slag"]);
}

#[test]
fn overlapping_bodies() {
    let text = base()
        + r#"
[[body]]
name = "intruder"
liquid = "matte"
shape = { kind = "sphere", center = [0.0, 0.0, 0.0], radius = 2.0e-4 }
"#;
    assert_names(&text, &["body[intruder]", "overlaps 'block'"]);
}

#[test]
fn body_with_too_few_particles() {
    let text = base().replace("[[body]]", "[[body]]\nname = \"tiny\"\nliquid = \"matte\"\nshape = { kind = \"box\", min = [0.0, 0.0, 2.0e-3], max = [1.0e-4, 1.0e-4, 2.3e-3] }\n[[body]]");
    assert_names(&text, &["body[tiny].shape", "3 particles", "at least 8"]);
}

#[test]
fn unaffordable_time_step() {
    // a fixed step far above the CFL limit (≈ 0.25·1.05e-4/12 ≈ 2.2e-6 s)
    let text = base().replace(
        "output_interval = 1.0e-4",
        "output_interval = 1.0e-4\ndt = 1.0e-4",
    );
    assert_names(&text, &["time.dt", "0.0001", "limit"]);
    // a run needing more steps than allowed
    let text = base().replace(
        "output_interval = 1.0e-4",
        "output_interval = 1.0e-4\nmax_steps = 10",
    );
    assert_names(&text, &["time.max_steps", "10", "steps"]);
}

#[test]
fn unknown_keys_are_rejected() {
    assert_names(
        &base().replace("sound_speed", "sound_sped"),
        &["sound_sped"],
    );
    assert_names(
        &base().replace("[effects]", "[effects]\nsurface_tenson = true"),
        &["surface_tenson"],
    );
    assert_names(
        &base().replace("kind = \"box\"", "kind = \"cube\""),
        &["cube"],
    );
}

#[test]
fn unknown_names_and_contradictions() {
    assert_names(
        &base().replace("liquid = \"matte\"", "liquid = \"mate\""),
        &["body[block].liquid", "mate"],
    );
    let text = base().replace("[effects]", "[density]\nreinit = \"shepard\"\n[effects]");
    assert_names(&text, &["density.reinit", "continuity"]);
    let text = with_plate("90.0").replace("radius = 1.0e-3 }", "radius = 1.0e-3 }\nlayers = 1");
    assert_names(&text, &["wall[plate].layers", "thick"]);
    let text = with_plate("90.0").replace("-6.0e-4], radius", "-6.5e-4], radius");
    assert_names(&text, &["wall[plate].shape.center[2]", "lattice"]);
}

#[test]
fn non_finite_values() {
    assert_names(
        &base().replace("sound_speed = 12.0", "sound_speed = nan"),
        &["discretisation.sound_speed", "NaN"],
    );
    assert_names(
        &base().replace("[effects]", "[effects]\ngravity = [0.0, 0.0, inf]"),
        &["effects.gravity"],
    );
}

#[test]
fn errors_are_values_not_panics() {
    // garbage and truncated files give a parse error naming the position
    for text in [
        "",
        "[[body]",
        "discretisation = 3",
        &base()[..base().len() / 2],
    ] {
        let r = std::panic::catch_unwind(|| Scene::from_toml_str(text));
        assert!(
            matches!(r, Ok(Err(_))),
            "should be an error value for {text:?}"
        );
    }
    let _ = SimError::Scene(solver::SceneError::Parse(String::new()));
}

#[test]
fn setting_supplies_defaults_and_explicit_values_win() {
    let d = |text: &str| {
        let s = Scene::from_toml_str(text).unwrap();
        (s.discretisation.h_over_l0, s.discretisation.re_over_l0)
    };
    // paper A's defaults without a setting
    assert_eq!(d(&base()), (1.05, 4.2));
    let b16 = base().replace("l0 = ", "setting = \"natsui2016\"\nl0 = ");
    // paper B: support 2h = 4.0 l0 and r_e = 4.0 l0
    assert_eq!(d(&b16), (2.0, 4.0));
    let explicit = b16.replace("l0 = ", "h_over_l0 = 1.3\nl0 = ");
    assert_eq!(d(&explicit), (1.3, 4.0));
    // the resolved values survive a round trip through the serialised scene (checkpoints)
    let s = Scene::from_toml_str(&b16).unwrap();
    let again = Scene::from_toml_str(&toml::to_string(&s).unwrap()).unwrap();
    assert_eq!(s, again);
    assert_names(
        &base().replace("l0 = ", "setting = \"natsui2019\"\nl0 = "),
        &["setting", "natsui2019", "line"],
    );
}

#[test]
fn negative_or_undefined_wall_depth_bound() {
    for v in ["-1.0", "nan"] {
        assert_names(
            &block_scene(
                6,
                1e-4,
                BASE_EFFECTS,
                &format!("[health]\nmax_wall_depth_over_l0 = {v}\n"),
            ),
            &["health.max_wall_depth_over_l0", "≥ 0"],
        );
    }
}

#[test]
fn wall_repulsion_without_walls_or_tension() {
    assert_names(
        &block_scene(
            6,
            1e-4,
            "interfacial_tension = true\nwall_repulsion = true",
            "",
        ),
        &["effects.wall_repulsion", "needs walls"],
    );
    let plate = "[[solid]]\nname = \"alumina\"\ncontact_angles = { matte = 90.0 }\n[[wall]]\nname = \"plate\"\nsolid = \"alumina\"\nshape = { kind = \"disk\", center = [0.0, 0.0, -6.0e-4], radius = 1.2e-3 }\n";
    assert_names(
        &block_scene(6, 1e-4, "wall_repulsion = true", plate),
        &["effects.wall_repulsion", "interfacial_tension"],
    );
}

#[test]
fn particle_shifting_coefficient_out_of_range() {
    for a in ["0.0", "-1.0", "9.0", "nan"] {
        assert_names(
            &block_scene(
                6,
                1e-4,
                &format!("particle_shifting = {{ coefficient = {a} }}"),
                "",
            ),
            &["effects.particle_shifting.coefficient", "(0, 8]"],
        );
    }
}

#[test]
fn implicit_viscosity_without_its_term_with_no_slip_walls_or_a_bad_rule() {
    assert_names(
        &block_scene(6, 1e-4, "implicit_viscosity = {}", ""),
        &["effects.implicit_viscosity", "laminar_viscosity = true"],
    );
    let viscous = "laminar_viscosity = true\nimplicit_viscosity = {}";
    let no_slip = with_plate("90.0").replace(
        "radius = 1.0e-3 }",
        "radius = 1.0e-3 }\nboundary = \"no_slip\"",
    );
    assert_names(
        &no_slip.replace(BASE_EFFECTS, &format!("{BASE_EFFECTS}\n{viscous}")),
        &[
            "effects.implicit_viscosity",
            "\"plate\" is no-slip",
            "free-slip",
        ],
    );
    for (rule, field) in [
        ("relative_tolerance = 0.0", "relative_tolerance"),
        ("relative_tolerance = 0.01", "relative_tolerance"),
        ("max_iterations = 0", "max_iterations"),
    ] {
        assert_names(
            &block_scene(
                6,
                1e-4,
                &format!("laminar_viscosity = true\nimplicit_viscosity = {{ {rule} }}"),
                "",
            ),
            &[&format!("effects.implicit_viscosity.{field}")],
        );
    }
    // and a valid one builds, free-slip plate included
    let ok = with_plate("90.0").replace(BASE_EFFECTS, &format!("{BASE_EFFECTS}\n{viscous}"));
    assert!(Simulation::new(&Scene::from_toml_str(&ok).unwrap()).is_ok());
}

#[test]
fn a_laminar_form_without_its_term_with_the_implicit_solve_or_misspelt() {
    let mcg = "laminar_form = \"monaghan_cleary_gingold\"";
    assert_names(
        &block_scene(6, 1e-4, mcg, ""),
        &["effects.laminar_form", "laminar_viscosity = true"],
    );
    assert_names(
        &block_scene(
            6,
            1e-4,
            &format!("laminar_viscosity = true\nimplicit_viscosity = {{}}\n{mcg}"),
            "",
        ),
        &["effects.laminar_form", "implicit", "hu_adams"],
    );
    assert_names(
        &block_scene(
            6,
            1e-4,
            "laminar_viscosity = true\nlaminar_form = \"mcg\"",
            "",
        ),
        &["mcg", "monaghan_cleary_gingold"],
    );
    // the default form may be written out
    let ok = block_scene(
        6,
        1e-4,
        "laminar_viscosity = true\nlaminar_form = \"hu_adams\"",
        "",
    );
    assert!(Simulation::new(&Scene::from_toml_str(&ok).unwrap()).is_ok());
}

#[test]
fn a_name_that_would_break_a_csv_column() {
    // liquid names head the time series' columns: `slag, FeO` would split one in two
    let text = base().replace("name = \"matte\"", "name = \"slag, FeO\"");
    assert_names(&text, &["slag, FeO", "CSV"]);
}
