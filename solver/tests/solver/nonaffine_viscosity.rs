//! The non-affine viscosity in a run (docs/model.md §3): it only dissipates, the budget counts
//! what it takes out, and it is refused outside its coefficient's range.

use super::common::sim;
use super::energy_budget::{closure, cube, SUMMATION_CLIP};
use solver::Scene;

fn with_nonaffine(alpha: f64) -> String {
    cube("lattice", SUMMATION_CLIP).replace(
        "[effects]",
        &format!("[effects]\nnonaffine_viscosity = {{ coefficient = {alpha} }}"),
    )
}

/// The cube turning round (energy_budget.rs) with the non-affine viscosity at α = 0.1: its
/// work is negative at every output, it took out a share of the energy, and the budget that
/// counts it still closes to 1 % of the largest kinetic energy (the same bound as without it:
/// its force is booked like the other dissipative terms). Without counting it the budget
/// would drift by what it took out — more than the bound (checked).
#[test]
fn a_cube_turning_round_with_it_closes_its_energy_budget() {
    let text = with_nonaffine(0.1);
    let c = closure(&text, 2.0e-3);
    assert!(
        c.drift_j <= 0.01 * c.max_kinetic_j,
        "drift {:e} J, largest kinetic energy {:e} J",
        c.drift_j,
        c.max_kinetic_j
    );
    let mut s = sim(&text);
    let mut last = 0.0;
    while s.time_s < 2.0e-3 {
        s.step(f64::INFINITY).unwrap();
        let w = s.dissipation.nonaffine.work_j;
        // no step may add energy: 1e-20 J is round-off slack only (the kick books the work at
        // its mean velocity, −Q dt to second order in dt)
        assert!(w <= last + 1e-20, "its work rose: {last:e} → {w:e} J");
        last = w;
    }
    assert!(
        -last > 0.01 * c.max_kinetic_j,
        "it took out {:e} J against a largest kinetic energy of {:e} J",
        -last,
        c.max_kinetic_j
    );
}

/// The coefficient must be in (0, 0.5]: the reason names the key and the range.
#[test]
fn a_coefficient_outside_its_range_is_refused() {
    for bad in [0.0, -0.1, 0.8] {
        let err = Scene::from_toml_str(&with_nonaffine(bad))
            .and_then(|s| s.validate())
            .expect_err("refused");
        let msg = err.to_string();
        assert!(
            msg.contains("effects.nonaffine_viscosity.coefficient") && msg.contains("(0, 0.5]"),
            "{msg}"
        );
    }
}
