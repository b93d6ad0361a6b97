//! A measured quantity with its reference, the paper's own value, and its tolerance.

use serde::{Deserialize, Serialize};

/// How far a metric may lie from its reference, and why.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Tolerance {
    /// Largest accepted `|value − reference|`, in the metric's unit (NaN, `null` in JSON, fails
    /// every value).
    #[serde(with = "nan_as_null")]
    pub abs: f64,
    /// Where the tolerance comes from.
    pub source: String,
}

impl Tolerance {
    /// A tolerance of `abs`, in the metric's unit.
    pub fn absolute(abs: f64, source: impl Into<String>) -> Self {
        Tolerance {
            abs,
            source: source.into(),
        }
    }

    /// No tolerance: the value must equal its reference (a count, or a yes/no check).
    pub fn exact(source: impl Into<String>) -> Self {
        Tolerance::absolute(0.0, source)
    }

    /// A tolerance of `fraction` of the reference's magnitude.
    pub fn relative(fraction: f64, reference: f64, source: impl Into<String>) -> Self {
        Tolerance {
            abs: fraction * reference.abs(),
            source: source.into(),
        }
    }
}

/// JSON has no NaN: a value that could not be measured is written as `null` and read back as NaN.
mod nan_as_null {
    use serde::{Deserialize, Deserializer, Serializer};

    pub fn serialize<S: Serializer>(v: &f64, s: S) -> Result<S::Ok, S::Error> {
        if v.is_finite() {
            s.serialize_f64(*v)
        } else {
            s.serialize_none()
        }
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
        Ok(Option::<f64>::deserialize(d)?.unwrap_or(f64::NAN))
    }
}

/// One row of a report.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Metric {
    /// Case name.
    pub case: String,
    /// Metric name, unique within the case (e.g. `period c2=150`).
    pub name: String,
    /// Unit of value, reference, paper value and tolerance.
    pub unit: String,
    /// This project's value (NaN if it could not be measured; `null` in JSON).
    #[serde(with = "nan_as_null")]
    pub value: f64,
    /// The analytic reference, computed by the code.
    pub reference: Option<f64>,
    /// The value the paper's own simulation reached.
    pub paper: Option<f64>,
    /// The acceptance tolerance against the reference.
    pub tolerance: Option<Tolerance>,
    /// Fluid particles of the run measured.
    pub particles: usize,
    /// Wall time of the run [s].
    pub wall_time_s: f64,
    /// What the number means, how it was measured, or why it missed.
    pub note: String,
    /// Whether the run measured reached its end time (`true` for a metric of no one run): a
    /// metric of a run that stopped early fails whatever its value.
    #[serde(default = "yes", skip_serializing_if = "is_yes")]
    pub run_completed: bool,
}

fn yes() -> bool {
    true
}

fn is_yes(b: &bool) -> bool {
    *b
}

impl Metric {
    /// A metric without reference (reported, not judged).
    pub fn new(case: &str, name: impl Into<String>, unit: &str, value: f64) -> Self {
        Metric {
            case: case.to_string(),
            name: name.into(),
            unit: unit.to_string(),
            value,
            reference: None,
            paper: None,
            tolerance: None,
            particles: 0,
            wall_time_s: 0.0,
            note: String::new(),
            run_completed: true,
        }
    }

    /// A yes/no check: 1 if `ok`, else 0, judged against 1 with no tolerance, for the reason
    /// `source`.
    pub fn check(
        case: &str,
        name: impl Into<String>,
        unit: &str,
        ok: bool,
        source: impl Into<String>,
    ) -> Self {
        Metric::new(case, name, unit, f64::from(u8::from(ok)))
            .against(1.0, Tolerance::exact(source))
    }

    /// With an analytic reference and its tolerance.
    pub fn against(mut self, reference: f64, tolerance: Tolerance) -> Self {
        self.reference = Some(reference);
        self.tolerance = Some(tolerance);
        self
    }

    /// With an analytic reference, judged where the measurement has an error bound
    /// (`Some`); where it has none the reference stands beside the value, unjudged, and the
    /// note says why. Call it after [`Metric::note`], which replaces the note.
    pub fn against_if(self, reference: f64, tolerance: Option<Tolerance>) -> Self {
        match tolerance {
            Some(t) => self.against(reference, t),
            None => self.beside(
                reference,
                "no error bound of the measurement at this resolution",
            ),
        }
    }

    /// With an analytic reference beside the value, not judged, the note ending with `why`.
    /// Call it after [`Metric::note`], which replaces the note.
    pub fn beside(mut self, reference: f64, why: &str) -> Self {
        self.reference = Some(reference);
        let why = format!("{why}: not judged");
        self.note = if self.note.is_empty() {
            why
        } else {
            format!("{}; {why}", self.note)
        };
        self
    }

    /// With the paper's own value.
    pub fn paper(mut self, value: Option<f64>) -> Self {
        self.paper = value;
        self
    }

    /// With the run's size and cost.
    pub fn run(mut self, run: &super::RunData) -> Self {
        self.particles = run.info.fluid_particles;
        self.wall_time_s = run.info.wall_time_s;
        self.run_completed = run.completed();
        self
    }

    /// With a note.
    pub fn note(mut self, note: impl Into<String>) -> Self {
        self.note = note.into();
        self
    }

    /// `value − reference`, if there is a reference.
    pub fn error(&self) -> Option<f64> {
        self.reference.map(|r| self.value - r)
    }

    /// Pass/fail against the tolerance, if there is one (a NaN value fails, and so does any
    /// value of a run that stopped early: its last state is not the settled one the metric
    /// judges).
    pub fn pass(&self) -> Option<bool> {
        let err = self.error()?;
        let tol = self.tolerance.as_ref()?;
        Some(self.run_completed && err.is_finite() && err.abs() <= tol.abs)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_reference_without_a_bound_is_shown_and_not_judged() {
        let m = Metric::new("c", "m", "deg", 10.0)
            .note("fit")
            .against_if(12.0, None);
        assert_eq!(
            (m.reference, m.pass(), m.error()),
            (Some(12.0), None, Some(-2.0))
        );
        assert!(m.note.starts_with("fit; ") && m.note.ends_with("not judged"));
        let t = Tolerance::absolute(3.0, "t");
        assert_eq!(
            Metric::new("c", "m", "deg", 10.0)
                .against_if(12.0, Some(t))
                .pass(),
            Some(true)
        );
    }

    #[test]
    fn a_value_of_a_run_that_stopped_early_fails_and_says_so_in_json() {
        let t = Tolerance::absolute(2.0, "t");
        let mut m = Metric::new("c", "cap", "deg", 120.0).against(120.0, t);
        assert_eq!(m.pass(), Some(true));
        // a completed run's metric is written as before: no new field
        assert!(!serde_json::to_string(&m).unwrap().contains("run_completed"));
        m.run_completed = false;
        assert_eq!(m.pass(), Some(false));
        let back: Metric = serde_json::from_str(&serde_json::to_string(&m).unwrap()).unwrap();
        assert_eq!((back.run_completed, back.pass()), (false, Some(false)));
    }

    #[test]
    fn unmeasured_values_survive_json() {
        let m = Metric::new("c", "m", "deg", f64::NAN).against(
            1.0,
            Tolerance {
                abs: 0.1,
                source: "t".into(),
            },
        );
        let back: Metric = serde_json::from_str(&serde_json::to_string(&m).unwrap()).unwrap();
        assert!(back.value.is_nan());
        assert_eq!(
            back.pass(),
            Some(false),
            "an unmeasured value fails its tolerance"
        );
    }

    #[test]
    fn a_check_passes_only_when_true() {
        let yes = Metric::check("c", "m", "yes", true, "exact");
        let no = Metric::check("c", "m", "yes", false, "exact");
        assert_eq!((yes.value, yes.pass()), (1.0, Some(true)));
        assert_eq!((no.value, no.pass()), (0.0, Some(false)));
        assert_eq!(yes.tolerance, Some(Tolerance::absolute(0.0, "exact")));
    }
}
