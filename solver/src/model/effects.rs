//! The effects built for a run, resolved from the scene's `[effects]`, `[density]` and walls.

use crate::scene::{
    DensityScheme, ImplicitViscosity, LaminarForm, NegativePressure, PressureGradient, Reinit,
    Scene, TensionModel, WallBoundary,
};
use serde::Serialize;

/// The form of a continuum tension between liquid phases (docs/model.md §4a, §4b).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum ContinuumForm {
    /// The capillary stress in pair form (Hu & Adams 2006): momentum-conserving, with a
    /// tangential tension.
    Stress,
    /// The force `σκ∇c` (Brackbill et al. 1992): normal only.
    Force,
}

/// The effects built for a run. Anything not listed here is not computed at all.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Effects {
    /// Gravity [m/s²], if any.
    pub gravity: Option<[f64; 3]>,
    /// Laminar viscosity.
    pub laminar_viscosity: bool,
    /// Its pair form.
    pub laminar_form: LaminarForm,
    /// The laminar viscosity integrated implicitly, with this stopping rule (else explicitly,
    /// as a term of the pair loop).
    pub implicit_viscosity: Option<ImplicitViscosity>,
    /// Artificial viscosity `(α1, α2)`, if any.
    pub artificial_viscosity: Option<(f64, f64)>,
    /// Pairwise-potential surface and interfacial tension.
    pub interfacial_tension: bool,
    /// A continuum tension between liquid phases, in this form, if any.
    pub continuum_tension: Option<ContinuumForm>,
    /// Wall particles (pressure extrapolation; with tension also wetting).
    pub walls: bool,
    /// Some wall is no-slip.
    pub no_slip_walls: bool,
    /// The short-range liquid–wall repulsion (Monaghan 1994).
    pub wall_repulsion: bool,
    /// Particle shifting's coefficient `A` [-], if shifting is on.
    pub particle_shifting: Option<f64>,
    /// The non-affine viscosity's coefficient `α` [-] (`μ_na = α ρ̄ c h`), if it is on.
    pub nonaffine_viscosity: Option<f64>,
    /// Density scheme.
    pub density: DensityScheme,
    /// Density re-initialisation `(filter, every n steps)`, if any.
    pub density_reinit: Option<(Reinit, u32)>,
    /// Negative EOS pressure clipped to zero.
    pub clip_negative_pressure: bool,
    /// The pressure force between liquid particles in the difference form (else symmetric).
    pub pressure_difference: bool,
}

impl Effects {
    /// The effects a (validated) scene declares.
    pub fn of(scene: &Scene) -> Effects {
        let e = &scene.effects;
        Effects {
            gravity: e.gravity,
            laminar_viscosity: e.laminar_viscosity,
            laminar_form: e.laminar_form,
            implicit_viscosity: e.implicit_viscosity.filter(|_| e.laminar_viscosity),
            artificial_viscosity: e
                .artificial_viscosity
                .as_ref()
                .map(|a| (a.alpha1, a.alpha2)),
            interfacial_tension: e.interfacial_tension.is_potential(),
            continuum_tension: match e.interfacial_tension {
                TensionModel::SurfaceStress => Some(ContinuumForm::Stress),
                TensionModel::SurfaceForce => Some(ContinuumForm::Force),
                TensionModel::Off | TensionModel::Potential => None,
            },
            walls: !scene.walls.is_empty(),
            wall_repulsion: e.wall_repulsion,
            particle_shifting: e.particle_shifting.as_ref().map(|p| p.coefficient),
            nonaffine_viscosity: e.nonaffine_viscosity.as_ref().map(|n| n.coefficient),
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
            pressure_difference: scene.density.pressure_gradient == PressureGradient::Difference,
        }
    }

    /// Whether the laminar viscosity is a term of the pair loop (declared and not implicit).
    pub fn explicit_laminar_viscosity(&self) -> bool {
        self.laminar_viscosity && self.implicit_viscosity.is_none()
    }

    /// Whether the pair loop's laminar term has the given form.
    pub fn explicit_laminar(&self, form: LaminarForm) -> bool {
        self.explicit_laminar_viscosity() && self.laminar_form == form
    }

    /// Whether the density follows the continuity equation (else the summation).
    pub fn continuity(&self) -> bool {
        self.density == DensityScheme::Continuity
    }

    /// Names of the built effects, for reports.
    pub fn names(&self) -> Vec<String> {
        let mut v = vec!["pressure (Tait EOS)".to_string()];
        if let Some(g) = self.gravity {
            v.push(format!("gravity {g:?} m/s²"));
        }
        if self.laminar_viscosity {
            v.push(match self.implicit_viscosity {
                None => match self.laminar_form {
                    LaminarForm::HuAdams => "laminar viscosity".into(),
                    LaminarForm::MonaghanClearyGingold => {
                        "laminar viscosity (Monaghan–Cleary–Gingold form)".into()
                    }
                },
                Some(iv) => format!(
                    "laminar viscosity (implicit: backward Euler, conjugate gradients to a relative residual of {:e})",
                    iv.relative_tolerance
                ),
            });
        }
        if let Some((a1, a2)) = self.artificial_viscosity {
            v.push(format!("artificial viscosity (α1 = {a1}, α2 = {a2})"));
        }
        if self.interfacial_tension {
            v.push("interfacial tension (pairwise potential, Fowkes pairs)".into());
        }
        match self.continuum_tension {
            Some(ContinuumForm::Stress) => {
                v.push("interfacial tension (continuum surface stress between liquids)".into())
            }
            Some(ContinuumForm::Force) => {
                v.push("interfacial tension (continuum surface force between liquids)".into())
            }
            None => {}
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
        if self.wall_repulsion {
            v.push("liquid–wall repulsion (Monaghan 1994, range 0.8 l0)".into());
        }
        if let Some(a) = self.particle_shifting {
            v.push(format!("particle shifting (A = {a})"));
        }
        if let Some(a) = self.nonaffine_viscosity {
            v.push(format!("non-affine viscosity (α = {a})"));
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
