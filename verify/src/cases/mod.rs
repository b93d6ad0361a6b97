//! The paper checks, one module each.

mod analysis;
mod convergence;
mod cube_drop;
mod doublet;
mod drop_oscillation;
mod hard_cases;
mod impact;
mod incline;
pub mod paper_values;
mod plate_eq23;
pub mod scene;
mod shear_wave;
pub mod substrate;
mod views;
mod water_oil_teflon;

use crate::suite::Case;

/// Every case, in report order.
pub fn all() -> Vec<Box<dyn Case>> {
    vec![
        Box::new(cube_drop::CubeDrop),
        Box::new(drop_oscillation::DropOscillation),
        Box::new(shear_wave::ShearWave),
        Box::new(convergence::Convergence),
        Box::new(doublet::Doublet(doublet::Pair::Equal)),
        Box::new(doublet::Doublet(doublet::Pair::MatteSlag)),
        Box::new(plate_eq23::PlateEq23),
        Box::new(water_oil_teflon::WaterOilTeflon),
        Box::new(impact::Impact(impact::Drop::Water)),
        Box::new(incline::Incline),
        Box::new(impact::Impact(impact::Drop::Aluminium)),
        Box::new(impact::Impact(impact::Drop::Iron)),
        Box::new(hard_cases::HardCases),
    ]
}
