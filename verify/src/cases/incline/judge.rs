//! The sliding drop's metrics, all reported (paper B gives no numbers): the advancing and
//! receding angles, their difference, the speed and acceleration along the plate; and no liquid
//! in the plate, judged.

use super::measure::InclineRun;
use super::INCLINE_DEG;
use crate::cases::substrate::{inside_plate_metric, G_M_S2};
use crate::suite::Metric;

/// The metrics of one run of the case `case`.
pub fn run_metrics(case: &str, m: &InclineRun) -> Vec<Metric> {
    let (s, id, theta) = (&m.slide, &m.run.id, m.theta_deg);
    let tail = format!(
        "{}mean over t ≥ {:.0} ms{}",
        m.run.status_note(),
        s.from_s * 1e3,
        if s.on_plate {
            ""
        } else {
            "; the drop reached the plate's downhill end"
        }
    );
    let ((a_mean, a_osc), (r_mean, r_osc)) = (s.advancing_deg, s.receding_deg);
    let reported = |name: String, unit: &str, value: f64| {
        Metric::new(case, format!("{name} {id}"), unit, value).run(m.run)
    };
    vec![
        reported("advancing angle".into(), "deg", a_mean).note(format!(
            "{tail}; downhill side-view angle ±{a_osc:.1}°; equilibrium angle {theta}°"
        )),
        reported("receding angle".into(), "deg", r_mean).note(format!(
            "{tail}; uphill side-view angle ±{r_osc:.1}°; equilibrium angle {theta}°"
        )),
        reported("hysteresis θa − θr".into(), "deg", a_mean - r_mean)
            .note("a sliding drop without pinning: the difference is dynamic (viscous bending of the interface), not contact-angle hysteresis"),
        reported("sliding speed".into(), "mm/s", s.speed_m_s * 1e3)
            .note(format!("{tail}; mean liquid velocity along the plate")),
        reported("acceleration along the plate".into(), "m/s²", s.acceleration_m_s2).note(format!(
            "second half of the run; {:.2} m/s² = g sin 60° would be a frictionless slide, 0 a steady one",
            G_M_S2 * INCLINE_DEG.to_radians().sin()
        )),
        inside_plate_metric(case, m.run),
    ]
}
