//! What the runs give: the free drop's fitted l = 2 oscillation and the caps' settled angles,
//! each with its resolution. References use the liquid of the run's own scene, so a `--set`
//! that changes a property is judged against the right analytic value.

use super::{HostModel, EPSILON, FIT_FROM_S, HOST_MODELS, Q2, RADIUS_M};
use crate::analytic::viscous_host::{self, Liquid};
use crate::analytic::{elastic_drop, lamb, spheroid, young_laplace};
use crate::cases::scene::artificial_viscosity_m2_s;
use crate::cases::substrate::tail_stats;
use crate::diagnostics::lattice_moduli::lattice_elasticity;
use crate::diagnostics::mode_stiffness::{self, Continuum};
use crate::measure::oscillation::{fit_damped_cosine, OscillationFit};
use crate::measure::surface;
use crate::measure::{geometry, invariants};
use crate::output::timeseries::{Axis, LiquidColumn, RunColumn};
use crate::suite::{Fidelity, RunData};
use solver::kernel::KernelKind;
use solver::physics::surface_tension::surface_force::BAND_GRADIENT_TIMES_R_E;
use solver::scene::TensionModel;

/// The free drop at one resolution.
pub struct DropPoint<'r> {
    /// The run.
    pub run: &'r RunData,
    /// `R/l0` with the nominal radius [-].
    pub r_over_l0: f64,
    /// The continuum model of a drop in a host (none: the potential's free drop).
    pub host_model: Option<HostModel>,
    /// The initial stretch `ε` of the spheroid along z [-].
    pub amplitude: f64,
    /// The drop's particles (without the surface-stress drop's host).
    pub drop_particles: usize,
    /// The l = 2 period for the drop's volume (its particles × l0³) [s]: Rayleigh's for the
    /// free drop; in a host, Lamb's slowed by the interface's boundary layer at the liquids'
    /// physical viscosities (Miller & Scriven 1968, [`viscous_host`]).
    pub reference_period_s: f64,
    /// The inviscid period [s]: Rayleigh's, or Lamb's in the host.
    pub inviscid_period_s: f64,
    /// A continuum model's static stiffness against the l = 2 mode of a lattice sphere of the
    /// same `R/l0` and `r_e/l0`, over Lamb's ([`mode_stiffness`]; jitter ±0.05 l0, ε = ±0.02):
    /// the force's share of the period error, `k^(−1/2) − 1`, apart from the run's inertia
    /// [-]. NaN for the potential's drop, and for a kernel other than the diagnostic's
    /// Wendland C2.
    pub static_stiffness: f64,
    /// Rayleigh's period shortened by the reference lattice's shear moduli at the run's setting
    /// (Rayleigh–Ritz, [`elastic_drop`]): with `C′`, which a stretch along the lattice's axis
    /// loads (this drop's), and with `C44` (a body diagonal) [s]; NaN without the potential.
    pub elastic_periods_s: [f64; 2],
    /// The l = 2 decay rate with the physical viscosities alone [1/s]: Lamb's for the free
    /// drop; in a host, the boundary layer's and the bulk's (Miller & Scriven 1968).
    pub decay_physical_per_s: f64,
    /// The same with ν + ν_AV (α1 h c/10) in each liquid [1/s].
    pub decay_with_av_per_s: f64,
    /// Times [s] and Q2 [-] of the series fitted (from [`FIT_FROM_S`]).
    pub series: (Vec<f64>, Vec<f64>),
    /// The damped cosine fitted to Q2 from [`FIT_FROM_S`], or why it failed.
    pub fit: Result<OscillationFit, String>,
    /// The damped cosine fitted to the z-extent (the outermost particles) from [`FIT_FROM_S`]:
    /// the same mode seen by the surface, beside the volume average Q2.
    pub extent_fit: Result<OscillationFit, String>,
    /// The largest distance of the total momentum from its start over the momentum scale
    /// `M |v|max` (all liquids' mass, the run's largest speed) [-]: round-off where every
    /// force is a pair's antisymmetric one (the surface stress's drop: 1e-16); the surface
    /// force, a force per particle, conserves it by symmetry only (1.8e-6 to 6.1e-5 at
    /// R/l0 = 10 to 20), and the difference form of the pressure force to its discretisation
    /// error (2.0e-3 at R/l0 = 10).
    pub momentum_drift: f64,
    /// The energy budget's secular trend from [`FIT_FROM_S`] on [W]: the slope of the
    /// budget (every energy plus everything dissipated) through its swing at half the
    /// reference period ([`invariants::secular_trend`]). Zero where every force derives from
    /// the energy the budget counts and the integrator keeps it; positive where the forces
    /// put in energy that the budget's interfacial energy does not give up.
    pub energy_trend_w: f64,
    /// The interfacial force's own share of that trend [W]: the same slope of its work plus
    /// its energy estimate (`interfacial_force_work_J + interfacial_energy_J`), the energy it
    /// put in that the estimate does not hold. `None` under the potential (its work is not
    /// booked apart: it derives from its energy) and for runs recorded before the column.
    pub force_trend_w: Option<f64>,
    /// The energy of the drop's mode at release [J]: the surface energy its spheroid holds
    /// beyond a sphere's of the same volume, `σ (A − 4πR²)`
    /// ([`spheroid::stretched_drop_excess_energy_j`]; 3.25e-9 J for the water drop at
    /// ε = 0.1). Not the budget's own interfacial energy, whose fall over a run is mostly the
    /// cut lattice's relaxation (11.6 nJ at R/l0 = 10 for the surface force).
    pub mode_energy_j: f64,
}

/// A cap at one angle and resolution.
pub struct CapPoint<'r> {
    /// The run.
    pub run: &'r RunData,
    /// The continuum model of a cap in a host (none: the potential's cap).
    pub host_model: Option<HostModel>,
    /// Spacings per initial hemisphere radius [-].
    pub n: f64,
    /// The typed Young angle [deg].
    pub typed_deg: f64,
    /// The settled height above the plate [m]: mean of the top particle over the last quarter,
    /// plus l0/2 (the particle's half-spacing).
    pub height_m: f64,
    /// Half the top's peak-to-peak range over that quarter [m]: how settled it is.
    pub height_swing_m: f64,
    /// The analytic cap height for the drop's volume at the typed angle [m].
    pub reference_height_m: f64,
    /// The angle of the spherical cap of the drop's volume and the settled height [deg].
    pub height_angle_deg: Option<f64>,
    /// The side-view fit's angle on the last state [deg], or why it failed.
    pub side_view_deg: Result<f64, String>,
}

/// Every run of the case, measured.
pub struct Measured<'r> {
    /// Free drops (the pairwise potential), coarsest first.
    pub drops: Vec<DropPoint<'r>>,
    /// Drops under each continuum model that ran, in their host, coarsest first (at the
    /// case's stretch [`EPSILON`]).
    pub host_drops: Vec<(HostModel, Vec<DropPoint<'r>>)>,
    /// Drops under each continuum model at the other stretches, smallest first.
    pub amplitude_drops: Vec<(HostModel, Vec<DropPoint<'r>>)>,
    /// Caps, the potential's then each continuum model's, by angle then coarsest first.
    pub caps: Vec<CapPoint<'r>>,
    /// The resolutions the fidelity declares: of the free drop, of each continuum model's
    /// drop, of each cap.
    pub declared: Declared,
}

/// How many resolutions a fidelity declares per family of runs.
pub struct Declared {
    /// The potential's free drop.
    pub drops: usize,
    /// Each continuum model's drop.
    pub host_drops: usize,
    /// The potential's cap at each angle.
    pub caps: usize,
    /// Each continuum model's cap at each angle.
    pub css_caps: usize,
    /// The continuum models whose caps leave out the finest of those.
    pub baseline_cap_models: &'static [HostModel],
}

impl Declared {
    /// The resolutions declared for a cap of `model` (`None`: the potential's) at each angle.
    pub fn caps_of(&self, model: Option<HostModel>) -> usize {
        match model {
            Some(m) if self.baseline_cap_models.contains(&m) => self.css_caps - 1,
            Some(_) => self.css_caps,
            None => self.caps,
        }
    }
}

/// The continuum model of `run`'s drop in a host, if it is one.
fn host_model(run: &RunData) -> Option<HostModel> {
    HostModel::of(&run.info.scene)
}

/// Measures the runs (drops have no wall, caps have one; the continuum models' drops have a
/// host).
pub fn measure(runs: &[RunData], f: Fidelity) -> Measured<'_> {
    let d = super::design(f);
    // the case's stretch (`at_epsilon`) or the others
    let drops = |model: Option<HostModel>, at_epsilon: bool| -> Vec<DropPoint> {
        let mut v: Vec<DropPoint> = runs
            .iter()
            .filter(|r| r.info.scene.walls.is_empty() && host_model(r) == model)
            .map(drop_point)
            .filter(|d| (d.amplitude == EPSILON) == at_epsilon)
            .collect();
        v.sort_by(|a, b| {
            (a.r_over_l0.total_cmp(&b.r_over_l0)).then(a.amplitude.total_cmp(&b.amplitude))
        });
        v
    };
    let by_model = |at_epsilon: bool| -> Vec<(HostModel, Vec<DropPoint>)> {
        HOST_MODELS
            .into_iter()
            .map(|h| (h, drops(Some(h), at_epsilon)))
            .filter(|(_, d)| !d.is_empty())
            .collect()
    };
    let mut m = Measured {
        drops: drops(None, true),
        host_drops: by_model(true),
        amplitude_drops: by_model(false),
        caps: runs
            .iter()
            .filter(|r| !r.info.scene.walls.is_empty())
            .map(cap_point)
            .collect(),
        declared: Declared {
            drops: d.drops.len(),
            host_drops: d.css_drops.len(),
            caps: d.caps.len(),
            css_caps: d.css_caps.len(),
            baseline_cap_models: d.baseline_cap_models,
        },
    };
    // the potential's first, then the continuum models' in the case's order
    let model_rank = |c: &CapPoint| {
        c.host_model
            .and_then(|h| super::CAP_ORDER.iter().position(|m| *m == h))
            .map_or(0, |k| k + 1)
    };
    m.caps.sort_by(|a, b| {
        model_rank(a)
            .cmp(&model_rank(b))
            .then(a.typed_deg.total_cmp(&b.typed_deg))
            .then(a.n.total_cmp(&b.n))
    });
    m
}

/// A cap's volume: its particles' rest volume l0³ [m³] (the host's left out).
fn volume_m3(run: &RunData) -> f64 {
    let l0 = run.info.scene.discretisation.l0;
    drop_particles(run) as f64 * l0 * l0 * l0
}

/// The drop's particles: the first liquid's count at the start (all of a free drop's).
fn drop_particles(run: &RunData) -> usize {
    let liquid = &run.info.scene.liquids[0].name;
    let count = run.timeseries.liquid_column(liquid, LiquidColumn::Count);
    count.first().map_or(0, |&c| c as usize)
}

fn drop_point(run: &RunData) -> DropPoint<'_> {
    let scene = &run.info.scene;
    let liquid = &scene.liquids[0];
    let l0 = scene.discretisation.l0;
    let n_drop = drop_particles(run);
    // the drop's volume: its particles' rest volume l0³
    let radius = lamb::sphere_radius_from_volume(n_drop as f64 * l0 * l0 * l0);
    let host_model = host_model(run);
    let css = host_model.is_some();
    let host = scene.liquids.get(1);
    let sigma = match host.filter(|_| css) {
        Some(h) => scene
            .interface_tension(&liquid.name, &h.name)
            .unwrap_or(f64::NAN),
        None => liquid.surface_tension.unwrap_or(f64::NAN),
    };
    let nu_av = artificial_viscosity_m2_s(scene);
    // in a host: Lamb's mode with the boundary layer and bulk of both liquids, at the
    // physical viscosities and with ν_AV added to each
    let host_mode = |av: f64| {
        host.filter(|_| css).map(|h| {
            let liquid_of = |density: f64, viscosity: f64| Liquid {
                density_kg_m3: density,
                viscosity_pa_s: viscosity + density * av,
            };
            viscous_host::mode_in_host(
                2,
                sigma,
                liquid_of(liquid.density, liquid.viscosity),
                liquid_of(h.density, h.viscosity),
                radius,
            )
        })
    };
    let nu = liquid.viscosity / liquid.density;
    let (reference_period_s, inviscid_period_s, decay_physical_per_s, decay_with_av_per_s) =
        match (host_mode(0.0), host_mode(nu_av)) {
            (Some(m), Some(m_av)) => (
                m.period_s(),
                m.inviscid_period_s(),
                m.damping_rate_per_s(),
                m_av.damping_rate_per_s(),
            ),
            _ => {
                let t = lamb::lamb_period(2, sigma, liquid.density, radius);
                (
                    t,
                    t,
                    lamb::lamb_damping_rate(2, nu, radius),
                    lamb::lamb_damping_rate(2, nu + nu_av, radius),
                )
            }
        };
    let t = run
        .probes
        .column(&RunColumn::Time.name())
        .unwrap_or_default();
    let q2 = run.probes.column(Q2).unwrap_or_default();
    let from = t.iter().position(|&x| x >= FIT_FROM_S).unwrap_or(t.len());
    let n = t.len().min(q2.len()).max(from);
    let series = (t[from..n].to_vec(), q2[from..n].to_vec());
    let ts = run.timeseries.run_column(RunColumn::Time);
    let extent = run
        .timeseries
        .liquid_column(&liquid.name, LiquidColumn::Extent(Axis::Z));
    let efrom = ts.iter().position(|&x| x >= FIT_FROM_S).unwrap_or(ts.len());
    let en = ts.len().min(extent.len()).max(efrom);
    let momentum =
        invariants::drift(Axis::ALL.map(|ax| run.timeseries.run_column(RunColumn::Momentum(ax))));
    let mass_kg: f64 = (scene.liquids.iter())
        .filter_map(|l| {
            (run.timeseries.liquid_column(&l.name, LiquidColumn::Mass))
                .first()
                .copied()
        })
        .sum();
    let speed_m_s =
        (run.timeseries.run_column(RunColumn::MaxSpeed).into_iter()).fold(0.0, f64::max);
    let budget = run.timeseries.run_column(RunColumn::EnergyBalance);
    let force_work = run.timeseries.run_column(RunColumn::InterfacialForceWork);
    let force_trend_w = (host_model.is_some() && force_work.len() == ts.len()).then(|| {
        let estimate = run.timeseries.run_column(RunColumn::InterfacialEnergy);
        let created: Vec<f64> = force_work
            .iter()
            .zip(&estimate)
            .map(|(w, e)| w + e)
            .collect();
        invariants::secular_trend(&ts, &created, FIT_FROM_S, 0.5 * reference_period_s)
    });
    let amplitude = amplitude(scene);
    DropPoint {
        run,
        r_over_l0: RADIUS_M / l0,
        host_model,
        amplitude,
        drop_particles: n_drop,
        reference_period_s,
        inviscid_period_s,
        static_stiffness: static_stiffness(scene, host_model, RADIUS_M / l0),
        elastic_periods_s: elastic_periods_s(scene, reference_period_s, sigma, radius),
        decay_physical_per_s,
        decay_with_av_per_s,
        fit: fit_damped_cosine(&series.0, &series.1),
        extent_fit: fit_damped_cosine(&ts[efrom..en], &extent[efrom..en]),
        series,
        momentum_drift: momentum / (mass_kg * speed_m_s),
        energy_trend_w: invariants::secular_trend(
            &ts,
            &budget,
            FIT_FROM_S,
            0.5 * reference_period_s,
        ),
        force_trend_w,
        mode_energy_j: spheroid::stretched_drop_excess_energy_j(sigma, radius, amplitude),
    }
}

/// The stretch `ε` of a drop scene's spheroid (its first body; semi-axis `R(1 + ε)` along z),
/// rounded to 1e-9 so that a scene's [`EPSILON`] compares equal [-]; NaN for another shape.
fn amplitude(scene: &solver::Scene) -> f64 {
    match scene.bodies.first().map(|b| &b.shape) {
        Some(solver::scene::BodyShape::Ellipsoid { semi_axes, .. }) => {
            ((semi_axes[2] / RADIUS_M - 1.0) * 1e9).round() / 1e9
        }
        _ => f64::NAN,
    }
}

/// [`DropPoint::static_stiffness`].
fn static_stiffness(scene: &solver::Scene, host: Option<HostModel>, r_over_l0: f64) -> f64 {
    // the diagnostic's lattice: jittered by ±0.05 l0, stretched by ε = ±0.02 (its defaults)
    const JITTER_OVER_L0: f64 = 0.05;
    const EPS: f64 = 0.02;
    let d = &scene.discretisation;
    let model = match host.map(|h| h.model) {
        Some(TensionModel::SurfaceForce) => Continuum::SurfaceForce,
        Some(TensionModel::SurfaceStress) => Continuum::SurfaceStress,
        _ => return f64::NAN,
    };
    if d.kernel != KernelKind::WendlandC2 {
        return f64::NAN;
    }
    mode_stiffness::stiffness_ratio(
        model,
        r_over_l0,
        d.re_over_l0,
        JITTER_OVER_L0,
        EPS,
        BAND_GRADIENT_TIMES_R_E,
    )
}

/// [`DropPoint::elastic_periods_s`]: the lattice's moduli (potential and pressure term, lattice
/// calibration; `σ/l0` units) in Pa.
fn elastic_periods_s(
    scene: &solver::Scene,
    rayleigh_period_s: f64,
    sigma_n_m: f64,
    radius_m: f64,
) -> [f64; 2] {
    if !scene.effects.interfacial_tension.is_potential() {
        return [f64::NAN; 2];
    }
    let d = &scene.discretisation;
    let moduli = lattice_elasticity(d.kernel, d.h_over_l0, d.re_over_l0, d.potential_order).total();
    let pa = sigma_n_m / d.l0;
    // the drop is stretched along z, a cube axis of its lattice; a body diagonal is the other bound
    [[0.0, 0.0, 1.0], [1.0, 1.0, 1.0]].map(|axis| {
        let g = elastic_drop::cubic_stretch_modulus(moduli.c_prime, moduli.g44, axis);
        elastic_drop::elastic_drop_period_s(rayleigh_period_s, g * pa, sigma_n_m, radius_m)
    })
}

fn cap_point(run: &RunData) -> CapPoint<'_> {
    let scene = &run.info.scene;
    let liquid = &scene.liquids[0].name;
    let l0 = scene.discretisation.l0;
    let typed_deg = scene.solids[0].contact_angles[liquid];
    let t = run.timeseries.run_column(RunColumn::Time);
    let top = run
        .timeseries
        .liquid_column(liquid, LiquidColumn::Max(Axis::Z));
    // the last quarter of the run: the settled state
    let from = t.last().map_or(f64::NAN, |end| 0.75 * end);
    let (mean_top, swing) = tail_stats(&t, &top, from);
    let height_m = mean_top + 0.5 * l0;
    let volume = volume_m3(run);
    let mut cloud = run.last.cloud(l0);
    let host_model = host_model(run);
    if host_model.is_some() {
        cloud.retain_phases(|p| p == 0); // the host is the gas
    }
    let classes = surface::classify(&cloud);
    CapPoint {
        run,
        host_model,
        n: RADIUS_M / l0,
        typed_deg,
        height_m,
        height_swing_m: swing,
        reference_height_m: young_laplace::spherical_cap(volume, typed_deg).height_m,
        height_angle_deg: young_laplace::spherical_cap_angle_from_height(volume, height_m),
        side_view_deg: geometry::sessile_contact_angle(&cloud, &classes, 0, 0.0),
    }
}
