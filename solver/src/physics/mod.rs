//! The physical model: equation of state, density, forces, walls, and the per-phase tables.

pub mod density;
pub mod eos;
pub mod forces;
pub mod implicit_viscosity;
pub mod nonaffine_viscosity;
pub mod shifting;
pub mod surface_tension;
pub mod walls;
