//! Scene building blocks shared by the cases: materials of the papers and TOML assembly.
//!
//! Cases write their scenes as TOML (the same language as users), parsed and validated by the
//! solver, so a case can never build a scene a user could not.

use solver::Scene;

/// A liquid's properties: `(name, ρ [kg/m³], μ [Pa·s], σ [N/m])`.
pub type LiquidProps = (&'static str, f64, f64, f64);

/// Molten copper matte at 1573 K (Natsui 2021 §3.1).
pub const MATTE: LiquidProps = ("matte", 4500.0, 3.13e-3, 0.40);
/// Molten slag (Natsui 2021 §3.2).
pub const SLAG: LiquidProps = ("slag", 3500.0, 0.10, 0.20);

/// A `[[liquid]]` table.
pub fn liquid(l: LiquidProps) -> String {
    format!(
        "[[liquid]]\nname = \"{}\"\ndensity = {:e}\nviscosity = {:e}\nsurface_tension = {:e}\n",
        l.0, l.1, l.2, l.3
    )
}

/// The `[discretisation]`, `[time]` and `[effects]` tables. `dt` fixes the step.
#[allow(clippy::too_many_arguments)]
pub fn header(
    l0_m: f64,
    sound_speed_m_s: f64,
    end_s: f64,
    output_interval_s: f64,
    dt_s: Option<f64>,
    gravity: bool,
    walls_note: &str,
) -> String {
    let dt = dt_s.map(|d| format!("dt = {d:e}\n")).unwrap_or_default();
    let g = if gravity {
        "gravity = [0.0, 0.0, -9.8]\n"
    } else {
        ""
    };
    format!(
        "# {walls_note}\n[discretisation]\nl0 = {l0_m:e}\nsound_speed = {sound_speed_m_s:e}\n\
         [time]\nend = {end_s:e}\noutput_interval = {output_interval_s:e}\n{dt}\
         [effects]\ninterfacial_tension = true\nlaminar_viscosity = true\n\
         artificial_viscosity = {{ alpha1 = 0.01, alpha2 = 0.01 }}\n{g}"
    )
}

/// Parses a scene a case built; a case that builds an invalid scene is a bug.
pub fn parse(text: &str) -> Scene {
    Scene::from_toml_str(text)
        .unwrap_or_else(|e| panic!("a case built an invalid scene: {e}\n{text}"))
}

/// The sound speed [m/s] that keeps the potential's cohesive pressure (≈ 1.75 σ/l0 at
/// r_e = 4.2 l0, physics.md §4) to a compression of 1 %: `c² = 1.75 σ / (l0 · 0.01 ρ)`, and at
/// least `floor`.
pub fn sound_speed_for(sigma_n_m: f64, rho_kg_m3: f64, l0_m: f64, floor_m_s: f64) -> f64 {
    (1.75 * sigma_n_m / (l0_m * 0.01 * rho_kg_m3))
        .sqrt()
        .max(floor_m_s)
}
