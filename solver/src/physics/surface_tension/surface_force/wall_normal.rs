//! The walls as a condition on the interface's normal (Breinlinger et al. 2013; docs/model.md
//! §4b): the surface force's second treatment of walls. The walls are no phase of the split:
//! the liquid|liquid term's colour gradients and curvatures run over the fluid only, and near a
//! wall each band particle's normal is turned towards the one that meets the wall at the
//! contact angle,
//!
//! `n_θ = t sin θ + n_w cos θ`,
//!
//! with `n_w` the wall's unit normal into the fluid and `t` the unit tangent of the wall that the
//! particle's own normal leans to (from side A, whose angle θ is, towards side B). The turned
//! normal is `f n + (1 − f) n_θ`, normalised, with `f = (d_w − l0)/h_c` clipped to [0, 1]:
//! `d_w` the particle's distance from the nearest wall particle along `n_w` (the first fluid
//! layer, `l0` from the wall's top layer, takes `n_θ` whole) and `h_c = r_e/2` the colour
//! kernel's smoothing length. An interface that meets the wall off θ then bends within `h_c` of
//! it, and that curvature pushes the contact line along the wall as Young's unbalanced tension
//! would. The cross-side colour gradient `g` takes the wall's side of the colour's jump as the
//! pressure gradient takes the wall's side of the pressure's: each wall particle holds its
//! fluid neighbours' colour, Shepard-averaged, as it holds their pressure (Adami et al. 2012).
//! Without it a cap started at 120° (R/l0 = 8) slid to 110° in 20 ms, with it it held 117.5°
//! (docs/findings.md). The force is `σ κ g` with that completed gradient, as away from walls.
//! Taking its component across the wall from the turned normal instead (`|g| n·n_w`), as this
//! treatment first did against a convex foot pushed into the wall before the wall held a colour,
//! drove a spurious flow at the contact line (0.78 µW in a 120° cap at R/l0 = 8, against 7 nW
//! with `σ κ g`) and stopped the caps at the same angles. No liquid face meets a wall face,
//! so the corner that gives the shares' treatment its line tension (`−0.34 σ r_e`) is not
//! there: on the lattice column the line tension left is `+0.08 σ r_e`, from the wall's
//! smeared colour (docs/findings.md).

use super::super::surface_stress::StressInput;
use crate::kernel::Kernel;
use crate::state::Vec3;
use rayon::prelude::*;

/// The blend's width over the colour kernel's support [-]: `h_c = r_e/2`, Wendland C2's
/// smoothing length (Breinlinger et al. 2013 blend over the smoothing length). On the lattice
/// channel, a quarter of the support hands the fluid 0.75 of Young's push, a half 0.885, the
/// whole support 0.95 (docs/findings.md); the model calibrates whichever share it is.
pub const BLEND_OVER_SUPPORT: f64 = 0.5;

/// What the wall normal's treatment needs of the model.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WallNormal {
    /// The walls' solid's phase.
    pub solid: usize,
    /// The lattice spacing `l0` [m].
    pub l0_m: f64,
}

/// The wall's unit normal into the fluid and the distance [m] along it to the nearest wall
/// particle, per fluid particle, into `out` (a zero normal where no wall particle is within the
/// colour kernel's support): `n_w = −Σ_w V_w ∇_i W_c(r_iw)`, normalised, over the particle's wall
/// neighbours, in list order (the same bits for any thread count).
pub fn wall_geometry<K: Kernel>(inp: &StressInput<K>, out: &mut Vec<(Vec3, f64)>) {
    let n = inp.n_fluid;
    out.clear();
    out.resize(n, (Vec3::zeros(), 0.0));
    let cut = inp.kernel.support_m();
    out.par_iter_mut().enumerate().for_each(|(i, o)| {
        let pi = inp.pos[i];
        let mut sum = Vec3::zeros();
        for j in inp.lists.all(i).filter(|&j| j >= n) {
            let d = inp.lists.delta(pi, inp.pos[j]);
            let r = d.norm();
            if r < cut && r > 0.0 {
                sum -= d * (inp.kernel.dw_dr(r) / r * inp.vol[j]);
            }
        }
        let m = sum.norm();
        if m == 0.0 {
            return;
        }
        let nw = sum / m;
        let mut dist = f64::INFINITY;
        for j in inp.lists.all(i).filter(|&j| j >= n) {
            let d = inp.lists.delta(pi, inp.pos[j]);
            if d.norm() < cut {
                dist = dist.min(d.dot(&nw));
            }
        }
        *o = (nw, dist);
    });
}

/// Completes each fluid particle's cross-side colour gradient `g` [1/m] (`out`, from
/// `interface_gradient` over the fluid) with its wall neighbours, as if they held the fluid's
/// colour extrapolated into the wall: each wall particle takes the Shepard fractions of its
/// fluid neighbours on side A and side B, `c_w = Σ_f V_f W_c(r_wf) [f on the side] / Σ_f V_f
/// W_c(r_wf)`, and a fluid particle on side `s` adds `s c_w(other side) V_w ∇_i W_c(r_iw)`. The
/// wall's pressure is extrapolated likewise (Adami et al. 2012), so the colour's jump and the
/// pressure's across an interface that meets the wall both see the wall (docs/model.md §4b).
/// Scratch `colour` holds the wall particles' fractions; the sums run in list order (the same
/// bits for any thread count).
pub fn complete_with_wall_colour<K: Kernel>(
    inp: &StressInput<K>,
    side_of: impl Fn(u8) -> f64 + Sync,
    colour: &mut Vec<(f64, f64)>,
    out: &mut [Vec3],
) {
    let n = inp.n_fluid;
    let cut = inp.kernel.support_m();
    colour.clear();
    colour.resize(inp.pos.len() - n, (0.0, 0.0));
    colour.par_iter_mut().enumerate().for_each(|(k, c)| {
        let w = n + k;
        let (mut a, mut b, mut all) = (0.0, 0.0, 0.0);
        for j in inp.lists.all(w).filter(|&j| j < n) {
            let r = inp.lists.delta(inp.pos[w], inp.pos[j]).norm();
            if r >= cut {
                continue;
            }
            let x = inp.vol[j] * inp.kernel.w(r);
            all += x;
            match side_of(inp.phase[j]) {
                s if s > 0.0 => a += x,
                s if s < 0.0 => b += x,
                _ => {}
            }
        }
        if all > 0.0 {
            *c = (a / all, b / all);
        }
    });
    out[..n].par_iter_mut().enumerate().for_each(|(i, g)| {
        let sign = side_of(inp.phase[i]);
        if sign == 0.0 {
            return;
        }
        let pi = inp.pos[i];
        for j in inp.lists.all(i).filter(|&j| j >= n) {
            let (ca, cb) = colour[j - n];
            let across = if sign > 0.0 { cb } else { ca };
            if across == 0.0 {
                continue;
            }
            let d = inp.lists.delta(pi, inp.pos[j]);
            let r = d.norm();
            if r < cut && r > 0.0 {
                *g += d * (inp.kernel.dw_dr(r) / r * sign * across * inp.vol[j]);
            }
        }
    });
}

/// The weight `1 − f` [-] of the contact angle's normal in [`turned`] at distance `dist_m`
/// [m] from the wall, `f = clip((d_w − l0)/blend, 0, 1)`: 1 on the first layer, 0 beyond the
/// blend `blend_m` [m] past the lattice spacing `l0_m` [m].
#[inline]
pub fn turned_weight(dist_m: f64, l0_m: f64, blend_m: f64) -> f64 {
    1.0 - ((dist_m - l0_m) / blend_m).clamp(0.0, 1.0)
}

/// The normal `n` (unit, from side A into side B) of a band particle at distance `dist_m` [m]
/// along the wall's normal `nw` (unit, into the fluid; zero: no wall near), turned towards the
/// one that meets the wall at the angle whose cosine is `cos_theta` (measured in side A), over
/// the blend `blend_m` [m] beyond the lattice spacing `l0_m` [m]. Unchanged where no wall is
/// near, beyond the blend, or where `n` is along `nw` (an interface parallel to the wall has no
/// contact line).
#[inline]
pub fn turned(n: Vec3, nw: Vec3, dist_m: f64, cos_theta: f64, l0_m: f64, blend_m: f64) -> Vec3 {
    if nw == Vec3::zeros() {
        return n;
    }
    let f = 1.0 - turned_weight(dist_m, l0_m, blend_m);
    if f == 1.0 {
        return n;
    }
    let t = n - nw * n.dot(&nw);
    let tm = t.norm();
    if tm < 1e-9 {
        return n;
    }
    let sin_theta = (1.0 - cos_theta * cos_theta).max(0.0).sqrt();
    let n_theta = t * (sin_theta / tm) + nw * cos_theta;
    let m = n * f + n_theta * (1.0 - f);
    m / m.norm()
}

#[cfg(test)]
mod tests {
    use super::*;

    const L0: f64 = 1e-4;

    #[test]
    fn the_first_layer_takes_the_contact_angles_normal_and_the_blend_ends_at_h_c() {
        let nw = Vec3::z();
        let n = Vec3::new(1.0, 0.0, 1.0).normalize(); // the interface meets the wall at 45°
        let cos60 = 0.5;
        let first = turned(n, nw, L0, cos60, L0, 2.0 * L0);
        let expected = Vec3::new(60f64.to_radians().sin(), 0.0, cos60);
        assert!((first - expected).norm() < 1e-15, "{first}");
        // beyond l0 + h_c: unchanged
        assert_eq!(turned(n, nw, 3.0 * L0, cos60, L0, 2.0 * L0), n);
        // half way: the normalised mean of the two
        let half = turned(n, nw, 2.0 * L0, cos60, L0, 2.0 * L0);
        assert!((half - (n + expected).normalize()).norm() < 1e-15, "{half}");
        // no wall near, or an interface parallel to the wall: unchanged
        assert_eq!(turned(n, Vec3::zeros(), L0, cos60, L0, 2.0 * L0), n);
        assert_eq!(turned(Vec3::z(), nw, L0, cos60, L0, 2.0 * L0), Vec3::z());
    }
}
