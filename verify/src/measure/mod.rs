//! Measurements on simulated data: oscillation period and damping, geometric fits.

pub mod convergence;
pub mod fit;
pub mod foot;
pub mod geometry;
pub mod invariants;
pub mod oscillation;
pub mod shape;
pub mod side_view;
pub mod surface;
