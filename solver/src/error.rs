//! Errors of a running simulation.

use crate::neighbours::CellKeyError;
use crate::scene::SceneError;

/// Why a simulation could not be built or had to stop.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SimError {
    /// The scene is invalid.
    #[error(transparent)]
    Scene(#[from] SceneError),
    /// A particle left the neighbour-search grid.
    #[error("step {step}: a particle left the domain: {source}")]
    Escaped {
        /// Step at which it happened.
        step: u64,
        /// Details.
        source: CellKeyError,
    },
    /// The implicit viscous solve did not reach its tolerance.
    #[error("step {step}, t = {time_s:e} s: the implicit viscous solve stopped at a relative residual of {relative_residual:.3e} after {iterations} iterations (tolerance {tolerance:e}) — raise effects.implicit_viscosity.max_iterations, loosen its relative_tolerance, or shorten the step (time.factors.cfl)")]
    ViscousSolve {
        /// Step at which it happened.
        step: u64,
        /// Simulated time [s].
        time_s: f64,
        /// Iterations taken.
        iterations: u32,
        /// `‖b − A v‖/‖b‖` reached [-].
        relative_residual: f64,
        /// The scene's tolerance [-].
        tolerance: f64,
    },
    /// The state became unphysical; the message names the step, particle, quantity and the most
    /// likely cause.
    #[error("step {step}, t = {time_s:e} s, particle {particle_id}: {quantity} — {cause}")]
    Unstable {
        /// Step at which it was detected.
        step: u64,
        /// Simulated time [s].
        time_s: f64,
        /// The particle's scene index ([`crate::state::Particles::id`]).
        particle_id: u32,
        /// What went wrong, with its value.
        quantity: String,
        /// The most likely cause and what to change.
        cause: String,
    },
}
