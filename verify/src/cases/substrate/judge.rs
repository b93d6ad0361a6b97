//! The metric every run of paper B's cases shares: no liquid inside the plate.

use super::Probe;
use crate::measure::invariants;
use crate::suite::{Metric, RunData, Tolerance};
use solver::scene::Setting;

/// A setting's name as scene files write it (`natsui2021`).
fn setting_name(setting: Setting) -> String {
    serde_json::to_value(setting)
        .ok()
        .and_then(|v| v.as_str().map(str::to_string))
        .unwrap_or_default()
}

/// The most liquid particles inside the plate at any output or in the final state (where a run
/// stopped by the wall-entry health check has its particle inside), judged against none.
pub fn inside_plate_metric(case: &str, run: &RunData) -> Metric {
    let setting = setting_name(run.info.scene.discretisation.setting);
    let last = &run.last;
    let liquid: Vec<[f64; 3]> = last
        .pos
        .iter()
        .zip(&last.wall)
        .filter(|(_, &wall)| !wall)
        .map(|(p, _)| *p)
        .collect();
    let at_end = invariants::inside_walls(&liquid, &run.info.scene) as f64;
    let worst = Probe::InsidePlate
        .series(run)
        .into_iter()
        .fold(at_end, f64::max);
    Metric::new(
        case,
        format!("liquid particles inside the plate {}", run.id),
        "-",
        worst,
    )
    .against(
        0.0,
        Tolerance::exact("none may enter a wall: the wall-entry invariant (a liquid particle never crosses a wall's surface)"),
    )
    .run(run)
    .note(format!(
        "{}setting {setting}; most at any output or in the final state (deeper than l0/2 past every face of the plate, the wall-entry health check's rule)",
        run.status_note()
    ))
}
