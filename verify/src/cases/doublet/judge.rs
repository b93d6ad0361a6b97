//! The doublets' metrics: G1G2/R0 against the analytic doublet, the regime against the Neumann
//! inequalities, the triple-line angles and the Eq. 27 residual; the oscillation and the
//! paper's trends reported.

use super::measure::DoubletRun;
use super::{drop_volume_m3, paper_values, Pair, Start, R0_M};
use crate::analytic::neumann::{self, Regime};
use crate::measure::geometry::DoubletAngles;
use crate::suite::{Metric, Tolerance};

/// What the metrics of a doublet case are judged with.
pub struct Judge<'a> {
    /// The case's name.
    pub case: &'a str,
    /// Which pair of liquids.
    pub pair: Pair,
    /// Surface tensions σ1, σ2 of the two liquids [N/m].
    pub sigma_n_m: (f64, f64),
    /// σ12 values [N/m] not simulated because their model equals that of another σ12 (the
    /// second), so their runs would be identical.
    pub same_as: Vec<(f64, f64)>,
}

impl Judge<'_> {
    /// Every metric of the case.
    pub fn metrics(&self, runs: &[DoubletRun]) -> anyhow::Result<Vec<Metric>> {
        let mut out = Vec::new();
        // the merged starts are judged only on parting (below)
        for m in runs
            .iter()
            .filter(|m| matches!(m.start, Start::Touching | Start::Fine))
        {
            out.extend(self.run_metrics(m)?);
        }
        if self.pair == Pair::Equal {
            let of = |start: Start, csf: bool| -> Vec<&DoubletRun> {
                runs.iter()
                    .filter(|m| m.start == start && m.surface_force == csf)
                    .collect()
            };
            let potential: Vec<&DoubletRun> = runs.iter().filter(|m| !m.surface_force).collect();
            out.extend(self.trends(&potential));
            out.extend(self.threshold(&of(Start::Touching, false), Start::Touching));
            out.extend(self.threshold(&of(Start::Merged, false), Start::Merged));
            out.extend(self.threshold(&of(Start::Touching, true), Start::Touching));
        } else {
            out.extend(self.ground_states(runs)?);
        }
        Ok(out)
    }

    /// The regime of the ground state where a run also started engulfed: both starts must end
    /// in a regime the Neumann inequalities accept; if they end apart, the regime depends on
    /// the start and the runs have not found the ground state.
    fn ground_states(&self, runs: &[DoubletRun]) -> anyhow::Result<Vec<Metric>> {
        let (s1, s2) = self.sigma_n_m;
        let mut out = Vec::new();
        for e in runs.iter().filter(|m| m.start == Start::Engulfed) {
            let s12 = e.sigma12_n_m;
            let Some(t) = runs
                .iter()
                .find(|m| m.start == Start::Touching && m.sigma12_n_m == s12)
            else {
                continue;
            };
            let regime = neumann::regime(s1, s2, s12).map_err(anyhow::Error::msg)?;
            let (expected, accepted) = expected_regime(regime);
            let both = accepted.contains(&t.regime_seen) && accepted.contains(&e.regime_seen);
            out.push(
                Metric::check(self.case, format!("ground state σ12={} (two starts)", S12(s12)), "match", both, "both starts end in the regime the Neumann inequalities give, or not")
                    .run(e.run)
                    .note(format!(
                        "expected {expected}; from touching drops: {} at {:.0} ms; from matte inside slag: {} at {:.0} ms{}",
                        t.regime_seen,
                        t.run.last.time_s * 1e3,
                        e.regime_seen,
                        e.run.last.time_s * 1e3,
                        if t.regime_seen == e.regime_seen { "" } else { " — the end state depends on the start" }
                    )),
            );
        }
        Ok(out)
    }

    /// Whether the drops of a run are together at the end: some liquid-1 particle within
    /// 1.5 l0 of a liquid-2 particle (docs/model.md §7's interface distance).
    fn joined(m: &DoubletRun) -> bool {
        m.contact_particles > 0
    }

    /// The separation limit σ12 = σ1 + σ2 (Eq. 25) measured by runs from one kind of start:
    /// each run joined or apart at the end against the limit, and the limit as the midpoint
    /// between the largest σ12 that stayed joined and the smallest that came apart, its
    /// tolerance half that bracket (the sweep's resolution).
    fn threshold(&self, runs: &[&DoubletRun], start: Start) -> Vec<Metric> {
        if runs.len() < 2 {
            return Vec::new();
        }
        let (s1, s2) = self.sigma_n_m;
        let limit = s1 + s2;
        let how = match start {
            Start::Touching => "touching start",
            Start::Merged => "merged start",
            Start::Engulfed => "engulfed start",
            Start::Fine => "touching start, R0/l0 = 16.7",
        };
        let how = if runs[0].surface_force {
            format!("{how}, surface force")
        } else {
            how.to_string()
        };
        let mut out = Vec::new();
        if start == Start::Merged {
            for m in runs {
                let s12 = m.sigma12_n_m;
                let expect_joined = s12 < limit;
                out.push(
                    Metric::check(self.case, format!("joined σ12={s12:.2} ({how})"), "match", Self::joined(m) == expect_joined, "the drops are together or apart at the end as Eq. 25 says, or not")
                        .run(m.run)
                        .note(format!("{}expected {} (σ12 {} σ1 + σ2 = {limit:.2} N/m); seen {} ({} liquid-1 particles within 1.5 l0 of liquid 2; G1G2/R0 = {:.2} at the end)", m.run.status_note(), if expect_joined { "together" } else { "apart" }, if expect_joined { "<" } else { "≥" }, if Self::joined(m) { "together" } else { "apart" }, m.contact_particles, m.separation.g1g2_r0.last().copied().unwrap_or(f64::NAN))),
                );
            }
        }
        let lo = runs
            .iter()
            .filter(|m| Self::joined(m))
            .map(|m| m.sigma12_n_m)
            .fold(f64::NEG_INFINITY, f64::max);
        let hi = runs
            .iter()
            .filter(|m| !Self::joined(m))
            .map(|m| m.sigma12_n_m)
            .fold(f64::INFINITY, f64::min);
        let same: Vec<String> = self
            .same_as
            .iter()
            .map(|(s, s0)| format!("{s:.2} (= {s0:.2})"))
            .collect();
        let same = if same.is_empty() || start == Start::Merged {
            String::new()
        } else {
            format!(
                "; not simulated, their model being identical to another's: σ12 = {}",
                same.join(", ")
            )
        };
        let metric = Metric::new(
            self.case,
            format!("separation limit ({how})"),
            "N/m",
            f64::NAN,
        );
        out.push(if lo < hi && lo.is_finite() && hi.is_finite() {
            Metric { value: 0.5 * (lo + hi), ..metric }
                .against(limit, Tolerance::absolute(0.5 * (hi - lo), format!("half the bracket of the sweep: joined up to σ12 = {lo:.2}, apart from {hi:.2} N/m")))
                .note(format!("Eq. 25: drops part for σ12 ≥ σ1 + σ2; {} runs from a {how}{same}", runs.len()))
        } else {
            metric.note(format!("no bracket: joined up to σ12 = {lo:.2}, apart from {hi:.2} N/m ({} runs from a {how}){same}", runs.len()))
        });
        out
    }

    /// A run's σ12 as its metrics' names show it, with the resolution where it is not the
    /// case's own and the model where it is not the paper's.
    fn tag(&self, m: &DoubletRun) -> String {
        match m.start {
            Start::Fine => format!("{} (R0/l0 = {:.1})", S12(m.sigma12_n_m), R0_M / m.l0_m),
            _ if m.surface_force => format!("{} (surface force)", S12(m.sigma12_n_m)),
            _ => S12(m.sigma12_n_m).to_string(),
        }
    }

    fn run_metrics(&self, m: &DoubletRun) -> anyhow::Result<Vec<Metric>> {
        let (s1, s2) = self.sigma_n_m;
        let regime = neumann::regime(s1, s2, m.sigma12_n_m).map_err(anyhow::Error::msg)?;
        let mut out = self.equilibrium(m, regime);
        out.extend(self.oscillation(m));
        if self.pair == Pair::MatteSlag {
            out.push(self.regime(m, regime));
        }
        if let Some(angles) = &m.angles {
            out.extend(self.angles(m, angles)?);
        }
        Ok(out)
    }

    /// G1G2/R0 at the end against the analytic doublet; where the tensions allow no lens,
    /// whether the drops touch at a point or part, before it.
    fn equilibrium(&self, m: &DoubletRun, regime: Regime) -> Vec<Metric> {
        let (s1, s2) = self.sigma_n_m;
        let (s12, status) = (m.sigma12_n_m, m.run.status_note());
        let (g_eq, g_sd) = (m.separation.equilibrium, m.separation.residual);
        let metric =
            Metric::new(self.case, format!("G1G2/R0 σ12={}", self.tag(m)), "-", g_eq).run(m.run);
        let v0 = drop_volume_m3();
        if regime == Regime::PointContact {
            // σ12 ≥ σ1 + σ2 (Eq. 24–25): no lens; the drops touch at a point or part
            let parted = g_eq >= 2.0 - m.l0_m / R0_M;
            vec![
                Metric::check(self.case, format!("separation σ12={}", self.tag(m)), "match", parted, "point contact or parting (G1G2/R0 ≥ 2 less one spacing) or not")
                    .run(m.run)
                    .note(format!("{status}G1G2/R0 = {g_eq:.3} at the end (Eq. 25: the liquids separate if σ12 ≥ 2σ1)")),
                metric.note(format!("{status}mean over the last quarter (±{g_sd:.3}); σ12 ≥ σ1 + σ2: touching spheres give 2, parting more")),
            ]
        } else if let Ok(d) = neumann::doublet(s1, s2, s12, v0, v0) {
            let reference = d.g1g2_m / R0_M;
            let mut out = vec![metric.against(reference, self.g1g2_tolerance(g_sd, m.l0_m)).note(format!("{status}mean over the last quarter of the run (residual oscillation ±{g_sd:.3}); reference: the analytic doublet (spherical caps at the Neumann angles, equal volumes)"))];
            // in a host the doublet rings for longer than the run: the fit's centre beside it
            if let (true, Some(fit)) = (m.surface_force, &m.separation.fit) {
                out.push(
                    Metric::new(self.case, format!("G1G2/R0 fitted centre σ12={}", self.tag(m)), "-", fit.offset)
                        .run(m.run)
                        .note(format!("{status}the centre of a damped cosine fitted to the whole G1G2(t) (period {:.1} ms, decay {:.0} 1/s); the analytic doublet's {reference:.3}", fit.period_s * 1e3, fit.damping_rate_per_s)),
                );
            }
            out
        } else {
            vec![metric.note(format!(
                "{status}mean over the last quarter (±{g_sd:.3}); no lens: complete engulfing"
            ))]
        }
    }

    /// The equilibrium is known to half a particle spacing, and no better than the oscillation
    /// left at the end of the run (standard deviation `sd` of the last quarter).
    fn g1g2_tolerance(&self, sd: f64, l0_m: f64) -> Tolerance {
        let half_spacing = 0.5 * l0_m / R0_M;
        Tolerance::absolute(
            half_spacing + 2.0 * sd,
            format!(
                "half a particle spacing (l0/2R0 = {half_spacing:.3}) plus twice the residual oscillation of the last quarter ({:.3})",
                2.0 * sd
            ),
        )
    }

    /// The oscillation of G1G2(t): the fit's period and damping, and the paper's definitions.
    fn oscillation(&self, m: &DoubletRun) -> Vec<Metric> {
        let sep = &m.separation;
        let mut out = Vec::new();
        if let Some(fit) = &sep.fit {
            out.push(
                Metric::new(
                    self.case,
                    format!("G1G2 period σ12={}", self.tag(m)),
                    "ms",
                    fit.period_s * 1e3,
                )
                .run(m.run)
                .note("full period of a damped-cosine fit of G1G2(t)"),
            );
            out.push(
                Metric::new(
                    self.case,
                    format!("G1G2 damping σ12={}", self.tag(m)),
                    "1/s",
                    fit.damping_rate_per_s,
                )
                .run(m.run)
                .note("amplitude decay rate of the fit"),
            );
        }
        if let Some(hp) = sep.paper_half_period_s {
            out.push(Metric::new(self.case, format!("half-period (paper's definition) σ12={}", self.tag(m)), "ms", hp * 1e3).run(m.run).note(format!("minimum to next maximum of G1G2 after {} extrema (the paper: after three oscillations)", sep.paper_skip)));
        }
        if let Some(dr) = sep.paper_damping_per_s {
            out.push(Metric::new(self.case, format!("damping (paper's definition) σ12={}", self.tag(m)), "1/s", dr).run(m.run).note("fall of (max − min) of G1G2/R0 per half-period, divided by the half-period (Natsui 2021 §3.1.3)"));
        }
        out
    }

    /// The regime of the final state against the Neumann inequalities.
    fn regime(&self, m: &DoubletRun, regime: Regime) -> Metric {
        let seen = m.regime_seen;
        let (expected, accepted) = expected_regime(regime);
        Metric::check(
            self.case,
            format!("regime σ12={}", self.tag(m)),
            "match",
            accepted.contains(&seen),
            "a regime either matches the Neumann inequalities or not",
        )
        .run(m.run)
        .note(format!(
            "expected {expected} (Eq. 24: |σ1 − σ2| < σ12 < σ1 + σ2 for a lens); seen: {seen}"
        ))
    }

    /// The triple-line angles against the analytic doublet's, and the Eq. 27 residual.
    fn angles(
        &self,
        m: &DoubletRun,
        angles: &Result<DoubletAngles, String>,
    ) -> anyhow::Result<Vec<Metric>> {
        let ((s1, s2), s12) = (self.sigma_n_m, m.sigma12_n_m);
        let v0 = drop_volume_m3();
        let d = neumann::doublet(s1, s2, s12, v0, v0).map_err(anyhow::Error::msg)?;
        let an = match angles {
            Ok(an) => an,
            Err(e) => {
                return Ok(vec![Metric::new(
                    self.case,
                    format!("θ12 σ12={}", self.tag(m)),
                    "deg",
                    f64::NAN,
                )
                .against(
                    d.theta12_deg,
                    self.angle_tolerance("θ12", s12, m.l0_m, false),
                )
                .run(m.run)
                .note(format!("angles could not be measured: {e}"))])
            }
        };
        let line_note = if an.line_from_spheres {
            "sphere fits to the gas–1, gas–2 and 1–2 surfaces of the final state; axis through the centroids; no particle is on both the free surface and the interface, so the triple line is started from the two free surfaces' intersection"
        } else {
            "sphere fits to the gas–1, gas–2 and 1–2 surfaces of the final state; axis through the centroids"
        };
        let mut out: Vec<Metric> = [
            ("θ1", an.theta1_deg, d.theta1_deg),
            ("θ2", an.theta2_deg, d.theta2_deg),
            ("θ12", an.theta12_deg, d.theta12_deg),
        ]
        .into_iter()
        .map(|(name, val, reference)| {
            Metric::new(self.case, format!("{name} σ12={}", self.tag(m)), "deg", val)
                .against(
                    reference,
                    self.angle_tolerance(name, s12, m.l0_m, an.line_from_spheres),
                )
                .run(m.run)
                .note(line_note)
        })
        .collect();
        out.push(
            Metric::new(self.case, format!("Eq. 27 residual σ12={}", self.tag(m)), "%", 100.0 * an.eq27_residual)
                .against(0.0, self.eq27_tolerance(s12, m.l0_m, an.line_from_spheres, (d.theta1_deg, d.theta2_deg, d.theta12_deg)))
                .paper(paper_values::lookup("matte_slag_doublet", "sigma12_n_m", s12, "eq27_residual_percent"))
                .run(m.run)
                .note(format!("(σ1 cos θ1 − σ2 cos θ2 − σ12 cos θ12)/σ1 from the measured angles; vector residual |Σσt|/σ1 = {:.1} %", 100.0 * an.vector_residual)),
        );
        Ok(out)
    }

    /// Twice the angle measurement's own worst error on voxelised analytic doublets
    /// (measure::geometry tests, 4 lattice shifts × 3 axes): at R0/l0 = 8, θ1/θ2 2.5°, θ12 4.8°
    /// (σ12 ≤ 0.4) and 13.7° (σ12 = 0.5: a nearly flat interface voxelises in steps); at
    /// R0/l0 = 16, 1.05°, 1.1° and 5.2° — 6.6° where the triple line is started from the free
    /// surfaces' intersection (`from_spheres`: no particle ring at the line; that test's worst).
    fn angle_tolerance(&self, what: &str, s12: f64, l0_m: f64, from_spheres: bool) -> Tolerance {
        let fine = R0_M / l0_m >= 16.0;
        let method_error = match (what, fine) {
            ("θ12", false) if s12 > 0.45 => 13.7,
            ("θ12", false) => 4.8,
            ("θ12", true) if s12 > 0.45 && from_spheres => 6.6,
            ("θ12", true) if s12 > 0.45 => 5.2,
            ("θ12", true) => 1.1,
            (_, false) => 2.5,
            (_, true) => 1.05,
        };
        Tolerance::absolute(
            2.0 * method_error,
            format!("twice the angle measurement's own error on a voxelised analytic doublet at this resolution ({method_error:.1}° for {what}; measure::geometry tests)"),
        )
    }

    /// The Eq. 27 residual's tolerance [%]: the angle measurement's own errors (as in
    /// [`Self::angle_tolerance`]) carried through `(σ1 cos θ1 − σ2 cos θ2 − σ12 cos θ12)/σ1`
    /// at the analytic angles `(θ1, θ2, θ12)` [deg], in quadrature, twice.
    fn eq27_tolerance(
        &self,
        s12: f64,
        l0_m: f64,
        from_spheres: bool,
        (t1, t2, t12): (f64, f64, f64),
    ) -> Tolerance {
        let (s1, s2) = self.sigma_n_m;
        let e = |what: &str| self.angle_tolerance(what, s12, l0_m, from_spheres).abs / 2.0;
        let term = |s: f64, t: f64, what: &str| s * t.to_radians().sin() * e(what).to_radians();
        let sd = (term(s1, t1, "θ1").powi(2)
            + term(s2, t2, "θ2").powi(2)
            + term(s12, t12, "θ12").powi(2))
        .sqrt()
            / s1;
        Tolerance::absolute(
            200.0 * sd,
            format!("twice the angle measurement's own errors ({:.1}°, {:.1}°, {:.1}°) carried through Eq. 27 at the analytic angles", e("θ1"), e("θ2"), e("θ12")),
        )
    }

    /// The paper's trends (Figs. 8–9), reported, not judged: the σ12 of the shortest period
    /// and of the strongest damping, below σ12 = 0.8 N/m.
    fn trends(&self, runs: &[&DoubletRun]) -> Vec<Metric> {
        let fits: Vec<(f64, f64, f64)> = runs
            .iter()
            .filter_map(|m| {
                let fit = m.separation.fit.as_ref()?;
                Some((m.sigma12_n_m, fit.period_s * 1e3, fit.damping_rate_per_s))
            })
            .collect();
        if fits.len() < 3 {
            return Vec::new();
        }
        let period: Vec<(f64, f64)> = fits.iter().map(|f| (f.0, f.1)).collect();
        let damping: Vec<(f64, f64)> = fits.iter().map(|f| (f.0, f.2)).collect();
        vec![
            Metric::new(
                self.case,
                "σ12 of the shortest period",
                "N/m",
                arg_best(&period, |x, y| x < y),
            )
            .paper(paper_values::number(
                "equal_doublet",
                "sigma12_shortest_period_n_m",
            ))
            .note("the paper's Fig. 8: the period falls up to σ12 ≈ 0.3 N/m, then rises"),
            Metric::new(
                self.case,
                "σ12 of the strongest damping",
                "N/m",
                arg_best(&damping, |x, y| x > y),
            )
            .paper(paper_values::number(
                "equal_doublet",
                "sigma12_strongest_damping_n_m",
            ))
            .note("the paper's Fig. 9: damping strongest at σ12 = 0.4 N/m"),
        ]
    }
}

/// σ12 [N/m] as a metric's name shows it: one decimal where that is exact (the paper's
/// values), two otherwise (the sweep across 2σ1), so no two runs share a name.
struct S12(f64);

impl std::fmt::Display for S12 {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if ((self.0 * 10.0).round() - self.0 * 10.0).abs() < 1e-9 {
            write!(f, "{:.1}", self.0)
        } else {
            write!(f, "{:.2}", self.0)
        }
    }
}

/// The σ12 of the point `(σ12, y)` below 0.8 N/m whose finite `y` is `best` (the first of
/// equals); NaN if none.
fn arg_best(pts: &[(f64, f64)], best: fn(f64, f64) -> bool) -> f64 {
    pts.iter()
        .filter(|p| p.0 < 0.8 && p.1.is_finite())
        .fold(None::<(f64, f64)>, |acc, &p| match acc {
            Some(a) if !best(p.1, a.1) => Some(a),
            _ => Some(p),
        })
        .map(|p| p.0)
        .unwrap_or(f64::NAN)
}

/// The regime the Neumann inequalities give, in words, and the regimes seen that match it.
fn expected_regime(r: Regime) -> (&'static str, &'static [&'static str]) {
    match r {
        Regime::CompleteEngulfing {
            engulfing_liquid: 2,
        } => (
            "complete engulfing (slag covers matte)",
            &["complete engulfing (slag covers matte)"],
        ),
        Regime::CompleteEngulfing { .. } => (
            "complete engulfing (matte covers slag)",
            &["complete engulfing (matte covers slag)"],
        ),
        // at the boundary the lens degenerates: either is correct
        Regime::EngulfingBoundary => (
            "engulfing boundary",
            &["complete engulfing (slag covers matte)", "lens"],
        ),
        Regime::Lens => ("lens", &["lens"]),
        Regime::PointContact => ("point contact", &["point contact or apart"]),
    }
}
