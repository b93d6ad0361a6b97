//! Pre-flight checks on the shipped scenes: every case's runs at every fidelity trip no check
//! the case does not accept (and say why), and each example scene trips exactly the checks
//! listed here with the reason it keeps them.

use std::collections::BTreeSet;
use verify::preflight::{self, Check};
use verify::suite::Fidelity;

#[test]
fn every_case_run_trips_only_checks_its_case_accepts() {
    let mut unaccepted = Vec::new();
    for case in verify::cases::all() {
        for f in [Fidelity::Smoke, Fidelity::Standard, Fidelity::Paper] {
            let accepted = case.accepted_findings(f);
            for (c, why) in &accepted {
                assert!(
                    !why.trim().is_empty(),
                    "{}: {c:?} accepted without a reason",
                    case.name()
                );
            }
            for run in case.runs(f) {
                for finding in preflight::sort_out(&run.scene, &accepted).0 {
                    unaccepted.push(format!(
                        "{} ({}) {}: {finding}",
                        case.name(),
                        f.name(),
                        run.id
                    ));
                }
            }
        }
    }
    assert!(
        unaccepted.is_empty(),
        "{} findings not accepted:\n{}",
        unaccepted.len(),
        unaccepted.join("\n")
    );
}

#[test]
fn example_scenes_trip_only_the_listed_checks() {
    use Check::*;
    // (file, checks, why they stay)
    let expected: [(&str, &[Check], &str); 18] = [
        // the scale benchmarks at the default setting meet the sound-speed rules (stable runs)
        ("bench_cube_160k.toml", &[], ""),
        ("bench_cube_1m.toml", &[], ""),
        // the paper's cube at its c² = 150 m²/s²: the PySPH comparison, a step's cost
        (
            "bench_cube_20k.toml",
            &[CohesiveSoundSpeed, FlowSoundSpeed],
            "paper's c²",
        ),
        (
            "bench_cube_20k_default.toml",
            &[CohesiveSoundSpeed, FlowSoundSpeed],
            "paper's c²",
        ),
        (
            "cap_in_host.toml",
            &[Resolution],
            "the surface force's cap at R/l0 = 11, as measured in docs/findings.md",
        ),
        (
            "cube_drop.toml",
            &[CohesiveSoundSpeed, FlowSoundSpeed],
            "paper's c² (Table A-1 sweeps it)",
        ),
        ("drop_in_host.toml", &[], ""),
        ("drop_on_plate.toml", &[], ""),
        ("matte_slag_doublet.toml", &[], ""),
        ("two_liquids_continuity.toml", &[], ""),
        ("two_liquids_on_plate.toml", &[], ""),
        // hard cases are extreme on purpose (hard_cases documents each)
        (
            "hard/coarse_long_cutoff.toml",
            &[Resolution],
            "coarse on purpose",
        ),
        (
            "hard/extreme_contact_angles.toml",
            &[Resolution],
            "small drops on purpose",
        ),
        (
            "hard/iron_small.toml",
            &[CohesiveSoundSpeed],
            "iron at small scale, 1.1 %",
        ),
        ("hard/point_contact.toml", &[Resolution], "two small drops"),
        ("hard/resting_drop.toml", &[Resolution], "1e5 cheap steps"),
        ("hard/splash.toml", &[], ""),
        (
            "hard/viscosity_ratio.toml",
            &[Resolution],
            "two small drops",
        ),
    ];
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenes");
    let mut shipped: BTreeSet<String> = BTreeSet::new();
    for sub in ["", "hard/"] {
        for e in std::fs::read_dir(dir.join(sub)).unwrap() {
            let name = e.unwrap().file_name().into_string().unwrap();
            if name.ends_with(".toml") {
                shipped.insert(format!("{sub}{name}"));
            }
        }
    }
    let listed: BTreeSet<String> = expected.iter().map(|(f, _, _)| f.to_string()).collect();
    assert_eq!(shipped, listed, "every example scene is listed here");
    for (file, checks, _) in expected {
        let scene = verify::run::load_scene(&dir.join(file)).unwrap();
        let found: BTreeSet<Check> = preflight::check(&scene).iter().map(|f| f.check).collect();
        let want: BTreeSet<Check> = checks.iter().copied().collect();
        assert_eq!(found, want, "{file}");
    }
}

#[test]
fn a_water_drop_typed_in_mn_per_m_is_refused_under_strict() {
    let text = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenes/drop_on_plate.toml"),
    )
    .unwrap();
    let mut scene = solver::Scene::from_toml_str(&text).unwrap();
    scene.liquids[0].surface_tension = Some(72.8);
    let out = std::env::temp_dir().join(format!("verify-preflight-{}", std::process::id()));
    let opts = verify::run::RunOptions {
        out_dir: out.clone(),
        strict: true,
        ..Default::default()
    };
    let e = verify::run::run_scene(&scene, std::path::Path::new("slip.toml"), &opts).unwrap_err();
    let text = e.to_string();
    assert!(
        text.contains("72.8 mN/m") && text.contains("7.28e-2"),
        "{text}"
    );
    assert!(!out.exists(), "refused before the output folder is made");
}

/// The scene of `scripts/python_example.sh` (a documented example, run by the nightly job with
/// `--strict`) trips no check.
#[test]
fn the_python_example_passes_its_own_preflight() {
    let script = include_str!("../../scripts/python_example.sh");
    let start = script.find("<<'TOML'\n").expect("the example's scene") + "<<'TOML'\n".len();
    let end = start + script[start..].find("\nTOML\n").expect("its end");
    let scene = solver::Scene::from_toml_str(&script[start..end]).expect("a valid scene");
    let findings = preflight::check(&scene);
    assert!(findings.is_empty(), "{findings:?}");
}
