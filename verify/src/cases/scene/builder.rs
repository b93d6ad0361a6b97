//! The typed scene builder: every case and the accuracy–cost study build their scenes with it.
//!
//! It sets the fields of a [`Scene`] (plain serde data) by typed methods and has the solver
//! validate the result ([`Scene::validate`]), so a case can build no scene a user could not
//! write. Fields left alone keep the scene schema's defaults, taken from the solver's own
//! deserialisation rather than repeated here.

use super::materials::LiquidProps;
use solver::kernel::KernelKind;
use solver::scene::{
    ArtificialViscosity, Body, BodyShape, Cut, DensityScheme, Interface, Liquid, PeriodicAxes,
    Reinit, Setting, Solid, VelocityWave, Wall, WallBoundary, WallShape,
};
use solver::Scene;

/// A scene under construction; [`SceneBuilder::build`] validates it.
#[derive(Clone, Debug)]
pub struct SceneBuilder {
    scene: Scene,
}

impl SceneBuilder {
    /// A scene with spacing `l0_m` [m] and sound speed `sound_speed_m_s` [m/s], every other
    /// field at the schema's default: no effects, materials or bodies, and no time control yet
    /// (set it with [`SceneBuilder::time`]; validation refuses a scene without).
    pub fn new(l0_m: f64, sound_speed_m_s: f64) -> Self {
        let table = |pairs: [(&str, f64); 2]| -> toml::Value {
            toml::Value::Table(
                pairs
                    .into_iter()
                    .map(|(k, v)| (k.to_string(), toml::Value::Float(v)))
                    .collect(),
            )
        };
        let mut root = toml::Table::new();
        root.insert(
            "discretisation".into(),
            table([("l0", l0_m), ("sound_speed", sound_speed_m_s)]),
        );
        root.insert(
            "time".into(),
            table([("end", 0.0), ("output_interval", 0.0)]),
        );
        let scene = root
            .try_into()
            .expect("the required fields are all a scene needs to deserialise");
        SceneBuilder { scene }
    }

    /// A scene file as the starting point (e.g. one of `scenes/`, compiled in).
    pub fn from_toml(text: &str) -> Self {
        let scene = Scene::from_toml_str(text)
            .unwrap_or_else(|e| panic!("a case's scene file is invalid: {e}\n{text}"));
        SceneBuilder { scene }
    }

    /// The scene as built so far.
    pub fn scene(&self) -> &Scene {
        &self.scene
    }

    /// Validates the scene; a case that builds an invalid scene is a bug, hence the panic.
    pub fn build(self) -> Scene {
        if let Err(e) = self.scene.validate() {
            panic!(
                "a case built an invalid scene: {e}\n{}",
                toml::to_string(&self.scene).unwrap_or_default()
            );
        }
        self.scene
    }

    /// Particle spacing `l0` [m].
    pub fn l0(mut self, l0_m: f64) -> Self {
        self.scene.discretisation.l0 = l0_m;
        self
    }

    /// Artificial sound speed [m/s].
    pub fn sound_speed(mut self, sound_speed_m_s: f64) -> Self {
        self.scene.discretisation.sound_speed = sound_speed_m_s;
        self
    }

    /// A paper's discretisation, with its defaults of `h/l0` and `r_e/l0` (as a scene file
    /// naming the setting and neither ratio).
    pub fn setting(mut self, setting: Setting) -> Self {
        let d = &mut self.scene.discretisation;
        d.setting = setting;
        d.h_over_l0 = setting.h_over_l0();
        d.re_over_l0 = setting.re_over_l0();
        self
    }

    /// Kernel, smoothing length over spacing `h/l0` [-] and potential cut-off over spacing
    /// `r_e/l0` [-].
    pub fn kernel(mut self, kernel: KernelKind, h_over_l0: f64, re_over_l0: f64) -> Self {
        let d = &mut self.scene.discretisation;
        d.kernel = kernel;
        d.h_over_l0 = h_over_l0;
        d.re_over_l0 = re_over_l0;
        self
    }

    /// Order `m` of the potential's zero at its cut-off (1: Kondo 2007).
    pub fn potential_order(mut self, m: u8) -> Self {
        self.scene.discretisation.potential_order = m;
        self
    }

    /// End time `end_s` [s] and interval between outputs `output_interval_s` [s].
    pub fn time(mut self, end_s: f64, output_interval_s: f64) -> Self {
        self.scene.time.end = end_s;
        self.scene.time.output_interval = output_interval_s;
        self
    }

    /// A fixed time step [s], or `None` for the adaptive one.
    pub fn fixed_dt(mut self, dt_s: Option<f64>) -> Self {
        self.scene.time.dt = dt_s;
        self
    }

    /// Continuity density, re-initialised by `reinit` every `every` steps.
    pub fn continuity_density(mut self, reinit: Reinit, every: u32) -> Self {
        let d = &mut self.scene.density;
        d.scheme = DensityScheme::Continuity;
        d.reinit = reinit;
        d.reinit_every = every;
        self
    }

    /// The effects of Natsui 2021: interfacial tension, laminar viscosity and the artificial
    /// viscosity with α1 = α2 = 0.01 (no gravity: see [`SceneBuilder::gravity`]).
    pub fn paper_effects(mut self) -> Self {
        let e = &mut self.scene.effects;
        e.interfacial_tension = true.into();
        e.laminar_viscosity = true;
        e.artificial_viscosity = Some(ArtificialViscosity {
            alpha1: 0.01,
            alpha2: 0.01,
        });
        self
    }

    /// The laminar viscosity integrated implicitly (backward Euler, the solver's default
    /// stopping rule): no viscous step limit, for very viscous liquids.
    pub fn implicit_viscosity(mut self) -> Self {
        self.scene.effects.implicit_viscosity = Some(Default::default());
        self
    }

    /// The pairwise potential (surface and interfacial tension) on or off.
    pub fn interfacial_tension(mut self, on: bool) -> Self {
        self.scene.effects.interfacial_tension = on.into();
        self
    }

    /// The tension model: off, the pairwise potential, or the continuum surface stress.
    pub fn tension_model(mut self, model: solver::scene::TensionModel) -> Self {
        self.scene.effects.interfacial_tension = model;
        self
    }

    /// How walls take part in the surface force: Young's shares or the wall normal.
    pub fn surface_force_walls(mut self, walls: solver::scene::SurfaceForceWalls) -> Self {
        self.scene.effects.surface_force_walls = walls;
        self
    }

    /// The form of the pressure force between liquid particles (and at walls): symmetric
    /// (Eq. 11, Natsui 2021) or the difference form (docs/model.md §3).
    pub fn pressure_gradient(mut self, g: solver::scene::PressureGradient) -> Self {
        self.scene.density.pressure_gradient = g;
        self
    }

    /// Particle shifting at its default coefficient on or off.
    pub fn particle_shifting(mut self, on: bool) -> Self {
        self.scene.effects.particle_shifting = on.then(solver::scene::ParticleShifting::default);
        self
    }

    /// The short-range liquid–wall repulsion on or off.
    pub fn wall_repulsion(mut self, on: bool) -> Self {
        self.scene.effects.wall_repulsion = on;
        self
    }

    /// Gravity [m/s²].
    pub fn gravity(mut self, g_m_s2: [f64; 3]) -> Self {
        self.scene.effects.gravity = Some(g_m_s2);
        self
    }

    /// A liquid phase.
    pub fn liquid(mut self, l: &LiquidProps) -> Self {
        self.scene.liquids.push(Liquid {
            name: l.name.into(),
            density: l.density_kg_m3,
            viscosity: l.viscosity_pa_s,
            surface_tension: Some(l.surface_tension_n_m),
        });
        self
    }

    /// A liquid phase without a surface tension (`l`'s is not read): under the continuum
    /// models, the gas around the others, which takes no contact angle on a solid (Young's
    /// `σ_gS = σ_S`; docs/model.md §4b).
    pub fn gas(mut self, l: &LiquidProps) -> Self {
        self = self.liquid(l);
        self.scene
            .liquids
            .last_mut()
            .expect("just added")
            .surface_tension = None;
        self
    }

    /// The interfacial tension [N/m] between liquids `a` and `b`.
    pub fn interface(mut self, a: &str, b: &str, tension_n_m: f64) -> Self {
        self.scene.interfaces.push(Interface {
            liquids: [a.into(), b.into()],
            tension: tension_n_m,
        });
        self
    }

    /// A solid with each liquid's contact angle on it, `(liquid, θ [deg])`.
    pub fn solid(mut self, name: &str, contact_angles_deg: &[(&str, f64)]) -> Self {
        self.scene.solids.push(Solid {
            name: name.into(),
            contact_angles: contact_angles_deg
                .iter()
                .map(|&(l, theta)| (l.to_string(), theta))
                .collect(),
        });
        self
    }

    /// A body of `liquid` at rest.
    pub fn body(self, name: &str, liquid: &str, shape: BodyShape) -> Self {
        self.moving_body(name, liquid, shape, [0.0; 3])
    }

    /// A body of `liquid` moving at `velocity_m_s` [m/s].
    pub fn moving_body(
        mut self,
        name: &str,
        liquid: &str,
        shape: BodyShape,
        velocity_m_s: [f64; 3],
    ) -> Self {
        self.scene.bodies.push(Body {
            name: name.into(),
            liquid: Some(liquid.into()),
            shape,
            cut: None,
            velocity: velocity_m_s,
            velocity_wave: None,
        });
        self
    }

    /// A body of `liquid` at rest but for a sinusoidal velocity `wave`.
    pub fn waving_body(
        mut self,
        name: &str,
        liquid: &str,
        shape: BodyShape,
        wave: VelocityWave,
    ) -> Self {
        self = self.body(name, liquid, shape);
        self.scene
            .bodies
            .last_mut()
            .expect("just added")
            .velocity_wave = Some(wave);
        self
    }

    /// Makes every axis periodic over the box `[min, max]` [m].
    pub fn periodic_box(mut self, min_m: [f64; 3], max_m: [f64; 3]) -> Self {
        let r = |k: usize| Some([min_m[k], max_m[k]]);
        self.scene.periodic = PeriodicAxes {
            x: r(0),
            y: r(1),
            z: r(2),
        };
        self
    }

    /// A body at rest cut by a plane into two liquids.
    pub fn cut_body(mut self, name: &str, shape: BodyShape, cut: Cut) -> Self {
        self.scene.bodies.push(Body {
            name: name.into(),
            liquid: None,
            shape,
            cut: Some(cut),
            velocity: [0.0; 3],
            velocity_wave: None,
        });
        self
    }

    /// A wall of `solid` with the default number of layers.
    pub fn wall(
        mut self,
        name: &str,
        solid: &str,
        shape: WallShape,
        boundary: WallBoundary,
    ) -> Self {
        self.scene.walls.push(Wall {
            name: name.into(),
            solid: solid.into(),
            shape,
            layers: None,
            boundary,
        });
        self
    }

    /// The last wall added with `layers` layers of particles instead of the default (enough
    /// for the kernels' reach from one face).
    pub fn wall_layers(mut self, layers: u32) -> Self {
        let wall = self
            .scene
            .walls
            .last_mut()
            .expect("wall_layers follows a wall");
        wall.layers = Some(layers);
        self
    }

    /// The continuum models' setting of a drop on a plate: the liquid `gas` (a body of that
    /// name) filling a box periodic along x, y and z, `2 half_m` square and `top_m` high above
    /// a free-slip plate named "plate", of solid "plate", whose top face is z = 0 and which
    /// spans the box in `layers` layers, so that the gas at the box's top meets the plate's
    /// underside [m].
    pub fn gas_over_plate(self, gas: &str, half_m: f64, top_m: f64, layers: u32) -> Self {
        let (half, top) = (half_m, top_m);
        let b = self
            .body(
                gas,
                gas,
                BodyShape::Surrounding {
                    min: [-half, -half, 0.0],
                    max: [half, half, top],
                },
            )
            .wall(
                "plate",
                "plate",
                WallShape::Plate {
                    min: [-half, -half],
                    max: [half, half],
                    top: 0.0,
                },
                WallBoundary::FreeSlip,
            )
            .wall_layers(layers);
        let s = b.scene();
        let below = s.wall_layers(&s.walls[0]) as f64 * s.discretisation.l0;
        b.periodic_box([-half, -half, -below], [half, half, top])
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cases::scene::MATTE;

    #[test]
    fn defaults_are_the_schemas() {
        let built = SceneBuilder::new(1e-4, 12.0)
            .time(1e-3, 1e-4)
            .liquid(&MATTE)
            .body(
                "drop",
                "matte",
                BodyShape::Sphere {
                    center: [0.0; 3],
                    radius: 5e-4,
                },
            )
            .build();
        let written = Scene::from_toml_str(
            "[discretisation]\nl0 = 1e-4\nsound_speed = 12.0\n[time]\nend = 1e-3\n\
             output_interval = 1e-4\n[[liquid]]\nname = \"matte\"\ndensity = 4500.0\n\
             viscosity = 3.13e-3\nsurface_tension = 0.40\n[[body]]\nname = \"drop\"\n\
             liquid = \"matte\"\nshape = { kind = \"sphere\", center = [0.0, 0.0, 0.0], \
             radius = 5e-4 }\n",
        )
        .unwrap();
        assert_eq!(built, written);
    }

    #[test]
    fn a_setting_brings_its_ratios() {
        let s = SceneBuilder::new(1e-4, 12.0)
            .setting(Setting::Natsui2016)
            .scene()
            .discretisation
            .clone();
        assert_eq!((s.h_over_l0, s.re_over_l0), (2.0, 4.0));
    }

    #[test]
    #[should_panic(expected = "time.end")]
    fn a_scene_without_time_is_refused() {
        let _ = SceneBuilder::new(1e-4, 12.0).liquid(&MATTE).build();
    }
}
