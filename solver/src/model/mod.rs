//! The resolved model: a validated scene turned into the constants the time step needs. The
//! step, the health checks and the observables read only these; the scene itself is kept by
//! the simulation for checkpoints and run records.

mod effects;
pub mod pairs;
mod walls;

pub use effects::{ContinuumForm, Effects};
pub use walls::WallSolid;

use crate::kernel::{Kernel, KernelKind};
use crate::lattice;
use crate::periodic::PeriodicBox;
use crate::physics::eos::TaitEos;
use crate::physics::forces::wall_repulsion as repulsion;
use crate::physics::surface_tension::surface_force::wall_normal::WallNormal;
use crate::physics::surface_tension::surface_force::{contact_line, Walls};
use crate::physics::surface_tension::{Kondo2007Potential, PairTable};
use crate::scene::{Health, ParticleMass, Scene, SceneError, SurfaceForceWalls, TimeControl};
use crate::state::Vec3;
use crate::with_kernel;

/// Constants of a run, derived once from the scene.
#[derive(Clone, Debug)]
pub struct Model {
    /// Kernel.
    pub kernel: KernelKind,
    /// Initial spacing `l0` [m].
    pub l0_m: f64,
    /// Smoothing length `h` [m].
    pub h_m: f64,
    /// Kernel support radius [m].
    pub support_m: f64,
    /// Potential cut-off `r_e` [m].
    pub r_e_m: f64,
    /// Sound speed `c` [m/s].
    pub c_m_s: f64,
    /// Equation of state.
    pub eos: TaitEos,
    /// Interparticle potential.
    pub potential: Kondo2007Potential,
    /// Number of liquid phases (phase indices below it are liquids).
    pub n_liquids: usize,
    /// Phase names, liquids then solids.
    pub phase_names: Vec<String>,
    /// Reference density per phase [kg/m³] (solids: mean of the liquids', for wall volumes).
    pub rho0: Vec<f64>,
    /// Dynamic viscosity per phase [Pa·s] (solids: 0).
    pub mu: Vec<f64>,
    /// Particle mass per phase [kg] (solids: 0).
    pub mass: Vec<f64>,
    /// Viscosity of each pair of phases [Pa·s], row-major: `2μ_aμ_b/(μ_a + μ_b)` for two
    /// liquids (Eq. 11, Natsui 2021; 0 if both are inviscid), the liquid's `μ` against a solid.
    pub mu_pair: Vec<f64>,
    /// Fowkes pair table (zero coefficients without interfacial tension).
    pub pairs: PairTable,
    /// The tension [N/m] of each pair of phases for the continuum surface stress, row-major
    /// (empty without it; [`pairs::surface_stress_table`]).
    pub surface_stress_sigma: Vec<f64>,
    /// How the walls take part in the continuum surface force (their solid's phase: its walls
    /// are all of one solid), [`Walls::Absent`] without walls or without the force.
    pub surface_force_walls: Walls,
    /// The factor on the liquid–solid tensions of the surface force at walls [-]: one over the
    /// share of Young's push the force hands to the liquid on the lattice
    /// ([`contact_line::young_share`]; with Wendland C2 at `r_e = 4.2 l0`, 1.117 for the
    /// shares' walls and 1.130 for the wall normal's), 1 where the walls take no part.
    pub contact_line_factor: f64,
    /// The factor on each liquid's coefficients from a relaxed-slab calibration
    /// ([`Model::scale_tension`]; 1 with the lattice calibration).
    pub tension_scales: Vec<f64>,
    /// Per unlike pair of phases `(a, b, f)` with `a < b` (two liquids, or a liquid and a
    /// solid): the factor the relaxed calibration put on `C_ab` beyond the liquids' own
    /// ([`Model::scale_pair_tension`]); empty with the lattice calibration.
    pub pair_tension_scales: Vec<(usize, usize, f64)>,
    /// `Σ_j W_ij` over the bulk lattice, self included [1/m³].
    pub lattice_kernel_sum: f64,
    /// Own-phase kernel sum below which particle shifting treats a particle as at a boundary
    /// of its phase [1/m³] ([`crate::lattice::shifting_boundary_sum`]).
    pub boundary_kernel_sum: f64,
    /// Rest volume of a particle `m/ρ0` [m³].
    pub rest_volume_m3: f64,
    /// Lattice surface sum of the potential `S` [m³].
    pub surface_sum_m3: f64,
    /// Bulk binding sum `Σ_{j≠i} P(r_ij)` over the lattice [m³] (interfacial-energy reference).
    pub bulk_potential_sum_m3: f64,
    /// The effects built.
    pub effects: Effects,
    /// End time, output interval, fixed step, step factors and step budget.
    pub time: TimeControl,
    /// The bounds of the health checks after every step.
    pub health: Health,
    /// Verlet skin of the neighbour lists [m].
    pub neighbour_skin_m: f64,
    /// Strength `D` of the liquid–wall repulsion per phase [J] (zero without the effect, and
    /// for solids): `10 p_b l0³` with the liquid's cohesive background pressure
    /// `p_b = −C_aa Σ r P'(r) / (6 l0³)` ([`crate::physics::forces::wall_repulsion`]).
    pub wall_repulsion_strength_j: Vec<f64>,
    /// Range `r0` of the liquid–wall repulsion [m].
    pub wall_repulsion_range_m: f64,
    /// The walls as solids liquid must stay out of (the health check's wall entry).
    pub walls: Vec<WallSolid>,
    /// The far radius of the neighbour search [m]: `r_e` with interfacial tension (the
    /// potential's cut-off, or the surface stress's colour kernel support), else the kernel
    /// support (the search uses the larger of it and the support).
    pub interaction_radius_m: f64,
    /// Periodic axes: pair vectors are minimum images ([`PeriodicBox`]).
    pub periodic: PeriodicBox,
    /// Uniform pressure added to every liquid particle's EOS pressure [Pa] (0 but in fully
    /// periodic diagnostic scenes).
    pub background_pressure_pa: f64,
}

impl Model {
    /// Derives the model from a validated scene.
    pub fn from_scene(scene: &Scene) -> Result<Model, SceneError> {
        let d = &scene.discretisation;
        let l0 = d.l0;
        let h = scene.h();
        let r_e = scene.r_e();
        let potential = Kondo2007Potential {
            l0_m: l0,
            r_e_m: r_e,
            order: d.potential_order,
        };
        let lattice_kernel_sum = with_kernel!(d.kernel, K => lattice::kernel_sum(&K::new(h), l0));
        let boundary_kernel_sum = with_kernel!(d.kernel, K => {
            lattice::shifting_boundary_sum(&K::new(h), l0)
        });
        let surface_sum_m3 = lattice::potential_surface_sum(&potential);
        if surface_sum_m3 <= 0.0 {
            return Err(SceneError::invalid(
                "discretisation.re_over_l0",
                d.re_over_l0,
                "the potential's lattice surface sum S is not positive for this cut-off",
            ));
        }
        let bulk_potential_sum_m3 = lattice::bulk_potential_sum(&potential);
        let n_liquids = scene.liquids.len();
        if n_liquids + scene.solids.len() > u8::MAX as usize {
            return Err(SceneError::invalid(
                "liquid/solid",
                n_liquids + scene.solids.len(),
                "at most 255 phases",
            ));
        }
        let mean_rho0 = scene.liquids.iter().map(|l| l.density).sum::<f64>() / n_liquids as f64;
        let mut phase_names: Vec<String> = scene.liquids.iter().map(|l| l.name.clone()).collect();
        phase_names.extend(scene.solids.iter().map(|s| s.name.clone()));
        let mut rho0: Vec<f64> = scene.liquids.iter().map(|l| l.density).collect();
        rho0.extend(scene.solids.iter().map(|_| mean_rho0));
        let mut mu: Vec<f64> = scene.liquids.iter().map(|l| l.viscosity).collect();
        mu.extend(scene.solids.iter().map(|_| 0.0));
        // m = ρ0 l0³ (physical) or ρ0 / Σ_lattice W (docs/model.md §1); either way V0 = m/ρ0
        let rest_volume_m3 = match d.particle_mass {
            ParticleMass::Physical => l0 * l0 * l0,
            ParticleMass::Lattice => 1.0 / lattice_kernel_sum,
        };
        let mut mass: Vec<f64> = scene
            .liquids
            .iter()
            .map(|l| l.density * rest_volume_m3)
            .collect();
        mass.extend(scene.solids.iter().map(|_| 0.0));
        let mu_pair = pairs::viscosity_table(&mu, n_liquids);
        let pairs = if scene.effects.interfacial_tension.is_potential() {
            pairs::fowkes_table(scene, surface_sum_m3)
        } else {
            PairTable::zero(phase_names.len())
        };
        let effects = Effects::of(scene);
        // the lattice virial sum only when the repulsion needs it
        let virial = effects
            .wall_repulsion
            .then(|| lattice::potential_virial_sum(&potential));
        let wall_repulsion_strength_j: Vec<f64> = (0..phase_names.len())
            .map(|a| {
                let Some(virial) = virial.filter(|_| a < n_liquids) else {
                    return 0.0;
                };
                let p_b = -pairs.c(a, a) * virial / (6.0 * l0 * l0 * l0);
                repulsion::STRENGTH_OVER_PB_L03 * p_b * l0 * l0 * l0
            })
            .collect();
        let support_m = scene.kernel_support();
        let surface_force_walls = scene
            .walls
            .first()
            .filter(|_| effects.continuum_tension == Some(ContinuumForm::Force))
            .and_then(|w| scene.solid_index(&w.solid))
            .map_or(Walls::Absent, |k| {
                let solid = n_liquids + k;
                match scene.effects.surface_force_walls {
                    SurfaceForceWalls::Shares => Walls::Shares(solid),
                    SurfaceForceWalls::Normal => Walls::Normal(WallNormal { solid, l0_m: l0 }),
                }
            });
        // the share of Young's push the force hands to the liquid at a wall, measured on the
        // lattice channel with the run's colour kernel (support r_e; docs/model.md §4b)
        let contact_line_factor = match surface_force_walls {
            Walls::Absent => 1.0,
            walls => {
                let turn_normals = matches!(walls, Walls::Normal(_));
                let share = with_kernel!(d.kernel, K => {
                    let colour = K::new(r_e / K::new(1.0).support_m());
                    contact_line::young_share(colour, l0, turn_normals)
                });
                1.0 / share
            }
        };
        let surface_stress_sigma = if effects.continuum_tension.is_some() {
            pairs::surface_stress_table(scene, contact_line_factor)
        } else {
            Vec::new()
        };
        let interaction_radius_m =
            if effects.interfacial_tension || effects.continuum_tension.is_some() {
                r_e
            } else {
                support_m
            };
        let neighbour_skin_m = d.neighbour_skin_over_l0 * l0;
        let periodic = scene.periodic.to_box();
        check_period(
            &periodic,
            support_m.max(interaction_radius_m) + neighbour_skin_m,
        )?;
        Ok(Model {
            kernel: d.kernel,
            l0_m: l0,
            h_m: h,
            support_m,
            r_e_m: r_e,
            c_m_s: d.sound_speed,
            eos: TaitEos {
                c2: d.sound_speed * d.sound_speed,
            },
            potential,
            n_liquids,
            phase_names,
            rho0,
            mu,
            mass,
            mu_pair,
            pairs,
            surface_stress_sigma,
            surface_force_walls,
            contact_line_factor,
            tension_scales: vec![1.0; n_liquids],
            pair_tension_scales: Vec::new(),
            lattice_kernel_sum,
            boundary_kernel_sum,
            rest_volume_m3,
            surface_sum_m3,
            bulk_potential_sum_m3,
            effects,
            time: scene.time.clone(),
            health: scene.health.clone(),
            neighbour_skin_m,
            interaction_radius_m,
            periodic,
            background_pressure_pa: scene.density.background_pressure,
            walls: WallSolid::of(scene),
            wall_repulsion_strength_j,
            wall_repulsion_range_m: repulsion::RANGE_OVER_L0 * l0,
        })
    }

    /// Scales each liquid's potential coefficients by its factor in `scales` (one per liquid;
    /// [`PairTable::scale_liquids`]) and the liquid–wall repulsion with them (it is
    /// proportional to the liquid's cohesive pressure, hence to `C_aa`).
    pub fn scale_tension(&mut self, scales: &[f64]) {
        assert_eq!(scales.len(), self.n_liquids, "one factor per liquid");
        self.pairs.scale_liquids(scales);
        for (t, f) in self.tension_scales.iter_mut().zip(scales) {
            *t *= f;
        }
        for (d, f) in self.wall_repulsion_strength_j.iter_mut().zip(scales) {
            *d *= f;
        }
    }

    /// Scales the coefficient of phases `a` and `b` (two liquids, or a liquid and a solid) by
    /// `f` (on top of the liquids' own factors) and records it.
    pub fn scale_pair_tension(&mut self, a: usize, b: usize, f: f64) {
        assert!(
            a < self.n_liquids || b < self.n_liquids,
            "a pair with a liquid"
        );
        self.pairs.scale_pair(a, b, f);
        let (a, b) = (a.min(b), a.max(b));
        match self
            .pair_tension_scales
            .iter_mut()
            .find(|p| (p.0, p.1) == (a, b))
        {
            Some(p) => p.2 *= f,
            None => self.pair_tension_scales.push((a, b, f)),
        }
    }

    /// Gravity vector [m/s²] (zero without the effect).
    pub fn gravity(&self) -> Vec3 {
        self.effects
            .gravity
            .map(Vec3::from)
            .unwrap_or_else(Vec3::zeros)
    }

    /// The kernel of this model (for callers generic over the kernel type).
    pub fn kernel_of<K: Kernel>(&self) -> K {
        K::new(self.h_m)
    }

    /// The tension [N/m] of liquid phases `a ≠ b` under the continuum surface stress (zero
    /// without it).
    pub fn surface_stress_sigma(&self, a: usize, b: usize) -> f64 {
        let n = self.phase_names.len();
        self.surface_stress_sigma
            .get(a * n + b)
            .copied()
            .unwrap_or(0.0)
    }

    /// The capillary step limit of the surface stress [s]: per pair of liquids with a tension,
    /// `capillary · √(ρ̄ h³/(2π σ_ab))` with the pair's mean density `ρ̄` (Brackbill et al.
    /// 1992's constraint with the two fluids' mean, docs/model.md §3); the smallest.
    fn surface_stress_step_limit(&self) -> Option<f64> {
        let f = self.time.factors.capillary;
        let h = self.h_m;
        let n = self.n_liquids;
        (0..n)
            .flat_map(|a| (0..n).map(move |b| (a, b)))
            .filter(|&(a, b)| self.surface_stress_sigma(a, b) > 0.0)
            .map(|(a, b)| {
                let rho = 0.5 * (self.rho0[a] + self.rho0[b]);
                let sigma = self.surface_stress_sigma(a, b);
                f * (rho * h * h * h / (2.0 * std::f64::consts::PI * sigma)).sqrt()
            })
            .reduce(f64::min)
    }

    /// The time-step limits that do not depend on the state: viscous and capillary [s].
    pub fn static_step_limits(&self) -> (Option<f64>, Option<f64>) {
        let f = &self.time.factors;
        let h = self.h_m;
        // the implicit solve is stable for any step: no viscous limit then
        let viscous = if self.effects.explicit_laminar_viscosity() {
            (0..self.n_liquids)
                .filter(|&a| self.mu[a] > 0.0)
                .map(|a| f.viscous * self.rho0[a] * h * h / self.mu[a]) // docs/model.md §3
                .reduce(f64::min)
        } else {
            None
        };
        // the non-affine viscosity μ_na = α ρ c h: ρ h²/μ_na = h/(α c)
        let nonaffine = self
            .effects
            .nonaffine_viscosity
            .map(|alpha| f.viscous * h / (alpha * self.c_m_s));
        let viscous = match (viscous, nonaffine) {
            (Some(a), Some(b)) => Some(a.min(b)),
            (a, b) => a.or(b),
        };
        let capillary = if self.effects.interfacial_tension {
            (0..self.n_liquids)
                .map(|a| {
                    let sigma = (0..self.pairs.n_phases)
                        .map(|b| self.pairs.sigma(a, b))
                        .fold(0.0, f64::max);
                    // docs/model.md §3: dt ≤ 0.25 √(ρ h³ / (2π σ))
                    f.capillary
                        * (self.rho0[a] * h * h * h / (2.0 * std::f64::consts::PI * sigma)).sqrt()
                })
                .reduce(f64::min)
        } else if self.effects.continuum_tension.is_some() {
            self.surface_stress_step_limit()
        } else {
            None
        };
        (viscous, capillary)
    }
}

/// Refuses a period shorter than twice the neighbour search's cut-off `cut_m` [m]: a pair
/// would then interact through two images at once.
fn check_period(periodic: &PeriodicBox, cut_m: f64) -> Result<(), SceneError> {
    for (k, axis) in ["x", "y", "z"].iter().enumerate() {
        let len = periodic.period_m(k);
        if periodic.axis_is_periodic(k) && len < 2.0 * cut_m {
            return Err(SceneError::invalid(
                format!("periodic.{axis}"),
                format!("a period of {len:e} m"),
                format!(
                    "the period must be at least twice the neighbour cut-off (max(support,                      r_e) + skin = {cut_m:e} m): at least {:e} m",
                    2.0 * cut_m
                ),
            ));
        }
    }
    Ok(())
}
