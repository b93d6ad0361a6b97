//! The accuracy–cost study: what each discretisation choice buys in accuracy and costs in time.
//!
//! Two problems with analytic answers — the cube drop (l = 4 period against Lamb) and a sessile
//! matte drop under gravity (height against Young–Laplace) — are run over resolution × variant,
//! where a variant fixes the kernel, `h/l0`, the potential cut-off `r_e/l0` and the density
//! scheme. Each point runs as its own `verify run` process, so its wall time and peak memory are
//! its own. The analysis draws error against wall time with the Pareto front, fits the
//! convergence order in `l0` per variant, and says in words which settings are worth it.

pub mod analysis;
pub mod grid;
pub mod points;
mod run_all;
pub mod summary;

pub use grid::{Grid, Point, Problem, Variant};
pub use run_all::{run_all, selected, write_outputs, StudyOptions};
