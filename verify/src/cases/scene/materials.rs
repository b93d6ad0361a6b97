//! Liquids of the papers and the sound speed that suits them.

/// A liquid's name and properties.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LiquidProps {
    /// Name of the liquid in the scene.
    pub name: &'static str,
    /// Reference density ρ0 [kg/m³].
    pub density_kg_m3: f64,
    /// Dynamic viscosity μ [Pa·s].
    pub viscosity_pa_s: f64,
    /// Surface tension σ against the gas [N/m].
    pub surface_tension_n_m: f64,
}

impl LiquidProps {
    /// The same liquid under another name (two drops of one liquid are two phases).
    pub const fn named(self, name: &'static str) -> Self {
        LiquidProps { name, ..self }
    }
}

/// Molten copper matte at 1573 K (Natsui 2021 §3.1).
pub const MATTE: LiquidProps = LiquidProps {
    name: "matte",
    density_kg_m3: 4500.0,
    viscosity_pa_s: 3.13e-3,
    surface_tension_n_m: 0.40,
};

/// Molten slag (Natsui 2021 §3.2).
pub const SLAG: LiquidProps = LiquidProps {
    name: "slag",
    density_kg_m3: 3500.0,
    viscosity_pa_s: 0.10,
    surface_tension_n_m: 0.20,
};

/// The sound speed [m/s] that keeps the potential's cohesive pressure (≈ 1.75 σ/l0 at
/// r_e = 4.2 l0, docs/model.md §4) to a compression of 1 %: `c² = 1.75 σ / (l0 · 0.01 ρ)`, and at
/// least `floor_m_s`.
pub fn sound_speed_for(liquid: &LiquidProps, l0_m: f64, floor_m_s: f64) -> f64 {
    (1.75 * liquid.surface_tension_n_m / (l0_m * 0.01 * liquid.density_kg_m3))
        .sqrt()
        .max(floor_m_s)
}

/// The sound speed [m/s] of a continuum capillarity model's drop of `radius_m` [m]: its Laplace
/// pressure 2σ/R compresses it by 1 % (`c² = 2σ/(R · 0.01 ρ)`; the continuum models carry no
/// cohesive pressure).
pub fn laplace_sound_speed(liquid: &LiquidProps, radius_m: f64) -> f64 {
    (2.0 * liquid.surface_tension_n_m / (radius_m * 0.01 * liquid.density_kg_m3)).sqrt()
}

/// Gravity of Natsui 2021's scenes on a plate [m/s²] (paper B's cases use 9.81 m/s², see
/// `substrate`).
pub const GRAVITY_M_S2: [f64; 3] = [0.0, 0.0, -9.8];

/// The artificial viscosity's effective kinematic viscosity `α1 h c/10` [m²/s] in `scene` (0
/// without it): Monaghan (1992)'s estimate for compressive flows.
pub fn artificial_viscosity_m2_s(scene: &solver::Scene) -> f64 {
    let alpha1 = scene
        .effects
        .artificial_viscosity
        .as_ref()
        .map_or(0.0, |a| a.alpha1);
    alpha1 * scene.h() * scene.discretisation.sound_speed / 10.0
}
