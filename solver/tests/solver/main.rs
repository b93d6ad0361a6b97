//! Integration tests of the solver: one binary, a module per area. Each test states the
//! physics it expects and where its tolerance comes from.

mod active_pairs;
mod checkpoint;
mod common;
mod conservation;
mod determinism;
mod effects;
mod energy_booking;
mod energy_budget;
mod failures;
mod far_pairs;
mod fuzz_scenes;
mod implicit_viscosity;
mod laminar_forms;
mod lattice_energy;
mod nonaffine_viscosity;
mod periodic;
mod pressure_forms;
mod scene_errors;
mod shifting;
mod surface_force_walls;
mod surface_stress;
mod surrounding;
mod tension_calibration;
mod walls;
