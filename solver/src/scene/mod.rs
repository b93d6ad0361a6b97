//! Scene files: what a user writes (TOML), and its validation.
//!
//! A scene declares the materials (liquids with ρ0, μ, σ; solids with each liquid's contact
//! angle; the interfacial tension of each pair of liquids), the bodies made of them, the
//! discretisation, the time control, and the effects to build. Unknown keys are rejected;
//! invalid values are reported with the field's path and value ([`SceneError`]).
//!
//! All particles sit on one simple cubic lattice with spacing `l0` whose sites are at
//! `(i + ½, j + ½, k + ½) l0` for integers `i, j, k`; a body takes the sites inside its shape.

mod names;
mod periodic;
mod shapes;
mod validate;

pub use periodic::{PeriodicAxes, SceneAxis, VelocityWave};
pub(crate) use shapes::for_sites_in_box as shapes_for_sites;
pub use shapes::{BodyShape, Cut, WallShape};

use crate::kernel::KernelKind;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// An error in a scene: it names the field and the value.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SceneError {
    /// The file is not valid TOML or does not match the schema (unknown key, wrong type, …).
    #[error("scene file: {0}")]
    Parse(String),
    /// A value is out of its physical or numerical range, or entries contradict each other.
    #[error("{field} = {value}: {message}")]
    Invalid {
        /// Path of the offending field, e.g. `liquid[matte].density`.
        field: String,
        /// The offending value as written.
        value: String,
        /// What is wrong and what would be accepted.
        message: String,
    },
}

impl SceneError {
    pub(crate) fn invalid(
        field: impl Into<String>,
        value: impl std::fmt::Display,
        message: impl Into<String>,
    ) -> Self {
        SceneError::Invalid {
            field: field.into(),
            value: value.to_string(),
            message: message.into(),
        }
    }
}

/// A complete scene.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Scene {
    /// Free text: what the scene is and where it comes from.
    #[serde(default)]
    pub description: String,
    /// Spatial discretisation and numerical parameters.
    pub discretisation: Discretisation,
    /// End time, output interval and time-step control.
    pub time: TimeControl,
    /// The physical effects to build; an absent effect is not built.
    #[serde(default)]
    pub effects: Effects,
    /// How density is computed.
    #[serde(default)]
    pub density: DensityControl,
    /// Liquid phases.
    #[serde(default, rename = "liquid")]
    pub liquids: Vec<Liquid>,
    /// Solid materials (walls are made of them).
    #[serde(default, rename = "solid")]
    pub solids: Vec<Solid>,
    /// Interfacial tension of each pair of liquids that may touch.
    #[serde(default, rename = "interface")]
    pub interfaces: Vec<Interface>,
    /// Liquid bodies.
    #[serde(default, rename = "body")]
    pub bodies: Vec<Body>,
    /// Fixed solid walls.
    #[serde(default, rename = "wall")]
    pub walls: Vec<Wall>,
    /// When a run stops as unstable.
    #[serde(default)]
    pub health: Health,
    /// Periodic axes (none by default).
    #[serde(default, skip_serializing_if = "is_default")]
    pub periodic: PeriodicAxes,
}

fn is_default<T: Default + PartialEq>(v: &T) -> bool {
    *v == T::default()
}

/// The bounds past which a run stops with a diagnosis instead of producing garbage.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Health {
    /// Largest particle speed over the sound speed [-]. Default 1.0: a blow-up detector. Weak
    /// compressibility assumes Mach ≲ 0.1 (docs/model.md §3), but single particles are thrown
    /// transiently to Mach 0.5 in violent relaxations that then recover (measured: the 27³ cube
    /// at r_e = 2.1 l0); a blow-up passes Mach 1 within a few steps.
    #[serde(default = "default_max_mach")]
    pub max_mach: f64,
    /// Largest compression `ρ/ρ0 − 1` of a fluid particle [-]. Default 1.0 (density doubled):
    /// a blow-up detector, not an accuracy bound — a relaxing cube's corners are transiently
    /// compressed by 20 % and more while the run stays healthy. (Expansion is not bounded: a
    /// summation density is legitimately low at a free surface.)
    #[serde(default = "default_max_compression")]
    pub max_compression: f64,
    /// Smallest adaptive step as a fraction of the first step [-]. Default 1e-3.
    #[serde(default = "default_min_dt_ratio")]
    pub min_dt_ratio: f64,
    /// Deepest a liquid particle may be inside a wall's solid, past its faces, in spacings
    /// [l0]. Default 0.5: the plane of the outer wall layer's centres, which a liquid particle
    /// in compressed contact does not pass; one that does has entered the wall lattice.
    #[serde(default = "default_max_wall_depth_over_l0")]
    pub max_wall_depth_over_l0: f64,
}

fn default_max_mach() -> f64 {
    1.0
}
fn default_max_compression() -> f64 {
    1.0
}
fn default_min_dt_ratio() -> f64 {
    1e-3
}

fn default_max_wall_depth_over_l0() -> f64 {
    0.5
}

impl Default for Health {
    fn default() -> Self {
        Self {
            max_mach: default_max_mach(),
            max_compression: default_max_compression(),
            min_dt_ratio: default_min_dt_ratio(),
            max_wall_depth_over_l0: default_max_wall_depth_over_l0(),
        }
    }
}

/// Spatial discretisation and numerical parameters.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Discretisation {
    /// Initial particle spacing `l0` [m] (simple cubic lattice).
    pub l0: f64,
    /// Which paper's discretisation supplies the defaults of `h_over_l0` and `re_over_l0`
    /// (values given explicitly win). Default `natsui2021`.
    #[serde(default)]
    pub setting: Setting,
    /// Smoothing kernel. Default: Wendland C2 (Eq. 5, Natsui 2021).
    #[serde(default)]
    pub kernel: KernelKind,
    /// Smoothing length over spacing, `h/l0` [-]. Default 1.05 (Natsui 2021 §2.2; 2.0 with
    /// `setting = "natsui2016"`).
    #[serde(default = "default_h_over_l0")]
    pub h_over_l0: f64,
    /// Cut-off of the interparticle potential over spacing, `r_e/l0` [-]. Default 4.2 (4.0 with
    /// `setting = "natsui2016"`), the 2021 paper's formula read literally (the papers leave 2.1
    /// vs 4.2 open, docs/model.md §4). Chosen by measurement: at 2.1 the particle lattice has a
    /// shear modulus G44 of 2.0 σ/l0 (potential and pressure term) — about 14 σ/R for a 12³
    /// drop — and drops do not flow; at 4.2 it is 0.126 σ/l0 (C′ = 0.047 σ/l0) and the cube drop
    /// oscillates within 6 % of Lamb's period at 15³.
    #[serde(default = "default_re_over_l0")]
    pub re_over_l0: f64,
    /// Order `m` of the potential's zero at its cut-off, `P'(r) = (r − l0)(r − r_e)^m / l0^(m−1)`:
    /// 1 is Kondo et al. (2007), the papers' potential (default); 2 and 3 are smoother at the
    /// cut-off, which makes the particle lattice's shear moduli small for any `r_e`.
    #[serde(default = "default_potential_order", skip_serializing_if = "is_kondo")]
    pub potential_order: u8,
    /// How the potential's coefficients are calibrated: `lattice` (default) fixes
    /// `C = 2σ l0²/S` on the rigid reference lattice; `relaxed_slab` then scales each liquid's
    /// coefficients so that a relaxed periodic slab of it has the typed σ, measured from the
    /// pair-force virial (Kirkwood–Buff; [`crate::simulation::calibration`]). Computed when
    /// the run starts (a slab of a few thousand particles per liquid), never typed in.
    #[serde(default, skip_serializing_if = "is_default")]
    pub tension_calibration: TensionCalibration,
    /// Artificial speed of sound `c` [m/s], the same for all phases (Tait EOS, Eq. 14).
    pub sound_speed: f64,
    /// Which mass a particle carries. Default `physical` (`ρ0 l0³`); `lattice` is docs/model.md
    /// §1's calibrated `ρ0 / Σ_j W_ij`, lighter by the kernel's lattice-sum excess.
    #[serde(default)]
    pub particle_mass: ParticleMass,
    /// Verlet skin of the neighbour lists over spacing [-]: lists hold pairs up to the cut-off
    /// plus this skin and are rebuilt when a particle has moved half of it. Default 0.2.
    #[serde(default = "default_skin_over_l0")]
    pub neighbour_skin_over_l0: f64,
    /// Most particles (liquid and wall) a scene may build; checked from the shapes' volumes
    /// before anything is allocated. Default 20 000 000 (about 20 GB at r_e = 4.2 l0).
    #[serde(default = "default_max_particles")]
    pub max_particles: u64,
}

/// How the potential's coefficients are calibrated (`discretisation.tension_calibration`).
#[derive(Clone, Copy, Debug, Serialize, Deserialize, PartialEq, Eq, Default)]
#[serde(rename_all = "snake_case")]
pub enum TensionCalibration {
    /// `C = 2σ l0²/S` from the rigid reference lattice (Natsui 2021's normalisation).
    #[default]
    Lattice,
    /// The lattice's `C` scaled per liquid by `σ/σ_KB`, `σ_KB` the tension of a relaxed
    /// periodic slab of that liquid with the lattice's `C`.
    RelaxedSlab,
}

/// A paper's discretisation: the defaults it gives `h/l0` and `r_e/l0`.
#[derive(Clone, Copy, Debug, Serialize, Deserialize, PartialEq, Eq, Default)]
#[serde(rename_all = "snake_case")]
pub enum Setting {
    /// Natsui et al. 2021 (paper A): `h/l0 = 1.05` (§2.2), `r_e/l0 = 4.2` (Eq. 15's cut-off
    /// read literally; docs/model.md §4).
    #[default]
    Natsui2021,
    /// Natsui et al. 2016 (paper B): its "effective radius" of 4.0 d is the kernel's support
    /// and, by its rule that the potential's radius equals the kernel's, also the potential's
    /// cut-off: `h/l0 = 2.0` (support 2h = 4.0 l0), `r_e/l0 = 4.0`. Paper B's dimensionless
    /// potential (its Eq. 9, in q = r/h) has the same shape — repulsive below d, zero force at
    /// d and at the cut-off — and its energy coefficient is fixed here by the same lattice
    /// normalisation `C = 2σ l0²/S` (docs/model.md §4, S/l0³ = 191.840 at 4.0), so only the two
    /// radii differ. Paper B does not name its kernel; the scene's kernel is used.
    Natsui2016,
}

impl Setting {
    /// Default `h/l0` [-].
    pub fn h_over_l0(self) -> f64 {
        match self {
            Setting::Natsui2021 => 1.05,
            Setting::Natsui2016 => 2.0,
        }
    }
    /// Default `r_e/l0` [-].
    pub fn re_over_l0(self) -> f64 {
        match self {
            Setting::Natsui2021 => 4.2,
            Setting::Natsui2016 => 4.0,
        }
    }
}

fn default_max_particles() -> u64 {
    20_000_000
}

/// Particle mass model. In both, the density summation is calibrated so that the undisturbed
/// lattice has exactly `ρ0`.
#[derive(Clone, Copy, Debug, Serialize, Deserialize, PartialEq, Eq, Default)]
#[serde(rename_all = "snake_case")]
pub enum ParticleMass {
    /// `m = ρ0 l0³`: the body's mass and weight equal ρ0 times its lattice volume.
    #[default]
    Physical,
    /// `m = ρ0 / Σ_j W_ij` over the bulk lattice (docs/model.md §1).
    Lattice,
}

fn default_h_over_l0() -> f64 {
    Setting::default().h_over_l0()
}
fn default_re_over_l0() -> f64 {
    Setting::default().re_over_l0()
}
fn default_potential_order() -> u8 {
    1
}

fn is_kondo(order: &u8) -> bool {
    *order == 1
}

fn default_skin_over_l0() -> f64 {
    0.2
}

/// End time, outputs and time-step control.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct TimeControl {
    /// Simulated end time [s].
    pub end: f64,
    /// Interval between two outputs (time-series rows) [s].
    pub output_interval: f64,
    /// Fixed time step [s]. Omit for the adaptive step (minimum over the active constraints).
    #[serde(default)]
    pub dt: Option<f64>,
    /// Safety factors of the time-step constraints (docs/model.md §3).
    #[serde(default)]
    pub factors: StepFactors,
    /// Largest number of steps the run may take; a scene needing more is refused before it
    /// starts. Default 10 000 000.
    #[serde(default = "default_max_steps")]
    pub max_steps: u64,
}

fn default_max_steps() -> u64 {
    10_000_000
}

/// Safety factors of the time-step constraints (docs/model.md §3).
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct StepFactors {
    /// CFL: `dt ≤ cfl · h/(c + |v|max)`. Default 0.25.
    #[serde(default = "f_025")]
    pub cfl: f64,
    /// Viscous: `dt ≤ viscous · ρ h²/μ`. Default 0.125.
    #[serde(default = "f_0125")]
    pub viscous: f64,
    /// Capillary: `dt ≤ capillary · √(ρ h³/(2π σ))`. Default 0.25.
    #[serde(default = "f_025")]
    pub capillary: f64,
    /// Body force: `dt ≤ force · √(h/|a|max)`. Default 0.25.
    #[serde(default = "f_025")]
    pub force: f64,
}

fn f_025() -> f64 {
    0.25
}
fn f_0125() -> f64 {
    0.125
}

impl Default for StepFactors {
    fn default() -> Self {
        Self {
            cfl: 0.25,
            viscous: 0.125,
            capillary: 0.25,
            force: 0.25,
        }
    }
}

/// The physical effects a scene asks for. Walls and wetting are built when the scene has
/// `[[wall]]` entries; wetting additionally needs `interfacial_tension`.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq, Default)]
#[serde(deny_unknown_fields)]
pub struct Effects {
    /// Gravitational acceleration vector [m/s²]. Omit for none.
    #[serde(default)]
    pub gravity: Option<[f64; 3]>,
    /// Laminar viscosity (Hu & Adams 2006 form, Eq. 11 of Natsui 2021, unless
    /// `laminar_form` says otherwise).
    #[serde(default)]
    pub laminar_viscosity: bool,
    /// The pair form of the laminar viscosity: `hu_adams` (the default, the paper's) or
    /// `monaghan_cleary_gingold` (docs/model.md §3). Needs `laminar_viscosity`; the implicit
    /// solve supports the default form only.
    #[serde(default, skip_serializing_if = "is_default")]
    pub laminar_form: LaminarForm,
    /// Monaghan artificial viscosity (Eq. 12–13 of Natsui 2021). Omit for none.
    #[serde(default)]
    pub artificial_viscosity: Option<ArtificialViscosity>,
    /// Surface and interfacial tension: `true` or `"potential"` — the pairwise potential
    /// (Eq. 15, Natsui 2021) with Fowkes pair strengths, also wetting of walls;
    /// `"surface_stress"` — the continuum surface stress between liquid phases (Lafaurie et al.
    /// 1994, Hu & Adams 2006; docs/model.md §4a), no walls yet; `"surface_force"` — the
    /// continuum surface force between liquid phases (Brackbill et al. 1992; §4b), walls as
    /// `surface_force_walls` says; `false` (the default): none.
    #[serde(default)]
    pub interfacial_tension: TensionModel,
    /// How walls take part in the surface force (with `interfacial_tension = "surface_force"`
    /// only): `"shares"` (the default) — their solid is a third phase of the force's split of
    /// the tensions, with each liquid's Young tension `−σ cos θ`; `"normal"` — they are no
    /// phase, and near them the interface's normal is turned to the contact angle's
    /// (Breinlinger et al. 2013; docs/model.md §4b).
    #[serde(default, skip_serializing_if = "is_default")]
    pub surface_force_walls: SurfaceForceWalls,
    /// A short-range liquid–wall repulsion that does not depend on the kernel (Monaghan 1994's
    /// boundary force, acting within 0.8 l0 of a wall particle), for wide kernels whose
    /// pressure does not hold a wetting liquid out of the gaps between wall particles. Needs
    /// walls. Default off.
    #[serde(default)]
    pub wall_repulsion: bool,
    /// Particle shifting (Lind et al. 2012; Sun et al. 2017's δ⁺-SPH form): each step's drift
    /// also moves a particle down the gradient of the particle concentration, only along the
    /// boundary near a free surface, another liquid or a wall. Omit for none (the default).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub particle_shifting: Option<ParticleShifting>,
    /// A viscosity on the non-affine part of the velocity (Morris et al. 1997's pair form on
    /// what the particles' fitted velocity gradients do not explain; docs/model.md §3): it
    /// damps particle-scale motion at the rate `α c/h` and does not act on any linear flow.
    /// Omit for none (the default).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub nonaffine_viscosity: Option<NonAffineViscosity>,
    /// Laminar viscosity integrated implicitly (backward Euler, conjugate gradients) instead of
    /// explicitly: the viscous step limit `0.125 ρh²/μ` no longer applies, for very viscous
    /// liquids. Needs `laminar_viscosity`; walls must be free-slip. Omit for the explicit term
    /// (the default).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub implicit_viscosity: Option<ImplicitViscosity>,
}

/// Which model of surface and interfacial tension a scene builds.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum TensionModel {
    /// No tension (`false`, the default).
    #[default]
    Off,
    /// The pairwise potential with Fowkes pair strengths (`true` or `"potential"`).
    Potential,
    /// The continuum surface stress between liquid phases (`"surface_stress"`).
    SurfaceStress,
    /// The continuum surface force between liquid phases (`"surface_force"`).
    SurfaceForce,
}

impl TensionModel {
    /// Whether the pairwise potential is built.
    pub fn is_potential(self) -> bool {
        self == TensionModel::Potential
    }
    /// Whether the continuum surface stress is built.
    pub fn is_surface_stress(self) -> bool {
        self == TensionModel::SurfaceStress
    }
    /// Whether a continuum model between liquid phases (the surface stress or force) is built.
    pub fn is_continuum(self) -> bool {
        matches!(
            self,
            TensionModel::SurfaceStress | TensionModel::SurfaceForce
        )
    }
    /// Whether some tension model is built.
    pub fn is_on(self) -> bool {
        self != TensionModel::Off
    }
}

impl From<bool> for TensionModel {
    /// `true` is the potential (the key was a switch before there were two models).
    fn from(on: bool) -> Self {
        if on {
            TensionModel::Potential
        } else {
            TensionModel::Off
        }
    }
}

impl Serialize for TensionModel {
    /// `false`, `true` (the potential: scenes and run records written before the second model
    /// read and compare unchanged), `"surface_stress"` or `"surface_force"`.
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self {
            TensionModel::Off => s.serialize_bool(false),
            TensionModel::Potential => s.serialize_bool(true),
            TensionModel::SurfaceStress => s.serialize_str("surface_stress"),
            TensionModel::SurfaceForce => s.serialize_str("surface_force"),
        }
    }
}

impl<'de> Deserialize<'de> for TensionModel {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl serde::de::Visitor<'_> for V {
            type Value = TensionModel;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("true, false, \"potential\", \"surface_stress\" or \"surface_force\"")
            }
            fn visit_bool<E: serde::de::Error>(self, v: bool) -> Result<TensionModel, E> {
                Ok(v.into())
            }
            fn visit_str<E: serde::de::Error>(self, v: &str) -> Result<TensionModel, E> {
                match v {
                    "potential" => Ok(TensionModel::Potential),
                    "surface_stress" => Ok(TensionModel::SurfaceStress),
                    "surface_force" => Ok(TensionModel::SurfaceForce),
                    _ => Err(E::invalid_value(serde::de::Unexpected::Str(v), &self)),
                }
            }
        }
        d.deserialize_any(V)
    }
}

/// The implicit viscous solve's stopping rule.
#[derive(Clone, Copy, Debug, Serialize, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct ImplicitViscosity {
    /// Stop when the residual is at most this fraction of the right-hand side's norm [-].
    /// Default 1e-6 (docs/model.md §3: against 1e-10, the water–oil–Teflon scene's energies
    /// after 632 steps agree to 1.3e-5 and its largest speed to 2.5e-4, at half the
    /// iterations).
    #[serde(default = "f_1e_6")]
    pub relative_tolerance: f64,
    /// Iterations after which a solve that has not converged stops the run. Default 200.
    #[serde(default = "default_max_iterations")]
    pub max_iterations: u32,
}

impl Default for ImplicitViscosity {
    fn default() -> Self {
        ImplicitViscosity {
            relative_tolerance: f_1e_6(),
            max_iterations: default_max_iterations(),
        }
    }
}

fn f_1e_6() -> f64 {
    1e-6
}

fn default_max_iterations() -> u32 {
    200
}

/// The coefficient of the non-affine viscosity.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct NonAffineViscosity {
    /// `α` in `μ_na = α ρ̄ c h` [-] (`ρ̄` a pair's mean rest density, `c` the sound speed, `h`
    /// the smoothing length). No default: it is a choice the scene states.
    pub coefficient: f64,
}

/// Coefficients of particle shifting.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct ParticleShifting {
    /// `A` in `δr = −A h U dt ∇C` [-] (`U` the largest fluid speed, `dt` the step). Default 4,
    /// Sun et al. 2017's `CFL·Ma·(2h)²`.
    #[serde(default = "f_4")]
    pub coefficient: f64,
}

fn f_4() -> f64 {
    4.0
}

impl Default for ParticleShifting {
    /// The documented default coefficient.
    fn default() -> Self {
        ParticleShifting { coefficient: f_4() }
    }
}

/// Coefficients of Monaghan's artificial viscosity.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct ArtificialViscosity {
    /// Linear coefficient α1 [-]. Default 0.01 (Natsui 2021).
    #[serde(default = "f_001")]
    pub alpha1: f64,
    /// Quadratic coefficient α2 [-]. Default 0.01 (Natsui 2021).
    #[serde(default = "f_001")]
    pub alpha2: f64,
}

fn f_001() -> f64 {
    0.01
}

/// Density computation.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct DensityControl {
    /// `summation` (number density, default) or `continuity`.
    #[serde(default)]
    pub scheme: DensityScheme,
    /// Periodic re-initialisation of the continuity density: `none` (default), `shepard` or
    /// `mls` (Colagrossi & Landrini 2003). Only with `scheme = "continuity"`.
    #[serde(default)]
    pub reinit: Reinit,
    /// Steps between two re-initialisations. Default 20.
    #[serde(default = "default_reinit_every")]
    pub reinit_every: u32,
    /// What the EOS does with a density below ρ0: `clip` (default) sets the pressure to zero,
    /// `keep` uses Tait's negative pressure. Cohesion comes from the interparticle potential;
    /// tension from a deficient free-surface density would add an uncontrolled surface tension
    /// (docs/model.md §2). Measured on the cube drop (15³, r_e = 4.2 l0): clipped, the kinetic
    /// energy peaks at 0.25 µJ of the 0.47 µJ the cube-to-sphere change releases; kept, at
    /// 2 µJ, drawn from the spurious surface tension.
    #[serde(default)]
    pub negative_pressure: NegativePressure,
    /// A uniform pressure added to every liquid particle's EOS pressure [Pa]. Default 0. Only
    /// in a scene periodic along x, y and z: it holds the reference lattice at the pressure a
    /// drop's interior carries, whose pair forces add to the lattice's shear stiffness (the
    /// `shear_wave` case); a free surface would feel it as a force. Its work is not booked in
    /// the energy budget (in a periodic box the liquid's volume hardly changes).
    #[serde(default, skip_serializing_if = "is_zero")]
    pub background_pressure: f64,
    /// The pressure force between liquid particles: `symmetric` (default; Eq. 11, Natsui 2021,
    /// the Hu & Adams 2006 form) or `difference` (`−V_i Σ_j V_j (p_j − p_i) ∇_i W_ij`, which a
    /// uniform pressure leaves at zero whatever the particles' arrangement: no pair stiffness
    /// from the pressure level, docs/model.md §3), with walls too; only with a continuum model.
    #[serde(default, skip_serializing_if = "is_symmetric")]
    pub pressure_gradient: PressureGradient,
}

fn is_symmetric(g: &PressureGradient) -> bool {
    *g == PressureGradient::Symmetric
}

/// The form of the pressure force between liquid particles (docs/model.md §2).
#[derive(Clone, Copy, Debug, Serialize, Deserialize, PartialEq, Eq, Default)]
#[serde(rename_all = "snake_case")]
pub enum PressureGradient {
    /// `−Σ_j (p_i V_i² + p_j V_j²) ∇_i W_ij` (Eq. 11, Natsui 2021): conserves momentum, and a
    /// pressure level loads every pair, which gives the particle arrangement a stiffness.
    #[default]
    Symmetric,
    /// `−V_i Σ_j V_j (p_j − p_i) ∇_i W_ij`: zeroth-order consistent (a uniform pressure exerts
    /// no force), not exactly momentum conserving; its departure from the symmetric form is
    /// booked in the energy budget.
    Difference,
}

fn is_zero(v: &f64) -> bool {
    *v == 0.0
}

/// Treatment of negative pressure in the equation of state.
#[derive(Clone, Copy, Debug, Serialize, Deserialize, PartialEq, Eq, Default)]
#[serde(rename_all = "snake_case")]
pub enum NegativePressure {
    /// `p = max(p_Tait, 0)`.
    #[default]
    Clip,
    /// Tait's pressure as is, tension included.
    Keep,
}

fn default_reinit_every() -> u32 {
    20
}

impl Default for DensityControl {
    fn default() -> Self {
        Self {
            scheme: DensityScheme::Summation,
            reinit: Reinit::None,
            reinit_every: default_reinit_every(),
            negative_pressure: NegativePressure::Clip,
            background_pressure: 0.0,
            pressure_gradient: PressureGradient::Symmetric,
        }
    }
}

/// How the density of a particle is obtained.
#[derive(Clone, Copy, Debug, Serialize, Deserialize, PartialEq, Eq, Default)]
#[serde(rename_all = "snake_case")]
pub enum DensityScheme {
    /// `ρ_i = ρ0_i Σ_j W_ij / Σ_lattice W` (number density calibrated on the lattice).
    #[default]
    Summation,
    /// `dρ_i/dt = ρ_i Σ_j V_j v_ij·∇_i W_ij`.
    Continuity,
}

/// Density re-initialisation filter.
#[derive(Clone, Copy, Debug, Serialize, Deserialize, PartialEq, Eq, Default)]
#[serde(rename_all = "snake_case")]
pub enum Reinit {
    /// No re-initialisation.
    #[default]
    None,
    /// Zeroth-order Shepard filter.
    Shepard,
    /// First-order moving-least-squares filter.
    Mls,
}

/// A liquid phase.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Liquid {
    /// Unique name.
    pub name: String,
    /// Reference density ρ0 [kg/m³].
    pub density: f64,
    /// Dynamic viscosity μ [Pa·s].
    pub viscosity: f64,
    /// Surface tension σ against the gas [N/m]. Required with interfacial tension.
    #[serde(default)]
    pub surface_tension: Option<f64>,
}

/// A solid material.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Solid {
    /// Unique name.
    pub name: String,
    /// Equilibrium contact angle of each liquid on this solid [degrees, measured inside the
    /// liquid], keyed by liquid name.
    #[serde(default)]
    pub contact_angles: BTreeMap<String, f64>,
}

/// The interfacial tension between two liquids.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Interface {
    /// The two liquids' names.
    pub liquids: [String; 2],
    /// Interfacial tension σ_ab [N/m].
    pub tension: f64,
}

/// A liquid body: a shape filled with one liquid, or cut by a plane into two liquids.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Body {
    /// Unique name (used in error messages).
    pub name: String,
    /// The liquid filling the shape (omit when `cut` is given).
    #[serde(default)]
    pub liquid: Option<String>,
    /// The region occupied.
    pub shape: BodyShape,
    /// A plane dividing the body into two liquids (instead of `liquid`).
    #[serde(default)]
    pub cut: Option<Cut>,
    /// Initial velocity [m/s].
    #[serde(default)]
    pub velocity: [f64; 3],
    /// A sinusoidal velocity added to `velocity` (e.g. a shear wave). Omit for none.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub velocity_wave: Option<VelocityWave>,
}

/// A fixed solid wall.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Wall {
    /// Unique name (used in error messages).
    pub name: String,
    /// The solid material.
    pub solid: String,
    /// The wall's geometry.
    pub shape: WallShape,
    /// Number of particle layers. Default: the fewest that make the wall at least as thick
    /// as both the kernel support and the potential cut-off `r_e`.
    #[serde(default)]
    pub layers: Option<u32>,
    /// Tangential boundary condition: `free_slip` (default) or `no_slip`.
    #[serde(default)]
    pub boundary: WallBoundary,
}

/// The pair form of the laminar viscosity.
#[derive(Clone, Copy, Debug, Serialize, Deserialize, PartialEq, Eq, Default)]
#[serde(rename_all = "snake_case")]
pub enum LaminarForm {
    /// Eq. (11), Natsui 2021 (Hu & Adams 2006): the pair force along `v_i − v_j`.
    #[default]
    HuAdams,
    /// Monaghan 2005 (after Monaghan & Gingold 1983 and Cleary 1998): the pair force along
    /// `x_i − x_j`, proportional to `v_ij·x_ij` — zero under a rigid rotation, conserving
    /// angular momentum, consistent at a free surface (Colagrossi et al. 2011).
    MonaghanClearyGingold,
}

/// How walls take part in the continuum surface force.
#[derive(Clone, Copy, Debug, Serialize, Deserialize, PartialEq, Eq, Default)]
#[serde(rename_all = "snake_case")]
pub enum SurfaceForceWalls {
    /// The walls' solid is a third phase of the split of the tensions (Young's shares).
    #[default]
    Shares,
    /// The walls turn the interface's normal to the contact angle (Breinlinger et al. 2013).
    Normal,
}

/// Tangential condition at a wall.
#[derive(Clone, Copy, Debug, Serialize, Deserialize, PartialEq, Eq, Default)]
#[serde(rename_all = "snake_case")]
pub enum WallBoundary {
    /// Walls take no part in the viscous terms.
    #[default]
    FreeSlip,
    /// Wall particles carry the negative of the kernel-averaged fluid velocity (Adami 2012).
    NoSlip,
}

impl Scene {
    /// Parses and validates a scene from TOML text.
    pub fn from_toml_str(text: &str) -> Result<Scene, SceneError> {
        // parsed straight into the schema, so that its errors keep their line and column
        let mut scene: Scene =
            toml::from_str(text).map_err(|e| SceneError::Parse(e.to_string()))?;
        apply_setting(&mut scene, text);
        scene.validate()?;
        Ok(scene)
    }

    /// Checks every value and every cross-reference; the first problem found is returned.
    pub fn validate(&self) -> Result<(), SceneError> {
        validate::validate(self)
    }

    /// Smoothing length `h` [m].
    pub fn h(&self) -> f64 {
        self.discretisation.h_over_l0 * self.discretisation.l0
    }

    /// Potential cut-off `r_e` [m].
    pub fn r_e(&self) -> f64 {
        self.discretisation.re_over_l0 * self.discretisation.l0
    }

    /// Kernel support radius [m].
    pub fn kernel_support(&self) -> f64 {
        self.discretisation.kernel.support_over_h() * self.h()
    }

    /// The number of wall layers used for `wall`: its own, or the fewest that cover both the
    /// kernel support and `r_e`.
    pub fn wall_layers(&self, wall: &Wall) -> u32 {
        wall.layers.unwrap_or_else(|| {
            let needed = self.kernel_support().max(self.r_e()) / self.discretisation.l0;
            // a tolerance of 1e-9 keeps e.g. 3.0000000000000004 from becoming 4 layers
            (needed - 1e-9).ceil().max(1.0) as u32
        })
    }

    /// Index of a liquid by name.
    pub fn liquid_index(&self, name: &str) -> Option<usize> {
        self.liquids.iter().position(|l| l.name == name)
    }

    /// Index of a solid by name.
    pub fn solid_index(&self, name: &str) -> Option<usize> {
        self.solids.iter().position(|s| s.name == name)
    }

    /// The interfacial tension between two different liquids [N/m], if given.
    pub fn interface_tension(&self, a: &str, b: &str) -> Option<f64> {
        self.interfaces
            .iter()
            .find(|i| {
                (i.liquids[0] == a && i.liquids[1] == b) || (i.liquids[0] == b && i.liquids[1] == a)
            })
            .map(|i| i.tension)
    }
}

/// Replaces the defaults of `h_over_l0` and `re_over_l0` by those of `discretisation.setting`
/// where `text` leaves them out (explicit values win). `text` has already been parsed into
/// `scene`, so it is valid TOML.
fn apply_setting(scene: &mut Scene, text: &str) {
    let table: toml::Table = toml::from_str(text).unwrap_or_default();
    let given = |key: &str| {
        table
            .get("discretisation")
            .and_then(|d| d.get(key))
            .is_some()
    };
    let d = &mut scene.discretisation;
    if !given("h_over_l0") {
        d.h_over_l0 = d.setting.h_over_l0();
    }
    if !given("re_over_l0") {
        d.re_over_l0 = d.setting.re_over_l0();
    }
}
