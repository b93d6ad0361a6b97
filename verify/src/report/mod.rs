//! Reports: the summary tables and the plots.

pub mod known_misses;
pub mod plot;
pub mod summary;
