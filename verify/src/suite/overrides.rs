//! Scene keys set from the command line (`--set discretisation.kernel=quintic_spline`): every
//! run of a case with one setting changed, e.g. to compare a kernel or a potential on the
//! checks. A number indexes an array of tables (`liquid.0.viscosity=0.0`). The value is read
//! as TOML (`1.3`, `true`, `"text"`); a bare word that is not TOML is taken as a string. The changed scene is validated like a scene file, and each run's
//! record stores the scene it ran.

use solver::Scene;

/// One `KEY=VALUE`: a dotted path into the scene's tables and a TOML value.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneOverride {
    /// Dotted key, e.g. `discretisation.h_over_l0`.
    pub key: String,
    /// The value.
    pub value: toml::Value,
}

impl std::str::FromStr for SceneOverride {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        let (key, raw) = s
            .split_once('=')
            .ok_or_else(|| format!("`{s}`: expected KEY=VALUE"))?;
        let key = key.trim();
        if key.is_empty() || key.split('.').any(str::is_empty) {
            return Err(format!("`{s}`: an empty key or key part"));
        }
        let raw = raw.trim();
        let value = toml::from_str::<toml::Table>(&format!("v = {raw}"))
            .ok()
            .and_then(|mut t| t.remove("v"))
            .unwrap_or_else(|| toml::Value::String(raw.to_string()));
        Ok(SceneOverride {
            key: key.to_string(),
            value,
        })
    }
}

/// `scene` with every override applied in order; an unknown key or a bad value is refused
/// with the scene's own message.
pub fn apply(scene: &Scene, overrides: &[SceneOverride]) -> anyhow::Result<Scene> {
    if overrides.is_empty() {
        return Ok(scene.clone());
    }
    let mut root = toml::Value::Table(toml::Table::try_from(scene)?);
    for o in overrides {
        let mut v = &mut root;
        for p in o.key.split('.') {
            v = match v {
                toml::Value::Array(a) => {
                    let n = a.len();
                    p.parse::<usize>()
                        .ok()
                        .and_then(|k| a.get_mut(k))
                        .ok_or_else(|| {
                            anyhow::anyhow!("--set {}: `{p}` is not an index below {n}", o.key)
                        })?
                }
                toml::Value::Table(t) => t
                    .entry(p.to_string())
                    .or_insert_with(|| toml::Value::Table(toml::Table::new())),
                _ => anyhow::bail!("--set {}: `{p}` is inside a value, not a table", o.key),
            };
        }
        *v = o.value.clone();
    }
    let text = toml::to_string(&root)?;
    Scene::from_toml_str(&text).map_err(|e| anyhow::anyhow!("--set: {e}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scene() -> Scene {
        Scene::from_toml_str(include_str!("../../../scenes/cube_drop.toml")).expect("scene")
    }

    #[test]
    fn keys_are_set_and_checked() {
        let o: Vec<SceneOverride> = [
            "discretisation.kernel=quintic_spline",
            "discretisation.h_over_l0 = 1.3",
            "discretisation.potential_order=2",
            "effects.laminar_viscosity=true",
            "liquid.0.viscosity=0.0",
        ]
        .iter()
        .map(|s| s.parse().expect("parse"))
        .collect();
        let s = apply(&scene(), &o).expect("valid");
        let d = &s.discretisation;
        assert_eq!(d.kernel, solver::kernel::KernelKind::QuinticSpline);
        assert_eq!((d.h_over_l0, d.potential_order), (1.3, 2));
        assert!(s.effects.laminar_viscosity);
        assert_eq!(s.liquids[0].viscosity, 0.0);
        let bad: SceneOverride = "liquid.1.viscosity=0.0".parse().expect("parse");
        assert!(apply(&scene(), &[bad]).is_err());
        // nothing else changed
        assert_eq!(s.bodies, scene().bodies);
        // an unknown key and a bad value are the scene's errors
        let bad: SceneOverride = "discretisation.h_over_l=1.3".parse().expect("parse");
        assert!(apply(&scene(), &[bad]).is_err());
        let bad: SceneOverride = "discretisation.potential_order=7".parse().expect("parse");
        assert!(apply(&scene(), &[bad]).is_err());
        assert!("no_equals".parse::<SceneOverride>().is_err());
        assert!("a..b=1".parse::<SceneOverride>().is_err());
    }
}
