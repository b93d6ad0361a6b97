//! Cubic B-spline (M4) kernel in 3D, support 2h.
use super::Kernel;
use std::f64::consts::PI;

/// Cubic spline (Monaghan & Lattanzio 1985): `W = 1/(π h³) [1 − 3q²/2 + 3q³/4]` for `q < 1`,
/// `1/(π h³) (2 − q)³/4` for `1 ≤ q < 2`.
#[derive(Clone, Copy, Debug)]
pub struct CubicSpline {
    inv_h: f64,
    /// 1/(π h³) [1/m³]
    norm: f64,
}

impl Kernel for CubicSpline {
    fn new(h_m: f64) -> Self {
        Self {
            inv_h: 1.0 / h_m,
            norm: 1.0 / (PI * h_m * h_m * h_m),
        }
    }
    #[inline(always)]
    fn support_m(&self) -> f64 {
        2.0 / self.inv_h
    }
    #[inline(always)]
    fn w(&self, r_m: f64) -> f64 {
        let q = r_m * self.inv_h;
        if q < 1.0 {
            self.norm * (1.0 - 1.5 * q * q + 0.75 * q * q * q)
        } else if q < 2.0 {
            let a = 2.0 - q;
            self.norm * 0.25 * a * a * a
        } else {
            0.0
        }
    }
    #[inline(always)]
    fn dw_dr(&self, r_m: f64) -> f64 {
        let q = r_m * self.inv_h;
        let d = if q < 1.0 {
            -3.0 * q + 2.25 * q * q
        } else if q < 2.0 {
            let a = 2.0 - q;
            -0.75 * a * a
        } else {
            0.0
        };
        self.norm * self.inv_h * d
    }
    #[inline(always)]
    fn d2w_dr2(&self, r_m: f64) -> f64 {
        let q = r_m * self.inv_h;
        let d = if q < 1.0 {
            -3.0 + 4.5 * q
        } else if q < 2.0 {
            1.5 * (2.0 - q)
        } else {
            0.0
        };
        self.norm * self.inv_h * self.inv_h * d
    }
}
