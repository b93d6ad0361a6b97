//! Binary droplets in zero gravity (Natsui 2021 §3): two touching drops of radius R0 = 1 mm.
//!
//! - **Equal** (§3.1): identical matte drops, σ12 = 0.1 … 0.8 and 1.0 N/m. Equilibrium G1G2/R0
//!   against the analytic doublet (spherical caps meeting at the Neumann angles, equal volumes);
//!   at σ12 ≥ 2σ1 the drops touch at a point or part (G1G2/R0 → 2). G1G2(t): period and damping
//!   against σ12 (the paper's Figs. 7–9 report trends only: the period falls then rises past
//!   σ12 ≈ 0.3; damping is strongest near 0.4).
//! - **Matte–slag** (§3.2): σ12 = 0.1 … 0.6 N/m. The regime (engulfing / lens / point contact)
//!   against the Neumann inequalities; where a lens exists (0.3–0.5) the triple-line angles and
//!   G1G2/R0 against the analytic doublet, and the Eq. 27 residual against the paper's Table 1.
//!
//! G1G2 is the distance between the two liquids' mass centroids, normalised by the initial
//! radius R0 (the paper's text says radius; its Fig. 7 caption says diameter).

mod draw;
mod judge;
mod measure;

use super::analysis::{self, Analysis};
use super::paper_values;
use super::scene::{laplace_sound_speed, LiquidProps, SceneBuilder, MATTE, SLAG};
use crate::suite::{
    smoke_is_coarse, Case, Check, DeclaredEffects, Fidelity, Metric, RunData, RunSpec,
};
use solver::scene::{BodyShape, Cut};
use std::path::Path;

/// Which of the two paper sections.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Pair {
    /// §3.1: two identical matte drops.
    Equal,
    /// §3.2: matte (liquid 1) and slag (liquid 2).
    MatteSlag,
}

/// The case.
pub struct Doublet(pub Pair);

impl Doublet {
    /// The surface tensions σ1, σ2 of the two liquids [N/m].
    fn sigmas(&self) -> (f64, f64) {
        let (a, b) = self.liquids();
        (a.surface_tension_n_m, b.surface_tension_n_m)
    }

    fn liquids(&self) -> (LiquidProps, LiquidProps) {
        match self.0 {
            Pair::Equal => (MATTE.named("matte1"), MATTE.named("matte2")),
            Pair::MatteSlag => (MATTE, SLAG),
        }
    }

    fn sigma12_values(&self, f: Fidelity) -> Vec<f64> {
        match (self.0, f) {
            (Pair::Equal, Fidelity::Smoke) => vec![0.4, 1.0],
            // the paper's values, and a sweep across 2σ1 = 0.8 N/m
            (Pair::Equal, _) => vec![
                0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.74, 0.76, 0.78, 0.8, 0.84, 0.9, 1.0,
            ],
            (Pair::MatteSlag, Fidelity::Smoke) => vec![0.4],
            (Pair::MatteSlag, _) => vec![0.1, 0.2, 0.3, 0.4, 0.5, 0.6],
        }
    }

    /// The σ12 [N/m] of the runs that start merged (one sphere cut into the two liquids): at
    /// and either side of 2σ1, where the drops must stay together below and part above.
    fn merged_sigma12_values(&self, f: Fidelity) -> Vec<f64> {
        match (self.0, f) {
            (Pair::Equal, Fidelity::Standard | Fidelity::Paper) => vec![0.7, 0.76, 0.78, 0.8],
            _ => vec![],
        }
    }

    /// `values` without those whose resolved pair table equals an earlier one's — the scenes
    /// differ only in σ12, so those runs would be identical (σ12 ≥ σ1 + σ2 all give the pair
    /// strength 0) — and those left out, each with the σ12 whose run it would repeat.
    fn distinct(&self, f: Fidelity, values: Vec<f64>) -> (Vec<f64>, Vec<(f64, f64)>) {
        let mut kept: Vec<(f64, Option<solver::physics::surface_tension::PairTable>)> = Vec::new();
        let mut same = Vec::new();
        for s in values {
            // a scene the solver refuses is kept: its run reports the error
            let pairs = solver::Model::from_scene(&self.scene(f, s))
                .ok()
                .map(|m| m.pairs);
            match kept.iter().find(|(_, p)| pairs.is_some() && *p == pairs) {
                Some((s0, _)) => same.push((s, *s0)),
                None => kept.push((s, pairs)),
            }
        }
        (kept.into_iter().map(|k| k.0).collect(), same)
    }

    /// The σ12 [N/m] of the runs that start engulfed (liquid 1 inside liquid 2): the
    /// matte–slag tensions at which Eq. 24 says slag engulfs matte (0.1) or is on the boundary
    /// (0.2), where paper A's own run ended as a lens.
    fn engulfed_sigma12_values(&self, f: Fidelity) -> Vec<f64> {
        match (self.0, f) {
            (Pair::MatteSlag, Fidelity::Standard | Fidelity::Paper) => vec![0.1, 0.2],
            _ => vec![],
        }
    }

    /// The σ12 [N/m] of the runs under the continuum surface force (drops in a host), beside
    /// the paper's potential: equal drops at two of the paper's σ12, one near the separation
    /// limit 2σ1 and one beyond it (the limit's bracket); matte–slag at the paper's three
    /// lenses (Table 1), whose angles and Eq. 27 residual are judged as the potential's.
    fn surface_force_sigma12_values(&self, f: Fidelity) -> Vec<f64> {
        match (self.0, f) {
            (Pair::Equal, Fidelity::Standard) => vec![0.2, 0.4, 0.76, 0.84],
            (Pair::MatteSlag, Fidelity::Standard) => vec![0.3, 0.4, 0.5],
            _ => vec![],
        }
    }

    /// The two touching drops under the continuum surface force (docs/model.md §4b) in a host
    /// liquid of their density and viscosity filling a periodic box one R0 beyond them
    /// (8 spacings, 1.9 r_e), each drop's σ its tension against the host: the gas the
    /// potential leaves empty, declared as a liquid. The continuum models' kernel (h = 1.3 l0)
    /// and sound speed (the drop's Laplace pressure compresses it by 1 %), as the convergence
    /// case's drops in a host.
    fn scene_in_host(&self, f: Fidelity, sigma12: f64) -> solver::Scene {
        let (a, b) = self.liquids();
        let l0 = Self::l0(f);
        let (min, max) = (
            [-3.0 * R0_M, -2.0 * R0_M, -2.0 * R0_M],
            [3.0 * R0_M, 2.0 * R0_M, 2.0 * R0_M],
        );
        SceneBuilder::new(l0, laplace_sound_speed(&a, R0_M))
            .time(IN_HOST_END_S, 1.0e-4)
            .kernel(
                solver::kernel::KernelKind::WendlandC2,
                CONTINUUM_H_OVER_L0,
                solver::scene::Setting::Natsui2021.re_over_l0(),
            )
            .paper_effects()
            .tension_model(solver::scene::TensionModel::SurfaceForce)
            .liquid(&a)
            .liquid(&b)
            .liquid(&HOST)
            .interface(a.name, b.name, sigma12)
            .interface(a.name, HOST.name, a.surface_tension_n_m)
            .interface(b.name, HOST.name, b.surface_tension_n_m)
            .body("drop1", a.name, drop_at(-R0_M))
            .body("drop2", b.name, drop_at(R0_M))
            .body("host", HOST.name, BodyShape::Surrounding { min, max })
            .periodic_box(min, max)
            .build()
    }

    /// The σ12 [N/m] of the lens runs repeated at the paper's spacing (R0/l0 = 16.7) in the
    /// standard suite: those whose angles R0/l0 = 8 cannot measure (a nearly flat interface).
    fn fine_sigma12_values(&self, f: Fidelity) -> Vec<f64> {
        match (self.0, f) {
            (Pair::MatteSlag, Fidelity::Standard) => vec![0.5],
            _ => vec![],
        }
    }

    fn l0(f: Fidelity) -> f64 {
        match f {
            Fidelity::Smoke => 2.0e-4,
            Fidelity::Standard => 1.25e-4,
            Fidelity::Paper => 6.0e-5,
        }
    }

    /// The run's end [s]: engulfing is slow, so the matte–slag runs at σ12 ≤ 0.2 N/m run
    /// 100 ms as the paper's (whose σ12 = 0.1 run was still a lens then).
    fn end(&self, f: Fidelity, sigma12: f64) -> f64 {
        match f {
            Fidelity::Smoke => 0.012,
            Fidelity::Standard if self.0 == Pair::MatteSlag && sigma12 <= 0.2 + 1e-9 => 0.1,
            Fidelity::Standard => 0.03,
            Fidelity::Paper => 0.1,
        }
    }

    fn scene(&self, f: Fidelity, sigma12: f64) -> solver::Scene {
        self.scene_started(f, sigma12, Start::Touching)
    }

    fn scene_started(&self, f: Fidelity, sigma12: f64, start: Start) -> solver::Scene {
        let (a, b) = self.liquids();
        // the fine runs: the paper's spacing, the standard run's time and adaptive step
        let l0 = if start == Start::Fine {
            Self::l0(Fidelity::Paper)
        } else {
            Self::l0(f)
        };
        // c² = 150 m²/s² as in the paper (§2.3); the cohesive compression stays below 1 %
        // for matte down to l0 = 0.06 mm (σ/(l0 ρ c²) · 1.75 = 1.7 % at the paper's l0)
        let builder = SceneBuilder::new(l0, 150f64.sqrt())
            .time(self.end(f, sigma12), 1.0e-4)
            .fixed_dt((f == Fidelity::Paper).then_some(1.0e-6))
            .paper_effects()
            .liquid(&a)
            .liquid(&b)
            .interface(a.name, b.name, sigma12);
        match start {
            Start::Touching => {
                builder
                    .body("drop1", a.name, drop_at(-R0_M))
                    .body("drop2", b.name, drop_at(R0_M))
            }
            // one sphere of twice a drop's volume, its halves the two liquids
            Start::Merged => builder.cut_body(
                "drop",
                BodyShape::Sphere {
                    center: [0.0; 3],
                    radius: R0_M * 2f64.cbrt(),
                },
                Cut {
                    point: [0.0; 3],
                    normal: [1.0, 0.0, 0.0],
                    liquids: [a.name.into(), b.name.into()],
                },
            ),
            Start::Fine => {
                builder
                    .body("drop1", a.name, drop_at(-R0_M))
                    .body("drop2", b.name, drop_at(R0_M))
            }
            Start::Engulfed => builder.body("core", a.name, drop_at(0.0)).body(
                "shell",
                b.name,
                BodyShape::Shell {
                    center: [0.0; 3],
                    inner_radius: R0_M,
                    outer_radius: R0_M * 2f64.cbrt(),
                },
            ),
        }
        .build()
    }
}

/// How a run starts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Start {
    /// Two spheres of radius R0 one spacing apart (the paper's start).
    Touching,
    /// One sphere of twice a drop's volume, cut in half into the two liquids: above the
    /// separation limit the halves must part, below it stay together.
    Merged,
    /// Touching drops at the paper's spacing (R0/l0 = 16.7) in the standard suite.
    Fine,
    /// A sphere of liquid 1 (radius R0) inside a shell of liquid 2 of the same volume: where
    /// the touching start ends in another regime, the two starts tell a ground state from a
    /// state the run has not left.
    Engulfed,
}

/// Initial radius of each drop [m].
const R0_M: f64 = 1.0e-3;

/// The host of the drops under the surface force: matte's density and viscosity (its σ is
/// not used: each drop's own σ is its tension against the host).
const HOST: LiquidProps = MATTE.named("host");

/// The end of the runs in a host [s]: twice the potential's 30 ms. The host doubles the
/// inertia, and the liquids' own viscosity damps the doublet's oscillation far less than the
/// potential's elasticity does: over the last quarter of 30 ms the σ12 = 0.4 N/m run still
/// swings between 1.16 and 1.68 in G1G2/R0 (over 45–60 ms: ±0.09).
const IN_HOST_END_S: f64 = 0.06;

/// `h/l0` of the continuum models (the convergence case's drops in a host).
const CONTINUUM_H_OVER_L0: f64 = 1.3;

/// A drop of radius R0 centred at `x` [m] on the x axis.
fn drop_at(x: f64) -> BodyShape {
    BodyShape::Sphere {
        center: [x, 0.0, 0.0],
        radius: R0_M,
    }
}

/// Volume of each drop [m³].
fn drop_volume_m3() -> f64 {
    4.0 / 3.0 * std::f64::consts::PI * R0_M.powi(3)
}

impl Case for Doublet {
    fn name(&self) -> &'static str {
        match self.0 {
            Pair::Equal => "equal_doublet",
            Pair::MatteSlag => "matte_slag_doublet",
        }
    }
    fn title(&self) -> &'static str {
        match self.0 {
            Pair::Equal => "Equal binary droplet in zero gravity: equilibrium, separation, oscillation against σ12",
            Pair::MatteSlag => "Matte–slag doublet: regimes, Neumann angles and the Eq. 27 residual against σ12",
        }
    }
    fn source(&self) -> &'static str {
        match self.0 {
            Pair::Equal => "Natsui et al. 2021 §3.1, Figs. 6–9 (trends), Eqs. 24–25",
            Pair::MatteSlag => "Natsui et al. 2021 §3.2, Figs. 11–15, Eq. 27, Table 1",
        }
    }
    fn effects(&self) -> Option<DeclaredEffects> {
        Some(DeclaredEffects::FREE_DROP)
    }
    fn accepted_findings(&self, f: Fidelity) -> Vec<(Check, String)> {
        let mut out = smoke_is_coarse(f);
        if f != Fidelity::Smoke {
            out.push((Check::CohesiveSoundSpeed, "at the paper's spacing (paper fidelity, and the standard suite's fine σ12 = 0.5 run) the paper's c² = 150 m²/s² (§2.3) is kept: up to 1.7 % compression".into()));
        }
        match self.0 {
            Pair::Equal => out.push((
                Check::InterfacialTension,
                "the separation sweep crosses σ1 + σ2 on purpose (Eq. 25)".into(),
            )),
            Pair::MatteSlag => {
                let why = "the engulfed start: a slag shell of one drop's volume around the matte is thin by construction, and settles";
                out.push((Check::Film, why.into()));
                if f == Fidelity::Paper {
                    out.push((Check::Resolution, why.into()));
                }
            }
        }
        out
    }
    fn resolution(&self, f: Fidelity) -> String {
        let l0 = Self::l0(f);
        let per_drop = 4.0 / 3.0 * std::f64::consts::PI * (R0_M / l0).powi(3);
        let why = match f {
            Fidelity::Smoke => "R0/l0 = 5, 12 ms: a seconds-scale check that the doublet forms",
            Fidelity::Standard => match self.0 {
                Pair::Equal => "R0/l0 = 8, 30 ms: the interface is 8 spacings across and the oscillation has decayed (G1G2 within 3 % of the analytic equilibrium at σ12 = 0.4); the paper's R0/l0 = 16.7 costs 10× more. Beside the paper's σ12, a sweep across 2σ1 from touching drops and from one drop cut in two; and four σ12 under the continuum surface force, the drops in a host liquid (49,152 particles, h = 1.3 l0, 60 ms)",
                Pair::MatteSlag => "R0/l0 = 8, 30 ms (100 ms at σ12 ≤ 0.2, where engulfing is slow, each also started engulfed); σ12 = 0.5, whose nearly flat interface R0/l0 = 8 cannot measure, also at the paper's R0/l0 = 16.7 (20× the cost); and the three lenses (σ12 = 0.3, 0.4, 0.5) under the continuum surface force, the drops in a host liquid (49,152 particles, h = 1.3 l0, 60 ms)",
            },
            Fidelity::Paper => "the paper's l0 = 0.06 mm (19,430 per drop), dt = 1e-6 s, 0.1 s",
        };
        format!(
            "l0 = {:.3} mm, about {:.0} particles per drop; {why}.",
            l0 * 1e3,
            per_drop
        )
    }
    fn runs(&self, f: Fidelity) -> Vec<RunSpec> {
        let (touching, _) = self.distinct(f, self.sigma12_values(f));
        let merged = self.merged_sigma12_values(f);
        let engulfed = self.engulfed_sigma12_values(f);
        let fine = self.fine_sigma12_values(f);
        let spec = |s: f64, start: Start| RunSpec {
            id: match start {
                Start::Touching => format!("sigma12_{s:.2}"),
                Start::Merged => format!("merged_sigma12_{s:.2}"),
                Start::Engulfed => format!("engulfed_sigma12_{s:.2}"),
                Start::Fine => format!("fine_sigma12_{s:.2}"),
            },
            scene: self.scene_started(f, s, start),
            snapshot_times_s: vec![],
        };
        let touching = touching.into_iter().map(|s| spec(s, Start::Touching));
        let in_host = self
            .surface_force_sigma12_values(f)
            .into_iter()
            .map(|s| RunSpec {
                id: format!("csf_sigma12_{s:.2}"),
                scene: self.scene_in_host(f, s),
                snapshot_times_s: vec![],
            });
        touching
            .chain(merged.into_iter().map(|s| spec(s, Start::Merged)))
            .chain(engulfed.into_iter().map(|s| spec(s, Start::Engulfed)))
            .chain(fine.into_iter().map(|s| spec(s, Start::Fine)))
            .chain(in_host)
            .collect()
    }
    fn analyse(&self, f: Fidelity, runs: &[RunData], dir: &Path) -> anyhow::Result<Vec<Metric>> {
        analysis::analyse(self, f, runs, dir)
    }
}

impl Analysis for Doublet {
    type Measured<'r> = Vec<measure::DoubletRun<'r>>;

    fn measure<'r>(&self, _: Fidelity, runs: &'r [RunData]) -> anyhow::Result<Self::Measured<'r>> {
        let (a, b) = self.liquids();
        measure::doublet_runs(self.0, (a.name, b.name), self.sigmas(), runs)
    }

    fn judge(&self, f: Fidelity, measured: &Self::Measured<'_>) -> anyhow::Result<Vec<Metric>> {
        let judge = judge::Judge {
            case: self.name(),
            pair: self.0,
            sigma_n_m: self.sigmas(),
            same_as: self.distinct(f, self.sigma12_values(f)).1,
        };
        judge.metrics(measured)
    }

    fn draw(&self, _: Fidelity, measured: &Self::Measured<'_>, dir: &Path) -> anyhow::Result<()> {
        draw::plots(self.title(), self.sigmas(), measured, dir)
    }
}
