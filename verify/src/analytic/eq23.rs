//! Solid/liquid/liquid contact angle θ12 of Natsui et al. 2021, Eq. (23), and
//! its regimes (Fig. 3 maps).
//!
//! Source: Natsui et al., Chem. Eng. Sci. 229 (2021) 116035 ("paper A"), §2.4,
//! Eqs. (19)–(23), Fig. 3 and §4. The printed text is damaged by OCR;
//! `docs/model.md` §5 and R8–R10 state the model. Departures from the
//! printed paper (docs/model.md C7, C8): Eq. (23) follows from Eqs. (19),
//! (21), (22), not "(19), (20), (21)"; Fig. 3's "σ3 = 0.1 N/m" is σ12 = 0.1 N/m
//! and its "eq. 26" is Eq. (23).
//!
//! Two liquids (surface tensions σ1, σ2 (N/m), interfacial tension σ12 (N/m))
//! sit on a solid 3; θ31 and θ23 are the Young angles of liquid 1 and liquid 2
//! on the solid in the gas, measured inside the liquid. Young's equation at the
//! three triple lines reads
//!
//! - (19) `σ1 cos θ31 + σ31 = σ3`,
//! - (21) `σ2 cos θ23 + σ23 = σ3`,
//! - (22) `σ12 cos θ12 + σ31 = σ23` (θ12 measured inside liquid 1),
//!
//! and eliminating the unknown σ3, σ31, σ23 gives
//! (23) `cos θ12 = (σ1 cos θ31 − σ2 cos θ23) / σ12`.
//!
//! If the right side exceeds 1 there is no solid/liquid/liquid line: liquid 1
//! spreads under liquid 2 (θ12 → 0°, liquid 2 rides on liquid 1 without
//! touching the solid); below −1 liquid 2 spreads under liquid 1 (θ12 → 180°).
//!
//! Boundary values: `|cos θ12| ≤ 1 + 1e-12` counts as a triple line (θ12 then
//! clamped to 0° or 180°), so that exact boundary cases written in degrees
//! (docs/model.md R9: θ23 = 60° → 180°, 120° → 0°) are not lost to the rounding
//! of `cos` (~1e-16, amplified by σ/σ12). A band of 1e-12 on cos θ12 is
//! 8e-5° at θ12 = 0°, far below any measurable angle.

/// Band on |cos θ12| beyond 1 still classified as a triple line (module doc).
const COS_BAND: f64 = 1e-12;

/// Tensions (σ1, σ2, σ12) in N/m of paper A's Fig. 3(a): identical matte
/// liquids (σ1 = σ2 = 0.4, σ12 = 0.1; docs/model.md R10).
pub const FIG3A_TENSIONS_N_PER_M: (f64, f64, f64) = (0.4, 0.4, 0.1);

/// Tensions (σ1, σ2, σ12) in N/m of paper A's Fig. 3(b): matte (1) and slag
/// (2) (σ1 = 0.4, σ2 = 0.2, σ12 = 0.1; docs/model.md R9).
pub const FIG3B_TENSIONS_N_PER_M: (f64, f64, f64) = (0.4, 0.2, 0.1);

/// How two liquids on a solid meet it, from Eq. (23), Natsui 2021.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SolidContact {
    /// A solid/liquid 1/liquid 2 triple line exists, with contact angle
    /// `theta12_deg` (degrees, in [0°, 180°], measured inside liquid 1).
    TripleLine {
        /// Contact angle θ12 at the solid/liquid/liquid line, degrees, inside
        /// liquid 1.
        theta12_deg: f64,
    },
    /// `cos θ12 > 1`: no triple line; liquid 1 spreads between the solid and
    /// liquid 2 (θ12 → 0°).
    Liquid1SpreadsUnder2,
    /// `cos θ12 < −1`: no triple line; liquid 2 spreads between the solid and
    /// liquid 1 (θ12 → 180°).
    Liquid2SpreadsUnder1,
}

impl SolidContact {
    /// θ12 in degrees, with the spreading regimes at their limits (0° when
    /// liquid 1 spreads under liquid 2, 180° when liquid 2 spreads under
    /// liquid 1): the saturated colour scale of paper A's Fig. 3.
    pub fn theta12_deg(&self) -> f64 {
        match *self {
            SolidContact::TripleLine { theta12_deg } => theta12_deg,
            SolidContact::Liquid1SpreadsUnder2 => 0.0,
            SolidContact::Liquid2SpreadsUnder1 => 180.0,
        }
    }

    /// True when a solid/liquid/liquid triple line exists.
    pub fn has_triple_line(&self) -> bool {
        matches!(self, SolidContact::TripleLine { .. })
    }
}

/// Checks the three tensions (N/m): finite and positive.
fn check_tensions(sigma1: f64, sigma2: f64, sigma12: f64) -> Result<(), String> {
    for (name, v) in [("sigma1", sigma1), ("sigma2", sigma2), ("sigma12", sigma12)] {
        if !(v.is_finite() && v > 0.0) {
            return Err(format!(
                "{name} = {v} N/m: a tension must be finite and > 0"
            ));
        }
    }
    Ok(())
}

/// Checks a Young contact angle (deg): finite and within [0°, 180°].
fn check_angle(name: &str, deg: f64) -> Result<(), String> {
    if deg.is_finite() && (0.0..=180.0).contains(&deg) {
        Ok(())
    } else {
        Err(format!(
            "{name} = {deg}°: a contact angle must be finite and within [0°, 180°]"
        ))
    }
}

/// Right-hand side of Eq. (23), Natsui 2021 (docs/model.md §5):
/// `cos θ12 = (σ1 cos θ31 − σ2 cos θ23) / σ12` (dimensionless; may lie outside
/// [−1, 1], which means no triple line — see [`solid_contact`]).
///
/// Tensions `sigma1_n_per_m`, `sigma2_n_per_m`, `sigma12_n_per_m` in N/m; Young
/// angles `theta31_deg` (liquid 1 on the solid) and `theta23_deg` (liquid 2 on
/// the solid) in degrees, inside the liquid. Returns NaN for a non-finite or
/// non-positive tension or a non-finite angle.
pub fn cos_theta12(
    sigma1_n_per_m: f64,
    sigma2_n_per_m: f64,
    sigma12_n_per_m: f64,
    theta31_deg: f64,
    theta23_deg: f64,
) -> f64 {
    if check_tensions(sigma1_n_per_m, sigma2_n_per_m, sigma12_n_per_m).is_err()
        || !theta31_deg.is_finite()
        || !theta23_deg.is_finite()
    {
        return f64::NAN;
    }
    // Eq. (23), Natsui 2021.
    (sigma1_n_per_m * theta31_deg.to_radians().cos()
        - sigma2_n_per_m * theta23_deg.to_radians().cos())
        / sigma12_n_per_m
}

/// Classifies the solid/liquid/liquid contact from Eq. (23), Natsui 2021:
/// a triple line with θ12 (degrees, inside liquid 1) when |cos θ12| ≤ 1 (within
/// the 1e-12 band of the module doc), otherwise which liquid spreads under the
/// other.
///
/// Tensions in N/m (finite, > 0); Young angles `theta31_deg`, `theta23_deg` in
/// degrees within [0°, 180°]. Errors name the offending argument.
pub fn solid_contact(
    sigma1_n_per_m: f64,
    sigma2_n_per_m: f64,
    sigma12_n_per_m: f64,
    theta31_deg: f64,
    theta23_deg: f64,
) -> Result<SolidContact, String> {
    check_tensions(sigma1_n_per_m, sigma2_n_per_m, sigma12_n_per_m)?;
    check_angle("theta31", theta31_deg)?;
    check_angle("theta23", theta23_deg)?;
    let c = cos_theta12(
        sigma1_n_per_m,
        sigma2_n_per_m,
        sigma12_n_per_m,
        theta31_deg,
        theta23_deg,
    );
    let contact = if c > 1.0 + COS_BAND {
        SolidContact::Liquid1SpreadsUnder2
    } else if c < -1.0 - COS_BAND {
        SolidContact::Liquid2SpreadsUnder1
    } else {
        SolidContact::TripleLine {
            theta12_deg: c.clamp(-1.0, 1.0).acos().to_degrees(),
        }
    };
    Ok(contact)
}

/// How θ12 of a triple line moves with the Young angles: `(∂θ12/∂θ31, ∂θ12/∂θ23)`
/// (dimensionless, deg per deg), from differentiating Eq. (23), Natsui 2021:
/// `∂θ12/∂θ31 = σ1 sin θ31 / (σ12 sin θ12)`, `∂θ12/∂θ23 = −σ2 sin θ23 / (σ12 sin θ12)`.
/// An error in a measured Young angle reaches θ12 multiplied by these. `Err` where Eq. (23)
/// has no line or the line is at θ12 = 0° or 180° (infinite sensitivity), or for invalid
/// input.
pub fn theta12_sensitivity(
    sigma1_n_per_m: f64,
    sigma2_n_per_m: f64,
    sigma12_n_per_m: f64,
    theta31_deg: f64,
    theta23_deg: f64,
) -> Result<(f64, f64), String> {
    let contact = solid_contact(
        sigma1_n_per_m,
        sigma2_n_per_m,
        sigma12_n_per_m,
        theta31_deg,
        theta23_deg,
    )?;
    let SolidContact::TripleLine { theta12_deg } = contact else {
        return Err("no solid/liquid/liquid line: θ12 has no sensitivity".into());
    };
    let s12 = theta12_deg.to_radians().sin();
    if s12 < 1e-9 {
        return Err(format!("θ12 = {theta12_deg}°: the sensitivity is infinite"));
    }
    Ok((
        sigma1_n_per_m * theta31_deg.to_radians().sin() / (sigma12_n_per_m * s12),
        -sigma2_n_per_m * theta23_deg.to_radians().sin() / (sigma12_n_per_m * s12),
    ))
}

/// Interval `(θ23_min, θ23_max)` in degrees of liquid 2's Young angle for which
/// a solid/liquid/liquid triple line exists, for given tensions (N/m) and
/// liquid 1's Young angle `theta31_deg` (deg): Eq. (23), Natsui 2021, solved
/// for cos θ23 with cos θ12 ∈ [−1, 1] (widened by the module's 1e-12 band, to
/// agree with [`solid_contact`]), intersected with [0°, 180°].
///
/// Below θ23_min liquid 2 spreads under liquid 1; above θ23_max liquid 1
/// spreads under liquid 2. `Ok(None)` when no θ23 in [0°, 180°] gives a triple
/// line; `Err` for invalid input.
pub fn triple_line_interval_theta23(
    sigma1_n_per_m: f64,
    sigma2_n_per_m: f64,
    sigma12_n_per_m: f64,
    theta31_deg: f64,
) -> Result<Option<(f64, f64)>, String> {
    check_tensions(sigma1_n_per_m, sigma2_n_per_m, sigma12_n_per_m)?;
    check_angle("theta31", theta31_deg)?;
    let c31 = theta31_deg.to_radians().cos();
    let reach = sigma12_n_per_m * (1.0 + COS_BAND);
    // Eq. (23), Natsui 2021, solved for cos θ23 at cos θ12 = ±1.
    let cos23_low = (sigma1_n_per_m * c31 - reach) / sigma2_n_per_m;
    let cos23_high = (sigma1_n_per_m * c31 + reach) / sigma2_n_per_m;
    if cos23_low > 1.0 || cos23_high < -1.0 {
        return Ok(None);
    }
    let theta23_min = cos23_high.min(1.0).acos().to_degrees();
    let theta23_max = cos23_low.max(-1.0).acos().to_degrees();
    Ok(Some((theta23_min, theta23_max)))
}

/// θ12 map of paper A's Fig. 3: [`solid_contact`] on the grid of Young angles
/// `theta31_deg` × `theta23_deg` (degrees), for tensions in N/m (Fig. 3(a):
/// [`FIG3A_TENSIONS_N_PER_M`], Fig. 3(b): [`FIG3B_TENSIONS_N_PER_M`]).
///
/// The result has one row per θ31 value and one column per θ23 value:
/// `map[i][j]` belongs to `(theta31_deg[i], theta23_deg[j])`. Use
/// [`SolidContact::theta12_deg`] for the saturated colour value. Errors name the
/// first invalid tension or angle.
pub fn theta12_map(
    sigma1_n_per_m: f64,
    sigma2_n_per_m: f64,
    sigma12_n_per_m: f64,
    theta31_deg: &[f64],
    theta23_deg: &[f64],
) -> Result<Vec<Vec<SolidContact>>, String> {
    theta31_deg
        .iter()
        .map(|&t31| {
            theta23_deg
                .iter()
                .map(|&t23| {
                    solid_contact(sigma1_n_per_m, sigma2_n_per_m, sigma12_n_per_m, t31, t23)
                })
                .collect()
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn theta12(s: (f64, f64, f64), t31: f64, t23: f64) -> SolidContact {
        solid_contact(s.0, s.1, s.2, t31, t23).unwrap()
    }

    /// Reference: docs/model.md R9 — Fig. 3(b) (σ1 0.4, σ2 0.2, σ12 0.1 N/m) at
    /// θ31 = 90°: θ23 60 → 180°, 75 → 121.17°, 90 → 90°, 105 → 58.83°,
    /// 120 → 0°, the ends being exact boundary cases (cos θ12 = ∓1) that must
    /// count as triple lines. Tolerance 0.005°: R9 gives 2 decimals; 1e-5° for
    /// the exact ends, where acos turns a rounding error δ ~ 1e-15 of cos θ12
    /// into √(2δ) ≈ 4.5e-8 rad = 2.6e-6°; 1e-9° at 90°, where acos is regular.
    #[test]
    fn r9_matte_slag_at_theta31_90() {
        let s = FIG3B_TENSIONS_N_PER_M;
        for (t23, expected) in [
            (60.0, 180.0),
            (75.0, 121.17),
            (90.0, 90.0),
            (105.0, 58.83),
            (120.0, 0.0),
        ] {
            match theta12(s, 90.0, t23) {
                SolidContact::TripleLine { theta12_deg } => {
                    assert!(
                        (theta12_deg - expected).abs() < 0.005,
                        "θ23 = {t23}: θ12 = {theta12_deg}"
                    );
                }
                other => panic!("θ23 = {t23}: expected a triple line, got {other:?}"),
            }
        }
        assert!((theta12(s, 90.0, 60.0).theta12_deg() - 180.0).abs() < 1e-5);
        assert!(theta12(s, 90.0, 120.0).theta12_deg().abs() < 1e-5);
        assert!((theta12(s, 90.0, 90.0).theta12_deg() - 90.0).abs() < 1e-9);
    }

    /// Reference: docs/model.md R9/R10 — the triple-line interval at θ31 = 90°:
    /// 75.52° ≤ θ23 ≤ 104.48° for identical matte liquids (Fig. 3(a)) and
    /// 60° … 120° for matte/slag (Fig. 3(b)). Tolerance 0.005°: 2 decimals.
    #[test]
    fn r10_triple_line_interval() {
        let (s1, s2, s12) = FIG3A_TENSIONS_N_PER_M;
        let (lo, hi) = triple_line_interval_theta23(s1, s2, s12, 90.0)
            .unwrap()
            .unwrap();
        assert!((lo - 75.52).abs() < 0.005, "{lo}");
        assert!((hi - 104.48).abs() < 0.005, "{hi}");
        let (s1, s2, s12) = FIG3B_TENSIONS_N_PER_M;
        let (lo, hi) = triple_line_interval_theta23(s1, s2, s12, 90.0)
            .unwrap()
            .unwrap();
        assert!(
            (lo - 60.0).abs() < 1e-6 && (hi - 120.0).abs() < 1e-6,
            "{lo} {hi}"
        );
    }

    /// Reference: docs/model.md R8 — water (1) / silicone oil (2) on Teflon
    /// (paper A Appendix): σ 72.8 / 20.1 / 52 mN/m, θ31 = 108.9°, θ23 = 16.4°
    /// → θ12 = 145.52°. Tolerance 0.005°: 2 decimals.
    #[test]
    fn r8_water_oil_teflon() {
        let c = theta12((0.0728, 0.0201, 0.052), 108.9, 16.4);
        let t = match c {
            SolidContact::TripleLine { theta12_deg } => theta12_deg,
            other => panic!("expected a triple line, got {other:?}"),
        };
        assert!((t - 145.52).abs() < 0.005, "{t}");
    }

    /// Physics (paper A §4.1, Fig. 3(a)): identical matte liquids, θ31 = 90°:
    /// liquid 1 rides on liquid 2 at θ23 = 30°, 60° (liquid 2 spreads under),
    /// half contact with θ12 = 90° at θ23 = 90°, liquid 2 rides on liquid 1 at
    /// 120°, 150°.
    #[test]
    fn section_4_1_regimes() {
        let s = FIG3A_TENSIONS_N_PER_M;
        for t23 in [30.0, 60.0] {
            assert_eq!(theta12(s, 90.0, t23), SolidContact::Liquid2SpreadsUnder1);
        }
        for t23 in [120.0, 150.0] {
            assert_eq!(theta12(s, 90.0, t23), SolidContact::Liquid1SpreadsUnder2);
        }
        assert!((theta12(s, 90.0, 90.0).theta12_deg() - 90.0).abs() < 1e-9);
        // Matte/slag (Fig. 3(b)) beyond the interval.
        let s = FIG3B_TENSIONS_N_PER_M;
        assert_eq!(theta12(s, 90.0, 45.0), SolidContact::Liquid2SpreadsUnder1);
        assert_eq!(theta12(s, 90.0, 135.0), SolidContact::Liquid1SpreadsUnder2);
    }

    /// Physics: Eq. (23) is the elimination of Young's Eqs. (19), (21), (22):
    /// for any solid tension σ3, σ31 and σ23 from (19) and (21) satisfy (22)
    /// with the θ12 returned. Tolerance 1e-14 N/m: rounding of a few terms of
    /// order 1 N/m.
    #[test]
    fn eq23_satisfies_youngs_equations() {
        let s = (0.4, 0.2, 0.1);
        for t31 in [70.0, 90.0, 110.0] {
            let (lo, hi) = triple_line_interval_theta23(s.0, s.1, s.2, t31)
                .unwrap()
                .unwrap();
            for k in 1..10 {
                let t23 = lo + (hi - lo) * k as f64 / 10.0;
                let t12 = theta12(s, t31, t23).theta12_deg();
                for sigma3 in [0.05, 0.5, 1.5] {
                    let sigma31 = sigma3 - s.0 * t31.to_radians().cos(); // Eq. (19)
                    let sigma23 = sigma3 - s.1 * t23.to_radians().cos(); // Eq. (21)
                    let res = s.2 * t12.to_radians().cos() + sigma31 - sigma23; // Eq. (22)
                    assert!(res.abs() < 1e-14, "residual {res} N/m");
                }
            }
        }
    }

    /// Physics: relabelling the liquids (σ1 ↔ σ2, θ31 ↔ θ23) measures the
    /// same corner from the other side: θ12 → 180° − θ12, and the spreading
    /// regimes swap. Tolerance 1e-9°: rounding.
    #[test]
    fn swapping_liquids_mirrors_theta12() {
        let s = (0.4, 0.2, 0.1);
        let swapped = (0.2, 0.4, 0.1);
        for t31 in (0..=12).map(|i| 15.0 * i as f64) {
            for t23 in (0..=12).map(|i| 15.0 * i as f64) {
                let a = theta12(s, t31, t23);
                let b = theta12(swapped, t23, t31);
                match (a, b) {
                    (SolidContact::Liquid1SpreadsUnder2, SolidContact::Liquid2SpreadsUnder1)
                    | (SolidContact::Liquid2SpreadsUnder1, SolidContact::Liquid1SpreadsUnder2) => {}
                    (
                        SolidContact::TripleLine { theta12_deg: x },
                        SolidContact::TripleLine { theta12_deg: y },
                    ) => {
                        assert!((x + y - 180.0).abs() < 1e-9, "{x} + {y}");
                    }
                    other => panic!("θ31 {t31}, θ23 {t23}: {other:?}"),
                }
            }
        }
    }

    /// Physics: identical liquids (σ1 = σ2) with equal Young angles meet the
    /// solid at θ12 = 90°, for any σ12 (the interface stands upright).
    #[test]
    fn identical_liquids_meet_at_right_angle() {
        for t in [10.0, 45.0, 90.0, 135.0, 170.0] {
            for s12 in [0.01, 0.1, 1.0] {
                let c = theta12((0.4, 0.4, s12), t, t);
                assert!((c.theta12_deg() - 90.0).abs() < 1e-9);
            }
        }
    }

    /// The interval agrees with the classification on a 0.1° grid: inside →
    /// triple line, below → liquid 2 spreads under 1, above → liquid 1 spreads
    /// under 2 (grid points closer than 1e-6° to an end are skipped).
    #[test]
    fn interval_agrees_with_classification() {
        for s in [
            FIG3A_TENSIONS_N_PER_M,
            FIG3B_TENSIONS_N_PER_M,
            (0.0728, 0.0201, 0.052),
        ] {
            for t31 in (0..=36).map(|i| 5.0 * i as f64) {
                let interval = triple_line_interval_theta23(s.0, s.1, s.2, t31).unwrap();
                for k in 0..=1800 {
                    let t23 = 0.1 * k as f64;
                    let c = theta12(s, t31, t23);
                    match interval {
                        None => assert!(!c.has_triple_line(), "θ31 {t31} θ23 {t23}"),
                        Some((lo, hi)) => {
                            if (t23 - lo).abs() < 1e-6 || (t23 - hi).abs() < 1e-6 {
                                continue;
                            }
                            let expected = if t23 < lo {
                                SolidContact::Liquid2SpreadsUnder1
                            } else if t23 > hi {
                                SolidContact::Liquid1SpreadsUnder2
                            } else {
                                c
                            };
                            assert_eq!(c, expected, "θ31 {t31} θ23 {t23} interval {lo}..{hi}");
                            assert_eq!(c.has_triple_line(), (lo..=hi).contains(&t23));
                        }
                    }
                }
            }
        }
    }

    /// Physics: a liquid 1 that wets the solid completely (θ31 = 0°) in the
    /// Fig. 3(b) system always spreads under liquid 2: cos θ12 ≥ (0.4 − 0.2)/0.1
    /// = 2, so no θ23 gives a triple line.
    #[test]
    fn no_interval_when_liquid1_wets_completely() {
        let (s1, s2, s12) = FIG3B_TENSIONS_N_PER_M;
        assert_eq!(triple_line_interval_theta23(s1, s2, s12, 0.0), Ok(None));
        assert_eq!(
            theta12((s1, s2, s12), 0.0, 180.0),
            SolidContact::Liquid1SpreadsUnder2
        );
        assert!(cos_theta12(s1, s2, s12, 0.0, 180.0) > 1.0);
    }

    /// The Fig. 3 maps: one row per θ31, one column per θ23, each cell equal to
    /// `solid_contact`; Fig. 3(b)'s θ31 = 90° row reproduces R9.
    #[test]
    fn fig3_maps() {
        let t31: Vec<f64> = (0..=36).map(|i| 5.0 * i as f64).collect();
        let t23: Vec<f64> = (0..=12).map(|i| 15.0 * i as f64).collect();
        for s in [FIG3A_TENSIONS_N_PER_M, FIG3B_TENSIONS_N_PER_M] {
            let map = theta12_map(s.0, s.1, s.2, &t31, &t23).unwrap();
            assert_eq!(map.len(), t31.len());
            for (i, row) in map.iter().enumerate() {
                assert_eq!(row.len(), t23.len());
                for (j, cell) in row.iter().enumerate() {
                    assert_eq!(*cell, theta12(s, t31[i], t23[j]));
                }
            }
        }
        let s = FIG3B_TENSIONS_N_PER_M;
        let row =
            &theta12_map(s.0, s.1, s.2, &[90.0], &[60.0, 75.0, 90.0, 105.0, 120.0]).unwrap()[0];
        let expected = [180.0, 121.17, 90.0, 58.83, 0.0];
        for (cell, e) in row.iter().zip(expected) {
            assert!(cell.has_triple_line() && (cell.theta12_deg() - e).abs() < 0.005);
        }
        assert!(theta12_map(s.0, s.1, s.2, &[], &t23).unwrap().is_empty());
    }

    /// Bad input gives an error (or NaN from the raw formula), never a panic.
    #[test]
    fn bad_input_is_rejected() {
        assert!(solid_contact(0.4, 0.2, 0.0, 90.0, 90.0).is_err());
        assert!(solid_contact(-0.4, 0.2, 0.1, 90.0, 90.0).is_err());
        assert!(solid_contact(0.4, f64::NAN, 0.1, 90.0, 90.0).is_err());
        assert!(solid_contact(0.4, 0.2, 0.1, -1.0, 90.0).is_err());
        assert!(solid_contact(0.4, 0.2, 0.1, 90.0, 181.0).is_err());
        assert!(solid_contact(0.4, 0.2, 0.1, f64::NAN, 90.0).is_err());
        assert!(triple_line_interval_theta23(0.4, 0.2, 0.1, 200.0).is_err());
        assert!(triple_line_interval_theta23(0.4, 0.0, 0.1, 90.0).is_err());
        assert!(theta12_map(0.4, 0.2, 0.1, &[90.0], &[90.0, f64::INFINITY]).is_err());
        assert!(cos_theta12(0.4, 0.2, 0.0, 90.0, 90.0).is_nan());
        assert!(cos_theta12(0.4, 0.2, 0.1, f64::NAN, 90.0).is_nan());
    }

    #[test]
    fn sensitivity_matches_finite_differences() {
        // matte–slag at θ31 = 90°, θ23 = 75° (θ12 = 121.2°) and identical liquids at 60°/68°
        for (s1, s2, th31, th23) in [(0.4, 0.2, 90.0, 75.0), (0.4, 0.4, 60.0, 68.0)] {
            let (d31, d23) = theta12_sensitivity(s1, s2, 0.1, th31, th23).unwrap();
            let at = |a: f64, b: f64| solid_contact(s1, s2, 0.1, a, b).unwrap().theta12_deg();
            let h = 1e-4;
            let f31 = (at(th31 + h, th23) - at(th31 - h, th23)) / (2.0 * h);
            let f23 = (at(th31, th23 + h) - at(th31, th23 - h)) / (2.0 * h);
            // central differences of a smooth function: error O(h²) ≈ 1e-8 relative
            assert!((d31 - f31).abs() < 1e-6 * f31.abs().max(1.0), "{d31} {f31}");
            assert!((d23 - f23).abs() < 1e-6 * f23.abs().max(1.0), "{d23} {f23}");
        }
        // no line (identical liquids, θ31 = 90°, θ23 = 30°): refused
        assert!(theta12_sensitivity(0.4, 0.4, 0.1, 90.0, 30.0).is_err());
    }
}
