//! The energies of the state [J]: interfacial, compression, gravitational and wall
//! repulsion (the kinetic energy is summed with the phase statistics).
//!
//! Which forces these are the potentials of, exactly, and where the discretisation departs:
//! - the pairwise potential's force is `−∇` of the interfacial energy (walls are fixed);
//! - gravity's is `−∇` of `−Σ m g·x`; the wall repulsion's is `−∇` of its energy;
//! - the pressure force `−Σ_j (p_i V_i² + p_j V_j²) ∇_i W_ij` is `−∇` of the compression
//!   energy only with the summation density, between liquid particles, and with the lattice
//!   particle mass `m = ρ0/S` (`S = Σ_lattice W`): with `ρ_k = ρ0_k Σ_j W_kj/S` and
//!   `dE = Σ_k m_k (p_k/ρ_k²) dρ_k`, `−∇_i E = −Σ_j (m_i ρ0_i p_i/ρ_i² + m_j ρ0_j p_j/ρ_j²)
//!   ∇_i W_ij / S`, which is the force when `m ρ0/S = m²`. With the physical mass `ρ0 l0³`
//!   the force is `l0³ S` times that gradient (1.028 at h = 1.05 l0 with Wendland C2); with
//!   the continuity density the rate `ρ_i Σ_j V_j v_ij·∇W` is not the
//!   force's conjugate unless neighbours have equal densities. At walls the part
//!   `p_i V_i²` is the gradient of the liquid's compression energy (walls count in its
//!   summation density), the walls' own `p_w V_w²` of none: its work is booked
//!   ([`crate::physics::forces::ledger`]). The budget measures the rest.

use crate::model::Model;
use crate::neighbours::NeighbourLists;
use crate::physics::forces::wall_repulsion::Monaghan1994WallRepulsion;
use crate::state::Particles;

/// Interfacial energy [J] (see [`super::Observables::interfacial_energy_j`]); zero without
/// tension.
pub fn interfacial_energy(model: &Model, p: &Particles, lists: &NeighbourLists) -> f64 {
    if !model.effects.interfacial_tension {
        return 0.0;
    }
    let pot = &model.potential;
    let mut e = 0.0;
    for i in 0..p.n_fluid {
        let a = p.phase[i] as usize;
        let mut ei = 0.5 * model.pairs.c(a, a) * model.bulk_potential_sum_m3;
        // a near pair of two liquid particles is in both lists (half of it here), a far pair
        // in one (all of it), a wall pair in the liquid particle's only
        let near = lists.near(i).map(|j| (j, j < p.n_fluid));
        for (j, in_both) in near.chain(lists.far(i).map(|j| (j, false))) {
            let r = lists.delta(p.pos[i], p.pos[j]).norm();
            let c = model.pairs.c(a, p.phase[j] as usize);
            let share = if in_both { 0.5 } else { 1.0 };
            ei -= share * c * pot.p(r);
        }
        e += ei;
    }
    e
}

/// Compression (EOS) energy of the liquid [J]: `Σ_i m_i e(ρ_i)` over fluid particles with
/// Tait's specific energy `e(ρ) = ∫_{ρ0}^{ρ} p/ρ'² dρ'` of the pressure the solver uses (clipped
/// at zero unless `negative_pressure = "keep"`; [`crate::physics::eos::TaitEos::energy_per_kg`]).
/// Wall particles carry none: they are fixed, and their density is not a state of their own
/// (it follows from the pressure extrapolated from the liquid).
pub fn compression_energy(model: &Model, p: &Particles) -> f64 {
    let clip = model.effects.clip_negative_pressure;
    (0..p.n_fluid)
        .map(|i| {
            let a = p.phase[i] as usize;
            model.mass[a] * model.eos.energy_per_kg(p.rho[i], model.rho0[a], clip)
        })
        .sum()
}

/// Gravitational potential energy `−Σ_i m_i g·x_i` [J] of the liquid (zero without gravity;
/// its zero is the origin).
pub fn gravity_energy(model: &Model, p: &Particles) -> f64 {
    let Some(g) = model.effects.gravity else {
        return 0.0;
    };
    let g = crate::state::Vec3::from(g);
    -(0..p.n_fluid)
        .map(|i| model.mass[p.phase[i] as usize] * g.dot(&p.pos[i]))
        .sum::<f64>()
}

/// Potential energy of the liquid–wall repulsion [J] (zero without it): the repulsion is a
/// central force between a liquid particle and a fixed wall particle, so it is conservative
/// with the pair energy `Φ(r) = D [((r0/r)¹² − 1)/12 − ((r0/r)⁴ − 1)/4]` for `r < r0`, zero
/// beyond ([`Monaghan1994WallRepulsion::pair_energy`]).
pub fn wall_repulsion_energy(model: &Model, p: &Particles, lists: &NeighbourLists) -> f64 {
    if !model.effects.wall_repulsion {
        return 0.0;
    }
    let term = Monaghan1994WallRepulsion {
        strength_j: &model.wall_repulsion_strength_j,
        range_m: model.wall_repulsion_range_m,
    };
    let mut e = 0.0;
    for i in 0..p.n_fluid {
        let d = model.wall_repulsion_strength_j[p.phase[i] as usize];
        for j in lists.all(i) {
            if j >= p.n_fluid {
                e += term.pair_energy(d, lists.delta(p.pos[i], p.pos[j]).norm());
            }
        }
    }
    e
}
