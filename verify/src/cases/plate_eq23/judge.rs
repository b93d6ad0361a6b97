//! The metrics of the drop on a plate: which liquids touch the plate against Eq. 23, θ12
//! against Eq. 23 where a line exists, and the height.

use super::measure::PlateRun;
use super::Prediction;
use crate::suite::{Metric, Tolerance};

/// The tolerance of θ12 at a solid/liquid/liquid line [deg].
pub fn triple_line_tolerance() -> Tolerance {
    Tolerance::absolute(
        5.4,
        "twice the fit's own error on voxelised tilted interfaces at R/l0 = 8 (2.7°, measure::geometry tests)",
    )
}

/// The metrics of one run.
pub fn run_metrics(case: &str, m: &PlateRun) -> anyhow::Result<Vec<Metric>> {
    let prediction = Prediction::of(m.sigma_n_m, m.theta23_deg)?;
    let mut out = vec![contact(case, m, &prediction)];
    if let (Some(theta12_ref), Some(measured)) = (prediction.line_to_measure(), &m.theta12_deg) {
        out.push(
            Metric::new(
                case,
                format!("θ12 {}", m.run.id),
                "deg",
                *measured.as_ref().unwrap_or(&f64::NAN),
            )
            .against(theta12_ref, triple_line_tolerance())
            .run(m.run)
            .note(match measured {
                Ok(_) => {
                    "fit of the 1–2 interface in a band above the plate, angle inside liquid 1"
                        .to_string()
                }
                Err(e) => format!("not measurable: {e}"),
            }),
        );
    }
    out.push(
        Metric::new(
            case,
            format!("height {}", m.run.id),
            "mm",
            m.contact.height_m * 1e3,
        )
        .run(m.run)
        .note("top of the drop above the plate at the end"),
    );
    Ok(out)
}

/// Which liquids touch the plate against Eq. 23.
fn contact(case: &str, m: &PlateRun, prediction: &Prediction) -> Metric {
    let cos12 = prediction.cos_theta12;
    // at |cos θ12| = 1 exactly the line is on the edge of existing: a line, or the spreading it
    // degenerates into on that side (cos = +1: θ12 → 0°, liquid 1 spreads under 2, i.e. 2 rides
    // on 1; cos = −1: 1 rides on 2), are both correct
    let limit = if cos12 > 0.0 {
        "liquid 2 rides on liquid 1"
    } else {
        "liquid 1 rides on liquid 2"
    };
    let seen = m.seen;
    let ok = seen == prediction.words()
        || (prediction.on_boundary() && (seen.starts_with("both") || seen == limit));
    let shares = &m.contact.wetted_fraction;
    Metric::check(case, format!("contact {}", m.run.id), "match", ok, "the contact regime matches Eq. 23 or not")
        .run(m.run)
        .note(format!(
            "{}Eq. 23: cos θ12 = {cos12:.3} → {}; seen at t = {:.0} ms: {seen} (plate-layer shares {:.2} / {:.2})",
            m.run.status_note(),
            prediction.words(),
            m.run.last.time_s * 1e3,
            shares.first().copied().unwrap_or(f64::NAN),
            shares.get(1).copied().unwrap_or(f64::NAN)
        ))
}
