//! The right-hand side at the current positions: density, EOS, wall values, then the pair
//! forces (assembled in [`super::force_terms`]); and the periodic density re-initialisation.

use super::Simulation;
use crate::kernel::Kernel;
use crate::model::ContinuumForm;
use crate::observables::compression_energy;
use crate::physics::surface_tension::surface_stress::StressInput;
use crate::physics::{density, walls};
use crate::scene::{DensityScheme, Reinit};
use crate::state::Vec3;
use rayon::prelude::*;
use std::time::Instant;

impl Simulation {
    /// Density, EOS, walls and forces at the current positions.
    pub(super) fn evaluate<K: Kernel>(&mut self) {
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
        let clip = m.effects.clip_negative_pressure;
        p.pressure[..nf]
            .par_iter_mut()
            .zip(p.vol[..nf].par_iter_mut())
            .zip(p.rho[..nf].par_iter().zip(p.phase[..nf].par_iter()))
            .for_each(|((pr, v), (&r, &ph))| {
                let p = eos.pressure(r, m.rho0[ph as usize]);
                // docs/model.md §2: tension from a deficient density would act as an extra,
                // uncontrolled surface tension; the potential alone carries cohesion
                *pr = if clip { p.max(0.0) } else { p };
                *v = m.mass[ph as usize] / r;
            });
        if m.background_pressure_pa != 0.0 {
            let p_bg = m.background_pressure_pa;
            p.pressure[..nf].par_iter_mut().for_each(|pr| *pr += p_bg);
        }
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

        // the accelerations and rates are written while the rest of the state is read
        let mut acc = std::mem::take(&mut self.particles.acc);
        let mut drho = std::mem::take(&mut self.drho_next);
        self.dissipation.power = self.pair_forces::<K>(&mut acc, &mut drho);
        if let Some(form) = self.model.effects.continuum_tension {
            self.add_continuum_tension::<K>(form, &mut acc);
        }
        if let Some(alpha) = self.model.effects.nonaffine_viscosity {
            self.add_nonaffine_viscosity::<K>(alpha, &mut acc);
        }
        self.particles.acc = acc;
        self.drho_next = drho;
        self.book_continuum_tension();
        self.book_nonaffine_viscosity();
        self.timings.forces_s += t1.elapsed().as_secs_f64();
    }

    /// Sets the continuum tension's power `P = Σ F·v` [W] and `Q = Σ F·a` [W/s] at the
    /// velocities the forces were evaluated with and the new accelerations, for the kicks to
    /// book its work ([`crate::physics::forces::ledger::InterfacialWork`]); zero without it.
    /// Summed serially in particle order: the same bits for any thread count.
    fn book_continuum_tension(&mut self) {
        let force = match self.model.effects.continuum_tension {
            Some(ContinuumForm::Stress) => &self.surface_stress.force,
            Some(ContinuumForm::Force) => &self.surface_force.force,
            None => return,
        };
        let (velocity_w, acceleration_w_s) = power(force, &self.particles);
        let w = &mut self.dissipation.interfacial;
        w.velocity_w = velocity_w;
        w.acceleration_w_s = acceleration_w_s;
    }

    /// Adds the non-affine viscosity's accelerations [m/s²] at the current velocities to `acc`
    /// (`μ_na = α ρ̄ c h`, [`crate::physics::nonaffine_viscosity`]); keeps its force for the
    /// booking.
    fn add_nonaffine_viscosity<K: Kernel>(&mut self, alpha: f64, acc: &mut [Vec3]) {
        use crate::physics::nonaffine_viscosity as na;
        let m = &self.model;
        let p = &self.particles;
        let inp = na::Input {
            kernel: K::new(m.h_m),
            pos: &p.pos,
            vel: &p.vel,
            vol: &p.vol,
            phase: &p.phase,
            nu_m2_s: alpha * m.c_m_s * m.h_m,
            rho0: &m.rho0,
            n_fluid: p.n_fluid,
            lists: &self.search.lists,
        };
        let s = &mut self.nonaffine;
        na::gradients(&inp, &mut s.gradient);
        na::forces(&inp, &s.gradient, &mut s.force);
        acc.par_iter_mut()
            .zip(s.force.par_iter().zip(p.phase.par_iter()))
            .for_each(|(a, (f, &ph))| *a += f / m.mass[ph as usize]);
    }

    /// Sets the non-affine viscosity's `P = Σ F·v` [W] and `Q = Σ F·a` [W/s] for the kicks
    /// (as [`Self::book_continuum_tension`]); zero without it.
    fn book_nonaffine_viscosity(&mut self) {
        if self.model.effects.nonaffine_viscosity.is_none() {
            return;
        }
        let (velocity_w, acceleration_w_s) = power(&self.nonaffine.force, &self.particles);
        let w = &mut self.dissipation.nonaffine;
        w.velocity_w = velocity_w;
        w.acceleration_w_s = acceleration_w_s;
    }

    /// Adds the continuum tension's accelerations [m/s²] of the current state to `acc`, in the
    /// form `form` (docs/model.md §4a, §4b): its colour kernel is the run's kernel with support
    /// `r_e`.
    fn add_continuum_tension<K: Kernel>(&mut self, form: ContinuumForm, acc: &mut [Vec3]) {
        let m = &self.model;
        let p = &self.particles;
        let support_over_h = K::new(1.0).support_m();
        let inp = StressInput {
            kernel: K::new(m.r_e_m / support_over_h),
            pos: &p.pos,
            vol: &p.vol,
            phase: &p.phase,
            n_fluid: p.n_fluid,
            lists: &self.search.lists,
        };
        let sigma = |a, b| m.surface_stress_sigma(a, b);
        let force = match form {
            ContinuumForm::Stress => {
                self.surface_stress.evaluate(&inp, m.n_liquids, sigma);
                &self.surface_stress.force
            }
            ContinuumForm::Force => {
                self.surface_force
                    .evaluate(&inp, m.n_liquids, sigma, m.surface_force_walls);
                &self.surface_force.force
            }
        };
        acc.par_iter_mut()
            .zip(force.par_iter().zip(p.phase.par_iter()))
            .for_each(|(a, (f, &ph))| *a += f / m.mass[ph as usize]);
    }

    /// Replaces the densities by a Shepard or MLS filter every `n` steps, if declared.
    pub(super) fn reinitialise_density<K: Kernel>(&mut self) {
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
        // the filter changes the compression energy without any force doing work: booked
        let before = compression_energy(m, p);
        self.particles.rho[..new.len()].copy_from_slice(&new);
        let after = compression_energy(&self.model, &self.particles);
        self.dissipation.density_reinit_j += before - after;
        self.timings.density_s += t0.elapsed().as_secs_f64();
    }
}

/// `(Σ F·v [W], Σ F·a [W/s])` of a force per fluid particle at the particles' velocities and
/// accelerations. Summed serially in particle order: the same bits for any thread count.
fn power(force: &[Vec3], p: &crate::state::Particles) -> (f64, f64) {
    let (mut velocity_w, mut acceleration_w_s) = (0.0, 0.0);
    for ((f, v), a) in force.iter().zip(&p.vel).zip(&p.acc) {
        velocity_w += f.dot(v);
        acceleration_w_s += f.dot(a);
    }
    (velocity_w, acceleration_w_s)
}
