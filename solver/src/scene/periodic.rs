//! Periodic axes of a scene and the initial velocity wave of a body: what verification boxes
//! (a shear wave, a slab) need.

use super::{shapes::on_lattice_plane, Scene, SceneError};
use crate::periodic::PeriodicBox;
use serde::{Deserialize, Serialize};

/// Axes along which the scene repeats: `x = [lo, hi]` [m] makes x periodic with period
/// `hi − lo`. Both ends must lie on lattice planes (multiples of `l0`) so that the lattice
/// tiles across the boundary, and every particle of every body and wall must lie within the
/// range (checked when the particles are built: one outside would overlap its own image).
#[derive(Clone, Debug, Default, Serialize, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct PeriodicAxes {
    /// Range along x [m].
    #[serde(default)]
    pub x: Option<[f64; 2]>,
    /// Range along y [m].
    #[serde(default)]
    pub y: Option<[f64; 2]>,
    /// Range along z [m].
    #[serde(default)]
    pub z: Option<[f64; 2]>,
}

impl PeriodicAxes {
    /// The ranges, x, y, z.
    pub fn ranges(&self) -> [Option<[f64; 2]>; 3] {
        [self.x, self.y, self.z]
    }

    /// The box the solver measures pair vectors in.
    pub fn to_box(&self) -> PeriodicBox {
        PeriodicBox::new(self.ranges())
    }
}

/// A coordinate axis in a scene file.
#[derive(Clone, Copy, Debug, Serialize, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "lowercase")]
pub enum SceneAxis {
    /// x.
    X,
    /// y.
    Y,
    /// z.
    Z,
}

impl SceneAxis {
    /// 0, 1 or 2.
    pub fn index(self) -> usize {
        self as usize
    }
}

/// A sinusoidal initial velocity added to a body's uniform one:
/// `v(x) = amplitude · sin(2π x_along / wavelength)` [m/s].
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct VelocityWave {
    /// Velocity amplitude vector [m/s].
    pub amplitude: [f64; 3],
    /// The coordinate the velocity varies with.
    pub along: SceneAxis,
    /// Wavelength [m].
    pub wavelength: f64,
}

impl VelocityWave {
    /// The wave's velocity at `p` [m], [m/s].
    pub fn at(&self, p: [f64; 3]) -> [f64; 3] {
        let s = (std::f64::consts::TAU * p[self.along.index()] / self.wavelength).sin();
        self.amplitude.map(|a| a * s)
    }
}

const AXES: [&str; 3] = ["x", "y", "z"];

/// Checks the periodic ranges against the lattice, and each body's wave.
pub(super) fn validate(s: &Scene) -> Result<(), SceneError> {
    let l0 = s.discretisation.l0;
    for (k, range) in s.periodic.ranges().iter().enumerate() {
        let Some([lo, hi]) = *range else { continue };
        let field = format!("periodic.{}", AXES[k]);
        if !(lo.is_finite() && hi.is_finite() && hi > lo) {
            return Err(SceneError::invalid(
                field,
                format!("[{lo}, {hi}]"),
                "must be [lo, hi] with lo < hi, finite [m]",
            ));
        }
        if !(on_lattice_plane(lo, l0) && on_lattice_plane(hi, l0)) {
            return Err(SceneError::invalid(
                field,
                format!("[{lo}, {hi}]"),
                format!(
                    "both ends must be multiples of l0 = {l0:e} m so that the particle \
                     lattice tiles across the boundary"
                ),
            ));
        }
    }
    for b in &s.bodies {
        let Some(w) = &b.velocity_wave else { continue };
        let field = format!("body[{}].velocity_wave", b.name);
        if !(w.amplitude.iter().all(|a| a.is_finite()) && w.wavelength.is_finite())
            || w.wavelength <= 0.0
        {
            return Err(SceneError::invalid(
                field,
                format!("{w:?}"),
                "amplitude [m/s] must be finite and wavelength [m] positive",
            ));
        }
    }
    Ok(())
}
