//! Plans run as independent tasks give the serial results: the smoke suite's tasks run one by
//! one in a shuffled order, one of them stopped by SIGTERM (as a scheduler does at its time
//! limit) and run again, collect to a `summary.csv` byte-identical to `verify case`'s. Every
//! case but `convergence` (two thirds of the smoke suite's time, whose runs take the same path;
//! the nightly SLURM job collects the whole suite). Bad input to the plan commands is refused
//! with exit 2 and a message that names it.

mod common;

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

fn dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("verify-plan-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

use common::{verify, Quiet, SMALL};

/// The tasks' labels and folders of the plan in `plan`.
fn tasks(plan: &Path) -> Vec<(String, String)> {
    let text = std::fs::read_to_string(plan.join("plan.json")).unwrap();
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    v["tasks"]
        .as_array()
        .unwrap()
        .iter()
        .map(|t| {
            (
                t["label"].as_str().unwrap().to_string(),
                t["dir"].as_str().unwrap().to_string(),
            )
        })
        .collect()
}

/// 0..n in an order fixed by a small linear congruential generator (Fisher–Yates).
fn shuffled(n: usize) -> Vec<usize> {
    let mut v: Vec<usize> = (0..n).collect();
    let mut x: u64 = 0x5eed;
    for i in (1..n).rev() {
        x = x
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        v.swap(i, (x >> 33) as usize % (i + 1));
    }
    v
}

/// `verify plan sweep SMALL --set S … --out OUT` (`plan`) or `verify sweep …` (the same, run).
fn sweep(scene: &Path, sets: &[&str], out: &Path, plan: bool) -> Command {
    let mut c = verify();
    if plan {
        c.args(["plan", "sweep"]);
    } else {
        c.arg("sweep");
    }
    c.arg(scene);
    for s in sets {
        c.args(["--set", s]);
    }
    c.arg("--out").arg(out).stdout(Stdio::null());
    c
}

/// The exit code and stderr of `c`.
fn stderr_of(c: &mut Command) -> (Option<i32>, String) {
    let o = c.output().unwrap();
    (
        o.status.code(),
        String::from_utf8_lossy(&o.stderr).to_string(),
    )
}

fn task(plan: &Path, index: usize) -> Command {
    let mut c = verify();
    c.arg("task")
        .arg(plan)
        .args(["--index", &index.to_string(), "--threads", "2"]);
    c
}

/// The smoke suite's cases but `convergence`.
const CASES: [&str; 12] = [
    "cube_drop",
    "drop_oscillation",
    "shear_wave",
    "equal_doublet",
    "matte_slag_doublet",
    "plate_eq23",
    "water_oil_teflon",
    "water_drop_impact",
    "water_incline",
    "aluminium_on_alumina",
    "iron_on_alumina",
    "hard_cases",
];

#[test]
fn smoke_suite_tasks_in_any_order_one_stopped_by_sigterm_collect_to_the_serial_summary() {
    // a case added to the suite is added here
    let list = verify()
        .args(["list", "--fidelity", "smoke"])
        .output()
        .unwrap();
    let listed: Vec<String> = String::from_utf8_lossy(&list.stdout)
        .lines()
        .filter(|l| !l.starts_with(' '))
        .filter_map(|l| l.split_whitespace().next().map(String::from))
        .filter(|c| c != "convergence")
        .collect();
    assert_eq!(listed, CASES, "the cases this test runs");
    let base = dir("suite");
    let serial = base.join("serial");
    let st = verify()
        .arg("case")
        .args(CASES)
        .args(["--fidelity", "smoke", "--threads", "2"])
        .arg("--out")
        .arg(&serial)
        .stderr(Stdio::null())
        .quiet()
        .unwrap();
    assert!(st.success());

    let plan = base.join("plan");
    let st = verify()
        .args(["plan", "suite", "--fidelity", "smoke"])
        .args(CASES)
        .arg("--out")
        .arg(&plan)
        .stdout(Stdio::null())
        .quiet()
        .unwrap();
    assert!(st.success());
    for f in ["run.sbatch", "submit.sh"] {
        assert!(plan.join(f).exists(), "{f}");
    }
    let list = tasks(&plan);
    // the longest smoke run (about 9 s on 2 cores) is the one stopped
    let stopped = list
        .iter()
        .position(|(l, _)| l == "equal_doublet/sigma12_0.40")
        .expect("the task exists");
    for i in shuffled(list.len()) {
        if i != stopped {
            let st = task(&plan, i).stderr(Stdio::null()).quiet().unwrap();
            assert!(st.success(), "task {i} ({})", list[i].0);
            continue;
        }
        let run_dir = plan.join(&list[i].1);
        let mut child = task(&plan, i)
            .args(["--checkpoint-minutes", "0.0002"])
            .stderr(Stdio::null())
            .spawn()
            .unwrap();
        let t0 = Instant::now();
        while !run_dir.join("checkpoint.bin").exists() {
            assert!(t0.elapsed() < Duration::from_secs(120), "no checkpoint");
            assert!(
                child.try_wait().unwrap().is_none(),
                "ended before a checkpoint"
            );
            std::thread::sleep(Duration::from_millis(5));
        }
        std::thread::sleep(Duration::from_millis(300));
        Command::new("kill")
            .args(["-TERM", &child.id().to_string()])
            .status()
            .unwrap();
        assert_eq!(child.wait().unwrap().code(), Some(130), "SIGTERM exits 130");
        let info = std::fs::read_to_string(run_dir.join("run_info.json")).unwrap();
        assert!(info.contains("\"status\": \"interrupted\""), "{info}");
    }

    // collected with one task stopped: its case is measured without it, and it is named
    let out = verify().arg("collect").arg(&plan).output().unwrap();
    assert_eq!(out.status.code(), Some(5));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("1 task(s) not finished") && err.contains("equal_doublet/sigma12_0.40"),
        "{err}"
    );

    // run again: resumed from its checkpoint
    let out = task(&plan, stopped).output().unwrap();
    assert!(out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("(resumed)"));
    // a finished task is skipped: nothing simulated, nothing printed about a run
    let out = task(&plan, stopped).output().unwrap();
    assert!(out.status.success());
    assert!(!String::from_utf8_lossy(&out.stderr).contains(&list[stopped].0));

    let st = verify().arg("collect").arg(&plan).quiet().unwrap();
    assert_eq!(st.code(), Some(0));
    let a = std::fs::read(serial.join("summary.csv")).unwrap();
    let b = std::fs::read(plan.join("summary.csv")).unwrap();
    assert!(
        a == b,
        "the collected summary.csv differs from the serial one"
    );
    let _ = std::fs::remove_dir_all(&base);
}

#[test]
fn a_sweep_runs_every_combination_and_tabulates_them() {
    let base = dir("sweep");
    let scene = base.join("drop.toml");
    std::fs::write(&scene, SMALL).unwrap();
    let out = base.join("sweep");
    let sets = ["liquid.matte.surface_tension=0.3,0.5", "time.end=1e-4,2e-4"];
    let st = sweep(&scene, &sets, &out, false)
        .args(["--threads", "2"])
        .stderr(Stdio::null())
        .quiet()
        .unwrap();
    assert_eq!(st.code(), Some(0));
    let mut rdr = csv::Reader::from_path(out.join("sweep.csv")).unwrap();
    let h = rdr.headers().unwrap().clone();
    let col = |n: &str| h.iter().position(|c| c == n).unwrap();
    let rows: Vec<csv::StringRecord> = rdr.records().map(|r| r.unwrap()).collect();
    assert_eq!(rows.len(), 4);
    let (sigma, end) = (col("liquid.matte.surface_tension"), col("time.end"));
    let (status, t) = (col("status"), col("simulated_time_s"));
    assert_eq!((&rows[1][sigma], &rows[1][end]), ("0.3", "0.0002"));
    for r in &rows {
        assert_eq!(&r[status], "completed");
        let want: f64 = r[end].parse().unwrap();
        let got: f64 = r[t].parse().unwrap();
        assert!((got - want).abs() < 1e-12, "ran to its own end time");
    }
    // the same sweep again: every task finished, nothing run, same table
    let before = std::fs::read(out.join("sweep.csv")).unwrap();
    let st = sweep(&scene, &sets, &out, false)
        .stderr(Stdio::null())
        .quiet()
        .unwrap();
    assert_eq!(st.code(), Some(0));
    assert_eq!(before, std::fs::read(out.join("sweep.csv")).unwrap());
    let _ = std::fs::remove_dir_all(&base);
}

#[test]
fn bad_input_to_the_plan_commands_is_named_and_exits_2() {
    let base = dir("errors");
    let scene = base.join("drop.toml");
    std::fs::write(&scene, SMALL).unwrap();
    // a key the scene does not have, found before anything runs
    let p = base.join("p");
    let (code, err) = stderr_of(&mut sweep(
        &scene,
        &["liquid.matte.surface_tensio=0.3,0.4"],
        &p,
        true,
    ));
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("surface_tensio"), "{err}");
    // a liquid that is not in the scene names the ones that are
    let (code, err) = stderr_of(&mut sweep(&scene, &["liquid.slag.viscosity=0.1"], &p, true));
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("`matte`"), "{err}");
    // a missing plan, and an index out of range
    let (code, err) = stderr_of(
        verify()
            .arg("task")
            .arg(base.join("none"))
            .args(["--index", "0"]),
    );
    assert_eq!(code, Some(2));
    assert!(err.contains("no plan"), "{err}");
    let plan = p;
    let mut st = sweep(&scene, &["time.end=1e-4,2e-4"], &plan, true);
    assert!(st.quiet().unwrap().success());
    let (code, err) = stderr_of(verify().arg("task").arg(&plan).args(["--index", "2"]));
    assert_eq!(code, Some(2));
    assert!(err.contains("the plan has 2 task(s), 0 to 1"), "{err}");
    // an unknown case, and another plan in the same folder
    let (code, err) = stderr_of(
        verify()
            .args(["plan", "suite", "no_such_case", "--out"])
            .arg(base.join("q")),
    );
    assert_eq!(code, Some(2));
    assert!(err.contains("no_such_case"), "{err}");
    let (code, err) = stderr_of(&mut sweep(&scene, &["time.end=3e-4"], &plan, true));
    assert_eq!(code, Some(2));
    assert!(err.contains("holds another plan"), "{err}");
    // nothing collected yet: the tasks are named
    let (code, err) = stderr_of(verify().arg("collect").arg(&plan));
    assert_eq!(code, Some(5));
    assert!(err.contains("2 task(s) not finished"), "{err}");
    let _ = std::fs::remove_dir_all(&base);
}
