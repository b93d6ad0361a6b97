//! The falling drops' metrics: the settled height and wetted radius against the Young–Laplace
//! sessile drop of the simulated volume, the angle against the equilibrium angle, no liquid in
//! the plate; the spreading, the settling time and (iron) the paper's ranges reported.

use super::measure::ImpactRun;
use super::{Drop, Impact};
use crate::analytic::young_laplace::{self, SessileDrop};
use crate::cases::paper_values;
use crate::cases::substrate::{inside_plate_metric, G_M_S2};
use crate::measure::side_view;
use crate::suite::{Case, Metric, Tolerance};

impl Impact {
    /// The paper's own value `key`, if the paper gives one for this drop.
    pub(super) fn paper(&self, key: &str) -> Option<f64> {
        self.spec()
            .paper_section
            .and_then(|sec| paper_values::number(sec, key))
    }

    /// The Young–Laplace sessile drop of a run's simulated volume.
    pub(super) fn young_laplace(&self, m: &ImpactRun) -> anyhow::Result<SessileDrop> {
        let l = self.spec().liquid;
        young_laplace::sessile_drop(
            m.volume_m3,
            l.density_kg_m3,
            l.surface_tension_n_m,
            m.theta_deg,
            G_M_S2,
        )
        .map_err(anyhow::Error::msg)
    }

    /// The metrics of one run measured at spacing `l0_m` [m].
    pub(super) fn run_metrics(&self, m: &ImpactRun, l0_m: f64) -> anyhow::Result<Vec<Metric>> {
        let yl = self.young_laplace(m)?;
        let mut out = self.equilibrium(m, &yl, l0_m);
        out.push(inside_plate_metric(self.name(), m.run));
        out.extend(self.spreading(m));
        if self.0 == Drop::Iron {
            out.extend(self.iron_ranges(m));
        }
        Ok(out)
    }

    /// "mean over t ≥ … ms (last fifth)", after the run's status.
    fn tail(m: &ImpactRun) -> String {
        format!(
            "{}mean over t ≥ {:.0} ms (last fifth)",
            m.run.status_note(),
            m.settled.from_s * 1e3
        )
    }

    /// Height, angle and wetted radius of the settled drop.
    fn equilibrium(&self, m: &ImpactRun, yl: &SessileDrop, l0_m: f64) -> Vec<Metric> {
        let (s, id, theta, tail) = (&m.settled, &m.run.id, m.theta_deg, Self::tail(m));
        // R of the sphere of the simulated volume, as in the side-view tests
        let r_over_l0 = (3.0 * m.volume_m3 / (4.0 * std::f64::consts::PI)).cbrt() / l0_m;
        let l = self.spec().liquid;
        let (rho, sigma) = (l.density_kg_m3, l.surface_tension_n_m);
        vec![
            Metric::new(self.name(), format!("equilibrium height {id}"), "mm", s.height_mm)
                .against(yl.height_m * 1e3, Tolerance::absolute(l0_m * 1e3, "one spacing: the top is known to ±l0/2 (highest particle + l0/2) and the plate surface to ±l0/2"))
                .paper(self.paper("height_equilibrium_mm"))
                .run(m.run)
                .note(format!(
                    "{tail}, residual oscillation ±{:.3} mm; Young–Laplace for the simulated volume {:.3} mm³ (ρ {rho}, σ {sigma} N/m, θ {theta}°, g {G_M_S2})",
                    s.height_osc_mm,
                    m.volume_m3 * 1e9
                )),
            Metric::new(self.name(), format!("equilibrium contact angle {id}"), "deg", s.theta_deg)
                .paper(self.paper("contact_angle_equilibrium_deg"))
                .run(m.run)
                .note(format!("{tail}, residual oscillation ±{:.1}°; mean of the left and right side-view angles", s.theta_osc_deg))
                .against_if(
                    theta,
                    side_view::side_view_angle_error_deg(r_over_l0).map(|e| Tolerance::absolute(
                        // an angle not measured has no oscillation: its value fails anyway
                        e + 2.0 * if s.theta_osc_deg.is_finite() { s.theta_osc_deg } else { 0.0 },
                        format!("the side-view measurement's own error bound on analytic caps at R/l0 = {r_over_l0:.1} ({e}°, measure::side_view tests) plus twice the residual oscillation of the last fifth (±{:.1}°)", s.theta_osc_deg),
                    )),
                ),
            Metric::new(self.name(), format!("wetted radius {id}"), "mm", s.contact_radius_mm)
                .against(yl.contact_radius_m * 1e3, Tolerance::absolute(l0_m * 1e3, "one spacing: the wetted disc is counted in whole first-layer particles"))
                .run(m.run)
                .note(format!("{tail}; radius of the disc with the first liquid layer's area")),
        ]
    }

    /// The largest spreading radius and the settling time, reported.
    fn spreading(&self, m: &ImpactRun) -> Vec<Metric> {
        let (s, id) = (&m.settled, &m.run.id);
        let ts = s.settling_time_s;
        vec![
            Metric::new(self.name(), format!("largest spreading radius {id}"), "mm", s.largest_radius_mm)
                .run(m.run)
                .note("largest wetted radius after impact"),
            Metric::new(self.name(), format!("settling time {id}"), "ms", ts * 1e3)
                .paper(self.paper("equilibrium_time_ms"))
                .run(m.run)
                .note(format!(
                    "last time the height was farther than {:.3} mm (2 % or l0/2) from its final mean{}",
                    s.band_mm,
                    if ts >= s.from_s { " — not settled within the run" } else { "" }
                )),
        ]
    }

    /// The ranges of the angle and the height while the iron drop oscillates: the paper's
    /// Fig. 4 describes them.
    fn iron_ranges(&self, m: &ImpactRun) -> Vec<Metric> {
        let s = &m.settled;
        [
            ("dynamic angle min", "deg", s.theta_range_deg.0, "contact_angle_min_deg"),
            ("dynamic angle max", "deg", s.theta_range_deg.1, "contact_angle_max_deg"),
            ("height min", "mm", s.height_range_mm.0, "height_min_mm"),
            ("height max", "mm", s.height_range_mm.1, "height_max_mm"),
        ]
        .into_iter()
        .map(|(label, unit, value, key)| {
            Metric::new(self.name(), format!("{label} {}", m.run.id), unit, value)
                .paper(self.paper(key))
                .run(m.run)
                .note("after the first 2 ms; the paper's Fig. 4 range, a description, not a reference")
        })
        .collect()
    }
}
