//! A user's sweep: one scene over every combination of values of some keys.

use super::{input_error, Kind, Planned};
use crate::suite::overrides::{self, SceneOverride};
use solver::Scene;
use std::path::PathBuf;

/// The tasks of `base` (read from `base_file`) over every combination of the values in `set`
/// (`KEY=V1,V2,…` each; the last key varies fastest). A key that is not in the scene, a bad
/// value, or a combination the scene refuses is an input error, found before anything runs.
pub fn sweep_tasks(
    base: &Scene,
    base_file: &str,
    set: &[String],
) -> anyhow::Result<(Kind, Vec<Planned>)> {
    if set.is_empty() {
        return Err(input_error(
            "a sweep needs at least one --set KEY=V1,V2,…".into(),
        ));
    }
    let axes: Vec<Vec<SceneOverride>> = set
        .iter()
        .map(|s| overrides::parse_values(s).map_err(input_error))
        .collect::<anyhow::Result<_>>()?;
    let mut combos: Vec<Vec<SceneOverride>> = vec![Vec::new()];
    for axis in &axes {
        combos = combos
            .iter()
            .flat_map(|c| {
                axis.iter().map(move |v| {
                    let mut c = c.clone();
                    c.push(v.clone());
                    c
                })
            })
            .collect();
    }
    let width = (combos.len() - 1).to_string().len().max(4);
    let mut tasks = Vec::new();
    for (k, combo) in combos.iter().enumerate() {
        let set: Vec<String> = combo.iter().map(ToString::to_string).collect();
        let label = set.join(" ");
        let scene = overrides::apply(base, combo)
            .map_err(|e| input_error(format!("{base_file} with {label}: {e:#}")))?;
        tasks.push(Planned {
            label,
            dir: PathBuf::from(format!("runs/{k:0width$}")),
            scene,
            set,
        });
    }
    let kind = Kind::Sweep {
        base: base_file.to_string(),
        set: set.to_vec(),
    };
    Ok((kind, tasks))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scene() -> Scene {
        Scene::from_toml_str(include_str!("../../../scenes/cube_drop.toml")).expect("scene")
    }

    #[test]
    fn every_combination_once_the_last_key_fastest() {
        let set = [
            "time.end=1e-3,2e-3".to_string(),
            "liquid.matte.surface_tension=0.3,0.4,0.5".to_string(),
        ];
        let (_, tasks) = sweep_tasks(&scene(), "cube.toml", &set).expect("plan");
        assert_eq!(tasks.len(), 6);
        assert_eq!(tasks[1].scene.liquids[0].surface_tension, Some(0.4));
        assert_eq!(tasks[1].scene.time.end, 1e-3);
        assert_eq!(tasks[5].scene.time.end, 2e-3);
        assert_eq!(
            tasks[5].label,
            "time.end=0.002 liquid.matte.surface_tension=0.5"
        );
        assert_eq!(tasks[5].dir, PathBuf::from("runs/0005"));
    }

    #[test]
    fn a_key_not_in_the_scene_is_refused_before_anything_runs() {
        let e = sweep_tasks(&scene(), "cube.toml", &["time.ende=1,2".to_string()])
            .expect_err("unknown key");
        assert!(e.downcast_ref::<super::super::InputError>().is_some());
        assert!(format!("{e:#}").contains("ende"), "{e:#}");
        assert!(sweep_tasks(&scene(), "cube.toml", &[]).is_err());
    }
}
