//! The resolved model: a validated scene turned into the constants the time step needs.

use crate::kernel::{Kernel, KernelKind};
use crate::lattice;
use crate::physics::eos::TaitEos;
use crate::physics::surface_tension::{Kondo2007Potential, PairTable};
use crate::scene::{
    DensityScheme, NegativePressure, ParticleMass, Reinit, Scene, SceneError, WallBoundary,
};
use crate::state::Vec3;
use crate::with_kernel;
use serde::Serialize;

/// The effects built for a run. Anything not listed here is not computed at all.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Effects {
    /// Gravity [m/s²], if any.
    pub gravity: Option<[f64; 3]>,
    /// Laminar viscosity.
    pub laminar_viscosity: bool,
    /// Artificial viscosity `(α1, α2)`, if any.
    pub artificial_viscosity: Option<(f64, f64)>,
    /// Pairwise-potential surface and interfacial tension.
    pub interfacial_tension: bool,
    /// Wall particles (pressure extrapolation; with tension also wetting).
    pub walls: bool,
    /// Some wall is no-slip.
    pub no_slip_walls: bool,
    /// Density scheme.
    pub density: DensityScheme,
    /// Density re-initialisation `(filter, every n steps)`, if any.
    pub density_reinit: Option<(Reinit, u32)>,
    /// Negative EOS pressure clipped to zero.
    pub clip_negative_pressure: bool,
}

impl Effects {
    /// Names of the built effects, for reports.
    pub fn names(&self) -> Vec<String> {
        let mut v = vec!["pressure (Tait EOS)".to_string()];
        if let Some(g) = self.gravity {
            v.push(format!("gravity {g:?} m/s²"));
        }
        if self.laminar_viscosity {
            v.push("laminar viscosity".into());
        }
        if let Some((a1, a2)) = self.artificial_viscosity {
            v.push(format!("artificial viscosity (α1 = {a1}, α2 = {a2})"));
        }
        if self.interfacial_tension {
            v.push("interfacial tension (pairwise potential, Fowkes pairs)".into());
        }
        if self.walls {
            let slip = if self.no_slip_walls {
                "no-slip"
            } else {
                "free-slip"
            };
            let wet = if self.interfacial_tension {
                " with wetting"
            } else {
                ""
            };
            v.push(format!("walls ({slip}){wet}"));
        }
        v.push(match self.density {
            DensityScheme::Summation => "density: summation".into(),
            DensityScheme::Continuity => "density: continuity".into(),
        });
        if self.clip_negative_pressure {
            v.push("EOS: negative pressure clipped to zero".into());
        }
        if let Some((r, n)) = self.density_reinit {
            v.push(format!("density re-initialisation: {r:?} every {n} steps"));
        }
        v
    }
}

/// Constants of a run, derived once from the scene.
#[derive(Clone, Debug)]
pub struct Model {
    /// The scene as resolved (defaults filled in).
    pub scene: Scene,
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
    /// `Σ_j W_ij` over the bulk lattice, self included [1/m³].
    pub lattice_kernel_sum: f64,
    /// Rest volume of a particle `m/ρ0` [m³].
    pub rest_volume_m3: f64,
    /// Lattice surface sum of the potential `S` [m³].
    pub surface_sum_m3: f64,
    /// Bulk binding sum `Σ_{j≠i} P(r_ij)` over the lattice [m³] (interfacial-energy reference).
    pub bulk_potential_sum_m3: f64,
    /// The effects built.
    pub effects: Effects,
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
        };
        let lattice_kernel_sum = with_kernel!(d.kernel, K => lattice::kernel_sum(&K::new(h), l0));
        let surface_sum_m3 = lattice::potential_surface_sum(&potential);
        if surface_sum_m3 <= 0.0 {
            return Err(SceneError::invalid(
                "discretisation.re_over_l0",
                d.re_over_l0,
                "the potential's lattice surface sum S is not positive for this cut-off",
            ));
        }
        let bulk_potential_sum_m3 = bulk_sum(&potential);
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
        // m = ρ0 l0³ (physical) or ρ0 / Σ_lattice W (physics.md §1); either way V0 = m/ρ0
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
        let n_phases = phase_names.len();
        let mut mu_pair = vec![0.0; n_phases * n_phases];
        for a in 0..n_phases {
            for b in a..n_phases {
                let v = match (a < n_liquids, b < n_liquids) {
                    (true, true) if mu[a] + mu[b] > 0.0 => 2.0 * mu[a] * mu[b] / (mu[a] + mu[b]),
                    (true, true) => 0.0,
                    (true, false) => mu[a],
                    (false, true) => mu[b],
                    (false, false) => 0.0,
                };
                mu_pair[a * n_phases + b] = v;
                mu_pair[b * n_phases + a] = v;
            }
        }
        let pairs = if scene.effects.interfacial_tension {
            PairTable::from_scene(scene, surface_sum_m3)
        } else {
            let n = phase_names.len();
            PairTable {
                n_phases: n,
                sigma_pair: vec![0.0; n * n],
                coeff: vec![0.0; n * n],
            }
        };
        let e = &scene.effects;
        let effects = Effects {
            gravity: e.gravity,
            laminar_viscosity: e.laminar_viscosity,
            artificial_viscosity: e
                .artificial_viscosity
                .as_ref()
                .map(|a| (a.alpha1, a.alpha2)),
            interfacial_tension: e.interfacial_tension,
            walls: !scene.walls.is_empty(),
            no_slip_walls: scene
                .walls
                .iter()
                .any(|w| w.boundary == WallBoundary::NoSlip),
            density: scene.density.scheme,
            density_reinit: match scene.density.reinit {
                Reinit::None => None,
                r => Some((r, scene.density.reinit_every)),
            },
            clip_negative_pressure: scene.density.negative_pressure == NegativePressure::Clip,
        };
        Ok(Model {
            scene: scene.clone(),
            kernel: d.kernel,
            l0_m: l0,
            h_m: h,
            support_m: scene.kernel_support(),
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
            lattice_kernel_sum,
            rest_volume_m3,
            surface_sum_m3,
            bulk_potential_sum_m3,
            effects,
        })
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

    /// The time-step limits that do not depend on the state: viscous and capillary [s].
    pub fn static_step_limits(&self) -> (Option<f64>, Option<f64>) {
        let f = &self.scene.time.factors;
        let h = self.h_m;
        let viscous = if self.effects.laminar_viscosity {
            (0..self.n_liquids)
                .filter(|&a| self.mu[a] > 0.0)
                .map(|a| f.viscous * self.rho0[a] * h * h / self.mu[a]) // physics.md §3
                .reduce(f64::min)
        } else {
            None
        };
        let capillary = if self.effects.interfacial_tension {
            (0..self.n_liquids)
                .map(|a| {
                    let sigma = (0..self.pairs.n_phases)
                        .map(|b| self.pairs.sigma(a, b))
                        .fold(0.0, f64::max);
                    // physics.md §3: dt ≤ 0.25 √(ρ h³ / (2π σ))
                    f.capillary
                        * (self.rho0[a] * h * h * h / (2.0 * std::f64::consts::PI * sigma)).sqrt()
                })
                .reduce(f64::min)
        } else {
            None
        };
        (viscous, capillary)
    }
}

/// `Σ_{j≠i} P(r_ij)` over the bulk lattice [m³].
fn bulk_sum(p: &Kondo2007Potential) -> f64 {
    let n = (p.r_e_m / p.l0_m).ceil() as i64 + 1;
    let mut s = 0.0;
    for k in -n..=n {
        for j in -n..=n {
            for i in -n..=n {
                if i == 0 && j == 0 && k == 0 {
                    continue;
                }
                s += p.p(p.l0_m * ((i * i + j * j + k * k) as f64).sqrt());
            }
        }
    }
    s
}
