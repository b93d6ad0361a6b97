//! The kicks with implicit viscosity (`physics::implicit_viscosity`): each half kick solves the
//! laminar term by backward Euler and books its work.

use super::Simulation;
use crate::error::SimError;
use crate::kernel::Kernel;
use crate::model::Model;
use crate::neighbours::NeighbourLists;
use crate::physics::forces::ledger::{channel, Ledger};
use crate::physics::implicit_viscosity::{ViscousInput, ViscousOperator, BLOCK};
use crate::state::{Particles, Vec3};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use std::time::Instant;

/// The implicit viscous solves of this process (not kept in checkpoints).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct ViscousSolves {
    /// Solves made (two per step).
    pub solves: u64,
    /// Conjugate-gradient iterations over all solves.
    pub iterations: u64,
    /// The most iterations one solve took.
    pub max_iterations: u32,
}

/// The operator's and the kick's buffers, kept between steps.
#[derive(Clone, Debug, Default)]
pub(super) struct ViscousScratch {
    op: ViscousOperator,
    before: Vec<Vec3>,
    /// The positions [m] and volumes [m³] `op` was built at: a kick at the same ones (the
    /// next step's first kick after this step's last) reuses it.
    built_pos: Vec<Vec3>,
    built_vol: Vec<f64>,
}

/// What the viscous operator reads of a state.
fn viscous_input<'a>(
    m: &'a Model,
    p: &'a Particles,
    lists: &'a NeighbourLists,
) -> ViscousInput<'a> {
    ViscousInput {
        pos: &p.pos,
        vol: &p.vol,
        phase: &p.phase,
        mass: &m.mass,
        mu_pair: &m.mu_pair,
        n_phases: m.pairs.n_phases,
        n_fluid: p.n_fluid,
        lists,
    }
}

impl Simulation {
    /// The viscous operator of the current state (for tests and diagnostics; the step keeps
    /// its own).
    pub fn viscous_operator<K: Kernel>(&self) -> ViscousOperator {
        let mut op = ViscousOperator::default();
        op.build(
            &self.model.kernel_of::<K>(),
            &viscous_input(&self.model, &self.particles, &self.search.lists),
        );
        op
    }

    /// The half kick `u → u'` of `tau_s` [s] with implicit viscosity:
    /// `(M/τ + K) u' = (M/τ)(u + τ a)` at the current positions, `a` the other forces'
    /// accelerations. The explicit terms' work is booked as in the explicit kick; the viscous
    /// work `Σ_i m_i (u'_i − u_i − τ a_i)·(u_i + u'_i)/2` — the kinetic energy change the
    /// viscous impulse makes at the kick's mean velocity — goes to the laminar ledger.
    pub(super) fn implicit_kick<K: Kernel>(&mut self, tau_s: f64) -> Result<(), SimError> {
        let iv = self
            .model
            .effects
            .implicit_viscosity
            .expect("implicit kicks only with implicit viscosity");
        let t0 = Instant::now();
        let m = &self.model;
        let p = &mut self.particles;
        let nf = p.n_fluid;
        let s = &mut self.viscous;
        let same = s.built_pos[..] == p.pos[..nf] && s.built_vol[..] == p.vol[..nf];
        if !same {
            s.built_pos.clear();
            s.built_pos.extend_from_slice(&p.pos[..nf]);
            s.built_vol.clear();
            s.built_vol.extend_from_slice(&p.vol[..nf]);
            s.op.build(
                &m.kernel_of::<K>(),
                &viscous_input(m, p, &self.search.lists),
            );
        }
        s.before.clear();
        s.before.extend_from_slice(&p.vel[..nf]);
        p.vel[..nf]
            .par_iter_mut()
            .zip(p.acc.par_iter())
            .for_each(|(v, a)| *v += a * tau_s);
        self.dissipation.kick(tau_s);
        let out = s.op.solve(
            &mut p.vel[..nf],
            tau_s,
            iv.relative_tolerance,
            iv.max_iterations,
        );
        let mass = s.op.mass();
        let work: f64 = (p.vel[..nf].par_chunks(BLOCK))
            .zip(s.before.par_chunks(BLOCK))
            .zip(p.acc.par_chunks(BLOCK).zip(mass.par_chunks(BLOCK)))
            .map(|((v, u), (a, m))| {
                (v.iter().zip(u).zip(a.iter().zip(m)))
                    .map(|((v, u), (a, m))| m * (v - u - a * tau_s).dot(&((u + v) * 0.5)))
                    .sum::<f64>()
            })
            .collect::<Vec<f64>>()
            .iter()
            .sum();
        self.dissipation.dissipated_j[channel(Ledger::Laminar as usize, false)] -= work;
        let st = &mut self.viscous_solves;
        st.solves += 1;
        st.iterations += out.iterations as u64;
        st.max_iterations = st.max_iterations.max(out.iterations);
        self.timings.forces_s += t0.elapsed().as_secs_f64();
        if !out.converged {
            return Err(SimError::ViscousSolve {
                step: self.step,
                time_s: self.time_s,
                iterations: out.iterations,
                relative_residual: out.relative_residual,
                tolerance: iv.relative_tolerance,
            });
        }
        Ok(())
    }
}
