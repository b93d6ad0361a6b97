//! No run loses its data: a run stopped by Ctrl-C (SIGINT), by a scheduler (SIGTERM) or killed
//! outright (SIGKILL) is continued with `run --resume DIR` and ends with exactly the outputs of a
//! run never stopped.

mod common;
use common::Quiet;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

const SCENE: &str = r#"
[discretisation]
l0 = 1.0e-4
sound_speed = 12.0
[time]
end = 3.0e-3
output_interval = 1.0e-4
[effects]
interfacial_tension = true
laminar_viscosity = true
artificial_viscosity = {}
gravity = [0.0, 0.0, -9.81]
[[liquid]]
name = "matte"
density = 4500.0
viscosity = 3.13e-3
surface_tension = 0.4
[[solid]]
name = "alumina"
contact_angles = { matte = 60.0 }
[[body]]
name = "drop"
liquid = "matte"
shape = { kind = "sphere", center = [0.0, 0.0, 6.0e-4], radius = 5.0e-4 }
velocity = [0.0, 0.0, -0.3]
[[wall]]
name = "plate"
solid = "alumina"
shape = { kind = "disk", center = [0.0, 0.0, 0.0], radius = 1.5e-3 }
"#;

fn dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("verify-resume-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn verify() -> Command {
    Command::new(env!("CARGO_BIN_EXE_verify"))
}

fn run_to_end(scene: &Path, out: &Path) {
    let st = verify()
        .arg("run")
        .arg(scene)
        .arg("--out")
        .arg(out)
        .args(["--threads", "2"])
        .quiet()
        .unwrap();
    assert!(st.success());
}

/// Waits (at most 2 minutes) until `written` says a checkpoint exists; the process `child` must
/// not end before.
fn wait_for_checkpoint(child: &mut std::process::Child, written: impl Fn() -> bool) {
    let t0 = Instant::now();
    while !written() {
        assert!(
            t0.elapsed() < Duration::from_secs(120),
            "no checkpoint written"
        );
        if let Some(st) = child.try_wait().unwrap() {
            panic!("ended before a checkpoint: {st:?}");
        }
        std::thread::sleep(Duration::from_millis(5));
    }
}

/// Starts a run with frequent checkpoints and stops it with `signal` once a checkpoint exists.
fn run_and_stop(scene: &Path, out: &Path, signal: &str) -> Option<i32> {
    let mut child = verify()
        .arg("run")
        .arg(scene)
        .arg("--out")
        .arg(out)
        .args(["--threads", "2", "--checkpoint-steps", "40"])
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    wait_for_checkpoint(&mut child, || out.join("checkpoint.bin").exists());
    std::thread::sleep(Duration::from_millis(150));
    if signal == "KILL" {
        child.kill().unwrap();
    } else {
        Command::new("kill")
            .args([&format!("-{signal}"), &child.id().to_string()])
            .status()
            .unwrap();
    }
    child.wait().unwrap().code()
}

#[test]
fn interrupted_or_killed_runs_resume_to_the_same_bits() {
    let base = dir("base");
    let scene = base.join("scene.toml");
    std::fs::write(&scene, SCENE).unwrap();
    let whole = base.join("whole");
    run_to_end(&scene, &whole);
    let expected = std::fs::read(whole.join("timeseries.csv")).unwrap();

    for signal in ["INT", "TERM", "KILL"] {
        let out = base.join(format!("stopped-{signal}"));
        let code = run_and_stop(&scene, &out, signal);
        let partial = std::fs::read(out.join("timeseries.csv")).unwrap();
        if code.is_none() && partial == expected {
            continue; // the run finished before the signal arrived: nothing to resume
        }
        if signal != "KILL" {
            // Ctrl-C, and a scheduler's SIGTERM at its time limit
            assert_eq!(code, Some(130), "SIG{signal} exits with 130");
            let info = std::fs::read_to_string(out.join("run_info.json")).unwrap();
            assert!(info.contains("\"status\": \"interrupted\""), "{info}");
        }
        assert_ne!(partial, expected, "stopped before the end");
        let st = verify()
            .arg("run")
            .arg("--resume")
            .arg(&out)
            .args(["--threads", "1"])
            .quiet()
            .unwrap();
        assert!(st.success(), "{signal}: resume failed");
        let got = std::fs::read(out.join("timeseries.csv")).unwrap();
        assert!(
            got == expected,
            "{signal}: resumed time series differs from the uninterrupted one"
        );
        assert!(
            !out.join("checkpoint.bin").exists(),
            "a completed run removes its checkpoint"
        );
        let info = std::fs::read_to_string(out.join("run_info.json")).unwrap();
        assert!(info.contains("\"status\": \"completed\""));
    }
    // resuming where there is nothing to resume is a clear error
    let out = verify()
        .arg("run")
        .arg("--resume")
        .arg(base.join("nothing"))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(3));
    assert!(String::from_utf8_lossy(&out.stderr).contains("no run to resume"));
    let _ = std::fs::remove_dir_all(&base);
}

/// The files of every run of a case's folder: `(run/file, bytes)`, sorted; the records and
/// summaries (which hold wall times) left out.
fn run_files(case_dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut out = Vec::new();
    for run in std::fs::read_dir(case_dir).unwrap() {
        let run = run.unwrap().path();
        if !run.is_dir() {
            continue;
        }
        for f in std::fs::read_dir(&run).unwrap() {
            let f = f.unwrap().path();
            let name = f.file_name().unwrap().to_string_lossy().to_string();
            if name.ends_with(".csv") {
                let key = format!("{}/{name}", run.file_name().unwrap().to_string_lossy());
                out.push((key, std::fs::read(&f).unwrap()));
            }
        }
    }
    out.sort();
    out
}

#[test]
fn a_suite_stopped_by_sigterm_resumes_its_run_to_the_same_bits() {
    let base = dir("suite");
    let case = |out: &Path| {
        let mut c = verify();
        c.args(["case", "cube_drop", "--fidelity", "smoke", "--threads", "2"])
            .arg("--out")
            .arg(out)
            .args(["--checkpoint-minutes", "0.0002"])
            .stderr(Stdio::null());
        c
    };
    let whole = base.join("whole");
    assert!(case(&whole).quiet().unwrap().success());
    let stopped = base.join("stopped");
    let mut child = case(&stopped).spawn().unwrap();
    wait_for_checkpoint(&mut child, || {
        std::fs::read_dir(stopped.join("cube_drop")).is_ok_and(|d| {
            d.filter_map(|e| e.ok())
                .any(|e| e.path().join("checkpoint.bin").exists())
        })
    });
    Command::new("kill")
        .args(["-TERM", &child.id().to_string()])
        .status()
        .unwrap();
    let code = child.wait().unwrap().code();
    assert_eq!(code, Some(130), "a stopped suite exits with 130");
    assert_ne!(
        run_files(&whole.join("cube_drop")),
        run_files(&stopped.join("cube_drop"))
    );
    // the same command again resumes the stopped run and runs the rest
    assert!(case(&stopped).quiet().unwrap().success());
    let (a, b) = (
        run_files(&whole.join("cube_drop")),
        run_files(&stopped.join("cube_drop")),
    );
    assert_eq!(a.len(), b.len());
    for ((na, fa), (nb, fb)) in a.iter().zip(&b) {
        assert_eq!(na, nb);
        assert!(fa == fb, "{na} differs after the resumed suite");
    }
}
