//! The verification harness and command-line tool of the Natsui SPH solver.
//!
//! `verify run SCENE.toml --out DIR` runs a scene and writes its time series, run record and
//! snapshots. The analytic references ([`analytic`]) and measurements ([`measure`]) are what the
//! paper checks are judged with.
//!
//! The modules are layered; each imports only those before it: [`analytic`], [`measure`],
//! [`diagnostics`] and [`output`] (leaves) ← [`preflight`] ← [`run`] ← [`suite`] ← [`report`] ←
//! [`cases`] ← [`study`] ← [`plan`] ← the command line. `tests/layers.rs` fails on any import circle between them.
#![deny(missing_docs)]

pub mod analytic;
pub mod cases;
pub mod diagnostics;
pub mod measure;
pub mod output;
pub mod plan;
pub mod preflight;
pub mod report;
pub mod run;
pub mod run_measures;
pub mod study;
pub mod suite;
