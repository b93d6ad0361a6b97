//! Smoothing kernels of SPH.
//!
//! All kernels here are radial, normalised in 3D (`∫ W dV = 1`) and written in terms of the
//! smoothing length `h` [m]. Their support radius differs: `2h` for Wendland C2, Wendland C4 and
//! the cubic spline, `3h` for the quintic spline. The solver is generic over [`Kernel`], so the
//! kernel choice is made once per run ([`KernelKind`]) and costs no branch in the pair loops.

mod cubic_spline;
mod quintic_spline;
mod wendland_c2;
mod wendland_c4;

pub use cubic_spline::CubicSpline;
pub use quintic_spline::QuinticSpline;
pub use wendland_c2::WendlandC2;
pub use wendland_c4::WendlandC4;

use serde::{Deserialize, Serialize};

/// A radial 3D smoothing kernel `W(r, h)`.
pub trait Kernel: Copy + Send + Sync + 'static {
    /// Builds the kernel for smoothing length `h_m` [m].
    fn new(h_m: f64) -> Self;
    /// Radius beyond which `W = 0` [m].
    fn support_m(&self) -> f64;
    /// Kernel value `W(r)` [1/m³] at distance `r_m` [m] (0 outside the support).
    fn w(&self, r_m: f64) -> f64;
    /// Radial derivative `dW/dr` [1/m⁴] at distance `r_m` [m] (≤ 0; 0 outside the support).
    fn dw_dr(&self, r_m: f64) -> f64;
    /// Second radial derivative `d²W/dr²` [1/m⁵] at distance `r_m` [m] (0 outside the
    /// support): for the elastic moduli of the particle lattice, not used by the step.
    fn d2w_dr2(&self, r_m: f64) -> f64;
    /// `W(r)` for `r` within the support, without the support test (branch-free where the
    /// kernel allows, for vectorised loops); equal to [`Kernel::w`] there.
    #[inline(always)]
    fn w_inside(&self, r_m: f64) -> f64 {
        self.w(r_m)
    }
    /// `dW/dr` for `r` within the support, without the support test; equal to
    /// [`Kernel::dw_dr`] there.
    #[inline(always)]
    fn dw_dr_inside(&self, r_m: f64) -> f64 {
        self.dw_dr(r_m)
    }
}

/// The kernels a scene can choose.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum KernelKind {
    /// Wendland C2 (Wendland 1995), support 2h; Eq. (5) of Natsui 2021. The default.
    #[default]
    WendlandC2,
    /// Wendland C4, support 2h.
    WendlandC4,
    /// Cubic B-spline M4 (Monaghan & Lattanzio 1985), support 2h.
    CubicSpline,
    /// Quintic B-spline M6 (Morris 1996), support 3h.
    QuinticSpline,
}

impl KernelKind {
    /// All kernels, in a fixed order (for studies and tests).
    pub const ALL: [KernelKind; 4] = [
        KernelKind::WendlandC2,
        KernelKind::WendlandC4,
        KernelKind::CubicSpline,
        KernelKind::QuinticSpline,
    ];

    /// Support radius divided by `h`.
    pub fn support_over_h(self) -> f64 {
        match self {
            KernelKind::QuinticSpline => 3.0,
            _ => 2.0,
        }
    }

    /// The scene-file name of the kernel.
    pub fn name(self) -> &'static str {
        match self {
            KernelKind::WendlandC2 => "wendland_c2",
            KernelKind::WendlandC4 => "wendland_c4",
            KernelKind::CubicSpline => "cubic_spline",
            KernelKind::QuinticSpline => "quintic_spline",
        }
    }
}

/// Calls `$body` with the type alias `$k` bound to the kernel type selected by `$kind`.
///
/// This is the single place where the run-time kernel choice becomes a compile-time type.
#[macro_export]
macro_rules! with_kernel {
    ($kind:expr, $k:ident => $body:expr) => {
        match $kind {
            $crate::kernel::KernelKind::WendlandC2 => {
                type $k = $crate::kernel::WendlandC2;
                $body
            }
            $crate::kernel::KernelKind::WendlandC4 => {
                type $k = $crate::kernel::WendlandC4;
                $body
            }
            $crate::kernel::KernelKind::CubicSpline => {
                type $k = $crate::kernel::CubicSpline;
                $body
            }
            $crate::kernel::KernelKind::QuinticSpline => {
                type $k = $crate::kernel::QuinticSpline;
                $body
            }
        }
    };
}

#[cfg(test)]
mod tests {
    //! Every kernel must integrate to one over its support and its derivative must be the
    //! derivative of its value: otherwise densities are biased and forces inconsistent.
    use super::*;

    fn integral<K: Kernel>(k: &K) -> f64 {
        // ∫ W dV = ∫_0^R 4π r² W(r) dr by composite Simpson with 20 000 intervals; the
        // integrand is a piecewise polynomial (C² at the cubic spline's knots), so the
        // quadrature error is below 1e-12.
        let n = 20_000;
        let r_max = k.support_m();
        let dr = r_max / n as f64;
        let f = |r: f64| 4.0 * std::f64::consts::PI * r * r * k.w(r);
        let mut s = f(0.0) + f(r_max);
        for i in 1..n {
            let w = if i % 2 == 1 { 4.0 } else { 2.0 };
            s += w * f(i as f64 * dr);
        }
        s * dr / 3.0
    }

    fn check_kernel<K: Kernel>(kind: KernelKind) {
        let h = 1.3e-4;
        let k = K::new(h);
        assert!((k.support_m() - kind.support_over_h() * h).abs() < 1e-18);
        let i = integral(&k);
        assert!((i - 1.0).abs() < 1e-10, "{kind:?}: ∫W dV = {i}");
        // dW/dr against a central difference: step 1e-6 h gives truncation error ~1e-12 of
        // the scale h⁻⁴ and round-off ~1e-10 relative; 1e-6 relative to max|dW/dr| is safe.
        let scale = (0..200)
            .map(|s| k.dw_dr(s as f64 / 200.0 * k.support_m()).abs())
            .fold(0.0, f64::max);
        let eps = 1e-6 * h;
        for s in 1..400 {
            let r = s as f64 / 400.0 * k.support_m();
            let fd = (k.w(r + eps) - k.w(r - eps)) / (2.0 * eps);
            let an = k.dw_dr(r);
            assert!(
                (fd - an).abs() < 1e-6 * scale,
                "{kind:?} at r/h = {}: analytic {an}, finite difference {fd}",
                r / h
            );
        }
        // d²W/dr² against a central difference of dW/dr, with the same step and bound
        let scale2 = (0..200)
            .map(|s| k.d2w_dr2(s as f64 / 200.0 * k.support_m()).abs())
            .fold(0.0, f64::max);
        for s in 1..400 {
            let r = s as f64 / 400.0 * k.support_m();
            let fd = (k.dw_dr(r + eps) - k.dw_dr(r - eps)) / (2.0 * eps);
            let an = k.d2w_dr2(r);
            assert!(
                (fd - an).abs() < 1e-6 * scale2,
                "{kind:?} at r/h = {}: d²W/dr² analytic {an}, finite difference {fd}",
                r / h
            );
        }
        assert_eq!(k.d2w_dr2(k.support_m() * 1.0001), 0.0);
        // The branch-free evaluation agrees with W inside the support, bit for bit.
        for s in 0..1000 {
            let r = s as f64 / 1000.0 * k.support_m();
            assert_eq!(
                k.w_inside(r).to_bits(),
                k.w(r).to_bits(),
                "{kind:?} at r = {r}"
            );
            assert_eq!(
                k.dw_dr_inside(r).to_bits(),
                k.dw_dr(r).to_bits(),
                "{kind:?} at r = {r}"
            );
        }
        // Outside the support both vanish; the derivative is never positive.
        assert_eq!(k.w(k.support_m() * 1.0001), 0.0);
        assert_eq!(k.dw_dr(k.support_m() * 1.0001), 0.0);
        assert!((0..1000).all(|s| k.dw_dr(s as f64 / 1000.0 * k.support_m()) <= 0.0));
    }

    #[test]
    fn every_kernel_integrates_to_one_and_has_a_consistent_gradient() {
        check_kernel::<WendlandC2>(KernelKind::WendlandC2);
        check_kernel::<WendlandC4>(KernelKind::WendlandC4);
        check_kernel::<CubicSpline>(KernelKind::CubicSpline);
        check_kernel::<QuinticSpline>(KernelKind::QuinticSpline);
    }

    #[test]
    fn with_kernel_selects_the_named_kernel() {
        for kind in KernelKind::ALL {
            let support = with_kernel!(kind, K => K::new(1.0).support_m());
            assert_eq!(support, kind.support_over_h());
        }
    }
}
