//! The falling drops' plots: height and wetted radius, the dynamic contact angle, and side
//! views of the snapshots.

use super::measure::ImpactRun;
use super::{Drop, Impact};
use crate::cases::substrate::{draw_history, draw_view, states};
use std::path::Path;

impl Impact {
    /// Draws the plots of one run measured at spacing `l0_m` [m] into `dir`.
    pub(super) fn run_plots(&self, m: &ImpactRun, l0_m: f64, dir: &Path) -> anyhow::Result<()> {
        let yl = self.young_laplace(m)?;
        let (name, solid, theta, h) = (self.spec().liquid.name, m.solid, m.theta_deg, &m.history);
        let id = &m.run.id;
        draw_history(
            &h.t_s,
            &[
                (&h.height_mm, "height"),
                (&h.contact_radius_mm, "wetted radius"),
            ],
            format!("{name} on {solid} (θ = {theta}°): height and wetted radius"),
            "[mm]",
            vec![
                (yl.height_m * 1e3, "Young–Laplace height".into()),
                (yl.contact_radius_m * 1e3, "Young–Laplace radius".into()),
            ],
            None,
            &dir.join(format!("height_{id}")),
        )?;
        let mut levels = vec![(theta, format!("equilibrium {theta}°"))];
        if self.0 == Drop::Iron {
            for key in ["contact_angle_min_deg", "contact_angle_max_deg"] {
                if let Some(v) = self.paper(key) {
                    levels.push((v, format!("paper's range {v}°")));
                }
            }
        }
        draw_history(
            &h.t_s,
            &[
                (&h.theta_mean_deg, "mean of left and right"),
                (&h.theta_left_deg, "left"),
                (&h.theta_right_deg, "right"),
                (&h.theta_sphere_deg, "3-D sphere fit of the whole rim"),
            ],
            format!("{name} on {solid}: dynamic contact angle in the side view"),
            "θ [deg]",
            levels,
            Some((0.0, 180.0)),
            &dir.join(format!("angle_{id}")),
        )?;
        let r_mm = self.spec().plate_radius_m * 1e3;
        for (time, d) in states(m.run) {
            draw_view(
                d,
                l0_m,
                format!(
                    "{name} on {solid}, t = {:.1} ms (side view, slice |y − y_c| < l0)",
                    time * 1e3
                ),
                (-r_mm, r_mm),
                false,
                &dir.join(format!("side_{id}_t{:05.1}ms", time * 1e3)),
            )?;
        }
        Ok(())
    }
}
