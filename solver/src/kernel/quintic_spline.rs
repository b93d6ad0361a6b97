//! Quintic B-spline (M6) kernel in 3D, support 3h.
use super::Kernel;
use std::f64::consts::PI;

/// Quintic spline (Morris 1996): `W = 1/(120π h³) [(3−q)⁵ − 6(2−q)⁵ + 15(1−q)⁵]`, each
/// bracket present only while positive.
#[derive(Clone, Copy, Debug)]
pub struct QuinticSpline {
    inv_h: f64,
    /// 1/(120π h³) [1/m³]
    norm: f64,
}

#[inline(always)]
fn pos(x: f64) -> f64 {
    x.max(0.0)
}

impl Kernel for QuinticSpline {
    fn new(h_m: f64) -> Self {
        Self {
            inv_h: 1.0 / h_m,
            norm: 1.0 / (120.0 * PI * h_m * h_m * h_m),
        }
    }
    #[inline(always)]
    fn support_m(&self) -> f64 {
        3.0 / self.inv_h
    }
    #[inline(always)]
    fn w(&self, r_m: f64) -> f64 {
        let q = r_m * self.inv_h;
        if q >= 3.0 {
            return 0.0;
        }
        let (a, b, c) = (pos(3.0 - q), pos(2.0 - q), pos(1.0 - q));
        let p5 = |x: f64| x * x * x * x * x;
        self.norm * (p5(a) - 6.0 * p5(b) + 15.0 * p5(c))
    }
    #[inline(always)]
    fn dw_dr(&self, r_m: f64) -> f64 {
        let q = r_m * self.inv_h;
        if q >= 3.0 {
            return 0.0;
        }
        let (a, b, c) = (pos(3.0 - q), pos(2.0 - q), pos(1.0 - q));
        let p4 = |x: f64| x * x * x * x;
        -5.0 * self.norm * self.inv_h * (p4(a) - 6.0 * p4(b) + 15.0 * p4(c))
    }
    #[inline(always)]
    fn d2w_dr2(&self, r_m: f64) -> f64 {
        let q = r_m * self.inv_h;
        if q >= 3.0 {
            return 0.0;
        }
        let (a, b, c) = (pos(3.0 - q), pos(2.0 - q), pos(1.0 - q));
        let p3 = |x: f64| x * x * x;
        20.0 * self.norm * self.inv_h * self.inv_h * (p3(a) - 6.0 * p3(b) + 15.0 * p3(c))
    }
}
