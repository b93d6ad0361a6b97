//! Measurements on simulated data: oscillation period and damping, geometric fits.

pub mod fit;
pub mod oscillation;
pub mod shape;
