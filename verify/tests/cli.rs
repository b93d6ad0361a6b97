//! The `run` and `check` commands: outputs, run record, pre-flight findings, refusal to overwrite,
//! and exit codes.

mod common;

use std::path::PathBuf;

fn scene_file(dir: &std::path::Path, text: &str) -> PathBuf {
    std::fs::create_dir_all(dir).unwrap();
    let p = dir.join("scene.toml");
    std::fs::write(&p, text).unwrap();
    p
}

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("verify-cli-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

use common::{verify, Quiet, SMALL};

#[test]
fn run_writes_timeseries_run_info_and_snapshots() {
    let dir = tmp("ok");
    let scene = scene_file(&dir, SMALL);
    let out = dir.join("out");
    let st = verify()
        .args(["run"])
        .arg(&scene)
        .arg("--out")
        .arg(&out)
        .args(["--vtk", "1", "--threads", "2"])
        .quiet()
        .unwrap();
    assert!(st.success());
    let info: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("run_info.json")).unwrap()).unwrap();
    assert_eq!(info["status"], "completed");
    assert_eq!(info["threads"], 2);
    assert!(info["particle_steps_per_second"].as_f64().unwrap() > 0.0);
    assert!(info["effects"]
        .as_array()
        .unwrap()
        .iter()
        .any(|e| e.as_str().unwrap().contains("interfacial tension")));
    let ts = verify::output::timeseries::Table::read(&out.join("timeseries.csv")).unwrap();
    assert_eq!(ts.rows.len(), 3, "rows at t = 0, 1e-5, 2e-5 s");
    let t = ts.column("time_s").unwrap();
    assert!((t[2] - 2e-5).abs() < 1e-12);
    assert!(ts.column("matte_centroid_x_m").is_some());
    for k in 0..3 {
        assert!(out.join(format!("particles_{k:06}.vtu")).exists());
    }
    check_snapshots(&out, info["fluid_particles"].as_u64().unwrap() as usize);
    // the final state: every fluid particle at the end time
    let last = verify::output::dump::Dump::read(&out.join(verify::run::FINAL)).unwrap();
    assert_eq!(
        last.pos.len() as u64,
        info["fluid_particles"].as_u64().unwrap()
    );
    assert!((last.time_s - 2e-5).abs() < 1e-12, "{}", last.time_s);

    // an existing output folder is not overwritten without --force (exit code 3)
    let st = verify()
        .args(["run"])
        .arg(&scene)
        .arg("--out")
        .arg(&out)
        .quiet()
        .unwrap();
    assert_eq!(st.code(), Some(3));
    let st = verify()
        .args(["run"])
        .arg(&scene)
        .arg("--out")
        .arg(&out)
        .arg("--force")
        .quiet()
        .unwrap();
    assert!(st.success());
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn measure_takes_the_final_state_of_a_run_without_snapshots() {
    let dir = tmp("final");
    let scene = scene_file(&dir, SMALL);
    let out = dir.join("out");
    let st = verify()
        .arg("run")
        .arg(&scene)
        .arg("--out")
        .arg(&out)
        .quiet()
        .unwrap();
    assert!(st.success());
    assert!(!out.join("particles.pvd").exists());
    let m = verify().arg("measure").arg(&out).output().unwrap();
    let err = String::from_utf8_lossy(&m.stderr);
    assert!(m.status.success(), "{err}");
    // the header and one row: the drop at the end time (2e-5 s), all of its particles
    let csv = std::fs::read_to_string(out.join("measures.csv")).unwrap();
    let rows: Vec<Vec<&str>> = csv.lines().map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 2, "{csv}");
    assert!(
        (rows[1][0].parse::<f64>().unwrap() - 2e-5).abs() < 1e-12,
        "{csv}"
    );
    let info: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("run_info.json")).unwrap()).unwrap();
    assert_eq!(rows[1][2], info["fluid_particles"].to_string(), "{csv}");
    // nothing to measure: neither snapshots nor a final state
    std::fs::remove_file(out.join(verify::run::FINAL)).unwrap();
    let m = verify().arg("measure").arg(&out).output().unwrap();
    assert!(!m.status.success());
    assert!(String::from_utf8_lossy(&m.stderr).contains("no final state"));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn an_invalid_scene_exits_with_code_2_and_names_the_field() {
    let dir = tmp("bad");
    let scene = scene_file(&dir, &SMALL.replace("density = 4500.0", "density = -1.0"));
    let out = verify()
        .args(["run"])
        .arg(&scene)
        .arg("--out")
        .arg(dir.join("out"))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("liquid[matte].density") && err.contains("-1"),
        "{err}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_case_refuses_an_unknown_key_and_a_change_of_model_before_writing_anything() {
    let dir = tmp("case-set");
    let out = dir.join("out");
    let refused = |set: &str| {
        let r = verify()
            .args([
                "case",
                "convergence",
                "--only",
                "csf_drop_r10",
                "--set",
                set,
                "--out",
            ])
            .arg(&out)
            .output()
            .unwrap();
        assert!(!out.exists(), "nothing written for {set}");
        (
            r.status.code(),
            String::from_utf8_lossy(&r.stderr).to_string(),
        )
    };
    let (code, err) = refused("nonsense.key=1");
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("unknown field `nonsense`"), "{err}");
    // the surface force's drop with the difference form and its walls as a phase: a model the
    // case does not declare, which it would otherwise measure as the potential's free drop
    let (code, err) = refused("density.pressure_gradient=\"difference\"");
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("none the case declares"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_failing_run_exits_1_keeps_its_outputs_and_says_why() {
    // gravity of 1e4 m/s² accelerates the drop past Mach 1 (12 m/s at c = 12 m/s) after about
    // 1.2 ms: several outputs are written before the health check stops the run
    let dir = tmp("fail");
    let text = SMALL
        .replace("end = 2.0e-5", "end = 3.0e-3")
        .replace("output_interval = 1.0e-5", "output_interval = 1.0e-4")
        .replace("[effects]", "[effects]\ngravity = [0.0, 0.0, -1.0e4]");
    let scene = scene_file(&dir, &text);
    let out = dir.join("out");
    let res = verify()
        .arg("run")
        .arg(&scene)
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    assert_eq!(
        res.status.code(),
        Some(1),
        "{}",
        String::from_utf8_lossy(&res.stderr)
    );
    let err = String::from_utf8_lossy(&res.stderr);
    assert!(err.contains("Mach") && err.contains("sound_speed"), "{err}");
    let info: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("run_info.json")).unwrap()).unwrap();
    assert_eq!(info["status"], "failed");
    assert!(info["error"].as_str().unwrap().contains("Mach"));
    let ts = verify::output::timeseries::Table::read(&out.join("timeseries.csv")).unwrap();
    assert!(ts.rows.len() > 3, "outputs before the failure are kept");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn check_names_the_unit_slip_and_strict_refuses_it() {
    let dir = tmp("check");
    // σ of the matte typed in mN/m (400) and a drop of 4 spacings
    let scene = scene_file(
        &dir,
        &SMALL.replace("surface_tension = 0.4", "surface_tension = 400.0"),
    );
    let out = verify().arg("check").arg(&scene).output().unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("did you mean 400 mN/m") && text.contains("surface_tension = 4e-1"),
        "{text}"
    );
    // the sample fails as the run would (Mach, at σ 1000 times too large): the check fails
    // with the run's exit code, and names the slip it flagged before the step that failed
    assert_eq!(out.status.code(), Some(1), "{text}");
    assert!(
        text.contains("sample: the run fails")
            && text.contains("flagged before step 1: surface tension of matte: σ = 400 N/m"),
        "{text}"
    );
    assert!(
        text.contains("resolution of body drop") && text.contains("time step:"),
        "{text}"
    );
    let strict = verify()
        .arg("check")
        .arg(&scene)
        .arg("--strict")
        .quiet()
        .unwrap();
    assert_eq!(strict.code(), Some(2));
    // `run --strict` refuses it before making the output folder; without it the run warns and
    // keeps the findings in its record
    let refused = verify()
        .arg("run")
        .arg(&scene)
        .arg("--out")
        .arg(dir.join("strict"))
        .arg("--strict")
        .output()
        .unwrap();
    assert_eq!(
        refused.status.code(),
        Some(2),
        "{}",
        String::from_utf8_lossy(&refused.stderr)
    );
    assert!(!dir.join("strict").exists());
}

#[test]
fn check_refuses_what_run_refuses() {
    let dir = tmp("check-overlap");
    // a plate whose top (z = 0) cuts through the drop centred at the origin
    let scene = scene_file(
        &dir,
        &format!(
            "{SMALL}\n[[solid]]\nname = \"plate\"\ncontact_angles = {{ matte = 90.0 }}\n\
             [[wall]]\nname = \"plate\"\nsolid = \"plate\"\n\
             shape = {{ kind = \"disk\", center = [0.0, 0.0, 0.0], radius = 1.0e-3 }}\n"
        ),
    );
    let check = verify().arg("check").arg(&scene).output().unwrap();
    let run = verify()
        .arg("run")
        .arg(&scene)
        .arg("--out")
        .arg(dir.join("out"))
        .output()
        .unwrap();
    assert_eq!(
        run.status.code(),
        Some(2),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    assert_eq!(
        check.status.code(),
        run.status.code(),
        "{}",
        String::from_utf8_lossy(&check.stdout)
    );
}

#[test]
fn slips_in_names_and_units_are_named() {
    let dir = tmp("slips");
    // a liquid named in the wrong case: refused, with the name meant
    let scene = scene_file(
        &dir,
        &SMALL.replace("liquid = \"matte\"", "liquid = \"Matte\""),
    );
    let out = verify().arg("check").arg(&scene).output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("did you mean \"matte\""), "{err}");
    // a finished run is not resumed: the message says it is finished
    let scene = scene_file(&dir, SMALL);
    let run = dir.join("run");
    assert!(verify()
        .arg("run")
        .arg(&scene)
        .arg("--out")
        .arg(&run)
        .quiet()
        .unwrap()
        .success());
    let again = verify()
        .arg("run")
        .arg("--resume")
        .arg(&run)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&again.stderr);
    assert_eq!(again.status.code(), Some(3), "{err}");
    assert!(err.contains("is finished: completed"), "{err}");
}

/// README's "Your first drop" as written: the same commands, on the same scene, end to end,
/// down to the measures of the run.
#[test]
fn the_readme_walkthrough_works_as_written() {
    let readme = include_str!("../../README.md");
    for line in [
        "target/release/verify check scenes/drop_on_plate.toml",
        "target/release/verify run scenes/drop_on_plate.toml --out /tmp/first --vtk 10",
        "target/release/verify measure /tmp/first",
    ] {
        assert!(readme.contains(line), "README no longer says `{line}`");
    }
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let scene = root.join("scenes/drop_on_plate.toml");
    let check = verify().arg("check").arg(&scene).output().unwrap();
    let text = String::from_utf8_lossy(&check.stdout);
    assert!(
        check.status.success() && text.contains("no findings"),
        "{text}"
    );
    let out = tmp("walkthrough");
    assert!(verify()
        .arg("run")
        .arg(&scene)
        .arg("--out")
        .arg(&out)
        .arg("--vtk")
        .arg("10")
        .quiet()
        .unwrap()
        .success());
    for f in [
        "timeseries.csv",
        "run_info.json",
        "particles.pvd",
        "walls.vtu",
    ] {
        assert!(out.join(f).exists(), "{f}");
    }
    let measure = verify().arg("measure").arg(&out).output().unwrap();
    let err = String::from_utf8_lossy(&measure.stderr);
    assert!(measure.status.success(), "{err}");
    assert!(
        err.contains("Young–Laplace for the scene's volume"),
        "{err}"
    );
    let csv = std::fs::read_to_string(out.join("measures.csv")).unwrap();
    // the header and one row per snapshot (11: t = 0, 5, …, 50 ms), the last one on the plate
    // with a wetted radius, a fitted angle and its bound
    let rows: Vec<&str> = csv.lines().collect();
    assert_eq!(rows.len(), 12, "{csv}");
    let last: Vec<&str> = rows[11].split(',').collect();
    for col in [7, 9, 10] {
        let v = last[col];
        assert!(
            v.parse::<f64>().is_ok_and(f64::is_finite),
            "column {col}: {v}"
        );
    }
    for f in ["measures_size.png", "measures_angle.png"] {
        assert!(out.join(f).exists(), "{f}");
    }
    let _ = std::fs::remove_dir_all(&out);
}

/// `verify list | head`: the listing ends on the closed pipe without a panic.
#[test]
fn a_reader_that_stops_early_ends_the_listing_without_a_panic() {
    // the reader closes its end before the listing starts (it fits in a pipe's buffer, so a
    // reader that took a line first would see no closed pipe): every write then meets EPIPE
    let mut child = verify()
        .arg("list")
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take());
    let out = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!err.contains("panicked"), "{err}");
}

/// The documented diagnostics and listing commands run and print their tables.
#[test]
fn diagnostics_and_list_print_their_tables() {
    for (args, expect) in [
        (vec!["list"], "convergence"),
        (
            vec!["lattice-moduli", "--h", "1.05", "--re", "4.2"],
            "G44 total",
        ),
        (vec!["surface-stress"], "potential f/γ"),
        (
            vec!["surface-stress", "--kernel", "quintic-spline", "--h", "1.3"],
            "| quintic_spline | 1.3 |",
        ),
    ] {
        let out = verify().args(&args).output().unwrap();
        let text = String::from_utf8_lossy(&out.stdout);
        assert!(
            out.status.success() && text.contains(expect),
            "{args:?}: {text}"
        );
    }
}

#[test]
fn a_run_keeps_its_findings_in_its_record() {
    let dir = tmp("warned");
    let scene = scene_file(&dir, SMALL);
    let out = dir.join("out");
    assert!(verify()
        .arg("run")
        .arg(&scene)
        .arg("--out")
        .arg(&out)
        .quiet()
        .unwrap()
        .success());
    let info: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("run_info.json")).unwrap()).unwrap();
    let warnings = info["warnings"]
        .as_array()
        .expect("the 4-spacing drop is recorded");
    assert!(warnings
        .iter()
        .any(|w| w.as_str().unwrap().starts_with("resolution of body drop")));
}

/// The `.vtu` snapshots of `out`, read back by an independent reader (vtkio): `n` points each,
/// the point data with their components, a matte's density; and the `.pvd` collection naming
/// them at their times.
fn check_snapshots(out: &std::path::Path, n: usize) {
    use vtkio::model::{Attribute, DataSet};
    for k in 0..3 {
        let vtk = vtkio::Vtk::import(out.join(format!("particles_{k:06}.vtu"))).unwrap();
        let DataSet::UnstructuredGrid { pieces, .. } = vtk.data else {
            panic!("not an unstructured grid");
        };
        let piece = pieces
            .into_iter()
            .next()
            .unwrap()
            .into_loaded_piece_data(None)
            .unwrap();
        assert_eq!(piece.num_points(), n);
        let mut names = Vec::new();
        for a in piece.data.point {
            let Attribute::DataArray(a) = a else { continue };
            let comps = a.elem.num_comp() as usize;
            let values: Vec<f64> = a.data.cast_into().unwrap();
            assert_eq!(values.len(), n * comps, "{}", a.name);
            if a.name == "density_kg_m3" {
                assert!(
                    values.iter().all(|r| (r / 4500.0 - 1.0).abs() < 0.5),
                    "{values:?}"
                );
            }
            names.push((a.name, comps));
        }
        assert_eq!(
            names,
            [
                ("velocity_m_s".to_string(), 3),
                ("density_kg_m3".to_string(), 1),
                ("pressure_Pa".to_string(), 1),
                ("phase".to_string(), 1)
            ]
        );
        let points: Vec<f64> = piece.points.cast_into().unwrap();
        assert!(points.len() == 3 * n && points.iter().all(|x| x.abs() < 1e-3));
    }
    let pvd = std::fs::read_to_string(out.join("particles.pvd")).unwrap();
    for (k, t) in ["0e0", "1e-5", "2e-5"].iter().enumerate() {
        assert!(
            pvd.contains(&format!(
                "timestep=\"{t}\" part=\"0\" file=\"particles_{k:06}.vtu\""
            )),
            "{pvd}"
        );
    }
}
