//! Analytic references, computed by the code (never typed in from the papers).

pub mod elastic_drop;
pub mod eq23;
pub mod lamb;
pub mod neumann;
pub mod spheroid;
pub mod viscous_host;
pub mod young_laplace;
