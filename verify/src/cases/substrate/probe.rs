//! The values recorded at every output of paper B's runs (`probes.csv`), named by [`Probe`] both
//! where they are written and where they are read back.

use super::WALL_Z_M;
use crate::measure::{geometry, side_view, surface};
use crate::output::dump::Dump;
use crate::output::timeseries::RunColumn;
use crate::suite::RunData;
use solver::Simulation;

/// A value recorded at every output.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Probe {
    /// Height of the drop above the plate [mm].
    Height,
    /// Radius of the wetted disc [mm].
    ContactRadius,
    /// Side-view contact angle on the −x side [deg].
    ThetaLeft,
    /// Side-view contact angle on the +x side [deg].
    ThetaRight,
    /// Mean of the left and right side-view angles [deg].
    ThetaSideMean,
    /// Contact angle of a sphere fitted to the whole rim [deg].
    ThetaSphere,
    /// x of the liquid's centroid [mm].
    CentroidX,
    /// Mean x velocity of the liquid [m/s].
    VelocityX,
    /// Liquid particles inside the plate [-].
    InsidePlate,
}

impl Probe {
    /// Every probe, in the order of the columns.
    pub const ALL: [Probe; 9] = [
        Probe::Height,
        Probe::ContactRadius,
        Probe::ThetaLeft,
        Probe::ThetaRight,
        Probe::ThetaSideMean,
        Probe::ThetaSphere,
        Probe::CentroidX,
        Probe::VelocityX,
        Probe::InsidePlate,
    ];

    /// The column's name in `probes.csv`.
    pub fn name(self) -> &'static str {
        match self {
            Probe::Height => "height_mm",
            Probe::ContactRadius => "contact_radius_mm",
            Probe::ThetaLeft => "theta_left_deg",
            Probe::ThetaRight => "theta_right_deg",
            Probe::ThetaSideMean => "theta_side_mean_deg",
            Probe::ThetaSphere => "theta_sphere_deg",
            Probe::CentroidX => "centroid_x_mm",
            Probe::VelocityX => "velocity_x_m_s",
            Probe::InsidePlate => "inside_plate",
        }
    }

    /// The probe's values over a run (empty if missing).
    pub fn series(self, run: &RunData) -> Vec<f64> {
        run.probes.column(self.name()).unwrap_or_default()
    }

    /// The output times of a run's probes [s] (empty if missing).
    pub fn times(run: &RunData) -> Vec<f64> {
        run.probes
            .column(&RunColumn::Time.name())
            .unwrap_or_default()
    }
}

/// Every [`Probe`] of the state of `sim`, by name. Angles are NaN while the drop does not touch
/// the plate or when they cannot be measured.
pub fn probe(sim: &Simulation) -> Vec<(&'static str, f64)> {
    let dump = Dump::of(&sim.particles, sim.time_s);
    let cloud = dump.cloud(sim.model.l0_m);
    // the wall-entry health check's rule: deeper than half a spacing past every face of a
    // wall's solid (a particle that went round the plate's rim and wets its underside is not
    // inside it)
    let half = 0.5 * sim.model.l0_m;
    let inside = (0..dump.pos.len())
        .filter(|&i| !dump.wall[i])
        .filter(|&i| sim.model.walls.iter().any(|w| w.holds(dump.pos[i], half)))
        .count();
    let values = values(&cloud, &dump, inside);
    Probe::ALL.iter().map(|p| p.name()).zip(values).collect()
}

/// The probes in the order of [`Probe::ALL`]: height and wetted radius of the drop, its
/// side-view angles (left, right, mean) and the 3-D sphere-fit angle, the centroid's x, the mean
/// x velocity, and `inside`, the number of liquid particles inside the plate.
fn values(cloud: &surface::Cloud, dump: &Dump, inside: usize) -> [f64; 9] {
    let contact = geometry::wall_contact(cloud, WALL_Z_M);
    let touching = contact.contact_radius_m > 0.0;
    // angles only once the drop touches the plate
    let (l, r, sphere) = if touching {
        let classes = surface::classify(cloud);
        let (l, r) = side_view::side_view_angles(cloud, &classes, 0, WALL_Z_M);
        (
            l.unwrap_or(f64::NAN),
            r.unwrap_or(f64::NAN),
            geometry::sessile_contact_angle(cloud, &classes, 0, WALL_Z_M).unwrap_or(f64::NAN),
        )
    } else {
        (f64::NAN, f64::NAN, f64::NAN)
    };
    let fluid: Vec<usize> = (0..dump.pos.len()).filter(|&i| !dump.wall[i]).collect();
    let n = fluid.len().max(1) as f64;
    let cx = fluid.iter().map(|&i| dump.pos[i][0]).sum::<f64>() / n;
    let vx = fluid.iter().map(|&i| dump.vel[i][0]).sum::<f64>() / n;
    [
        contact.height_m * 1e3,
        contact.contact_radius_m * 1e3,
        l,
        r,
        0.5 * (l + r),
        sphere,
        cx * 1e3,
        vx,
        inside as f64,
    ]
}
