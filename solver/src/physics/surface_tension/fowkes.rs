//! Pair strengths from the Fowkes hypothesis (Eqs. 16–20, Natsui 2021): a liquid with itself
//! `σ_a`; two liquids `σ_D = (σ_a + σ_b − σ_ab)/2`; a liquid and a solid
//! `σ_D = σ_a (1 + cos θ_a)/2`. A negative `σ_D` (no adhesion) is clipped to zero. The
//! potential coefficient of a pair is `C = 2 σ_pair l0² / S` with the lattice surface sum `S`.

/// Like pairs of a liquid carry its surface tension `σ_a` [N/m].
pub fn like_pair(sigma_n_m: f64) -> f64 {
    sigma_n_m.max(0.0)
}

/// Two liquids of surface tensions `σ_a`, `σ_b` and interfacial tension `σ_ab` [N/m]:
/// `σ_D = (σ_a + σ_b − σ_ab)/2` [N/m], from Eq. (18), Natsui 2021 (`σ_ab = σ_a + σ_b − 2σ_D`).
pub fn liquid_liquid(sigma_a: f64, sigma_b: f64, sigma_ab: f64) -> f64 {
    (0.5 * (sigma_a + sigma_b - sigma_ab)).max(0.0)
}

/// A liquid of surface tension `σ` [N/m] on a solid where its contact angle is `θ` [°]:
/// `σ_D = σ (1 + cos θ)/2` [N/m], from Eq. (20), Natsui 2021 (`cos θ = 2σ_D/σ − 1`).
pub fn liquid_solid(sigma_n_m: f64, theta_deg: f64) -> f64 {
    (0.5 * sigma_n_m * (1.0 + theta_deg.to_radians().cos())).max(0.0)
}

/// The strength `σ_pair` [N/m] of every pair of phases (liquids first, then solids) and the
/// potential coefficients `C_ij = 2 σ_pair l0² / S` [N/m²].
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
    /// The table of `n_phases` phases with pair strengths `sigma_pair` [N/m] (row-major), for
    /// spacing `l0` [m] and the lattice surface sum `S` [m³] of
    /// [`crate::lattice::potential_surface_sum`].
    pub fn new(n_phases: usize, sigma_pair: Vec<f64>, l0_m: f64, s_m3: f64) -> PairTable {
        assert_eq!(sigma_pair.len(), n_phases * n_phases, "a square table");
        let coeff = sigma_pair
            .iter()
            .map(|s| 2.0 * s * l0_m * l0_m / s_m3)
            .collect();
        PairTable {
            n_phases,
            sigma_pair,
            coeff,
        }
    }

    /// No tension: every coefficient zero.
    pub fn zero(n_phases: usize) -> PairTable {
        PairTable {
            n_phases,
            sigma_pair: vec![0.0; n_phases * n_phases],
            coeff: vec![0.0; n_phases * n_phases],
        }
    }

    /// Scales the coefficients by liquid: `C_aa` by `f_a`, two liquids' `C_ab` by `√(f_a f_b)`,
    /// a liquid's against a solid by its `f`; `scales` has one factor per liquid (the first
    /// `scales.len()` phases). The pair strengths `σ_pair` stay the typed ones.
    pub fn scale_liquids(&mut self, scales: &[f64]) {
        let nl = scales.len();
        let f = |a: usize| if a < nl { Some(scales[a]) } else { None };
        for a in 0..self.n_phases {
            for b in 0..self.n_phases {
                let s = match (f(a), f(b)) {
                    (Some(fa), Some(_)) if a == b => fa,
                    (Some(fa), Some(fb)) => (fa * fb).sqrt(),
                    (Some(fl), None) | (None, Some(fl)) => fl,
                    (None, None) => 1.0,
                };
                self.coeff[a * self.n_phases + b] *= s;
            }
        }
    }

    /// Scales the coefficient of the unlike pair `a`, `b` (both orders) by `f`.
    pub fn scale_pair(&mut self, a: usize, b: usize, f: f64) {
        assert_ne!(a, b, "an unlike pair");
        self.coeff[a * self.n_phases + b] *= f;
        self.coeff[b * self.n_phases + a] *= f;
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

    /// Row `a` of the coefficients [N/m²].
    #[inline(always)]
    pub fn row(&self, a: usize) -> &[f64] {
        &self.coeff[a * self.n_phases..(a + 1) * self.n_phases]
    }
}
