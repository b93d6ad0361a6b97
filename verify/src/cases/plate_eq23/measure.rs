//! What a run of the drop on a plate gives: which liquids wet the plate, the drop's height,
//! and θ12 at the solid/liquid/liquid line where Eq. 23 has one; for a single liquid's drop,
//! its contact angle (an ingredient of Eq. 23).

use super::Prediction;
use crate::cases::substrate::tail_stats;
use crate::measure::foot;
use crate::measure::geometry::{self, WallContact};
use crate::measure::surface;
use crate::output::timeseries::{Axis, LiquidColumn, RunColumn};
use crate::suite::RunData;

/// One run, measured on its final state.
pub struct PlateRun<'r> {
    /// The run.
    pub run: &'r RunData,
    /// Surface tensions σ1, σ2 of its liquids [N/m].
    pub sigma_n_m: (f64, f64),
    /// Young angle θ31 of liquid 1 on the plate, as typed [deg].
    pub theta31_deg: f64,
    /// Young angle θ23 of liquid 2 on the plate, as typed [deg].
    pub theta23_deg: f64,
    /// Under the continuum surface force, in a gas (else the paper's potential).
    pub surface_force: bool,
    /// Wetted shares of the plate and the drop's height.
    pub contact: WallContact,
    /// What touches the plate, in the words of [`Prediction::words`].
    pub seen: &'static str,
    /// θ12 inside liquid 1 at the line [deg], where Eq. 23 has a line off its boundary, or why
    /// it could not be measured.
    pub theta12_deg: Option<Result<f64, String>>,
    /// θ12 at the foot of the 1–2 interface [deg] ([`foot::foot_angle_deg`]), where Eq. 23 has
    /// a line off its boundary, or why it could not be read (a lens or a layer).
    pub foot_theta12_deg: Option<Result<f64, String>>,
    /// The drop's speed along the plate over the run's last quarter [m/s]: its two liquids'
    /// centre of mass, whose velocity the time series holds per liquid ([`drift_m_s`]).
    pub drift_m_s: f64,
}

/// A single liquid's drop on the plate, measured on its final state.
pub struct SingleRun<'r> {
    /// The run.
    pub run: &'r RunData,
    /// Its liquid's surface tension [N/m].
    pub sigma_n_m: f64,
    /// Its Young angle on the plate, as typed [deg].
    pub typed_deg: f64,
    /// Under the continuum surface force, in a gas (else the paper's potential).
    pub surface_force: bool,
    /// Its contact angle [deg], or why it could not be measured.
    pub measured_deg: Result<f64, String>,
}

/// The case's runs, measured: binary drops and single drops.
pub struct Measured<'r> {
    /// Drops of two liquids.
    pub binaries: Vec<PlateRun<'r>>,
    /// Drops of one liquid.
    pub singles: Vec<SingleRun<'r>>,
}

impl Measured<'_> {
    /// The measured contact angle [deg] of the liquid of surface tension `sigma_n_m` [N/m]
    /// typed at `typed_deg`, under the surface force or the potential, if its single drop was
    /// run and measured.
    pub fn ingredient(&self, sigma_n_m: f64, typed_deg: f64, surface_force: bool) -> Option<f64> {
        self.singles
            .iter()
            .find(|s| {
                s.sigma_n_m == sigma_n_m
                    && s.typed_deg == typed_deg
                    && s.surface_force == surface_force
            })
            .and_then(|s| s.measured_deg.as_ref().ok().copied())
    }
}

/// Measures every run at spacing `l0_m` [m]: runs with one liquid besides a gas (a liquid
/// without a surface tension) are single drops.
pub fn measure(runs: &[RunData], l0_m: f64) -> anyhow::Result<Measured<'_>> {
    let mut m = Measured {
        binaries: Vec::new(),
        singles: Vec::new(),
    };
    for run in runs {
        let liquids = &run.info.scene.liquids;
        if liquids
            .iter()
            .filter(|l| l.surface_tension.is_some())
            .count()
            == 1
        {
            m.singles.push(single_run(run, l0_m));
        } else {
            m.binaries.push(plate_run(run, l0_m)?);
        }
    }
    Ok(m)
}

/// Measures a single drop at spacing `l0_m` [m]: the sessile angle on the plate (z = 0).
fn single_run(run: &RunData, l0_m: f64) -> SingleRun<'_> {
    let sc = &run.info.scene;
    let surface_force = is_surface_force(sc);
    let mut cloud = run.last.cloud(l0_m);
    if surface_force {
        cloud.retain_phases(|p| p == 0); // the gas, the second liquid, is left out
    }
    let classes = surface::classify(&cloud);
    SingleRun {
        run,
        sigma_n_m: sc.liquids[0].surface_tension.unwrap_or(0.0),
        typed_deg: sc.solids[0].contact_angles[&sc.liquids[0].name],
        surface_force,
        measured_deg: geometry::sessile_contact_angle(&cloud, &classes, 0, 0.0),
    }
}

/// Measures a binary drop at spacing `l0_m` [m].
pub fn plate_run(run: &RunData, l0_m: f64) -> anyhow::Result<PlateRun<'_>> {
    let sc = &run.info.scene;
    let sigma_n_m = (
        sc.liquids[0].surface_tension.unwrap_or(0.0),
        sc.liquids[1].surface_tension.unwrap_or(0.0),
    );
    let theta31_deg = sc.solids[0].contact_angles[&sc.liquids[0].name];
    let theta23_deg = sc.solids[0].contact_angles[&sc.liquids[1].name];
    let prediction = Prediction::of(sigma_n_m, theta31_deg, theta23_deg)?;
    let surface_force = is_surface_force(sc);
    let mut cloud = run.last.cloud(l0_m);
    if surface_force {
        cloud.retain_phases(|p| p < 2); // the gas, the third liquid, is left out
    }
    let classes = surface::classify(&cloud);
    let contact = geometry::wall_contact(&cloud, 0.0);
    Ok(PlateRun {
        run,
        sigma_n_m,
        theta31_deg,
        theta23_deg,
        surface_force,
        seen: seen_words(&contact.wetted_fraction),
        theta12_deg: prediction
            .line_to_measure()
            .map(|_| geometry::solid_liquid_liquid_angle(&cloud, &classes, 0.0)),
        foot_theta12_deg: prediction
            .line_to_measure()
            .map(|_| foot::foot_angle_deg(&cloud, &classes, 0.0)),
        contact,
        drift_m_s: drift_m_s(run),
    })
}

/// Whether a run's scene is under the continuum surface force (else the paper's potential).
fn is_surface_force(sc: &solver::Scene) -> bool {
    sc.effects.interfacial_tension == solver::scene::TensionModel::SurfaceForce
}

/// The speed along the plate [m/s] of the centre of mass of a run's first two liquids (the
/// drop; a third is its gas), from their centroid velocities averaged over the last quarter of
/// the run (velocities, not positions: a drop that crosses the periodic box's side keeps its
/// velocity). A drop at rest, as Eq. 23 describes it, has none; on a free-slip plate only the
/// forces' failure to conserve momentum can start one moving (docs/findings.md).
pub fn drift_m_s(run: &RunData) -> f64 {
    let ts = &run.timeseries;
    let t = ts.run_column(RunColumn::Time);
    let from = t.last().map_or(f64::NAN, |end| 0.75 * end);
    let liquids: Vec<&str> = (run.info.scene.liquids.iter().take(2))
        .map(|l| l.name.as_str())
        .collect();
    let along = |axis: Axis| {
        let mut momentum = vec![0.0; t.len()];
        let mut mass = vec![0.0; t.len()];
        for l in &liquids {
            let m = ts.liquid_column(l, LiquidColumn::Mass);
            let v = ts.liquid_column(l, LiquidColumn::CentroidVelocity(axis));
            if m.len() != t.len() || v.len() != t.len() {
                return f64::NAN; // a record without the columns
            }
            for k in 0..t.len() {
                momentum[k] += m[k] * v[k];
                mass[k] += m[k];
            }
        }
        let v: Vec<f64> = momentum.iter().zip(&mass).map(|(p, m)| p / m).collect();
        tail_stats(&t, &v, from).0
    };
    along(Axis::X).hypot(along(Axis::Y))
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
