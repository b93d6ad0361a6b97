//! The force loop visits only the near entries the summation density marked as interacting
//! (`NeighbourSearch::active`); the skipped ones — the Verlet skin's shell — would add exact
//! zeros. So the accelerations must be bitwise those of a loop over every entry (up to the sign
//! of a zero), for each way the kernel support and `r_e` can compare, with walls, and for lists
//! longer than the 64 entries a mask covers.

use super::common::{advance, block_scene, sim, ALUMINA_PLATE};
use solver::kernel::WendlandC2;
use solver::state::Vec3;
use solver::Simulation;

/// Accelerations [m/s²] of the current state with the masks `active`.
fn accelerations(s: &Simulation, active: Vec<u64>) -> Vec<Vec3> {
    let mut s = s.clone();
    s.search.active = active;
    let mut acc = vec![Vec3::zeros(); s.particles.n_fluid];
    s.pair_forces::<WendlandC2>(&mut acc, &mut []);
    acc
}

fn check(discretisation: &str, with_plate: bool, skips: bool) {
    let text = block_scene(
        10,
        1e-4,
        "interfacial_tension = true\nlaminar_viscosity = true\nartificial_viscosity = {}\ngravity = [0.0, 0.0, -9.81]",
        if with_plate { ALUMINA_PLATE } else { "" },
    )
    .replace("sound_speed = 12.0", &format!("sound_speed = 12.0\n{discretisation}"));
    let mut s = sim(&text);
    advance(&mut s, 30);
    let n = s.particles.n_fluid;
    let masked: usize = s
        .search
        .active
        .iter()
        .map(|m| m.count_ones() as usize)
        .sum();
    let near: usize = (0..n).map(|i| s.search.lists.near(i).count().min(64)).sum();
    // with r_e beyond support + skin every near entry interacts; otherwise the skin's shell
    // must be skipped, or the test compares nothing
    assert_eq!(masked < near, skips, "{masked} of {near} entries marked");
    let skipping = accelerations(&s, s.search.active.clone());
    let all = accelerations(&s, vec![u64::MAX; n]);
    for (i, (a, b)) in skipping.iter().zip(&all).enumerate() {
        // == treats −0 and +0 as equal: the only difference adding an exact zero can make
        assert!(
            a == b,
            "particle {i}: {a:?} with masks, {b:?} over every entry"
        );
    }
}

#[test]
fn skipping_the_skin_changes_no_bit() {
    // r_e (4.2 l0) beyond the support (2.1 l0); equal (2.1 l0); r_e inside a wider support
    // (2.6 l0, lists of ~90 near entries: beyond the 64 bits of a mask)
    check("h_over_l0 = 1.05\nre_over_l0 = 4.2", true, false);
    check("h_over_l0 = 1.05\nre_over_l0 = 2.1", false, true);
    check("h_over_l0 = 1.3\nre_over_l0 = 2.1", true, true);
}
