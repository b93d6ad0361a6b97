//! Reports: the summary tables and the plots.

pub mod plot;
pub mod summary;
