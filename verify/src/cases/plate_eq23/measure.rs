//! What a run of the drop on a plate gives: which liquids wet the plate, the drop's height,
//! and θ12 at the solid/liquid/liquid line where Eq. 23 has one.

use super::Prediction;
use crate::measure::geometry::{self, WallContact};
use crate::measure::surface;
use crate::suite::RunData;

/// One run, measured on its final state.
pub struct PlateRun<'r> {
    /// The run.
    pub run: &'r RunData,
    /// Surface tensions σ1, σ2 of its liquids [N/m].
    pub sigma_n_m: (f64, f64),
    /// Contact angle θ23 of liquid 2 on the plate [deg].
    pub theta23_deg: f64,
    /// Wetted shares of the plate and the drop's height.
    pub contact: WallContact,
    /// What touches the plate, in the words of [`Prediction::words`].
    pub seen: &'static str,
    /// θ12 inside liquid 1 at the line [deg], where Eq. 23 has a line off its boundary, or why
    /// it could not be measured.
    pub theta12_deg: Option<Result<f64, String>>,
}

/// Measures a run at spacing `l0_m` [m].
pub fn plate_run(run: &RunData, l0_m: f64) -> anyhow::Result<PlateRun<'_>> {
    let sc = &run.info.scene;
    let sigma_n_m = (
        sc.liquids[0].surface_tension.unwrap_or(0.0),
        sc.liquids[1].surface_tension.unwrap_or(0.0),
    );
    let theta23_deg = sc.solids[0].contact_angles[&sc.liquids[1].name];
    let prediction = Prediction::of(sigma_n_m, theta23_deg)?;
    let cloud = run.last.cloud(l0_m);
    let classes = surface::classify(&cloud);
    let contact = geometry::wall_contact(&cloud, 0.0);
    Ok(PlateRun {
        run,
        sigma_n_m,
        theta23_deg,
        seen: seen_words(&contact.wetted_fraction),
        theta12_deg: prediction
            .line_to_measure()
            .map(|_| geometry::solid_liquid_liquid_angle(&cloud, &classes, 0.0)),
        contact,
    })
}

/// What touches the plate: a liquid with under 10 % of the plate's first particle layer does
/// not wet it (a few stray particles may touch).
pub fn seen_words(fractions: &[f64]) -> &'static str {
    let f1 = fractions.first().copied().unwrap_or(0.0);
    let f2 = fractions.get(1).copied().unwrap_or(0.0);
    let total = f1 + f2;
    if total <= 0.0 {
        "no liquid on the plate"
    } else if f1 < 0.1 * total {
        "liquid 1 rides on liquid 2"
    } else if f2 < 0.1 * total {
        "liquid 2 rides on liquid 1"
    } else {
        "both liquids touch the plate (solid/liquid/liquid line)"
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn who_wets_the_plate() {
        assert_eq!(seen_words(&[]), "no liquid on the plate");
        assert_eq!(seen_words(&[0.05, 0.95]), "liquid 1 rides on liquid 2");
        assert_eq!(seen_words(&[0.95, 0.05]), "liquid 2 rides on liquid 1");
        assert_eq!(
            seen_words(&[0.5, 0.5]),
            "both liquids touch the plate (solid/liquid/liquid line)"
        );
    }
}
