//! The potential's far pairs are evaluated once each and added to both particles
//! (`physics::forces::pairs_once`). The accelerations must be those of the direct sum
//! `F_i = Σ_j C_ij P'(r_ij) e_ij` over every particle within `r_e` (liquid and wall), up to the
//! rounding of a sum taken in another order — with walls, several liquids' worth of pairs
//! across the pass's chunks, and for any thread count bitwise the same.

use super::common::{advance, block_scene, sim, ALUMINA_PLATE};
use solver::physics::forces::{fluid_forces, Off};
use solver::state::Vec3;
use solver::Simulation;

/// Potential-only accelerations [m/s²] of the current state, by the force loop.
fn by_the_loop(s: &Simulation) -> Vec<Vec3> {
    let mut acc = vec![Vec3::zeros(); s.particles.n_fluid];
    let inp = s.loop_input::<solver::kernel::WendlandC2>();
    fluid_forces(&inp, &(s.potential_term(), Off), &mut acc, &mut []);
    acc
}

#[test]
fn far_pairs_once_give_the_direct_sum() {
    // 12³ = 1728 particles: two chunks of the pass (1024 each), pairs across them
    let text = block_scene(
        12,
        1e-4,
        "interfacial_tension = true\ngravity = [0.0, 0.0, -9.81]",
        ALUMINA_PLATE,
    )
    .replace(
        "sound_speed = 12.0",
        "sound_speed = 12.0\nh_over_l0 = 1.05\nre_over_l0 = 4.2",
    );
    let mut s = sim(&text);
    advance(&mut s, 20);
    let p = &s.particles;
    let m = &s.model;
    let r_e = m.r_e_m;
    let g = m.gravity();
    let got = by_the_loop(&s);
    let mut scale = 0.0f64;
    let mut direct = Vec::with_capacity(p.n_fluid);
    for i in 0..p.n_fluid {
        let mut f = Vec3::zeros();
        for j in 0..p.pos.len() {
            let d = p.pos[i] - p.pos[j];
            let r = d.norm();
            if j != i && r < r_e {
                let c = m.pairs.c(p.phase[i] as usize, p.phase[j] as usize);
                let fij = d * (m.potential.pair_force_inside(c, r) / r);
                scale = scale.max(fij.norm());
                f += fij;
            }
        }
        direct.push(f / m.mass[p.phase[i] as usize] + g);
    }
    let a_scale = scale / m.mass[0];
    for (i, (a, b)) in got.iter().zip(&direct).enumerate() {
        // ~250 pair forces summed in two orders: rounding of 1e-13 of the largest pair force
        // per term, far above f64's 1.1e-16 and far below any physical difference
        assert!(
            (a - b).norm() < 1e-13 * 250.0 * a_scale,
            "particle {i}: loop {a:?}, direct {b:?}"
        );
    }
    // the same bits on one thread
    let one = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap()
        .install(|| by_the_loop(&s));
    assert!(one == got, "one thread and the pool differ");
}
