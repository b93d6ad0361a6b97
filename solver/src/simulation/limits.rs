//! The time-step limits of the current state, and the check that a scene can afford its step.

use super::Simulation;
use crate::error::SimError;
use crate::scene::SceneError;
use crate::timestep::StepLimits;

impl Simulation {
    /// The time-step limits of the current state.
    pub fn step_limits(&self) -> StepLimits {
        let m = &self.model;
        let f = &m.time.factors;
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
            .time
            .dt
            .unwrap_or_else(|| self.step_limits().min().0)
    }

    pub(super) fn check_affordable(&self) -> Result<(), SimError> {
        let t = &self.model.time;
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
}
