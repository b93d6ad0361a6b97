//! The pair forces on fluid particles, in one fused gather loop per particle.
//!
//! `m_i dv_i/dt = − Σ_j (p_i V_i² + p_j V_j² + m_i m_j Π_ij) ∇_i W_ij`            (pressure, AV)
//! `            + Σ_j μ_ij (V_i² + V_j²) ((dW/dr)/r) v_ij`                       (laminar)
//! `            + Σ_j C_ij P'(r_ij) e_ij + m_i g`                                (tension, gravity)
//!
//! — Eqs. (11)–(13) and (15) of Natsui 2021 as corrected in docs/model.md §3–4 (C2–C4, C6).
//! Each term is a type in its own file implementing [`PairTerm`]: [`Pressure`], [`LaminarViscosity`],
//! [`ArtificialViscosity`], the potential's
//! [`PairwisePotential`](crate::physics::surface_tension::PairwisePotential), and the
//! continuity density rate [`ContinuityRate`], and the liquid–wall repulsion
//! [`Monaghan1994WallRepulsion`]. The loop ([`fluid_forces`]) takes a list of them,
//! `(A, (B, (C, Off)))`; a term the scene does not declare is [`Off`] and compiles away. Walls
//! act through these terms: pressure (with the walls' extrapolated pressure), the potential
//! (wetting), and laminar viscosity at no-slip walls.
//!
//! Every pair term is written so that the `j`-on-`i` term is the exact bitwise negative of the
//! `i`-on-`j` one (commutative products and sums), which conserves momentum to round-off.

pub mod artificial_viscosity;
mod booking;
mod chunk;
pub mod continuity;
pub mod fused;
pub mod laminar_viscosity;
pub mod ledger;
pub mod pairs_once;
pub mod pressure;
pub mod pressure_difference;
pub mod term;
pub mod wall_repulsion;

pub use artificial_viscosity::ArtificialViscosity;
pub use continuity::ContinuityRate;
pub use fused::{fluid_forces, LoopInput};
pub use laminar_viscosity::{LaminarViscosity, MonaghanClearyGingold};
pub use ledger::{Dissipation, Ledger, Power};
pub use pressure::Pressure;
pub use pressure_difference::PressureDifference;
pub use term::{Neighbourhood, Off, PairTerm};
pub use wall_repulsion::Monaghan1994WallRepulsion;
