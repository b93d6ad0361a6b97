//! Elastic (Born) moduli of the reference particle lattice.
//!
//! A liquid has no shear stiffness. The simple cubic lattice the particles start on has some:
//! its pair forces — the potential's, and the pressure term's with the background pressure the
//! equation of state carries — resist a shear of the lattice like a crystal's bonds. This module
//! computes that stiffness from lattice sums, for any kernel, `h/l0` and `r_e/l0`.
//!
//! Units: lengths in `l0`, energies such that `σ = 1`: moduli and pressures come out in `σ/l0`.
//!
//! Pair energies (per pair): the potential's `φ_pot(r) = −C P(r)` with `C = 2σ l0²/S`
//! (Eq. 15, Natsui 2021, with the lattice normalisation `S`); the pressure term's
//! `φ_p(r) = 2 p_b V² W(r)`: with a uniform pressure `p_b` and volume `V = l0³` the force
//! `−Σ_j (p V² + p V²) ∇_i W_ij` (Eq. 11, Natsui 2021) derives from it. The background pressure
//! `p_b` is the one that makes the lattice's total virial stress zero (the equation of state
//! settles there): `p_b M + P_pot = 0` with `P_pot = (C/6) Σ_j r P'(r)` (negative: cohesion)
//! and `M = −(1/3) Σ_j r W'(r) l0³` (1 for a continuum).
//!
//! Moduli per site volume `Ω = l0³`, from the energy per site `E(γ) = ½ Σ_j φ(|F(γ) x_j|)`:
//! `G44 = E''(0)` under the pure shear `F = [[cosh γ/2, sinh γ/2], [sinh γ/2, cosh γ/2]]`
//! (engineering strain `γ` in the x–y plane) and `C' = (C11 − C12)/2 = E''(0)` under the
//! volume-preserving stretch `F = diag(e^{γ/2}, e^{−γ/2}, 1)`. The Born sums use `φ''` and
//! `φ'` analytically; [`shear_stress`] gives `E'(γ)` at a finite strain, whose central
//! difference checks them.

use solver::kernel::{Kernel, KernelKind};
use solver::lattice::potential_surface_sum;
use solver::physics::surface_tension::Kondo2007Potential;
use solver::with_kernel;

/// A lattice deformation mode.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    /// Pure shear in the x–y plane (modulus `G44` = `C44`).
    Shear44,
    /// Volume-preserving stretch along x against y (modulus `C' = (C11 − C12)/2`).
    Stretch,
}

/// The two shear moduli [σ/l0].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Moduli {
    /// `G44` [σ/l0].
    pub g44: f64,
    /// `C'` [σ/l0].
    pub c_prime: f64,
}

impl std::ops::Add for Moduli {
    type Output = Moduli;
    fn add(self, o: Moduli) -> Moduli {
        Moduli {
            g44: self.g44 + o.g44,
            c_prime: self.c_prime + o.c_prime,
        }
    }
}

/// The elasticity of the reference lattice at one setting.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LatticeElasticity {
    /// The potential's lattice surface sum `S` [l0³].
    pub surface_sum: f64,
    /// The potential's virial pressure `P_pot` [σ/l0] (negative: cohesive).
    pub potential_pressure: f64,
    /// The pressure term's virial factor `M = −(1/3) Σ r W'(r) l0³` [-].
    pub kernel_virial: f64,
    /// The background pressure `p_b = −P_pot/M` the equation of state carries [σ/l0].
    pub background_pressure: f64,
    /// Moduli of the potential alone [σ/l0].
    pub potential: Moduli,
    /// Moduli of the pressure term at `p_b` [σ/l0].
    pub pressure: Moduli,
}

impl LatticeElasticity {
    /// Potential and pressure term together [σ/l0]: the lattice's stiffness (a liquid: 0).
    pub fn total(&self) -> Moduli {
        self.potential + self.pressure
    }
}

/// A radial pair energy `φ(r)` with its first two derivatives, in lattice units.
trait PairEnergy {
    /// Beyond this distance [l0] the energy vanishes.
    fn reach(&self) -> f64;
    /// `(φ'(r), φ''(r))`.
    fn derivatives(&self, r: f64) -> (f64, f64);
}

/// `φ(r) = −C P(r)` of the potential.
struct PotentialEnergy {
    potential: Kondo2007Potential,
    c: f64,
}

impl PairEnergy for PotentialEnergy {
    fn reach(&self) -> f64 {
        self.potential.r_e_m
    }
    fn derivatives(&self, r: f64) -> (f64, f64) {
        let p = &self.potential;
        (-self.c * p.dp_dr(r), -self.c * p.d2p_dr2(r))
    }
}

/// `φ(r) = 2 p_b W(r)` of the pressure term (`V = l0³ = 1`).
struct PressureEnergy<K: Kernel> {
    kernel: K,
    p_b: f64,
}

impl<K: Kernel> PairEnergy for PressureEnergy<K> {
    fn reach(&self) -> f64 {
        self.kernel.support_m()
    }
    fn derivatives(&self, r: f64) -> (f64, f64) {
        let k = &self.kernel;
        (2.0 * self.p_b * k.dw_dr(r), 2.0 * self.p_b * k.d2w_dr2(r))
    }
}

/// Lattice offsets `(x, y, z)` [l0] with `0 < r < reach`.
fn sites(reach: f64) -> Vec<[f64; 3]> {
    let n = reach.ceil() as i64 + 1;
    let mut out = Vec::new();
    for k in -n..=n {
        for j in -n..=n {
            for i in -n..=n {
                let x = [i as f64, j as f64, k as f64];
                let r2 = x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
                if r2 > 0.0 && r2 < reach * reach {
                    out.push(x);
                }
            }
        }
    }
    out
}

/// `(r², d(r²)/dγ, d²(r²)/dγ²)` of the offset `x` under `mode` at strain `gamma`.
fn stretch_of(mode: Mode, x: [f64; 3], gamma: f64) -> (f64, f64, f64) {
    let [a, b, c] = x;
    match mode {
        // r² = (a² + b²) cosh γ + 2ab sinh γ + c²
        Mode::Shear44 => {
            let (ch, sh) = (gamma.cosh(), gamma.sinh());
            let s = a * a + b * b;
            (
                s * ch + 2.0 * a * b * sh + c * c,
                s * sh + 2.0 * a * b * ch,
                s * ch + 2.0 * a * b * sh,
            )
        }
        // r² = a² e^γ + b² e^−γ + c²
        Mode::Stretch => {
            let (ep, em) = (gamma.exp(), (-gamma).exp());
            (
                a * a * ep + b * b * em + c * c,
                a * a * ep - b * b * em,
                a * a * ep + b * b * em,
            )
        }
    }
}

/// The Born modulus `E''(0)` [σ/l0] of `phi` under `mode`.
///
/// A shell of sites exactly at the reach (e.g. `(4, 0, 0)` at `r_e = 4 l0`) makes `E''`
/// one-sided — the potential's `φ''` jumps at `r_e`, so stretching and compressing such a bond
/// cost differently; such sites count with weight ½, giving the mean of the two one-sided
/// moduli (what a central difference of the stress measures).
fn born(phi: &dyn PairEnergy, mode: Mode) -> f64 {
    let mut sum = 0.0;
    let reach = phi.reach();
    for x in sites(reach + 1.0) {
        let (r2, d1, d2) = stretch_of(mode, x, 0.0);
        let r = r2.sqrt();
        let weight = if (r - reach).abs() <= 1e-12 * reach {
            0.5
        } else if r < reach {
            1.0
        } else {
            continue;
        };
        let (f1, f2) = phi.derivatives(r);
        // r' = (r²)'/(2r), r'' = (r²)''/(2r) − ((r²)')²/(4r³)
        let dr = d1 / (2.0 * r);
        let ddr = d2 / (2.0 * r) - d1 * d1 / (4.0 * r * r * r);
        sum += weight * (f2 * dr * dr + f1 * ddr);
    }
    0.5 * sum
}

/// The conjugate stress `E'(γ)` [σ/l0] of `phi` under `mode` at a finite strain `gamma`.
fn conjugate_stress(phi: &dyn PairEnergy, mode: Mode, gamma: f64) -> f64 {
    let mut sum = 0.0;
    for x in sites(phi.reach() + 1.0) {
        let (r2, d1, _) = stretch_of(mode, x, gamma);
        let r = r2.sqrt();
        if r < phi.reach() {
            sum += phi.derivatives(r).0 * d1 / (2.0 * r);
        }
    }
    0.5 * sum
}

/// The virial pressure `−(1/6) Σ_j r φ'(r)` [σ/l0] of `phi` on the undeformed lattice.
fn virial_pressure(phi: &dyn PairEnergy) -> f64 {
    let s: f64 = sites(phi.reach())
        .into_iter()
        .map(|x| {
            let r = (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]).sqrt();
            r * phi.derivatives(r).0
        })
        .sum();
    -s / 6.0
}

/// The two pair energies of a setting: the potential, and the pressure term at the background
/// pressure that balances it.
fn energies<K: Kernel>(
    h_over_l0: f64,
    re_over_l0: f64,
    order: u8,
) -> (PotentialEnergy, PressureEnergy<K>, f64) {
    let potential = Kondo2007Potential {
        l0_m: 1.0,
        r_e_m: re_over_l0,
        order,
    };
    let s = potential_surface_sum(&potential);
    let pot = PotentialEnergy {
        potential,
        c: 2.0 / s, // C = 2σ l0²/S, Eq. (15)–(16), Natsui 2021
    };
    let kernel = K::new(h_over_l0);
    let unit = PressureEnergy { kernel, p_b: 1.0 };
    // with p_b = 1 the pressure term's virial pressure is M
    let m = virial_pressure(&unit);
    let p_b = -virial_pressure(&pot) / m;
    (pot, PressureEnergy { kernel, p_b }, s)
}

/// The elasticity of the reference lattice for a kernel, `h/l0`, `r_e/l0` and the potential's
/// order (1: Kondo 2007).
pub fn lattice_elasticity(
    kernel: KernelKind,
    h_over_l0: f64,
    re_over_l0: f64,
    order: u8,
) -> LatticeElasticity {
    with_kernel!(kernel, K => {
        let (pot, pres, s) = energies::<K>(h_over_l0, re_over_l0, order);
        let moduli = |phi: &dyn PairEnergy| Moduli {
            g44: born(phi, Mode::Shear44),
            c_prime: born(phi, Mode::Stretch),
        };
        let p_pot = virial_pressure(&pot);
        LatticeElasticity {
            surface_sum: s,
            potential_pressure: p_pot,
            kernel_virial: -p_pot / pres.p_b,
            background_pressure: pres.p_b,
            potential: moduli(&pot),
            pressure: moduli(&pres),
        }
    })
}

/// The total conjugate stress `E'(γ)` [σ/l0] (potential and pressure term) of the lattice at a
/// finite strain `gamma` of `mode`: the check of the Born moduli by finite differences.
pub fn shear_stress(
    kernel: KernelKind,
    (h_over_l0, re_over_l0, order): (f64, f64, u8),
    mode: Mode,
    gamma: f64,
) -> f64 {
    with_kernel!(kernel, K => {
        let (pot, pres, _) = energies::<K>(h_over_l0, re_over_l0, order);
        conjugate_stress(&pot, mode, gamma) + conjugate_stress(&pres, mode, gamma)
    })
}

/// A markdown table of the lattice's elasticity for every kernel × `h/l0` × `r_e/l0` ×
/// potential order.
pub fn table(
    kernels: &[KernelKind],
    h_over_l0: &[f64],
    re_over_l0: &[f64],
    orders: &[u8],
) -> String {
    let mut out = String::from(
        "| kernel | h/l0 | r_e/l0 | order | S/l0³ | p_b [σ/l0] | G44 potential | C′ potential | G44 pressure | C′ pressure | **G44 total** | **C′ total** |\n\
         |---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    for &kernel in kernels {
        for &order in orders {
            for &re in re_over_l0 {
                for &h in h_over_l0 {
                    let e = lattice_elasticity(kernel, h, re, order);
                    let t = e.total();
                    out.push_str(&format!(
                    "| {} | {h} | {re} | {order} | {:.4} | {:.3} | {:+.3} | {:+.3} | {:+.3} | {:+.3} | **{:+.3}** | **{:+.3}** |\n",
                    kernel.name(),
                    e.surface_sum,
                    e.background_pressure,
                    e.potential.g44,
                    e.potential.c_prime,
                    e.pressure.g44,
                    e.pressure.c_prime,
                    t.g44,
                    t.c_prime
                ));
                }
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The Born sums against the central difference of the stress at ±δ. For a smooth `E` the
    /// difference's truncation error is `E''''(0) δ²/6` (~1e-12 σ/l0 at δ = 1e-6); where a shell
    /// of sites sits exactly at `r_e` (r_e = 4 l0) the slope of `E'` jumps and the error is
    /// first order, about 0.2 δ σ/l0 (measured: 1.8e-5 at δ = 1e-4); round-off is
    /// `ε |E'| / δ` ~ 1e-10. So 1e-6 σ/l0 bounds all with margin, while a wrong sum (errors
    /// of 0.01–0.1 σ/l0) fails.
    #[test]
    fn born_moduli_match_finite_differences_of_the_stress() {
        let delta = 1e-6;
        for kernel in KernelKind::ALL {
            for (h, re, order) in [
                (1.05, 4.2, 1),
                (1.3, 4.2, 1),
                (2.0, 4.0, 1),
                (1.05, 2.1, 1),
                (1.5, 3.1, 1),
                (1.05, 4.8, 3),
                (1.3, 4.4, 2),
            ] {
                let e = lattice_elasticity(kernel, h, re, order);
                let t = e.total();
                for (mode, born) in [(Mode::Shear44, t.g44), (Mode::Stretch, t.c_prime)] {
                    let fd = (shear_stress(kernel, (h, re, order), mode, delta)
                        - shear_stress(kernel, (h, re, order), mode, -delta))
                        / (2.0 * delta);
                    assert!(
                        (fd - born).abs() < 1e-6,
                        "{kernel:?} h = {h} l0, r_e = {re} l0, {mode:?}: Born {born}, finite difference {fd}"
                    );
                }
            }
        }
    }

    /// The undeformed lattice carries no shear stress (cubic symmetry), and the background
    /// pressure cancels the potential's virial pressure exactly.
    #[test]
    fn the_reference_lattice_is_in_equilibrium() {
        let e = lattice_elasticity(KernelKind::WendlandC2, 1.05, 4.2, 1);
        for mode in [Mode::Shear44, Mode::Stretch] {
            let s = shear_stress(KernelKind::WendlandC2, (1.05, 4.2, 1), mode, 0.0);
            assert!(s.abs() < 1e-12, "{mode:?}: stress {s} at zero strain");
        }
        assert!(e.potential_pressure < 0.0, "the potential is cohesive");
        // p_b M + P_pot = 0 by construction: the residual is round-off of sums of O(1) terms
        assert!((e.background_pressure * e.kernel_virial + e.potential_pressure).abs() < 1e-12);
    }
}
