//! A viscosity on the non-affine part of the velocity: Morris et al. 1997's pair viscosity
//! applied to what the particles' fitted velocity gradients do not explain (docs/model.md §3).
//!
//! Each fluid particle `i` fits a velocity gradient `L_i` to its fluid neighbours by weighted
//! least squares, `L_i = argmin Σ_j c_ij |v_j − v_i − L x_ji|²` with `x_ji = x_j − x_i` and
//! the pair weight `c_ij = μ_ij V_i V_j (−W′(r_ij)/r_ij)` [kg/s]. The rate form
//!
//! `Q = Σ_i min_L Σ_j c_ij |v_j − v_i − L x_ji|²` [W]
//!
//! is a positive semi-definite quadratic form of the velocities that vanishes for every
//! linear velocity field (a uniform translation, a rigid rotation, any uniform strain rate),
//! and the force is its Rayleigh gradient `F = −½ ∂Q/∂v`; at the fitted gradients (the
//! envelope theorem) that is the pair force
//!
//! `F_k = 2 Σ_j c_kj [v_j − v_k − ½(L_k + L_j)(x_j − x_k)]`,
//!
//! Morris's viscosity on the relative velocity less the pair's mean fitted gradient. So its
//! power is exactly `Σ F·v = −Q ≤ 0` (it only dissipates), it conserves linear momentum
//! (antisymmetric pairs) and angular momentum (`Q` does not change under a rigid rotation),
//! and it does not act on a linear flow at all — the l = 2 mode of a drop is one — while a
//! particle-scale motion (a disorder of the velocities over a spacing) is damped at the rate
//! `μ_na / (ρ h²)`. With `μ_na = α ρ̄ c h` (`α` the scene's coefficient, `ρ̄` the pair's mean
//! rest density, `c` the sound speed, `h` the smoothing length) that rate is `α c / h`, the
//! artificial viscosity's scale.
//!
//! The fit is regularised, `B_i + ε (tr B_i / 3) I` with `ε =` [`REGULARISATION`], so that a
//! particle whose neighbours lie in a plane or on a line (or that has none) has a bounded
//! gradient; the force stays the exact Rayleigh gradient of the regularised form (the
//! regulariser does not depend on the velocities), and rotation invariance holds to `ε`.
//! Wall particles take no part.

use crate::kernel::Kernel;
use crate::neighbours::NeighbourLists;
use crate::state::Vec3;
use nalgebra::Matrix3;
use rayon::prelude::*;

/// The fit's relative regularisation `ε` [-] (module doc): small enough that a full
/// neighbourhood's gradient is exact to 1e-6, large enough that a degenerate one stays bounded.
pub const REGULARISATION: f64 = 1e-6;

/// What the force reads.
pub struct Input<'a, K> {
    /// The kernel (the run's, support `2h` or `3h`).
    pub kernel: K,
    /// Positions [m], fluid then walls.
    pub pos: &'a [Vec3],
    /// Velocities [m/s].
    pub vel: &'a [Vec3],
    /// Volumes [m³].
    pub vol: &'a [f64],
    /// Phase per particle.
    pub phase: &'a [u8],
    /// `α c h` [m²/s]: a pair's viscosity is `μ_ij = α c h (ρ0_a + ρ0_b)/2` [Pa·s].
    pub nu_m2_s: f64,
    /// Rest density per liquid phase [kg/m³].
    pub rho0: &'a [f64],
    /// Number of fluid particles (indices `0..n_fluid`).
    pub n_fluid: usize,
    /// The neighbour lists (near part: within the kernel's support).
    pub lists: &'a NeighbourLists,
}

/// The fluid pairs of `i` within the support, in list order: `(j, x_j − x_i [m], c_ij [kg/s])`.
fn pairs<'a, K: Kernel>(
    inp: &'a Input<'a, K>,
    i: usize,
) -> impl Iterator<Item = (usize, Vec3, f64)> + 'a {
    let support2 = inp.kernel.support_m() * inp.kernel.support_m();
    let (xi, vi, ph) = (inp.pos[i], inp.vol[i], inp.phase[i]);
    inp.lists.near(i).filter_map(move |j| {
        if j >= inp.n_fluid {
            return None;
        }
        let d = inp.lists.delta(inp.pos[j], xi); // x_j − x_i
        let r2 = d.norm_squared();
        if r2 >= support2 || r2 == 0.0 {
            return None;
        }
        let r = r2.sqrt();
        let mu = 0.5 * inp.nu_m2_s * (inp.rho0[ph as usize] + inp.rho0[inp.phase[j] as usize]);
        Some((j, d, -mu * vi * inp.vol[j] * inp.kernel.dw_dr_inside(r) / r))
    })
}

/// The fitted velocity gradient `L_i` [1/s] of every fluid particle (module doc), into `out`
/// (resized to `n_fluid`).
pub fn gradients<K: Kernel>(inp: &Input<'_, K>, out: &mut Vec<Matrix3<f64>>) {
    out.resize(inp.n_fluid, Matrix3::zeros());
    out.par_iter_mut().enumerate().for_each(|(i, l)| {
        let mut b = Matrix3::zeros();
        let mut c = Matrix3::zeros();
        for (j, x, w) in pairs(inp, i) {
            b += x * x.transpose() * w;
            c += (inp.vel[j] - inp.vel[i]) * x.transpose() * w;
        }
        let reg = REGULARISATION * b.trace() / 3.0;
        // no neighbour: nothing to fit; else b is symmetric positive definite
        *l = if reg > 0.0 {
            let b = b + Matrix3::identity() * reg;
            c * b.try_inverse().unwrap_or_else(Matrix3::zeros)
        } else {
            Matrix3::zeros()
        };
    });
}

/// The force [N] on every fluid particle into `out` (resized to `n_fluid`), from the fitted
/// gradients `grad` ([`gradients`]); its power is `−Q` ([`rate_form`]).
/// Summed in list order per particle: the same bits for any thread count.
pub fn forces<K: Kernel>(inp: &Input<'_, K>, grad: &[Matrix3<f64>], out: &mut Vec<Vec3>) {
    out.resize(inp.n_fluid, Vec3::zeros());
    out.par_iter_mut().enumerate().for_each(|(k, f)| {
        let mut s = Vec3::zeros();
        for (j, x, w) in pairs(inp, k) {
            let mean = (grad[k] + grad[j]) * 0.5;
            s += (inp.vel[j] - inp.vel[k] - mean * x) * w;
        }
        *f = s * 2.0;
    });
}

/// The rate form `Q = Σ_i Σ_j c_ij |v_j − v_i − L_i x_ji|² + ε_i |L_i|²` [W] at the fitted
/// gradients (the power the force takes out, for tests). Serial.
pub fn rate_form<K: Kernel>(inp: &Input<'_, K>, grad: &[Matrix3<f64>]) -> f64 {
    let mut q = 0.0;
    for (i, l) in grad.iter().enumerate() {
        let mut trace = 0.0;
        for (j, x, w) in pairs(inp, i) {
            q += w * (inp.vel[j] - inp.vel[i] - l * x).norm_squared();
            trace += w * x.norm_squared();
        }
        q += REGULARISATION * trace / 3.0 * l.norm_squared();
    }
    q
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::WendlandC2;
    use crate::neighbours::NeighbourSearch;
    use crate::physics::surface_tension::lattice_cloud::{jittered_sites, LatticeCloud};

    const L0: f64 = 1e-4; // m
    const H: f64 = 1.3 * L0; // m
    const NU: f64 = 2e-6; // m²/s
    const RHO0: [f64; 2] = [997.0, 1495.5]; // kg/m³

    /// A 10³ lattice cube jittered by up to 0.2 l0, phase 0 (water) below the plane z = 5 l0
    /// and 1 (a liquid of 1.5 times its density) above: unlike pairs weigh differently.
    fn cloud() -> LatticeCloud {
        let pos = jittered_sites([10, 10, 10], L0, 0.4 * L0);
        let search = NeighbourSearch::new(2.0 * H, 2.0 * H, 0.2 * L0);
        LatticeCloud::new(
            search,
            pos,
            |x| u8::from(x.z > 5.0 * L0),
            Vec::new(),
            0,
            L0 * L0 * L0,
        )
    }

    fn input<'a>(c: &'a LatticeCloud, vel: &'a [Vec3]) -> Input<'a, WendlandC2> {
        Input {
            kernel: WendlandC2::new(H),
            pos: &c.pos,
            vel,
            vol: &c.vol,
            phase: &c.phase,
            nu_m2_s: NU,
            rho0: &RHO0,
            n_fluid: c.n_fluid,
            lists: &c.search.lists,
        }
    }

    fn run(c: &LatticeCloud, vel: &[Vec3]) -> (Vec<Vec3>, f64) {
        let inp = input(c, vel);
        let (mut g, mut f) = (Vec::new(), Vec::new());
        gradients(&inp, &mut g);
        forces(&inp, &g, &mut f);
        (f, rate_form(&inp, &g))
    }

    /// A velocity field made of a linear part and a particle-scale disorder [m/s].
    fn field(c: &LatticeCloud, disorder: f64) -> Vec<Vec3> {
        let l = Matrix3::new(0.3, -1.2, 0.5, 0.7, 0.1, -0.4, 2.0, 0.9, -0.4) * 1e2; // 1/s
        c.pos
            .iter()
            .enumerate()
            .map(|(i, x)| {
                let k = i as f64;
                Vec3::new(0.01, -0.02, 0.005)
                    + l * x
                    + Vec3::new((1.7 * k).sin(), (2.3 * k).cos(), (0.9 * k).sin()) * disorder
            })
            .collect()
    }

    /// A linear velocity field — translation, rotation and strain at once — feels no force:
    /// every fit is exact to the regulariser (1e-6 of `B`). Bound: 1e-5 of the largest force
    /// Morris's viscosity (the same pairs without the fit) puts on the same field — the
    /// regulariser's 1e-6 times a margin of 10 (measured 1.3e-6).
    #[test]
    fn a_linear_velocity_field_feels_no_force() {
        let c = cloud();
        let v = field(&c, 0.0);
        let (f, q) = run(&c, &v);
        let inp = input(&c, &v);
        let morris = (0..c.n_fluid)
            .map(|k| {
                let s: Vec3 = pairs(&inp, k).map(|(j, _, w)| (v[j] - v[k]) * w).sum();
                (s * 2.0).norm()
            })
            .fold(0.0, f64::max);
        let largest = f.iter().map(|x| x.norm()).fold(0.0, f64::max);
        assert!(
            largest < 1e-5 * morris,
            "{largest:e} N against {morris:e} N"
        );
        assert!(q >= 0.0);
    }

    /// The force is the Rayleigh gradient of the rate form: its power is `−Q` exactly (to
    /// round-off, 1e-10 relative), `Q > 0` for a disordered field, linear and angular
    /// momentum are conserved (to round-off; angular to the regulariser's 1e-6 of `Σ |x × F|`).
    #[test]
    fn it_only_dissipates_and_conserves_both_momenta() {
        let c = cloud();
        let v = field(&c, 1e-2);
        let (f, q) = run(&c, &v);
        let power: f64 = f.iter().zip(&v).map(|(f, v)| f.dot(v)).sum();
        assert!(q > 0.0);
        assert!(
            (power + q).abs() < 1e-10 * q,
            "power {power:e} W, Q {q:e} W"
        );
        let scale: f64 = f.iter().map(|x| x.norm()).sum();
        let net: Vec3 = f.iter().sum();
        assert!(net.norm() < 1e-12 * scale, "net force {net:?}");
        let centre = Vec3::repeat(5.0 * L0);
        let torque: Vec3 = c
            .pos
            .iter()
            .zip(&f)
            .map(|(x, f)| (x - centre).cross(f))
            .sum();
        let lever: f64 = c
            .pos
            .iter()
            .zip(&f)
            .map(|(x, f)| (x - centre).cross(f).norm())
            .sum();
        assert!(
            torque.norm() < 1e-6 * lever,
            "torque {torque:?} of {lever:e}"
        );
    }

    /// The force is the Rayleigh gradient `−½ ∂Q/∂v`: a central difference of `Q` along one
    /// particle's velocity gives it (to 1e-6 relative: the difference's own error is zero for
    /// a quadratic form, so this bounds round-off and the envelope argument).
    #[test]
    fn the_force_is_the_gradient_of_the_rate_form() {
        let c = cloud();
        let v = field(&c, 1e-2);
        let (f, _) = run(&c, &v);
        let k = 437;
        for axis in 0..3 {
            let dv = 1e-4;
            let mut up = v.clone();
            up[k][axis] += dv;
            let mut down = v.clone();
            down[k][axis] -= dv;
            let dq = (run(&c, &up).1 - run(&c, &down).1) / (2.0 * dv);
            let expected = -0.5 * dq;
            assert!(
                (f[k][axis] - expected).abs() < 1e-6 * f[k].norm(),
                "axis {axis}: {} against {expected}",
                f[k][axis]
            );
        }
    }

    /// The same bits for one and three threads.
    #[test]
    fn deterministic_across_threads() {
        let c = cloud();
        let v = field(&c, 1e-2);
        let on = |n| {
            rayon::ThreadPoolBuilder::new()
                .num_threads(n)
                .build()
                .unwrap()
                .install(|| run(&c, &v))
        };
        let (f1, q1) = on(1);
        let (f3, q3) = on(3);
        assert_eq!(q1.to_bits(), q3.to_bits());
        assert!(f1.iter().zip(&f3).all(|(a, b)| a == b));
    }
}
