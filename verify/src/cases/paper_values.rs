//! The papers' own simulated values, from `reference/paper_values.toml` (compiled in).

use std::sync::OnceLock;

static TEXT: &str = include_str!("../../../reference/paper_values.toml");

fn table() -> &'static toml::Table {
    static T: OnceLock<toml::Table> = OnceLock::new();
    T.get_or_init(|| {
        TEXT.parse()
            .expect("reference/paper_values.toml is valid TOML (tested)")
    })
}

/// A number `section.key`.
pub fn number(section: &str, key: &str) -> Option<f64> {
    table().get(section)?.get(key)?.as_float()
}

/// A list `section.key`.
pub fn list(section: &str, key: &str) -> Vec<f64> {
    table()
        .get(section)
        .and_then(|s| s.get(key))
        .and_then(|v| v.as_array())
        .map(|a| a.iter().filter_map(|x| x.as_float()).collect())
        .unwrap_or_default()
}

/// The value of `key` at the entry of `at_key` equal to `at` (e.g. the period at c² = 150).
pub fn lookup(section: &str, at_key: &str, at: f64, key: &str) -> Option<f64> {
    let xs = list(section, at_key);
    let ys = list(section, key);
    xs.iter()
        .position(|&x| (x - at).abs() < 1e-9 * x.abs().max(1.0))
        .and_then(|k| ys.get(k).copied())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paper_values_parse_and_pair_up() {
        assert_eq!(
            list("cube_drop", "c2_m2_s2").len(),
            list("cube_drop", "period_ms").len()
        );
        assert_eq!(
            lookup("cube_drop", "c2_m2_s2", 150.0, "period_ms"),
            Some(1.24)
        );
        assert_eq!(number("water_oil_teflon", "theta12_deg"), Some(147.3));
        assert_eq!(lookup("cube_drop", "c2_m2_s2", 151.0, "period_ms"), None);
    }
}
