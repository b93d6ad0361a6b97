//! The sliding drop's plots: the side-view angles and the position over time, and side and
//! bird's-eye views of the snapshots.

use super::measure::InclineRun;
use crate::cases::substrate::{draw_history, draw_view, states};
use std::path::Path;

/// Draws the plots of one run into `dir`: particles seen at spacing `l0_m` [m] on the plate
/// spanning `plate_x_mm` [mm].
pub fn run_plots(
    m: &InclineRun,
    l0_m: f64,
    plate_x_mm: (f64, f64),
    dir: &Path,
) -> anyhow::Result<()> {
    let (solid, theta, id) = (m.solid, m.theta_deg, &m.run.id);
    draw_history(
        &m.t_s,
        &[
            (&m.advancing_deg, "advancing (downhill)"),
            (&m.receding_deg, "receding (uphill)"),
        ],
        format!("water on {solid} inclined 60°: side-view angles"),
        "θ [deg]",
        vec![(theta, format!("equilibrium {theta}°"))],
        Some((0.0, 180.0)),
        &dir.join(format!("angles_{id}")),
    )?;
    draw_history(
        &m.t_s,
        &[(&m.centroid_x_mm, "centroid")],
        format!("water on {solid} inclined 60°: centroid position along the plate"),
        "x [mm]",
        vec![],
        None,
        &dir.join(format!("position_{id}")),
    )?;
    for (time, d) in states(m.run) {
        for (top, view) in [(false, "side"), (true, "top")] {
            let seen = if top {
                "bird's-eye view"
            } else {
                "side view, slice |y − y_c| < l0"
            };
            draw_view(
                d,
                l0_m,
                format!(
                    "water on {solid}, 60° incline (downhill → +x), t = {:.1} ms, {seen}",
                    time * 1e3
                ),
                plate_x_mm,
                top,
                &dir.join(format!("{view}_{id}_t{:05.1}ms", time * 1e3)),
            )?;
        }
    }
    Ok(())
}
