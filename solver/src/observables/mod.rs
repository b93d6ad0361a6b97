//! Observables of the state, computed at output steps.
//!
//! Sums run serially in particle order, which is fixed by the state (not by the thread count),
//! so the values are reproducible bit for bit.
//!
//! The energy budget: the kinetic, interfacial, compression, gravitational and wall-repulsion
//! energies are functions of the state ([`energy`]); what the dissipative terms and the
//! density re-initialisation took out is booked at every step by the simulation
//! ([`Dissipation`]). Their sum, [`Observables::energy_balance_j`], is constant up to the
//! time integration's error and the parts of the model that are not conservative (see
//! [`energy`]).

mod energy;
mod stress;

pub use energy::{compression_energy, gravity_energy, interfacial_energy, wall_repulsion_energy};
pub use stress::particle_virials;

use crate::model::Model;
use crate::neighbours::NeighbourLists;
use crate::physics::forces::{Dissipation, Ledger};
use crate::state::{Particles, Vec3};
use serde::{Deserialize, Serialize};

/// Statistics of one liquid phase.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct PhaseStats {
    /// Phase name.
    pub name: String,
    /// Number of particles.
    pub count: usize,
    /// Mass [kg].
    pub mass_kg: f64,
    /// Mass centroid [m].
    pub centroid_m: [f64; 3],
    /// Velocity of the centroid [m/s].
    pub centroid_velocity_m_s: [f64; 3],
    /// Extent (max − min of particle positions) along x, y, z [m].
    pub extent_m: [f64; 3],
    /// Lowest particle position along x, y, z [m].
    pub min_m: [f64; 3],
    /// Highest particle position along x, y, z [m].
    pub max_m: [f64; 3],
    /// Kinetic energy [J].
    pub kinetic_energy_j: f64,
}

/// Observables of the whole system at one instant.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Observables {
    /// Simulated time [s].
    pub time_s: f64,
    /// Last time step [s].
    pub dt_s: f64,
    /// Steps taken.
    pub step: u64,
    /// Per liquid phase.
    pub phases: Vec<PhaseStats>,
    /// Total kinetic energy [J].
    pub kinetic_energy_j: f64,
    /// Interfacial (potential) energy relative to the bulk liquids and the dry solids [J]:
    /// `Σ_i [½ C_aa B − ½ Σ_{j liquid} C_ij P(r_ij) − Σ_{w wall} C_iw P(r_iw)]`, `B` the bulk
    /// lattice sum. On a lattice it equals σ times the free area (docs/model.md §4).
    pub interfacial_energy_j: f64,
    /// Compression (EOS) energy of the liquid [J] ([`compression_energy`]).
    pub compression_energy_j: f64,
    /// Gravitational potential energy `−Σ m g·x` [J] (zero without gravity).
    pub gravity_energy_j: f64,
    /// Potential energy of the liquid–wall repulsion [J] (zero without it,
    /// [`wall_repulsion_energy`]).
    pub wall_repulsion_energy_j: f64,
    /// Energy dissipated by laminar viscosity between liquid particles since the start [J].
    pub dissipated_laminar_j: f64,
    /// Energy the liquid lost through laminar viscosity at no-slip walls since the start [J]:
    /// the work of the liquid–wall pair forces, `−∫ Σ f_iw·v_i dt`. The walls' ghost velocity
    /// (Adami 2012) mirrors the liquid's, so this is mostly the dissipation of the layer next
    /// to the wall, but it is not sign-definite step by step.
    pub dissipated_laminar_walls_j: f64,
    /// Energy dissipated by artificial viscosity since the start [J].
    pub dissipated_artificial_j: f64,
    /// Energy the liquid lost to the walls' own pressure `p_w V_w²` since the start [J]: not
    /// a physical dissipation but the work of a force that is the gradient of no energy (the
    /// extrapolated wall pressure, Adami 2012); either sign. In the difference form it is the
    /// wall pairs' whole departure from `−p_i V_i² ∇_i W_iw`, the compression energy's part.
    pub dissipated_wall_pressure_j: f64,
    /// Energy the liquid lost to the difference form of the pressure force beyond the
    /// symmetric form's work since the start [J] (zero with the symmetric form): the work of
    /// `−V_i Σ_j V_j (p_j − p_i) ∇_i W_ij + Σ_j (p_i V_i² + p_j V_j²) ∇_i W_ij`, which is the
    /// gradient of no energy; either sign.
    pub dissipated_pressure_difference_j: f64,
    /// Compression energy removed by the density re-initialisations since the start [J]
    /// (either sign).
    pub dissipated_density_reinit_j: f64,
    /// Energy the particle shifting took out since the start [J] (either sign; first order
    /// in the shift, see [`crate::physics::forces::ledger::Dissipation::shifting_j`]).
    pub dissipated_shifting_j: f64,
    /// The energy budget [J]: kinetic + interfacial + compression + gravity + wall repulsion
    /// + everything dissipated. Constant for a conservative discretisation.
    pub energy_balance_j: f64,
    /// The work of the continuum models' interfacial force on the liquid since the start [J]
    /// (zero under the pairwise potential; not in the budget, which counts their interfacial
    /// energy estimate instead: [`crate::physics::forces::ledger::InterfacialWork`]).
    #[serde(default)]
    pub interfacial_force_work_j: f64,
    /// Total momentum [kg m/s].
    pub momentum_kg_m_s: [f64; 3],
    /// Largest particle speed [m/s].
    pub max_speed_m_s: f64,
    /// Largest `|ρ/ρ0 − 1|` over fluid particles [-].
    pub max_density_deviation: f64,
    /// Largest compression `ρ/ρ0 − 1` over fluid particles [-] (expansion at a free surface
    /// excluded).
    pub max_compression: f64,
}

/// Computes the observables of `p` at time `time_s` [s], with the energy dissipated so far;
/// `surface_stress_energy_j` [J] is the continuum surface stress's interfacial energy of the
/// state (zero without it: it is computed with the stress itself).
#[allow(clippy::too_many_arguments)]
pub fn observe(
    model: &Model,
    p: &Particles,
    lists: &NeighbourLists,
    surface_stress_energy_j: f64,
    dissipation: &Dissipation,
    time_s: f64,
    dt_s: f64,
    step: u64,
) -> Observables {
    let nl = model.n_liquids;
    let mut phases: Vec<PhaseStats> = (0..nl)
        .map(|a| PhaseStats {
            name: model.phase_names[a].clone(),
            min_m: [f64::INFINITY; 3],
            max_m: [f64::NEG_INFINITY; 3],
            ..Default::default()
        })
        .collect();
    let mut momentum = Vec3::zeros();
    let mut max_speed2: f64 = 0.0;
    let mut max_dev: f64 = 0.0;
    let mut max_comp = f64::NEG_INFINITY;
    let mut mx = vec![Vec3::zeros(); nl];
    let mut mv = vec![Vec3::zeros(); nl];
    for i in 0..p.n_fluid {
        let a = p.phase[i] as usize;
        let m = model.mass[a];
        let (x, v) = (p.pos[i], p.vel[i]);
        let s = &mut phases[a];
        s.count += 1;
        s.mass_kg += m;
        mx[a] += x * m;
        mv[a] += v * m;
        s.kinetic_energy_j += 0.5 * m * v.norm_squared();
        for k in 0..3 {
            s.min_m[k] = s.min_m[k].min(x[k]);
            s.max_m[k] = s.max_m[k].max(x[k]);
        }
        momentum += v * m;
        max_speed2 = max_speed2.max(v.norm_squared());
        let dev = p.rho[i] / model.rho0[a] - 1.0;
        max_dev = max_dev.max(dev.abs());
        max_comp = max_comp.max(dev);
    }
    for (a, s) in phases.iter_mut().enumerate() {
        if s.count > 0 {
            s.centroid_m = (mx[a] / s.mass_kg).into();
            s.centroid_velocity_m_s = (mv[a] / s.mass_kg).into();
            for k in 0..3 {
                s.extent_m[k] = s.max_m[k] - s.min_m[k];
            }
        } else {
            s.min_m = [f64::NAN; 3];
            s.max_m = [f64::NAN; 3];
        }
    }
    let kinetic_energy_j: f64 = phases.iter().map(|s| s.kinetic_energy_j).sum();
    let interfacial_energy_j = interfacial_energy(model, p, lists) + surface_stress_energy_j;
    let compression_energy_j = compression_energy(model, p);
    let gravity_energy_j = gravity_energy(model, p);
    let wall_repulsion_energy_j = wall_repulsion_energy(model, p, lists);
    let d = dissipation;
    Observables {
        time_s,
        dt_s,
        step,
        kinetic_energy_j,
        phases,
        interfacial_energy_j,
        compression_energy_j,
        gravity_energy_j,
        wall_repulsion_energy_j,
        dissipated_laminar_j: d.of(Ledger::Laminar, false),
        dissipated_laminar_walls_j: d.of(Ledger::Laminar, true),
        // booked on one side each (between liquid particles; with wall particles): the other
        // side stays zero
        dissipated_artificial_j: d.of(Ledger::Artificial, false) + d.of(Ledger::Artificial, true),
        dissipated_wall_pressure_j: d.of(Ledger::Pressure, true),
        dissipated_pressure_difference_j: d.of(Ledger::Pressure, false),
        dissipated_density_reinit_j: d.density_reinit_j,
        dissipated_shifting_j: d.shifting_j,
        energy_balance_j: kinetic_energy_j
            + interfacial_energy_j
            + compression_energy_j
            + gravity_energy_j
            + wall_repulsion_energy_j
            + d.total_j(),
        interfacial_force_work_j: d.interfacial.work_j,
        momentum_kg_m_s: momentum.into(),
        max_speed_m_s: max_speed2.sqrt(),
        max_density_deviation: max_dev,
        max_compression: max_comp,
    }
}
