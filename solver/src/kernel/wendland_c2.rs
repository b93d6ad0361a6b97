//! Wendland C2 kernel in 3D, support 2h.
use super::Kernel;
use std::f64::consts::PI;

/// Wendland C2: `W = 21/(16π h³) (1 − q/2)⁴ (2q + 1)`, `q = r/h < 2` — Eq. (5), Natsui 2021.
#[derive(Clone, Copy, Debug)]
pub struct WendlandC2 {
    inv_h: f64,
    /// 21/(16π h³) [1/m³]
    norm: f64,
}

impl Kernel for WendlandC2 {
    fn new(h_m: f64) -> Self {
        Self {
            inv_h: 1.0 / h_m,
            norm: 21.0 / (16.0 * PI * h_m * h_m * h_m),
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
        let a2 = a * a;
        self.norm * a2 * a2 * (2.0 * q + 1.0) // Eq. (5), Natsui 2021
    }
    #[inline(always)]
    fn w_inside(&self, r_m: f64) -> f64 {
        let q = r_m * self.inv_h;
        let a = 1.0 - 0.5 * q;
        let a2 = a * a;
        self.norm * a2 * a2 * (2.0 * q + 1.0) // Eq. (5), Natsui 2021
    }
    #[inline(always)]
    fn dw_dr_inside(&self, r_m: f64) -> f64 {
        let q = r_m * self.inv_h;
        let a = 1.0 - 0.5 * q;
        -5.0 * self.norm * self.inv_h * q * a * a * a
    }
    #[inline(always)]
    fn dw_dr(&self, r_m: f64) -> f64 {
        let q = r_m * self.inv_h;
        if q >= 2.0 {
            return 0.0;
        }
        let a = 1.0 - 0.5 * q;
        // d/dr of Eq. (5): −105/(16π h⁴) q (1 − q/2)³ = −5 q · norm/h · (1 − q/2)³
        -5.0 * self.norm * self.inv_h * q * a * a * a
    }
    #[inline(always)]
    fn d2w_dr2(&self, r_m: f64) -> f64 {
        let q = r_m * self.inv_h;
        if q >= 2.0 {
            return 0.0;
        }
        let a = 1.0 - 0.5 * q;
        // d/dq [−5 q (1 − q/2)³] = −5 (1 − q/2)² (1 − 2q)
        -5.0 * self.norm * self.inv_h * self.inv_h * a * a * (1.0 - 2.0 * q)
    }
}
