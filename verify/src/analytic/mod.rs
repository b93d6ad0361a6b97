//! Analytic references, computed by the code (never typed in from the papers).

pub mod elastic_drop;
pub mod eq23;
pub mod lamb;
pub mod neumann;
pub mod spheroid;
pub mod viscous_host;
pub mod young_laplace;

/// `true` when `value` is a finite, strictly positive number: the inputs the references accept.
pub(crate) fn is_positive_finite(value: f64) -> bool {
    value.is_finite() && value > 0.0
}
