//! Known misses of the model (`reference/known_misses.toml`, compiled in): failing metrics whose
//! cause is measured and documented. `summary.md` labels them, so a new failure stands out.

use crate::suite::Metric;
use serde::Deserialize;
use std::sync::OnceLock;

static TEXT: &str = include_str!("../../../reference/known_misses.toml");

/// One documented miss: the metrics of a case it covers, why, and where it is measured.
#[derive(Clone, Debug, Deserialize, PartialEq)]
pub struct KnownMiss {
    /// Case name.
    pub case: String,
    /// Prefixes of the metric names it covers.
    pub metrics: Vec<String>,
    /// Why the metric misses.
    pub reason: String,
    /// Where the measurement behind it is documented.
    pub r#where: String,
}

#[derive(Deserialize)]
struct File {
    miss: Vec<KnownMiss>,
}

/// Every known miss.
pub fn all() -> &'static [KnownMiss] {
    static T: OnceLock<Vec<KnownMiss>> = OnceLock::new();
    T.get_or_init(|| {
        toml::from_str::<File>(TEXT)
            .expect("reference/known_misses.toml is valid (tested)")
            .miss
    })
}

impl KnownMiss {
    /// Whether `m` is one of the metrics this miss covers.
    pub fn covers(&self, m: &Metric) -> bool {
        m.case == self.case && self.metrics.iter().any(|p| m.name.starts_with(p.as_str()))
    }
}

/// The known miss that covers `m`, if `m` fails.
pub fn known(m: &Metric) -> Option<&'static KnownMiss> {
    if m.pass() != Some(false) {
        return None;
    }
    all().iter().find(|k| k.covers(m))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::suite::Tolerance;

    #[test]
    fn the_list_parses_and_every_entry_says_why() {
        // that each names a real case: tests/suite_smoke.rs (cases sit above report)
        assert!(!all().is_empty());
        for k in all() {
            assert!(!k.metrics.is_empty() && !k.reason.is_empty() && !k.r#where.is_empty());
        }
    }

    #[test]
    fn only_a_failing_metric_of_a_listed_prefix_is_known() {
        let m = |name: &str, value: f64| {
            Metric::new("drop_oscillation", name, "ms", value)
                .against(7.45, Tolerance::absolute(0.22, "t"))
        };
        assert!(known(&m("period ε=0.10", 5.59)).is_some());
        assert!(
            known(&m("period ε=0.10", 7.45)).is_none(),
            "a pass is not a miss"
        );
        assert!(known(&m("lattice shear modulus G44", 5.59)).is_none());
        let other = Metric::new("cube_drop", "period ε=0.10", "ms", 5.59)
            .against(7.45, Tolerance::absolute(0.22, "t"));
        assert!(known(&other).is_none(), "the prefix is per case");
    }
}
