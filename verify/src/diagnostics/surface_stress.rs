//! Surface energy and surface stress of a flat surface of the reference particle lattice.
//!
//! A liquid's interface has a surface stress equal to its surface energy: stretching it adds
//! area at the same energy per area, `f = d(γA)/dA = γ`. A solid's surface energy per area
//! changes with the stretch (Shuttleworth 1950): `f = γ + A dγ/dA`. This module measures `f/γ`
//! of a capillarity model on the simple cubic lattice, split by the plane `z = 0` between two
//! layers and stretched in that plane, `F = diag(1 + ε, 1 + ε, 1)`, so `A = A0 (1 + ε)²` and
//! `f = γ + ½ (1 + ε) dγ/dε`; at `ε = 0`, `f/γ = 1 + ½ d ln γ/dε`.
//!
//! Two energies (lattice units: `l0 = 1`, `σ = 1`):
//! - the **pairwise potential** (Eq. 15, Natsui 2021) of cut-off `r_e` and order `m`: pair energy
//!   `−C P(r)`, `C = 2σ l0²/S`; the energy per area of the two faces of the split is
//!   `γ(ε) = C S(ε)/(2A)` with `S(ε) = Σ_{i in a column below} Σ_{j above} P(|F r_ij|)`. Between
//!   two liquids or a liquid and a solid every pair strength (Fowkes, Eqs. 16–20) multiplies the
//!   same `S(ε)`: the interface energy is `(σ_a + σ_b − 2σ_D) S(ε)/(S(0) (1 + ε)²)` and the
//!   work of adhesion on a solid `σ(1 + cos θ)` times the same factor, so every interface of
//!   the model has the same `f/γ`;
//! - the **square-gradient energy** `E = Σ_i V_i K |g_i|²`, `g_i = Σ_j V_j ∇_i W_ij` for a kernel
//!   and `h` (the local limit of a pair energy; a candidate of the liquid model), with
//!   `V = det F` and `K = σ/I(0)`: `γ(ε) = K I(ε)/A`, `I(ε) = Σ_{i in a column} V |g_i|²` on the
//!   half-space (the bulk has `g = 0`).
//!
//! No pair energy can be a liquid's surface under this stretch: on a uniform density the
//! pairs across the plane per reference area scale as `(1 + ε)⁻²` (substitute `s = F r`, whose
//! volume element is `(1 + ε)²` larger), so per deformed area `γ(ε) = γ0 (1 + ε)⁻⁴` and
//! `f = −γ` exactly, whatever the profile; a lattice sum differs from it only by the lattice's
//! discreteness, which a disordered liquid removes.
//!
//! The equation of state's energy is not included: with the pressure clipped at zero the
//! deficient surface layers carry none, and the bulk's is not a surface term.
//! `dγ/dε` is summed analytically; [`surface_energy`] at `±δ` checks it by a central difference.

use solver::kernel::{Kernel, KernelKind};
use solver::lattice::potential_surface_sum;
use solver::physics::surface_tension::Kondo2007Potential;
use solver::with_kernel;

/// A capillarity energy on the lattice.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Energy {
    /// The pairwise potential of cut-off `r_e/l0` and order (1: Kondo 2007).
    Potential {
        /// `r_e/l0` [-].
        re_over_l0: f64,
        /// Order of the force's zero at `r_e`.
        order: u8,
    },
    /// The square-gradient energy of a kernel at `h/l0`.
    SquareGradient {
        /// The kernel.
        kernel: KernelKind,
        /// `h/l0` [-].
        h_over_l0: f64,
    },
}

/// Surface energy and stress of the flat lattice surface at one strain.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfaceStress {
    /// Surface energy per deformed area `γ` [σ].
    pub gamma: f64,
    /// `dγ/dε` under the isotropic in-plane stretch [σ].
    pub dgamma_deps: f64,
}

impl SurfaceStress {
    /// The surface stress `f = γ + ½ (1 + ε) dγ/dε` at strain `eps` [σ].
    pub fn stress(&self, eps: f64) -> f64 {
        self.gamma + 0.5 * (1.0 + eps) * self.dgamma_deps
    }
}

/// Half-space column depth [l0] and lateral extent beyond the reach: every site within the
/// reach of the column is summed.
fn extent(reach: f64) -> i64 {
    reach.ceil() as i64 + 2
}

/// Surface energy per area and its derivative of `energy` under the in-plane stretch `eps`.
pub fn surface_energy(energy: Energy, eps: f64) -> SurfaceStress {
    match energy {
        Energy::Potential { re_over_l0, order } => potential(re_over_l0, order, eps),
        Energy::SquareGradient { kernel, h_over_l0 } => {
            with_kernel!(kernel, K => square_gradient(&K::new(h_over_l0), eps))
        }
    }
}

/// `f/γ` of `energy` on the undeformed lattice (a liquid: 1).
pub fn stress_over_energy(energy: Energy) -> f64 {
    let s = surface_energy(energy, 0.0);
    s.stress(0.0) / s.gamma
}

fn potential(re_over_l0: f64, order: u8, eps: f64) -> SurfaceStress {
    let p = Kondo2007Potential {
        l0_m: 1.0,
        r_e_m: re_over_l0,
        order,
    };
    let c = 2.0 / potential_surface_sum(&p); // C = 2σ l0²/S, Eqs. (15)–(16), Natsui 2021
    let stretch = 1.0 + eps;
    let n = extent(re_over_l0);
    let (mut s, mut ds) = (0.0, 0.0);
    // i: the column (0, 0, −(a + ½)); j: the sites (b, c, d + ½) above the plane
    for a in 0..=n {
        for d in 0..=n {
            let dz = (a + d + 1) as f64;
            for cy in -n..=n {
                for bx in -n..=n {
                    let lateral = ((bx * bx + cy * cy) as f64) * stretch * stretch;
                    let r = (lateral + dz * dz).sqrt();
                    if r < re_over_l0 {
                        s += p.p(r);
                        // dr/dε = (1 + ε)(x² + y²)/r for the undeformed offsets x, y
                        ds += p.dp_dr(r) * lateral / (stretch * r);
                    }
                }
            }
        }
    }
    let area = stretch * stretch;
    SurfaceStress {
        gamma: 0.5 * c * s / area,
        dgamma_deps: 0.5 * c * (ds / area - s * 2.0 * stretch / (area * area)),
    }
}

/// `I(ε) = Σ_{column} V |g|²` and `dI/dε` of the half-space below the plane.
fn gradient_sum<K: Kernel>(kernel: &K, eps: f64) -> (f64, f64) {
    let stretch = 1.0 + eps;
    let volume = stretch * stretch; // V = det F (l0³ = 1)
    let dvolume = 2.0 * stretch;
    let reach = kernel.support_m();
    let n = extent(reach);
    let (mut sum, mut dsum) = (0.0, 0.0);
    for a in 0..=n {
        // g_i = V Σ_j W'(r) u/r with u = F (x_i − x_j); dg/dε from dV/dε, du/dε and dr/dε
        let mut g = [0.0; 3];
        let mut dg = [0.0; 3];
        for k in 0..=(a + n) {
            let dz = (k - a) as f64; // z_i − z_j with j at depth k below the plane
            for cy in -n..=n {
                for bx in -n..=n {
                    if bx == 0 && cy == 0 && k == a {
                        continue;
                    }
                    let (x, y) = (-bx as f64, -cy as f64);
                    let u = [stretch * x, stretch * y, dz];
                    let r = (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]).sqrt();
                    if r >= reach {
                        continue;
                    }
                    let w1 = kernel.dw_dr(r);
                    let w2 = kernel.d2w_dr2(r);
                    let dr = stretch * (x * x + y * y) / r;
                    let q = w1 / r;
                    let dq = (w2 / r - w1 / (r * r)) * dr;
                    let du = [x, y, 0.0];
                    for c in 0..3 {
                        g[c] += volume * q * u[c];
                        dg[c] += dvolume * q * u[c] + volume * (dq * u[c] + q * du[c]);
                    }
                }
            }
        }
        let g2: f64 = g.iter().map(|x| x * x).sum();
        let gdg: f64 = g.iter().zip(&dg).map(|(x, y)| x * y).sum();
        sum += volume * g2;
        dsum += dvolume * g2 + 2.0 * volume * gdg;
    }
    (sum, dsum)
}

fn square_gradient<K: Kernel>(kernel: &K, eps: f64) -> SurfaceStress {
    let k = 1.0 / gradient_sum(kernel, 0.0).0; // K = σ/I(0): the flat surface carries σ
    let (i, di) = gradient_sum(kernel, eps);
    let stretch = 1.0 + eps;
    let area = stretch * stretch;
    SurfaceStress {
        gamma: k * i / area,
        dgamma_deps: k * (di / area - i * 2.0 * stretch / (area * area)),
    }
}

/// The interface energies of the potential on the undeformed lattice [N/m], from the Fowkes
/// pair strengths: a free surface `σ_a`, the a|b interface `σ_a + σ_b − 2σ_D` and the work of
/// adhesion on a solid `2σ_D = σ_a (1 + cos θ)`; each is its pair strength combination times
/// `γ(0)/σ`, and under a stretch each scales with the same `γ(ε)/γ(0)`.
pub fn fowkes_interfaces(
    sigma_a: f64,
    sigma_b: f64,
    sigma_ab: f64,
    theta_deg: f64,
) -> [(&'static str, f64); 3] {
    use solver::physics::surface_tension::fowkes;
    let sigma_d_ab = fowkes::liquid_liquid(sigma_a, sigma_b, sigma_ab);
    let sigma_d_as = fowkes::liquid_solid(sigma_a, theta_deg);
    [
        ("free surface", sigma_a),
        ("liquid–liquid", sigma_a + sigma_b - 2.0 * sigma_d_ab),
        ("liquid–solid (work of adhesion)", 2.0 * sigma_d_as),
    ]
}

/// A markdown table of `γ(0)/σ` and `f/γ` of both energies for each setting
/// `(kernel, h/l0, r_e/l0, order)`.
pub fn table(settings: &[(KernelKind, f64, f64, u8)]) -> String {
    let mut out = String::from(
        "| kernel | h/l0 | r_e/l0 | order | potential γ/σ | **potential f/γ** | square-gradient γ/σ | **square-gradient f/γ** |\n\
         |---|---|---|---|---|---|---|---|\n",
    );
    for &(kernel, h, re, order) in settings {
        let pot = Energy::Potential {
            re_over_l0: re,
            order,
        };
        let sg = Energy::SquareGradient {
            kernel,
            h_over_l0: h,
        };
        out.push_str(&format!(
            "| {} | {h} | {re} | {order} | {:.4} | **{:+.3}** | {:.4} | **{:+.3}** |\n",
            kernel.name(),
            surface_energy(pot, 0.0).gamma,
            stress_over_energy(pot),
            surface_energy(sg, 0.0).gamma,
            stress_over_energy(sg),
        ));
    }
    out.push_str(
        "\nf/γ = 1 + ½ d ln γ/dε under the in-plane stretch (a liquid: 1). Every interface of the \
         potential (liquid–liquid, liquid–solid) scales with the same lattice sum, so has the same f/γ; \
         e.g. matte (σ 0.4 N/m) and slag (σ 0.2 N/m) at σ12 = 0.3 N/m, matte at θ = 60° on a solid:\n",
    );
    for (name, gamma) in fowkes_interfaces(0.4, 0.2, 0.3, 60.0) {
        out.push_str(&format!("- {name}: γ = {gamma:.3} N/m\n"));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn energies() -> Vec<Energy> {
        let mut v: Vec<Energy> = [(4.2, 1), (2.1, 1), (3.1, 1), (4.0, 1), (4.4, 2), (5.0, 3)]
            .map(|(re_over_l0, order)| Energy::Potential { re_over_l0, order })
            .into();
        for kernel in KernelKind::ALL {
            for h_over_l0 in [1.05, 1.3, 2.0] {
                v.push(Energy::SquareGradient { kernel, h_over_l0 });
            }
        }
        v
    }

    /// The summed `dγ/dε` against a central difference of `γ` at `±δ`, at zero and at a finite
    /// strain. The difference's truncation error is `γ''' δ²/6` (~1e-9 σ at δ = 1e-4 for
    /// derivatives of order 1–100) and its round-off `1e-16 γ/δ` ~ 1e-12; 1e-6 σ bounds both
    /// while a wrong term in the sum (errors of order γ) fails. The potential's `P''` jumps at
    /// `r_e`: no lattice site sits at `r_e` exactly under these strains, so `γ` is smooth there.
    #[test]
    fn the_summed_derivative_matches_finite_differences() {
        let delta = 1e-4;
        for e in energies() {
            for eps in [0.0, 0.013] {
                let s = surface_energy(e, eps);
                let fd = (surface_energy(e, eps + delta).gamma
                    - surface_energy(e, eps - delta).gamma)
                    / (2.0 * delta);
                assert!(
                    (fd - s.dgamma_deps).abs() < 1e-6,
                    "{e:?} at ε = {eps}: summed {}, finite difference {fd}",
                    s.dgamma_deps
                );
            }
        }
    }

    /// The undeformed flat surface carries σ: for the potential through the independent
    /// surface sum `S` of `solver::lattice` (a different loop over the same split), for the
    /// square gradient by the calibration `K = σ/I(0)` (exact by construction: checked only as
    /// a guard on the normalisation).
    #[test]
    fn the_flat_surface_carries_sigma() {
        for e in energies() {
            let g = surface_energy(e, 0.0).gamma;
            assert!((g - 1.0).abs() < 1e-12, "{e:?}: γ = {g}");
        }
    }

    /// The facts the liquid work rests on: the Kondo potential's surface stress is negative
    /// (its energy per area falls as the surface is stretched: fewer pairs per area), the
    /// square-gradient energy's close to a liquid's. Bounds: the sign for the potential; for
    /// the square gradient within 0.2 of 1 (a lattice sum of a local energy is near its
    /// continuum limit, f = γ, but not at it).
    #[test]
    fn the_potential_is_not_a_liquid_surface_and_the_square_gradient_nearly_is() {
        let pot = stress_over_energy(Energy::Potential {
            re_over_l0: 4.2,
            order: 1,
        });
        assert!(pot < 0.0, "potential f/γ = {pot}");
        let sg = stress_over_energy(Energy::SquareGradient {
            kernel: KernelKind::WendlandC2,
            h_over_l0: 1.05,
        });
        assert!((sg - 1.0).abs() < 0.2, "square-gradient f/γ = {sg}");
    }

    /// Any pair energy has `f = −γ` on a uniform density (module doc); the lattice sums tend to
    /// it as the reach grows and the sum approaches its integral, for every order. Bounds: 2 %
    /// from r_e = 3.1 l0 on, 0.2 % at 8 l0 (the lattice's quadrature error falls with the
    /// number of shells; both are far from a liquid's +1).
    #[test]
    fn every_pair_potential_tends_to_minus_gamma() {
        for order in 1..=3 {
            for (re, bound) in [(3.1, 0.02), (4.2, 0.02), (6.0, 0.02), (8.0, 0.002)] {
                let r = stress_over_energy(Energy::Potential {
                    re_over_l0: re,
                    order,
                });
                assert!(
                    (r + 1.0).abs() < bound,
                    "order {order}, r_e = {re} l0: f/γ = {r}"
                );
            }
        }
    }

    /// The Fowkes combinations give the typed inputs: σ12 between the liquids, σ(1 + cos θ)
    /// on the solid (Eqs. 16–20, Natsui 2021).
    #[test]
    fn interfaces_follow_the_typed_inputs() {
        let [free, ab, solid] = fowkes_interfaces(0.4, 0.2, 0.3, 60.0);
        assert!((free.1 - 0.4).abs() < 1e-15);
        assert!((ab.1 - 0.3).abs() < 1e-15);
        assert!((solid.1 - 0.4 * 1.5).abs() < 1e-15);
    }
}
