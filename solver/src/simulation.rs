//! The time step: kick–drift–kick with an adaptive step.
//!
//! One step, from `(x_n, v_n, ρ_n, a_n)`:
//! 1. choose `dt` (fixed, or the minimum over the active constraints, physics.md §3);
//! 2. kick and drift: `v ← v + ½dt a`, `x ← x + dt v` (continuity: `ρ ← ρ + dt dρ/dt`, a
//!    predictor);
//! 3. rebuild the neighbour lists if a particle moved half the skin (re-sorting by cell);
//! 4. density (summation), EOS, wall pressures, pair forces → `a_{n+1}` (velocities at the
//!    half step enter the viscous terms);
//! 5. kick: `v ← v + ½dt a_{n+1}` (continuity: trapezoidal corrector `ρ ← ρ + ½dt (D_{n+1} −
//!    D_n)`), health check, and periodic density re-initialisation.

use crate::error::SimError;
use crate::health;
use crate::kernel::Kernel;
use crate::model::Model;
use crate::neighbours::NeighbourSearch;
use crate::observables::{observe, Observables};
use crate::physics::{density, forces, walls};
use crate::scene::{DensityScheme, NegativePressure, Reinit, Scene, SceneError};
use crate::setup::{build_particles, Inventory};
use crate::state::{Particles, Vec3};
use crate::timestep::StepLimits;
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
    /// Kicks, drift and health checks.
    pub integration_s: f64,
}

/// A running simulation.
#[derive(Clone, Debug)]
pub struct Simulation {
    /// The resolved model.
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
    pub(crate) max_speed2: f64,
    pub(crate) max_acc2: f64,
    /// The stable step of the initial state [s] (for the collapse check).
    pub(crate) first_dt_s: f64,
    drho_next: Vec<f64>,
}

impl Simulation {
    /// Builds the particles of a scene, evaluates the initial forces and checks that the scene
    /// can afford its time step.
    pub fn new(scene: &Scene) -> Result<Simulation, SimError> {
        scene.validate()?;
        let model = Model::from_scene(scene)?;
        let (particles, no_slip, inventory) = build_particles(scene, &model)?;
        let far = if model.effects.interfacial_tension {
            model.r_e_m
        } else {
            model.support_m
        };
        let skin = scene.discretisation.neighbour_skin_over_l0 * model.l0_m;
        let search = NeighbourSearch::new(model.support_m, far, skin);
        let n_fluid = particles.n_fluid;
        let continuity = scene.density.scheme == DensityScheme::Continuity;
        let mut sim = Simulation {
            model,
            particles,
            search,
            wall_no_slip: no_slip,
            inventory,
            time_s: 0.0,
            step: 0,
            last_dt_s: 0.0,
            timings: StepTimings::default(),
            max_speed2: 0.0,
            max_acc2: 0.0,
            first_dt_s: 0.0,
            drho_next: if continuity {
                vec![0.0; n_fluid]
            } else {
                Vec::new()
            },
        };
        sim.sort_walls()?;
        sim.rebuild_neighbours()?;
        with_kernel!(sim.model.kernel, K => sim.evaluate::<K>());
        sim.health()?;
        sim.first_dt_s = sim.step_limits().min().0;
        sim.check_affordable()?;
        Ok(sim)
    }

    /// Assembles a simulation from restored parts (see [`crate::checkpoint`]).
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn from_parts(
        model: Model,
        particles: Particles,
        search: NeighbourSearch,
        wall_no_slip: Vec<bool>,
        inventory: Inventory,
        (time_s, step, last_dt_s): (f64, u64, f64),
        (max_speed2, max_acc2, first_dt_s): (f64, f64, f64),
        timings: StepTimings,
        n_fluid: usize,
    ) -> Simulation {
        Simulation {
            model,
            particles,
            search,
            wall_no_slip,
            inventory,
            time_s,
            step,
            last_dt_s,
            timings,
            max_speed2,
            max_acc2,
            first_dt_s,
            drho_next: vec![0.0; n_fluid],
        }
    }

    fn sort_walls(&mut self) -> Result<(), SimError> {
        let nf = self.particles.n_fluid;
        let perm = self
            .search
            .sort_order(&self.particles.pos[nf..])
            .map_err(|source| SimError::Escaped { step: 0, source })?;
        fn gather<T: Copy>(v: &mut [T], perm: &[u32]) {
            let old = v.to_vec();
            for (k, &p) in perm.iter().enumerate() {
                v[k] = old[p as usize];
            }
        }
        let p = &mut self.particles;
        gather(&mut p.pos[nf..], &perm);
        gather(&mut p.vel[nf..], &perm);
        gather(&mut p.rho[nf..], &perm);
        gather(&mut p.pressure[nf..], &perm);
        gather(&mut p.vol[nf..], &perm);
        gather(&mut p.phase[nf..], &perm);
        gather(&mut p.id[nf..], &perm);
        gather(&mut self.wall_no_slip, &perm);
        Ok(())
    }

    /// Re-sorts the fluid particles by cell and rebuilds the neighbour lists.
    fn rebuild_neighbours(&mut self) -> Result<(), SimError> {
        let t0 = Instant::now();
        let nf = self.particles.n_fluid;
        let step = self.step;
        let perm = self
            .search
            .sort_order(&self.particles.pos[..nf])
            .map_err(|source| SimError::Escaped { step, source })?;
        self.particles.permute_fluid(&perm);
        self.particles
            .x_ref
            .copy_from_slice(&self.particles.pos[..nf]);
        self.search
            .build(&self.particles.pos, nf)
            .map_err(|source| SimError::Escaped { step, source })?;
        self.timings.search_s += t0.elapsed().as_secs_f64();
        Ok(())
    }

    /// The time-step limits of the current state.
    pub fn step_limits(&self) -> StepLimits {
        let m = &self.model;
        let f = &m.scene.time.factors;
        let (viscous_s, capillary_s) = m.static_step_limits();
        let a = self.max_acc2.sqrt();
        StepLimits {
            cfl_s: f.cfl * m.h_m / (m.c_m_s + self.max_speed2.sqrt()),
            viscous_s,
            capillary_s,
            force_s: if a > 0.0 {
                f.force * (m.h_m / a).sqrt()
            } else {
                f64::INFINITY
            },
        }
    }

    /// The step the next [`Simulation::step`] will take without a cap [s].
    pub fn next_dt(&self) -> f64 {
        self.model
            .scene
            .time
            .dt
            .unwrap_or_else(|| self.step_limits().min().0)
    }

    fn check_affordable(&self) -> Result<(), SimError> {
        let t = &self.model.scene.time;
        let (stable, which) = self.step_limits().min();
        if let Some(dt) = t.dt {
            if dt > stable {
                return Err(SceneError::invalid(
                    "time.dt",
                    dt,
                    format!(
                        "the fixed step exceeds the {which} limit of {stable:e} s; use a step \
                         at most that, or omit time.dt for the adaptive step"
                    ),
                )
                .into());
            }
        }
        let dt = t.dt.unwrap_or(stable);
        let steps = t.end / dt;
        if steps > t.max_steps as f64 {
            return Err(SceneError::invalid(
                "time.max_steps",
                t.max_steps,
                format!(
                    "time.end = {:e} s at dt = {dt:e} s (set by the {which} limit) needs at least \
                     {steps:.3e} steps; shorten the run, coarsen l0, or raise time.max_steps",
                    t.end
                ),
            )
            .into());
        }
        Ok(())
    }

    /// Advances one step, no longer than `max_dt_s` [s]; returns the step taken [s].
    pub fn step(&mut self, max_dt_s: f64) -> Result<f64, SimError> {
        with_kernel!(self.model.kernel, K => self.step_with::<K>(max_dt_s))
    }

    fn step_with<K: Kernel>(&mut self, max_dt_s: f64) -> Result<f64, SimError> {
        let dt = self.next_dt().min(max_dt_s);
        let half = 0.5 * dt;
        let continuity = self.model.effects.density == DensityScheme::Continuity;
        let t0 = Instant::now();
        {
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
        {
            let p = &mut self.particles;
            p.vel[..nf]
                .par_iter_mut()
                .zip(p.acc.par_iter())
                .for_each(|(v, a)| *v += a * half);
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

    /// Density, EOS, walls and forces at the current positions.
    fn evaluate<K: Kernel>(&mut self) {
        let t0 = Instant::now();
        let m = &self.model;
        let k = K::new(m.h_m);
        let search = &mut self.search;
        let p = &mut self.particles;
        let nf = p.n_fluid;
        if m.effects.density == DensityScheme::Summation {
            // the pairs that interact: within the search's far radius — the support, or r_e
            // with the potential if larger
            let active_radius = search.far_radius_m;
            density::summation(
                &k,
                &p.pos,
                &p.phase,
                &m.rho0,
                &search.lists,
                m.lattice_kernel_sum,
                active_radius,
                &mut p.rho[..nf],
                &mut search.active,
            );
        }
        let lists = &self.search.lists;
        let eos = m.eos;
        let clip = m.scene.density.negative_pressure == NegativePressure::Clip;
        p.pressure[..nf]
            .par_iter_mut()
            .zip(p.vol[..nf].par_iter_mut())
            .zip(p.rho[..nf].par_iter().zip(p.phase[..nf].par_iter()))
            .for_each(|((pr, v), (&r, &ph))| {
                let p = eos.pressure(r, m.rho0[ph as usize]);
                // physics.md §2: tension from a deficient density would act as an extra,
                // uncontrolled surface tension; the potential alone carries cohesion
                *pr = if clip { p.max(0.0) } else { p };
                *v = m.mass[ph as usize] / r;
            });
        if m.effects.walls {
            walls::update(
                &k,
                &eos,
                p,
                lists,
                &m.rho0,
                m.rest_volume_m3,
                m.effects.gravity.map(Vec3::from),
                &self.wall_no_slip,
            );
        }
        let t1 = Instant::now();
        self.timings.density_s += (t1 - t0).as_secs_f64();

        let e = &m.effects;
        // the accelerations are written while the rest of the state is read
        let mut acc = std::mem::take(&mut p.acc);
        let inp = forces::ForceInput::new(k, m, p, &self.wall_no_slip, &self.search);
        forces::dispatch(
            &inp,
            e.laminar_viscosity,
            e.artificial_viscosity.is_some(),
            e.interfacial_tension,
            e.walls,
            e.density == DensityScheme::Continuity,
            &mut acc,
            &mut self.drho_next,
        );
        self.particles.acc = acc;
        self.timings.forces_s += t1.elapsed().as_secs_f64();
    }

    fn reinitialise_density<K: Kernel>(&mut self) {
        let Some((method, every)) = self.model.effects.density_reinit else {
            return;
        };
        if self.step % every as u64 != 0 {
            return;
        }
        let t0 = Instant::now();
        let m = &self.model;
        let k = K::new(m.h_m);
        let p = &self.particles;
        let lists = &self.search.lists;
        let new = match method {
            Reinit::Shepard => {
                density::shepard(&k, &p.pos, &p.phase, &m.mass, &p.rho, lists, p.n_fluid)
            }
            Reinit::Mls => density::mls(
                &k, &p.pos, &p.phase, &m.mass, &p.rho, lists, p.n_fluid, m.l0_m,
            ),
            Reinit::None => return,
        };
        self.particles.rho[..new.len()].copy_from_slice(&new);
        self.timings.density_s += t0.elapsed().as_secs_f64();
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
        let total: usize = (0..p.n_fluid)
            .into_par_iter()
            .map(|i| {
                self.search
                    .lists
                    .all(i)
                    .iter()
                    .filter(|&&j| (p.pos[i] - p.pos[j as usize]).norm_squared() < r2)
                    .count()
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
            self.time_s,
            self.last_dt_s,
            self.step,
        )
    }
}
