//! The metrics of the drops on a plate: which liquids touch the plate against Eq. 23, θ12
//! against Eq. 23 where a line exists — from the typed Young angles, and from the angles the
//! single drops of the same setting measured (so an error of the ingredients is told apart
//! from an error at the triple line) — each single drop's angle, and the height.

use super::measure::{Measured, PlateRun, SingleRun};
use super::{Prediction, SIGMA12};
use crate::analytic::eq23;
use crate::measure::{foot, geometry};
use crate::suite::{Metric, Tolerance};

/// The tolerance of θ12 at a solid/liquid/liquid line [deg] for a drop of `r_over_l0`
/// spacings: twice the line fit's own error bound (measure::geometry tests); `None` where no
/// test bounds it (below R/l0 = 8: the angle is reported, not judged). The bound is the fit's
/// on planar and spherical interfaces; the note says that a bent one reads towards 90° by
/// more (measured, not added to the tolerance).
pub fn triple_line_tolerance(r_over_l0: f64) -> Option<Tolerance> {
    geometry::triple_line_angle_error_deg(r_over_l0).map(|e| {
        Tolerance::absolute(
            2.0 * e,
            format!("twice the line fit's own error bound on voxelised tilted interfaces at R/l0 = {r_over_l0:.0} ({e}°, measure::geometry tests); an interface bent over the fit's 8 l0 band reads towards 90° by more (a saddle bent with radius 3R: 12–17° at R/l0 = 8, same tests)"),
        )
    })
}

/// What the metrics are judged with.
pub struct Judge<'a> {
    /// The case's name.
    pub case: &'a str,
    /// Drop radius over particle spacing.
    pub r_over_l0: f64,
}

impl Judge<'_> {
    /// Every metric of the case.
    pub fn metrics(&self, m: &Measured) -> anyhow::Result<Vec<Metric>> {
        let mut out = Vec::new();
        for b in &m.binaries {
            out.extend(self.binary(b, m)?);
        }
        for s in &m.singles {
            out.push(self.single(s));
        }
        Ok(out)
    }

    /// The error bound of a single drop's sessile angle at `theta_deg` [deg] (None: not
    /// bounded).
    fn sessile_error(&self, theta_deg: f64) -> Option<f64> {
        geometry::sessile_angle_error_deg(self.r_over_l0, theta_deg)
    }

    /// A single drop's angle against its typed Young angle.
    fn single(&self, s: &SingleRun) -> Metric {
        let tol = self.sessile_error(s.typed_deg).map(|e| Tolerance::absolute(2.0 * e, format!("twice the sessile fit's own error bound on voxelised caps at R/l0 = {:.0} ({e}°, measure::geometry tests)", self.r_over_l0)));
        let metric = Metric::new(
            self.case,
            format!("contact angle {}", s.run.id),
            "deg",
            *s.measured_deg.as_ref().unwrap_or(&f64::NAN),
        );
        metric
            .run(s.run)
            .note(match &s.measured_deg {
                Ok(_) => format!("{}sphere fit of the free surface within 6 l0 of the plate, at t = {:.0} ms: an ingredient of Eq. 23", s.run.status_note(), s.run.last.time_s * 1e3),
                Err(e) => format!("{}not measurable: {e}", s.run.status_note()),
            })
            .against_if(s.typed_deg, tol)
    }

    /// The metrics of one binary drop.
    fn binary(&self, b: &PlateRun, m: &Measured) -> anyhow::Result<Vec<Metric>> {
        let prediction = Prediction::of(b.sigma_n_m, b.theta31_deg, b.theta23_deg)?;
        let mut out = vec![contact(self.case, b, &prediction)];
        if let (Some(theta12_ref), Some(measured)) = (prediction.line_to_measure(), &b.theta12_deg)
        {
            let value = *measured.as_ref().unwrap_or(&f64::NAN);
            let metric = Metric::new(self.case, format!("θ12 {}", b.run.id), "deg", value);
            out.push(
                metric
                    .run(b.run)
                    .note(match measured {
                        Ok(_) => "fit of the 1–2 interface in a band above the plate, angle inside liquid 1; reference: Eq. 23 from the typed Young angles".to_string(),
                        Err(e) => format!("not measurable: {e}"),
                    })
                    .against_if(theta12_ref, triple_line_tolerance(self.r_over_l0)),
            );
            out.extend(self.against_ingredients(b, m, value, theta12_ref));
        }
        if let (Some(theta12_ref), Some(foot)) = (prediction.line_to_measure(), &b.foot_theta12_deg)
        {
            out.push(self.at_the_foot(b, foot, theta12_ref));
        }
        out.push(
            Metric::new(
                self.case,
                format!("height {}", b.run.id),
                "mm",
                b.contact.height_m * 1e3,
            )
            .run(b.run)
            .note("top of the drop above the plate at the end"),
        );
        out.push(
            Metric::new(
                self.case,
                format!("drift {}", b.run.id),
                "mm/s",
                b.drift_m_s * 1e3,
            )
            .run(b.run)
            .note("speed of the drop's centre of mass along the plate, mean over the last quarter of the run: Eq. 23 describes a drop at rest, and on a free-slip plate a drop that moves was set moving by forces that do not conserve momentum (docs/findings.md)"),
        );
        Ok(out)
    }

    /// θ12 read at the foot of the 1–2 interface (a quadric through the interface near the
    /// plate, measure::foot) beside Eq. 23 from the typed angles, not judged: the reading is
    /// free of the line fit's bias on a bent interface, but at the resolutions the case runs
    /// it scatters with the lattice by more than the θ12 tolerance (its note gives the bound).
    fn at_the_foot(&self, b: &PlateRun, foot: &Result<f64, String>, typed_theta12: f64) -> Metric {
        let name = format!("θ12 at the foot {}", b.run.id);
        let value = *foot.as_ref().unwrap_or(&f64::NAN);
        let why = match foot::foot_angle_error_deg(self.r_over_l0) {
            Some(e) => format!("its error on voxelised sheets (planes, spheres, saddles) at R/l0 = {:.0} reaches {e}° either way (measure::foot tests), more than θ12's tolerance", self.r_over_l0),
            None => format!("no error bound of the reading at R/l0 = {:.0}", self.r_over_l0),
        };
        let metric = Metric::new(self.case, name, "deg", value).run(b.run);
        let note = match foot {
            Ok(_) => "quadric through the 1–2 interface within 12 l0 of the plate, its slope at the plate (measure::foot); reference: Eq. 23 from the typed Young angles".to_string(),
            Err(e) => format!("not read: {e}"),
        };
        metric.note(note).beside(typed_theta12, &why)
    }

    /// θ12 against Eq. 23 evaluated at the Young angles the single drops of the same model
    /// measured: the error left at the triple line once the ingredients' errors are taken
    /// out. The tolerance adds the single fits' error bounds, amplified by Eq. 23's
    /// sensitivity, to the line fit's (in quadrature, twice, as the other angle tolerances).
    fn against_ingredients(
        &self,
        b: &PlateRun,
        m: &Measured,
        measured: f64,
        typed_theta12: f64,
    ) -> Option<Metric> {
        let (s1, s2) = b.sigma_n_m;
        let t31 = m.ingredient(s1, b.theta31_deg, b.surface_force)?;
        let t23 = m.ingredient(s2, b.theta23_deg, b.surface_force)?;
        let name = format!("θ12 from measured angles {}", b.run.id);
        let metric = Metric::new(self.case, name, "deg", measured).run(b.run);
        let contact = match eq23::solid_contact(s1, s2, SIGMA12, t31, t23) {
            Ok(c) => c,
            Err(e) => return Some(metric.note(format!("Eq. 23 at the measured angles: {e}"))),
        };
        let eq23::SolidContact::TripleLine { theta12_deg } = contact else {
            return Some(metric.note(format!(
                "Eq. 23 at the measured angles θ31 = {t31:.1}°, θ23 = {t23:.1}° has no line (one liquid spreads under the other; typed: θ12 = {typed_theta12:.1}°)"
            )));
        };
        let (Some(e31), Some(e23), Some(e_l)) = (
            self.sessile_error(t31),
            self.sessile_error(t23),
            geometry::triple_line_angle_error_deg(self.r_over_l0),
        ) else {
            return Some(metric.note(format!("Eq. 23 at the measured angles θ31 = {t31:.1}°, θ23 = {t23:.1}° gives {theta12_deg:.1}°; no error bound of the fits at these angles: not judged")));
        };
        let Ok((d31, d23)) = eq23::theta12_sensitivity(s1, s2, SIGMA12, t31, t23) else {
            return Some(metric.note("Eq. 23 at the measured angles gives θ12 at 0° or 180°"));
        };
        let e = (e_l.powi(2) + (d31 * e31).powi(2) + (d23 * e23).powi(2)).sqrt();
        Some(
            metric
                .against(theta12_deg, Tolerance::absolute(2.0 * e, format!("twice the line fit's bound ({e_l}°) and the single fits' ({e31}°, {e23}°) amplified by Eq. 23 (∂θ12/∂θ31 = {d31:.2}, ∂θ12/∂θ23 = {d23:.2}), in quadrature")))
                .note(format!("reference: Eq. 23 at the angles the single drops measured, θ31 = {t31:.1}°, θ23 = {t23:.1}° (typed {:.0}°, {:.0}° → {typed_theta12:.1}°)", b.theta31_deg, b.theta23_deg)),
        )
    }
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
            "{}Eq. 23 (θ31 = {:.0}°, θ23 = {:.0}°): cos θ12 = {cos12:.3} → {}; seen at t = {:.0} ms: {seen} (plate-layer shares {:.2} / {:.2})",
            m.run.status_note(),
            m.theta31_deg,
            m.theta23_deg,
            prediction.words(),
            m.run.last.time_s * 1e3,
            shares.first().copied().unwrap_or(f64::NAN),
            shares.get(1).copied().unwrap_or(f64::NAN)
        ))
}
