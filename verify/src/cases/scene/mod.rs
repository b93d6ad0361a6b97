//! How cases (and the accuracy–cost study) build their scenes: a typed builder on the solver's
//! [`solver::Scene`], validated by the solver, and the materials of the papers.

mod builder;
mod materials;

pub use builder::SceneBuilder;
pub use materials::{
    artificial_viscosity_m2_s, laplace_sound_speed, sound_speed_for, LiquidProps, GRAVITY_M_S2,
    MATTE, SLAG,
};
