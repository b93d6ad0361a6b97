//! Property test of the scene reader and validator: valid scenes mutated at random (lines
//! deleted, duplicated or swapped; numbers replaced by negative, zero, huge, tiny, NaN or
//! infinite values; strings garbled; the text cut short) must never make the reader or the
//! simulation builder panic, and every refusal must name a field (or, for a syntax error, the
//! line). The counts of each outcome are printed (`cargo test -p solver fuzz -- --nocapture`).

use proptest::prelude::*;
use solver::{Scene, SceneError, SimError, Simulation};
use std::sync::atomic::{AtomicUsize, Ordering};

const BASES: [&str; 5] = [
    include_str!("../../../scenes/cube_drop.toml"),
    include_str!("../../../scenes/drop_in_host.toml"),
    include_str!("../../../scenes/drop_on_plate.toml"),
    include_str!("../../../scenes/matte_slag_doublet.toml"),
    r#"
[discretisation]
l0 = 2.0e-4
sound_speed = 10.0
[time]
end = 1.0e-3
output_interval = 1.0e-4
[effects]
interfacial_tension = true
gravity = [0.0, 0.0, -9.8]
[density]
scheme = "continuity"
reinit = "mls"
[[liquid]]
name = "a"
density = 1000.0
viscosity = 1.0e-3
surface_tension = 0.07
[[liquid]]
name = "b"
density = 900.0
viscosity = 0.05
surface_tension = 0.02
[[interface]]
liquids = ["a", "b"]
tension = 0.05
[[solid]]
name = "s"
contact_angles = { a = 100.0, b = 20.0 }
[[body]]
name = "drop"
shape = { kind = "ellipsoid", center = [0.0, 0.0, 1.1e-3], semi_axes = [1.0e-3, 8.0e-4, 1.0e-3] }
cut = { point = [0.0, 0.0, 1.1e-3], normal = [0.0, 0.0, 1.0], liquids = ["a", "b"] }
[[wall]]
name = "box"
solid = "s"
shape = { kind = "box", min = [-2.0e-3, -2.0e-3, 0.0], max = [2.0e-3, 2.0e-3, 4.0e-3], open_top = true }
"#,
];

const NUMBERS: [&str; 12] = [
    "-1.0", "0.0", "0", "1e300", "1e-300", "nan", "inf", "-inf", "180.0", "3", "-7", "1.0e-9",
];
const STRINGS: [&str; 6] = ["\"\"", "\"x\"", "\"a\"", "\"matte\"", "\"sphere\"", "\"€\""];

static OK: AtomicUsize = AtomicUsize::new(0);
static PARSE: AtomicUsize = AtomicUsize::new(0);
static INVALID: AtomicUsize = AtomicUsize::new(0);
static BUILD_ERR: AtomicUsize = AtomicUsize::new(0);

/// Applies mutation `kind` at position `at` (both arbitrary) to `text`.
fn mutate(text: &str, kind: u8, at: usize, pick: usize) -> String {
    let lines: Vec<&str> = text.lines().collect();
    if lines.is_empty() {
        return text.to_string();
    }
    let n = lines.len();
    let i = at % n;
    let mut v: Vec<String> = lines.iter().map(|s| s.to_string()).collect();
    match kind % 6 {
        0 => {
            v.remove(i);
        }
        1 => v.insert(i, lines[i].to_string()),
        2 => v.swap(i, (i + pick) % n),
        3 => {
            // replace the first number on the line
            let l = &v[i];
            if let Some(start) = l.find(|c: char| c.is_ascii_digit() || c == '-') {
                let end = l[start..]
                    .find(|c: char| {
                        !(c.is_ascii_alphanumeric() || c == '.' || c == '-' || c == '+')
                    })
                    .map_or(l.len(), |e| start + e);
                v[i] = format!(
                    "{}{}{}",
                    &l[..start],
                    NUMBERS[pick % NUMBERS.len()],
                    &l[end..]
                );
            }
        }
        4 => {
            let l = &v[i];
            if let (Some(a), Some(b)) = (l.find('"'), l.rfind('"')) {
                if b > a {
                    v[i] = format!(
                        "{}{}{}",
                        &l[..a],
                        STRINGS[pick % STRINGS.len()],
                        &l[b + 1..]
                    );
                }
            }
        }
        _ => {
            let cut = (at % text.len().max(1)).min(text.len());
            let cut = (0..=cut)
                .rev()
                .find(|&c| text.is_char_boundary(c))
                .unwrap_or(0);
            return text[..cut].to_string();
        }
    }
    v.join("\n")
}

fn check(text: &str) {
    match Scene::from_toml_str(text) {
        Err(SceneError::Parse(msg)) => {
            assert!(!msg.is_empty());
            PARSE.fetch_add(1, Ordering::Relaxed);
        }
        Err(SceneError::Invalid { field, message, .. }) => {
            assert!(!field.is_empty() && !message.is_empty());
            INVALID.fetch_add(1, Ordering::Relaxed);
        }
        Ok(scene) => {
            // build only what is small enough to build in a test
            let l0 = scene.discretisation.l0;
            let volume: f64 = scene
                .bodies
                .iter()
                .map(|b| {
                    let (lo, hi) = b.shape.bounds();
                    (0..3).map(|k| hi[k] - lo[k]).product::<f64>()
                })
                .sum();
            if volume / l0.powi(3) < 3.0e4 && scene.walls.iter().all(|_| (1e-3 / l0) < 60.0) {
                match Simulation::new(&scene) {
                    Ok(_) => OK.fetch_add(1, Ordering::Relaxed),
                    Err(SimError::Scene(SceneError::Invalid { field, .. })) => {
                        assert!(!field.is_empty());
                        BUILD_ERR.fetch_add(1, Ordering::Relaxed)
                    }
                    Err(e) => {
                        assert!(!e.to_string().is_empty());
                        BUILD_ERR.fetch_add(1, Ordering::Relaxed)
                    }
                };
            } else {
                OK.fetch_add(1, Ordering::Relaxed);
            }
        }
    }
}

#[test]
fn mutated_scenes_never_panic() {
    use proptest::test_runner::{Config, TestRunner};
    let mut runner = TestRunner::new(Config {
        cases: 1000,
        failure_persistence: None,
        ..Config::default()
    });
    let strategy = (
        0usize..BASES.len(),
        proptest::collection::vec((any::<u8>(), any::<usize>(), any::<usize>()), 1..4),
    );
    runner
        .run(&strategy, |(base, muts)| {
            let mut text = BASES[base].to_string();
            for (kind, at, pick) in muts {
                text = mutate(&text, kind, at, pick);
            }
            check(&text);
            Ok(())
        })
        .unwrap();
    println!(
        "scene fuzzing: 1000 mutated scenes: {} accepted, {} syntax errors, {} invalid values, {} refused when built",
        OK.load(Ordering::Relaxed),
        PARSE.load(Ordering::Relaxed),
        INVALID.load(Ordering::Relaxed),
        BUILD_ERR.load(Ordering::Relaxed)
    );
}
