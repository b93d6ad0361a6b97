//! A chunk of neighbours as the fused loop holds it: relative positions and velocities in
//! lanes, and the geometry of each pair.

use super::ledger::Part;
use super::term::{PairKinematics, CHUNK};
use crate::kernel::Kernel;
use crate::state::Vec3;

/// `x_i − x_j` [m] and `v_i − v_j` [m/s] of one chunk of neighbours, and which are walls.
pub(super) struct Relative {
    pub dx: [f64; CHUNK],
    pub dy: [f64; CHUNK],
    pub dz: [f64; CHUNK],
    pub vx: [f64; CHUNK],
    pub vy: [f64; CHUNK],
    pub vz: [f64; CHUNK],
    /// Filled only when some term books its wall pairs.
    pub wall: [bool; CHUNK],
}

impl Relative {
    pub fn new() -> Self {
        Relative {
            dx: [0.0; CHUNK],
            dy: [0.0; CHUNK],
            dz: [0.0; CHUNK],
            vx: [0.0; CHUNK],
            vy: [0.0; CHUNK],
            vz: [0.0; CHUNK],
            wall: [false; CHUNK],
        }
    }

    /// The geometry of the pair in lane `n` for kernel `k` with support² `support2` [m²].
    #[inline(always)]
    pub fn kinematics<K: Kernel>(&self, k: &K, n: usize, support2: f64) -> PairKinematics {
        let (dx, dy, dz) = (self.dx[n], self.dy[n], self.dz[n]);
        let r2 = dx * dx + dy * dy + dz * dz;
        let r = r2.sqrt();
        let ir = 1.0 / r;
        let apart = r2 > 0.0;
        PairKinematics {
            r2,
            r,
            ir,
            apart,
            inside: apart & (r2 < support2),
            dw_r: k.dw_dr_inside(r.min(k.support_m())) * ir, // dW/dr / r [1/m⁵]
            vr: self.vx[n] * dx + self.vy[n] * dy + self.vz[n] * dz,
        }
    }

    /// What a coefficient of kind `part` multiplies in lane `n`: `x_i − x_j` [m] or
    /// `v_i − v_j` [m/s].
    #[inline(always)]
    pub fn along(&self, part: Part, n: usize) -> Vec3 {
        match part {
            Part::Central => Vec3::new(self.dx[n], self.dy[n], self.dz[n]),
            Part::Shear => Vec3::new(self.vx[n], self.vy[n], self.vz[n]),
        }
    }

    /// The lanes a coefficient of kind `part` multiplies.
    #[inline(always)]
    pub fn lanes(&self, part: Part) -> [&[f64; CHUNK]; 3] {
        match part {
            Part::Central => [&self.dx, &self.dy, &self.dz],
            Part::Shear => [&self.vx, &self.vy, &self.vz],
        }
    }
}
