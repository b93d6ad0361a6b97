//! The time step: kick–drift–kick with an adaptive step.
//!
//! One step, from `(x_n, v_n, ρ_n, a_n)`:
//! 1. choose `dt` (fixed, or the minimum over the active constraints, docs/model.md §3);
//! 2. kick and drift: `v ← v + ½dt a`, `x ← x + dt v` (continuity: `ρ ← ρ + dt dρ/dt`, a
//!    predictor);
//! 3. rebuild the neighbour lists if a particle moved half the skin (re-sorting by cell);
//! 4. density (summation), EOS, wall pressures, pair forces → `a_{n+1}` (velocities at the
//!    half step enter the viscous terms) — `evaluate.rs`;
//! 5. kick: `v ← v + ½dt a_{n+1}` (continuity: trapezoidal corrector `ρ ← ρ + ½dt (D_{n+1} −
//!    D_n)`), health check, and periodic density re-initialisation.
//!
//! With implicit viscosity both kicks also solve the laminar term by backward Euler at the
//! kick's positions (`viscous.rs`), and the drift uses the first kick's result.
//!
//! Each kick also books the work of the dissipative terms in it (the energy budget,
//! [`crate::physics::forces::ledger`]): a few multiplications per step, from the power the
//! force loop returns.
//!
//! The step reads only the resolved [`Model`]; the scene is kept for checkpoints and records.

pub mod calibration;
mod evaluate;
mod force_terms;
mod limits;
mod neighbours;
mod shifting;
mod viscous;

pub use viscous::ViscousSolves;

use crate::error::SimError;
use crate::health;
use crate::kernel::Kernel;
use crate::model::Model;
use crate::neighbours::NeighbourSearch;
use crate::observables::{observe, Observables};
use crate::physics::forces::Dissipation;
use crate::physics::surface_tension::surface_force::Walls;
use crate::scene::{Scene, TensionCalibration};
use crate::setup::{build_particles, Inventory};
use crate::state::Particles;
use crate::with_kernel;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use std::time::Instant;

/// Wall-clock time spent in each part of the step since the start [s].
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct StepTimings {
    /// Neighbour search (sorting and list building).
    pub search_s: f64,
    /// Density (summation or re-initialisation), EOS and wall pressures.
    pub density_s: f64,
    /// Pair forces.
    pub forces_s: f64,
    /// Kicks, drift (and particle shifting, if on) and health checks.
    pub integration_s: f64,
}

/// A running simulation.
#[derive(Clone, Debug)]
pub struct Simulation {
    /// The scene as resolved (defaults filled in): what checkpoints and run records store.
    pub scene: Scene,
    /// The resolved model: everything the step reads.
    pub model: Model,
    /// The particles.
    pub particles: Particles,
    /// Neighbour search and lists.
    pub search: NeighbourSearch,
    /// Per wall particle: no-slip?
    pub wall_no_slip: Vec<bool>,
    /// Particles per body and wall.
    pub inventory: Inventory,
    /// Simulated time [s].
    pub time_s: f64,
    /// Steps taken.
    pub step: u64,
    /// Last time step [s].
    pub last_dt_s: f64,
    /// Time per part of the step.
    pub timings: StepTimings,
    /// The energy the dissipative terms and the density re-initialisation took out so far,
    /// and the booked power of the current accelerations.
    pub dissipation: Dissipation,
    pub(crate) max_speed2: f64,
    pub(crate) max_acc2: f64,
    /// The stable step of the initial state [s] (for the collapse check).
    pub(crate) first_dt_s: f64,
    drho_next: Vec<f64>,
    /// This step's shifting displacement per fluid particle [m] (empty without shifting).
    shift: Vec<crate::state::Vec3>,
    /// Scratch of the far pass, kept between steps.
    far_spills: crate::physics::forces::pairs_once::Spills,
    /// The continuum surface stress of the current state (empty without it).
    pub surface_stress: crate::physics::surface_tension::surface_stress::StressScratch,
    /// The continuum surface force's scratch (empty unless the scene chose it).
    pub surface_force: crate::physics::surface_tension::surface_force::ForceScratch,
    /// The non-affine viscosity's scratch (empty without it).
    nonaffine: NonAffineScratch,
    /// Scratch of the fluid's re-sort, kept between rebuilds.
    rebuild: neighbours::RebuildScratch,
    /// The implicit viscous solves of this process (zero without implicit viscosity).
    pub viscous_solves: ViscousSolves,
    /// Scratch of the implicit viscous solve, kept between steps.
    viscous: viscous::ViscousScratch,
}

/// The non-affine viscosity's fitted gradients [1/s] and force [N] per fluid particle, kept
/// between steps.
#[derive(Clone, Debug, Default)]
struct NonAffineScratch {
    gradient: Vec<nalgebra::Matrix3<f64>>,
    force: Vec<crate::state::Vec3>,
}

impl Simulation {
    /// Builds the particles of a scene, evaluates the initial forces and checks that the scene
    /// can afford its time step.
    pub fn new(scene: &Scene) -> Result<Simulation, SimError> {
        let mut sim = Simulation::assemble(scene)?;
        sim.sort_walls()?;
        sim.rebuild_neighbours()?;
        with_kernel!(sim.model.kernel, K => sim.evaluate::<K>());
        sim.health()?;
        sim.first_dt_s = sim.step_limits().min().0;
        sim.check_affordable()?;
        Ok(sim)
    }

    /// The simulation of a scene at time zero before anything is computed: the model, the
    /// particles as built (walls unsorted, no lists), an empty search. Shared by
    /// [`Simulation::new`] and [`Simulation::resume`](crate::checkpoint).
    pub(crate) fn assemble(scene: &Scene) -> Result<Simulation, SimError> {
        scene.validate()?;
        let mut model = Model::from_scene(scene)?;
        if scene.discretisation.tension_calibration == TensionCalibration::RelaxedSlab
            && model.effects.interfacial_tension
        {
            let t = calibration::tension_scales(scene, calibration::SlabDesign::default())?;
            model.scale_tension(&t.liquids);
            for &(a, b, f) in &t.pairs {
                model.scale_pair_tension(a, b, f);
            }
        }
        let (particles, wall_no_slip, inventory) = build_particles(scene, &model)?;
        let mut search = NeighbourSearch::new(
            model.support_m,
            model.interaction_radius_m,
            model.neighbour_skin_m,
        );
        search.set_periodic(model.periodic);
        // the surface force's colour gradient at walls reaches r_e from the wall side
        search.walls_reach_far = model.surface_force_walls != Walls::Absent;
        let drho_next = if model.effects.continuity() {
            vec![0.0; particles.n_fluid]
        } else {
            Vec::new()
        };
        let shift = if model.effects.particle_shifting.is_some() {
            vec![crate::state::Vec3::zeros(); particles.n_fluid]
        } else {
            Vec::new()
        };
        Ok(Simulation {
            scene: scene.clone(),
            model,
            particles,
            search,
            wall_no_slip,
            inventory,
            time_s: 0.0,
            step: 0,
            last_dt_s: 0.0,
            timings: StepTimings::default(),
            dissipation: Dissipation::default(),
            max_speed2: 0.0,
            max_acc2: 0.0,
            first_dt_s: 0.0,
            drho_next,
            far_spills: Default::default(),
            surface_stress: Default::default(),
            surface_force: Default::default(),
            rebuild: Default::default(),
            nonaffine: Default::default(),
            viscous_solves: Default::default(),
            viscous: Default::default(),
            shift,
        })
    }

    /// Advances one step, no longer than `max_dt_s` [s]; returns the step taken [s].
    pub fn step(&mut self, max_dt_s: f64) -> Result<f64, SimError> {
        with_kernel!(self.model.kernel, K => self.step_with::<K>(max_dt_s))
    }

    fn step_with<K: Kernel>(&mut self, max_dt_s: f64) -> Result<f64, SimError> {
        let dt = self.next_dt().min(max_dt_s);
        let half = 0.5 * dt;
        let continuity = self.model.effects.continuity();
        let t0 = Instant::now();
        if let Some(a) = self.model.effects.particle_shifting {
            self.shift_particles::<K>(a, dt);
        }
        let implicit = self.model.effects.implicit_viscosity.is_some();
        if implicit {
            // the kick with the viscous solve (its time goes to the forces'), then the drift
            let tv = Instant::now();
            self.implicit_kick::<K>(half)?;
            self.timings.integration_s -= tv.elapsed().as_secs_f64();
            let p = &mut self.particles;
            let nf = p.n_fluid;
            p.pos[..nf]
                .par_iter_mut()
                .zip(p.vel[..nf].par_iter())
                .for_each(|(x, v)| *x += *v * dt);
        } else {
            let p = &mut self.particles;
            let nf = p.n_fluid;
            p.vel[..nf]
                .par_iter_mut()
                .zip(p.pos[..nf].par_iter_mut())
                .zip(p.acc.par_iter())
                .for_each(|((v, x), a)| {
                    *v += a * half;
                    *x += *v * dt;
                });
            // the booked terms' work in this kick, at its mean velocity (physics::forces::ledger)
            self.dissipation.kick(half);
        }
        {
            let p = &mut self.particles;
            let nf = p.n_fluid;
            if continuity {
                p.rho[..nf]
                    .par_iter_mut()
                    .zip(p.drho.par_iter())
                    .for_each(|(r, d)| *r += dt * d);
            }
        }
        self.timings.integration_s += t0.elapsed().as_secs_f64();

        let nf = self.particles.n_fluid;
        if self
            .search
            .needs_rebuild(&self.particles.pos[..nf], &self.particles.x_ref)
        {
            self.rebuild_neighbours()?;
        }
        self.evaluate::<K>();

        let t0 = Instant::now();
        if implicit {
            let tv = Instant::now();
            self.implicit_kick::<K>(half)?;
            self.timings.integration_s -= tv.elapsed().as_secs_f64();
        } else {
            let p = &mut self.particles;
            p.vel[..nf]
                .par_iter_mut()
                .zip(p.acc.par_iter())
                .for_each(|(v, a)| *v += a * half);
            self.dissipation.kick(half); // likewise, with the new accelerations
        }
        {
            let p = &mut self.particles;
            if continuity {
                p.rho[..nf]
                    .par_iter_mut()
                    .zip(self.drho_next.par_iter().zip(p.drho.par_iter()))
                    .for_each(|(r, (dn, d))| *r += half * (dn - d));
                std::mem::swap(&mut p.drho, &mut self.drho_next);
            }
        }
        self.time_s += dt;
        self.step += 1;
        self.last_dt_s = dt;
        self.timings.integration_s += t0.elapsed().as_secs_f64();
        self.health()?;
        self.reinitialise_density::<K>();
        Ok(dt)
    }

    /// Updates the speed and acceleration maxima and checks the state against the scene's
    /// health bounds ([`crate::health`]).
    fn health(&mut self) -> Result<(), SimError> {
        let ex = health::extremes(&self.particles, &self.model.rho0);
        self.max_speed2 = ex.speed2.0;
        self.max_acc2 = ex.acc2.0;
        health::check(&health::Context {
            model: &self.model,
            particles: &self.particles,
            step: self.step,
            time_s: self.time_s,
            extremes: ex,
            limits: self.step_limits(),
            dt_s: self.last_dt_s,
            first_dt_s: self.first_dt_s,
        })
    }

    /// Mean number of neighbours per fluid particle within the largest interaction radius
    /// (kernel support, or `r_e` with interfacial tension) — the pairs a step evaluates per
    /// particle; the lists hold a few more (the Verlet skin).
    pub fn mean_neighbours(&self) -> f64 {
        let p = &self.particles;
        let r = self.search.far_radius_m;
        let r2 = r * r;
        let lists = &self.search.lists;
        let total: usize = (0..p.n_fluid)
            .into_par_iter()
            .map(|i| {
                let within = |&j: &usize| lists.delta(p.pos[i], p.pos[j]).norm_squared() < r2;
                // a far pair of two liquid particles is listed once and counts for both
                let far: usize = lists
                    .far(i)
                    .filter(within)
                    .map(|j| if j < p.n_fluid { 2 } else { 1 })
                    .sum();
                lists.near(i).filter(within).count() + far
            })
            .sum();
        total as f64 / p.n_fluid.max(1) as f64
    }

    /// Observables of the current state.
    pub fn observe(&self) -> Observables {
        observe(
            &self.model,
            &self.particles,
            &self.search.lists,
            self.surface_stress.interface_energy_j + self.surface_force.interface_energy_j,
            &self.dissipation,
            self.time_s,
            self.last_dt_s,
            self.step,
        )
    }
}
