//! Wendland C4 kernel in 3D, support 2h.
use super::Kernel;
use std::f64::consts::PI;

/// Wendland C4: `W = 495/(256π h³) (1 − q/2)⁶ (35q²/12 + 3q + 1)`, `q = r/h < 2`
/// (Wendland 1995; 3D normalisation as in Dehnen & Aly 2012 with support 2h).
#[derive(Clone, Copy, Debug)]
pub struct WendlandC4 {
    inv_h: f64,
    /// 495/(256π h³) [1/m³]
    norm: f64,
}

impl Kernel for WendlandC4 {
    fn new(h_m: f64) -> Self {
        Self {
            inv_h: 1.0 / h_m,
            norm: 495.0 / (256.0 * PI * h_m * h_m * h_m),
        }
    }
    #[inline(always)]
    fn support_m(&self) -> f64 {
        2.0 / self.inv_h
    }
    #[inline(always)]
    fn w(&self, r_m: f64) -> f64 {
        let q = r_m * self.inv_h;
        if q >= 2.0 {
            return 0.0;
        }
        let a = 1.0 - 0.5 * q;
        let a3 = a * a * a;
        self.norm * a3 * a3 * (35.0 / 12.0 * q * q + 3.0 * q + 1.0)
    }
    #[inline(always)]
    fn w_inside(&self, r_m: f64) -> f64 {
        let q = r_m * self.inv_h;
        let a = 1.0 - 0.5 * q;
        let a3 = a * a * a;
        self.norm * a3 * a3 * (35.0 / 12.0 * q * q + 3.0 * q + 1.0)
    }
    #[inline(always)]
    fn dw_dr_inside(&self, r_m: f64) -> f64 {
        let q = r_m * self.inv_h;
        let a = 1.0 - 0.5 * q;
        let a5 = a * a * a * a * a;
        -self.norm * self.inv_h * (14.0 / 3.0) * q * (1.0 + 2.5 * q) * a5
    }
    #[inline(always)]
    fn dw_dr(&self, r_m: f64) -> f64 {
        let q = r_m * self.inv_h;
        if q >= 2.0 {
            return 0.0;
        }
        let a = 1.0 - 0.5 * q;
        let a5 = a * a * a * a * a;
        // d/dq [(1 − q/2)⁶ (35q²/12 + 3q + 1)] = −(14/3) q (1 + 5q/2) (1 − q/2)⁵
        -self.norm * self.inv_h * (14.0 / 3.0) * q * (1.0 + 2.5 * q) * a5
    }
    #[inline(always)]
    fn d2w_dr2(&self, r_m: f64) -> f64 {
        let q = r_m * self.inv_h;
        if q >= 2.0 {
            return 0.0;
        }
        let a = 1.0 - 0.5 * q;
        let a4 = a * a * a * a;
        // d/dq [−(14/3) q (1 + 5q/2) (1 − q/2)⁵] = −(14/3) (1 − q/2)⁴ (1 + 2q − 35q²/4)
        -self.norm * self.inv_h * self.inv_h * (14.0 / 3.0) * a4 * (1.0 + 2.0 * q - 8.75 * q * q)
    }
}
