//! Surface and interfacial tension by a pairwise interparticle potential.
//!
//! The potential is Kondo et al. (2007)'s, used in 3D SPH by Natsui et al. (2016, 2021):
//! `P(r) = (1/3)(r − 1.5 l0 + 0.5 r_e)(r − r_e)²` for `r < r_e` [m³], and the force on `i` is
//! `F_i = Σ_j C_ij P'(r_ij) e_ij` [N] with `P'(r) = (r − l0)(r − r_e)` — Eq. (15), Natsui 2021,
//! in the corrected form of physics.md §4: the pair coefficient sits inside the sum and the
//! normalisation `S` is a constant of the reference lattice, not each particle's current sum
//! (which would blow up at the surface). The force is repulsive below `l0`, attractive between
//! `l0` and `r_e`, and antisymmetric in `i, j`, so momentum is conserved.
//!
//! Pair strengths follow the Fowkes hypothesis (Eqs. 16–20, Natsui 2021): a liquid with itself
//! `σ_a`; two liquids `σ_D = (σ_a + σ_b − σ_ab)/2`; a liquid and a solid
//! `σ_D = σ_a (1 + cos θ_a)/2`. A negative `σ_D` (no adhesion) is clipped to zero.

use crate::scene::Scene;

/// Kondo et al. (2007)'s pairwise potential with spacing `l0` and cut-off `r_e`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Kondo2007Potential {
    /// Initial particle spacing `l0` [m]: the force vanishes there.
    pub l0_m: f64,
    /// Cut-off `r_e` [m]: potential and force vanish there.
    pub r_e_m: f64,
}

impl Kondo2007Potential {
    /// Potential `P(r)` [m³]; the physical pair energy is `−C P(r)`.
    #[inline(always)]
    pub fn p(&self, r_m: f64) -> f64 {
        if r_m >= self.r_e_m {
            return 0.0;
        }
        let a = r_m - self.r_e_m;
        (r_m - 1.5 * self.l0_m + 0.5 * self.r_e_m) * a * a / 3.0 // Kondo 2007; physics.md §4
    }

    /// Derivative `P'(r) = (r − l0)(r − r_e)` [m²] (0 beyond `r_e`).
    #[inline(always)]
    pub fn dp_dr(&self, r_m: f64) -> f64 {
        if r_m >= self.r_e_m {
            return 0.0;
        }
        (r_m - self.l0_m) * (r_m - self.r_e_m)
    }
}

/// The strength `σ_pair` [N/m] of every pair of phases (liquids first, then solids), from the
/// Fowkes hypothesis, and the potential coefficients `C_ij = 2 σ_pair l0² / S` [N/m²].
#[derive(Clone, Debug, PartialEq)]
pub struct PairTable {
    /// Number of phases (liquids then solids).
    pub n_phases: usize,
    /// `σ_pair` [N/m], row-major `n_phases × n_phases`.
    pub sigma_pair: Vec<f64>,
    /// `C_ij` [N/m²], row-major `n_phases × n_phases`.
    pub coeff: Vec<f64>,
}

impl PairTable {
    /// Builds the table for a validated scene with interfacial tension on. `s_m3` is the
    /// lattice surface sum `S` [m³] of [`crate::lattice::potential_surface_sum`].
    pub fn from_scene(scene: &Scene, s_m3: f64) -> PairTable {
        let nl = scene.liquids.len();
        let n = nl + scene.solids.len();
        let l0 = scene.discretisation.l0;
        let sigma = |a: usize| scene.liquids[a].surface_tension.unwrap_or(0.0);
        let mut sigma_pair = vec![0.0; n * n];
        for a in 0..n {
            for b in 0..n {
                let s = match (a < nl, b < nl) {
                    (true, true) if a == b => sigma(a), // Fowkes: like pairs carry σ_a
                    (true, true) => {
                        let (na, nb) = (&scene.liquids[a].name, &scene.liquids[b].name);
                        match scene.interface_tension(na, nb) {
                            // Eq. (18), Natsui 2021: σ12 = σ1 + σ2 − 2σ_D
                            Some(s_ab) => 0.5 * (sigma(a) + sigma(b) - s_ab),
                            // liquids that never meet: validation guarantees they are not both
                            // present; no adhesion is the neutral choice
                            None => 0.0,
                        }
                    }
                    (true, false) | (false, true) => {
                        let (l, so) = if a < nl { (a, b - nl) } else { (b, a - nl) };
                        let angle = scene.solids[so].contact_angles.get(&scene.liquids[l].name);
                        match angle {
                            // Eq. (20), Natsui 2021: cos θ = 2σ_D/σ − 1
                            Some(&theta_deg) => {
                                0.5 * sigma(l) * (1.0 + theta_deg.to_radians().cos())
                            }
                            None => 0.0,
                        }
                    }
                    (false, false) => 0.0, // solids are fixed: no solid–solid force
                };
                sigma_pair[a * n + b] = s.max(0.0);
            }
        }
        let coeff = sigma_pair
            .iter()
            .map(|s| 2.0 * s * l0 * l0 / s_m3)
            .collect();
        PairTable {
            n_phases: n,
            sigma_pair,
            coeff,
        }
    }

    /// `C_ab` [N/m²].
    #[inline(always)]
    pub fn c(&self, a: usize, b: usize) -> f64 {
        self.coeff[a * self.n_phases + b]
    }

    /// `σ_pair(a, b)` [N/m].
    pub fn sigma(&self, a: usize, b: usize) -> f64 {
        self.sigma_pair[a * self.n_phases + b]
    }
}
