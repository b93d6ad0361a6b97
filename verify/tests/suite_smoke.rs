//! Every case at smoke fidelity: the metrics that smoke resolution can judge must pass their
//! stated tolerances, the summary must match its snapshot (rounded to the digits that are stable
//! across machines), reports must redraw without simulating, and finished runs are reused.

mod common;
use common::Quiet;
use std::path::PathBuf;
use verify::suite::overrides::SceneOverride;
use verify::suite::runner::{self, SuiteOptions};
use verify::suite::{Case, Fidelity, Metric};

fn out_dir(case: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("verify-smoke-{}-{case}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

fn case(name: &str) -> Box<dyn Case> {
    verify::cases::all()
        .into_iter()
        .find(|c| c.name() == name)
        .expect("case exists")
}

fn run(name: &str) -> (Vec<Metric>, PathBuf) {
    let out = out_dir(name);
    let opts = SuiteOptions {
        fidelity: Fidelity::Smoke,
        out: out.clone(),
        force: false,
        threads: Some(2),
        progress: false,
        overrides: vec![],
        only: vec![],
        strict: true,
        checkpoint_minutes: None,
        interrupt: None,
    };
    let metrics = runner::run_case(case(name).as_ref(), &opts).expect("case runs");
    (metrics, out)
}

/// Three significant digits: runs are bitwise reproducible for any build and thread count
/// (`.cargo/config.toml`); only a different system libm (cos/pow) could change a last bit,
/// which thousands of steps grow to parts in 1e3 — then a snapshot's third digit may move and
/// the change is reviewed like any other. An angle below 1e-4° is a failed fit whose digits
/// are noise.
fn round3_unit(v: f64, unit: &str) -> String {
    if unit == "deg" && v.abs() < 1e-4 {
        return "0".into();
    }
    if !v.is_finite() {
        return "NaN".into();
    }
    if v == 0.0 {
        return "0".into();
    }
    let mag = v.abs().log10().floor() as i32;
    if !(-3..5).contains(&mag) {
        return format!("{v:.2e}");
    }
    let scale = 10f64.powi(2 - mag);
    format!("{}", (v * scale).round() / scale)
}

fn summary(metrics: &[Metric]) -> String {
    metrics
        .iter()
        .map(|m| {
            let pass = match m.pass() {
                Some(true) => "pass",
                Some(false) => "FAIL",
                None => "-",
            };
            // round-off-level quantities (momentum, centroid drift) differ between machines in
            // every digit: only whether they pass is stable
            let value = if m.name.contains("drift") {
                "round-off".to_string()
            } else {
                round3_unit(m.value, &m.unit)
            };
            format!("{} = {value} {} [{pass}]", m.name, m.unit)
        })
        .collect::<Vec<_>>()
        .join("\n")
}

fn must_pass(metrics: &[Metric], names: &[&str]) {
    for n in names {
        let m = metrics
            .iter()
            .find(|m| &m.name == n)
            .unwrap_or_else(|| panic!("metric {n} missing"));
        assert_eq!(
            m.pass(),
            Some(true),
            "{n}: value {} vs reference {:?} ± {:?} — {}",
            m.value,
            m.reference,
            m.tolerance,
            m.note
        );
    }
}

#[test]
fn cube_drop_smoke() {
    let (m, out) = run("cube_drop");
    // The width of a 10³ cube is set by single outermost particles and too noisy to fit; the
    // l = 4 moment Q4 is judged: Lamb's period within the case's 10 % (measured +7 %).
    must_pass(&m, &["period (Q4) c²=150"]);
    insta::assert_snapshot!("cube_drop", summary(&m));

    // the report redraws from saved data: delete a plot, reanalyse, it is back; runs reused
    let plot = out.join("cube_drop/period_vs_c2.png");
    std::fs::remove_file(&plot).unwrap();
    let stamp = std::fs::metadata(out.join("cube_drop/c2_150/run_info.json"))
        .unwrap()
        .modified()
        .unwrap();
    let again =
        runner::analyse_case(case("cube_drop").as_ref(), Fidelity::Smoke, &out, &[]).unwrap();
    assert!(plot.exists());
    assert_eq!(summary(&again), summary(&m));
    let opts = SuiteOptions {
        fidelity: Fidelity::Smoke,
        out: out.clone(),
        force: false,
        threads: Some(2),
        progress: false,
        overrides: vec![],
        only: vec![],
        strict: true,
        checkpoint_minutes: None,
        interrupt: None,
    };
    runner::run_case(case("cube_drop").as_ref(), &opts).unwrap();
    let stamp2 = std::fs::metadata(out.join("cube_drop/c2_150/run_info.json"))
        .unwrap()
        .modified()
        .unwrap();
    assert_eq!(
        stamp, stamp2,
        "a finished run is reused, not simulated again"
    );

    // a folder holding another scene's run is stale: measured under other `--set` keys, no
    // run is the case's, so none is measured (a stale run reported as current was the defect)
    let other: Vec<SceneOverride> = vec!["discretisation.sound_speed=13.0".parse().unwrap()];
    let stale = runner::analyse_case(case("cube_drop").as_ref(), Fidelity::Smoke, &out, &other);
    let stale = stale.unwrap();
    // no run measured: no metric
    assert!(stale.is_empty(), "{}", summary(&stale));
    // the suite's record keeps the keys, so that `verify report` measures what the suite ran
    // (per case: another case run as written keeps its own record)
    runner::write_record(&out, Fidelity::Smoke, &["cube_drop"], &other).unwrap();
    runner::write_record(&out, Fidelity::Smoke, &["shear_wave"], &[]).unwrap();
    let record = runner::read_record(&out).unwrap();
    assert_eq!(record.overrides("cube_drop").unwrap(), other);
    assert!(record.overrides("shear_wave").unwrap().is_empty());
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn drop_oscillation_smoke() {
    let (m, out) = run("drop_oscillation");
    // the l = 2 oscillation of Q2 must be fitted (a failed fit gives NaN); how far its period
    // and damping are from Rayleigh's and Lamb's is the measurement, kept by the snapshot
    for name in ["period ε=0.10", "damping ε=0.10"] {
        let v = m.iter().find(|x| x.name == name).map(|x| x.value);
        assert!(v.is_some_and(f64::is_finite), "{name}: {v:?}");
    }
    insta::assert_snapshot!("drop_oscillation", summary(&m));
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn known_misses_name_real_cases() {
    let names: Vec<&str> = verify::cases::all().iter().map(|c| c.name()).collect();
    for k in verify::report::known_misses::all() {
        assert!(names.contains(&k.case.as_str()), "{}", k.case);
    }
}

#[test]
fn convergence_smoke() {
    let (m, out) = run("convergence");
    // every run is measured (a failed fit or cap gives NaN) and each metric's order is
    // computed; whether the errors fall at these coarse spacings is the measurement, kept by
    // the snapshot. Except the surface force's drops: at R/l0 = 5 and 6 (R = 1.2 and 1.4 r_e)
    // they gain energy (kinetic energy up to 9 and 15 nJ, on a mode of about 10 nJ, with
    // the band at 0.01 r_e⁻¹; docs/findings.md) and drift instead of ringing down, so no damped
    // cosine fits them: those NaNs are the measurement
    let measured =
        |x: &&Metric| !x.name.contains("side view") && !x.name.starts_with("surface-force drop");
    for x in m.iter().filter(measured) {
        if !x.name.contains("falls with resolution") {
            assert!(x.value.is_finite(), "{}: {}", x.name, x.value);
        }
    }
    for s in [
        "drop l = 2 period",
        "cap 60° (from height)",
        "surface-stress drop l = 2 period",
        "surface-force drop l = 2 period",
    ] {
        let name = format!("{s}: observed order");
        assert!(m.iter().any(|x| x.name == name), "{name}");
    }
    // the continuum drops' energy trends carry the force's own share, from its booked work
    // (the potential's, whose force derives from its energy, none)
    for x in m.iter().filter(|x| x.name.contains("energy trend")) {
        let continuum = x.name.starts_with("surface-");
        assert_eq!(
            x.note.contains("of it the interfacial force's own"),
            continuum,
            "{}: {}",
            x.name,
            x.note
        );
    }
    assert!(out.join("convergence/error_vs_spacing.png").exists());
    // the drop's table carries the elastic drop's bracket for the default setting, whose
    // lattice has C′ and C44 > 0: both estimates are finite and shorter than Rayleigh's
    let table = std::fs::read_to_string(out.join("convergence/table.md")).unwrap();
    assert!(table.contains("elastic drop"), "{table}");
    // the potential's drops: the first table, up to the blank line before the next
    let first = table.split("\n\n").next().unwrap();
    for row in first.lines().skip(2) {
        let bracket = row.split('|').nth(7).unwrap_or_default();
        assert!(
            bracket.contains('…') && bracket.matches('-').count() == 2,
            "{row}"
        );
    }
    insta::assert_snapshot!("convergence", summary(&m));
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn shear_wave_smoke() {
    let (m, out) = run("shear_wave");
    // without the potential the lattice carries no stress: the SPH viscous operator alone
    // must give the liquid's viscosity in the bulk (10 %: the liquid model's target) and the
    // wave must not reverse; the run with the potential is the measurement, kept by the
    // snapshot
    let value = |name: &str| m.iter().find(|x| x.name == name).map(|x| x.value);
    let nu = value("viscosity_only: ν_eff / ν").expect("measured");
    assert!((nu - 1.0).abs() < 0.1, "ν_eff/ν = {nu}");
    assert_eq!(value("viscosity_only: reversals of A(t)"), Some(0.0));
    insta::assert_snapshot!("shear_wave", summary(&m));
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn equal_doublet_smoke() {
    let (m, out) = run("equal_doublet");
    // G1G2/R0 at σ12 = 0.4 against the analytic doublet, within half a spacing plus the
    // residual oscillation; σ12 = 1.0 ≥ 2σ1 parts or touches (Eq. 25)
    must_pass(&m, &["G1G2/R0 σ12=0.4", "separation σ12=1.0"]);
    insta::assert_snapshot!("equal_doublet", summary(&m));
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn matte_slag_doublet_smoke() {
    let (m, out) = run("matte_slag_doublet");
    // the lens regime and G1G2/R0; the triple-line angles need more than R0/l0 = 5 (at smoke
    // resolution no particle is both on the free surface and at the interface)
    must_pass(&m, &["regime σ12=0.4", "G1G2/R0 σ12=0.4"]);
    insta::assert_snapshot!("matte_slag_doublet", summary(&m));
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn plate_eq23_smoke() {
    let (m, out) = run("plate_eq23");
    // θ23 = θ31 = 90°: both liquids on the plate (Eq. 23). θ12 (90°) is reported, not judged:
    // at the smoke resolution R/l0 = 5 no test bounds the line fit's error
    must_pass(&m, &["contact identical_theta23_90"]);
    // both models' θ12 and their single drops' angles are measured, and θ12 is set against
    // Eq. 23 at the angles each model's own single drops measured
    for name in [
        "θ12 identical_theta23_90",
        "contact angle single_matte_theta_90",
        "θ12 from measured angles identical_theta23_90",
        "θ12 csfn_identical_theta23_90",
        "contact angle csfn_single_matte_theta_90",
        "θ12 from measured angles csfn_identical_theta23_90",
    ] {
        assert!(
            m.iter().any(|x| x.name == name && x.value.is_finite()),
            "{name} not measured"
        );
    }
    for map in ["theta12_map_fig3a.png", "theta12_map_fig3b.png"] {
        assert!(out.join("plate_eq23").join(map).exists());
    }
    insta::assert_snapshot!("plate_eq23", summary(&m));
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn water_oil_teflon_smoke() {
    let (m, out) = run("water_oil_teflon");
    // 20 ms at l0 = 0.35 mm is far from equilibrium (the oil has not spread yet): nothing has an
    // analytic value to meet; the run must complete and be measured
    let info =
        std::fs::read_to_string(out.join("water_oil_teflon/water_oil/run_info.json")).unwrap();
    assert!(info.contains("\"status\": \"completed\""));
    assert!(m
        .iter()
        .any(|x| x.name == "water share of the wetted plate" && x.value.is_finite()));
    insta::assert_snapshot!("water_oil_teflon", summary(&m));
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn water_drop_impact_smoke() {
    let (m, out) = run("water_drop_impact");
    // 4 ms after impact at R/l0 = 5: the Teflon (90°) drop has already relaxed to a hemisphere
    // (height and wetted radius within one spacing of Young–Laplace); the glass (30°) drop is
    // still spreading and not judged here. In paper A's setting no particle enters the plate.
    must_pass(
        &m,
        &[
            "equilibrium height teflon_90",
            "wetted radius teflon_90",
            "liquid particles inside the plate glass_30",
            "liquid particles inside the plate teflon_90",
        ],
    );
    for png in [
        "angle_glass_30.png",
        "height_teflon_90.png",
        "side_glass_30_t002.0ms.png",
    ] {
        assert!(out.join("water_drop_impact").join(png).exists(), "{png}");
    }
    insta::assert_snapshot!("water_drop_impact", summary(&m));
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn water_incline_smoke() {
    let (m, out) = run("water_incline");
    must_pass(
        &m,
        &[
            "liquid particles inside the plate glass_30",
            "liquid particles inside the plate teflon_90",
        ],
    );
    // gravity along the plate (+x) makes the drop slide downhill: the mean velocity over the
    // second half of the run is positive and of the order of mm/s–cm/s, not a blow-up
    for id in ["glass_30", "teflon_90"] {
        let v = m
            .iter()
            .find(|x| x.name == format!("sliding speed {id}"))
            .unwrap()
            .value;
        assert!(v > 0.0 && v < 500.0, "{id}: {v} mm/s");
    }
    assert!(out
        .join("water_incline/top_teflon_90_t004.0ms.png")
        .exists());
    insta::assert_snapshot!("water_incline", summary(&m));
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn molten_metal_drops_smoke() {
    for (case, id) in [
        ("aluminium_on_alumina", "alumina_90"),
        ("iron_on_alumina", "alumina_125"),
    ] {
        let (m, out) = run(case);
        must_pass(&m, &[&format!("liquid particles inside the plate {id}")]);
        let info = std::fs::read_to_string(out.join(case).join(id).join("run_info.json")).unwrap();
        assert!(info.contains("\"status\": \"completed\""), "{case}");
        // the drop has landed: the side-view angles are measured after the first outputs
        let angle = m
            .iter()
            .find(|x| x.name == format!("equilibrium contact angle {id}"))
            .unwrap();
        assert!(angle.value.is_finite(), "{case}: {}", angle.note);
        insta::assert_snapshot!(case, summary(&m));
        let _ = std::fs::remove_dir_all(&out);
    }
}

#[test]
fn hard_cases_smoke() {
    let (m, out) = run("hard_cases");
    // every judged invariant of every hard scene: completion, particles kept, mass exact, no
    // particle inside a wall, momentum to round-off and bounded energy where no external force
    // acts, compression after the transient, one body and no clumping for the drop at rest
    let failed: Vec<String> = m
        .iter()
        .filter(|x| x.pass() == Some(false))
        .map(|x| format!("{}: {} ({})", x.name, x.value, x.note))
        .collect();
    assert!(failed.is_empty(), "failed invariants: {failed:#?}");
    assert!(m.iter().filter(|x| x.pass().is_some()).count() >= 40);
    insta::assert_snapshot!("hard_cases", summary(&m));
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn compare_flags_a_worse_metric_and_the_cli_exits_4() {
    // a baseline where the cube's Q4 period error was 0: the smoke run's +7 % (more than a
    // quarter of the 10 % tolerance above it) is a regression
    let dir = out_dir("compare");
    std::fs::create_dir_all(&dir).unwrap();
    let base = dir.join("baseline.csv");
    std::fs::write(
        &base,
        "case,name,unit,value,reference,paper,error,tolerance,tolerance_source,pass,particles,wall_time_s,note\n\
         cube_drop,period (Q4) c²=150,ms,1.2135,1.2135,,0,0.12135,test,pass,1000,1,\n",
    )
    .unwrap();
    let out = dir.join("out");
    let st = std::process::Command::new(env!("CARGO_BIN_EXE_verify"))
        .args(["case", "cube_drop", "--fidelity", "smoke", "--out"])
        .arg(&out)
        .quiet()
        .unwrap();
    assert!(st.success());
    // the case's rows only: the baseline's other cases did not run here
    let st = std::process::Command::new(env!("CARGO_BIN_EXE_verify"))
        .args(["case", "cube_drop", "--fidelity", "smoke", "--out"])
        .arg(&out)
        .arg("--compare")
        .arg(&base)
        .output()
        .unwrap();
    assert_eq!(
        st.status.code(),
        Some(4),
        "{}",
        String::from_utf8_lossy(&st.stderr)
    );
    assert!(String::from_utf8_lossy(&st.stderr).contains("period (Q4) c²=150"));
    // against its own summary nothing is worse
    let st = std::process::Command::new(env!("CARGO_BIN_EXE_verify"))
        .args(["case", "cube_drop", "--fidelity", "smoke", "--out"])
        .arg(&out)
        .arg("--compare")
        .arg(out.join("summary.csv"))
        .quiet()
        .unwrap();
    assert_eq!(st.code(), Some(0));
    let _ = std::fs::remove_dir_all(&dir);
}
