//! Scene keys set from the command line (`--set discretisation.kernel=quintic_spline`): every
//! run of a case with one setting changed, e.g. to compare a kernel or a potential on the
//! checks. A number indexes an array of tables (`liquid.0.viscosity=0.0`), and so does a name
//! (`liquid.matte.viscosity=0.0`: the table whose `name` it is). The value is read
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

impl std::fmt::Display for SceneOverride {
    /// `KEY=VALUE` with the value as TOML: parses back to the same override.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}={}", self.key, self.value)
    }
}

/// Splits the values of a sweep's `KEY=V1,V2,…` at the commas outside brackets and quotes
/// (`gravity=[0,0,-9.81],[0,0,0]` is two values); every value parsed as in [`SceneOverride`].
pub fn parse_values(s: &str) -> Result<Vec<SceneOverride>, String> {
    let (key, raw) = s
        .split_once('=')
        .ok_or_else(|| format!("`{s}`: expected KEY=VALUE[,VALUE…]"))?;
    let mut parts = Vec::new();
    let (mut depth, mut quote, mut start) = (0i32, None, 0);
    for (i, c) in raw.char_indices() {
        match (quote, c) {
            (Some(q), c) if c == q => quote = None,
            (Some(_), _) => {}
            (None, '"' | '\'') => quote = Some(c),
            (None, '[' | '{') => depth += 1,
            (None, ']' | '}') => depth -= 1,
            (None, ',') if depth == 0 => {
                parts.push(&raw[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    parts.push(&raw[start..]);
    if parts.iter().any(|p| p.trim().is_empty()) {
        return Err(format!("`{s}`: an empty value"));
    }
    parts.iter().map(|v| format!("{key}={v}").parse()).collect()
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
                    let names: Vec<String> = a
                        .iter()
                        .filter_map(|t| t.get("name").and_then(toml::Value::as_str))
                        .map(|n| format!("`{n}`"))
                        .collect();
                    let n = a.len();
                    let k = match p.parse::<usize>() {
                        Ok(k) => Some(k),
                        Err(_) => a
                            .iter()
                            .position(|t| t.get("name").and_then(toml::Value::as_str) == Some(p)),
                    };
                    k.and_then(|k| a.get_mut(k)).ok_or_else(|| {
                        anyhow::anyhow!(
                            "--set {}: `{p}` is neither an index below {n} nor a name ({})",
                            o.key,
                            if names.is_empty() {
                                "none".to_string()
                            } else {
                                names.join(", ")
                            }
                        )
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
    Scene::from_toml_str(&text).map_err(|e| {
        // an unknown key is reported by the key the user typed, not by a line of the
        // generated scene
        let msg = e.to_string();
        let unknown = |seg: &str| msg.contains(&format!("unknown field `{seg}`"));
        match overrides.iter().find(|o| o.key.split('.').any(unknown)) {
            Some(o) => {
                let why = msg
                    .lines()
                    .find(|l| l.contains("unknown field"))
                    .unwrap_or(&msg);
                anyhow::anyhow!("--set {}: {}", o.key, why.trim())
            }
            None => anyhow::anyhow!("--set: {e}"),
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scene() -> Scene {
        Scene::from_toml_str(include_str!("../../../scenes/cube_drop.toml")).expect("scene")
    }

    #[test]
    fn a_misspelt_key_is_reported_as_typed() {
        let o = parse_values("liquid.0.surface_tensio=0.3").unwrap();
        let e = apply(&scene(), &o).unwrap_err().to_string();
        assert!(
            e.starts_with("--set liquid.0.surface_tensio: unknown field `surface_tensio`")
                && e.contains("`surface_tension`")
                && !e.contains("line"),
            "{e}"
        );
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
        // a table of an array by its name; an unknown name lists the names
        let o: SceneOverride = "liquid.matte.viscosity=0.5".parse().expect("parse");
        assert_eq!(
            apply(&scene(), &[o]).expect("valid").liquids[0].viscosity,
            0.5
        );
        let bad: SceneOverride = "liquid.slag.viscosity=0.5".parse().expect("parse");
        let e = apply(&scene(), &[bad]).expect_err("no slag").to_string();
        assert!(e.contains("`matte`"), "{e}");
        assert!("a..b=1".parse::<SceneOverride>().is_err());
    }

    #[test]
    fn sweep_values_split_outside_brackets_and_quotes() {
        let v = parse_values("time.end=1e-3, 2e-3").expect("two");
        assert_eq!(v.len(), 2);
        assert_eq!(v[1].value, toml::Value::Float(2e-3));
        let v = parse_values("gravity=[0,0,-9.81],[0,0,0]").expect("two arrays");
        assert_eq!(v.len(), 2);
        assert!(v[0].value.is_array());
        let v = parse_values(r#"liquid.0.name="a,b",c"#).expect("quoted comma");
        assert_eq!(v[0].value, toml::Value::String("a,b".into()));
        assert_eq!(v.len(), 2);
        assert!(parse_values("a=1,,2").is_err());
        assert!(parse_values("a").is_err());
        // Display parses back to the same override
        for o in parse_values("discretisation.kernel=quintic_spline,2.5").expect("two") {
            assert_eq!(o.to_string().parse::<SceneOverride>().expect("back"), o);
        }
    }
}
