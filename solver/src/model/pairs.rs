//! The scene's liquids, interfaces and contact angles resolved into per-phase tables: the
//! Fowkes pair strengths and the pair viscosities.

use crate::physics::surface_tension::{fowkes, PairTable};
use crate::scene::Scene;

/// The Fowkes pair table of a validated scene with interfacial tension on; `s_m3` is the
/// lattice surface sum `S` [m³] of [`crate::lattice::potential_surface_sum`].
pub fn fowkes_table(scene: &Scene, s_m3: f64) -> PairTable {
    let nl = scene.liquids.len();
    let n = nl + scene.solids.len();
    let sigma = |a: usize| scene.liquids[a].surface_tension.unwrap_or(0.0);
    let mut sigma_pair = vec![0.0; n * n];
    for a in 0..n {
        for b in 0..n {
            sigma_pair[a * n + b] = match (a < nl, b < nl) {
                (true, true) if a == b => fowkes::like_pair(sigma(a)),
                (true, true) => {
                    let (na, nb) = (&scene.liquids[a].name, &scene.liquids[b].name);
                    match scene.interface_tension(na, nb) {
                        Some(s_ab) => fowkes::liquid_liquid(sigma(a), sigma(b), s_ab),
                        // liquids that never meet: validation guarantees they are not both
                        // present; no adhesion is the neutral choice
                        None => 0.0,
                    }
                }
                (true, false) | (false, true) => {
                    let (l, so) = if a < nl { (a, b - nl) } else { (b, a - nl) };
                    let angle = scene.solids[so].contact_angles.get(&scene.liquids[l].name);
                    angle.map_or(0.0, |&theta_deg| fowkes::liquid_solid(sigma(l), theta_deg))
                }
                (false, false) => 0.0, // solids are fixed: no solid–solid force
            };
        }
    }
    PairTable::new(n, sigma_pair, scene.discretisation.l0, s_m3)
}

/// The tension of each pair of phases for the continuum models [N/m], row-major: the scene's
/// `[[interface]]` tension between two different liquids, zero for a liquid with itself and
/// liquids that never meet. A liquid `a` against a solid `S` (the surface force's walls) has
/// Young's `σ_aS = σ_S − σ_a cos θ_aS` up to the solid's own `σ_S`, which the surface force
/// does not need (docs/model.md §4b): `−σ_a cos θ_aS`, with the liquid's surface tension and
/// its contact angle on the solid (zero for a liquid without a surface tension: a gas), times
/// `contact_line_factor` [-], the surface force's calibration at walls
/// ([`crate::physics::surface_tension::surface_force::contact_line`]).
pub fn surface_stress_table(scene: &Scene, contact_line_factor: f64) -> Vec<f64> {
    let nl = scene.liquids.len();
    let n = nl + scene.solids.len();
    let mut sigma = vec![0.0; n * n];
    for a in 0..nl {
        for b in 0..nl {
            if a != b {
                let (na, nb) = (&scene.liquids[a].name, &scene.liquids[b].name);
                sigma[a * n + b] = scene.interface_tension(na, nb).unwrap_or(0.0);
            }
        }
        let liquid = &scene.liquids[a];
        for (k, solid) in scene.solids.iter().enumerate() {
            let young = match (
                liquid.surface_tension,
                solid.contact_angles.get(&liquid.name),
            ) {
                (Some(s), Some(theta_deg)) => {
                    -s * theta_deg.to_radians().cos() * contact_line_factor
                }
                _ => 0.0,
            };
            sigma[a * n + nl + k] = young;
            sigma[(nl + k) * n + a] = young;
        }
    }
    sigma
}

/// Viscosity of each pair of phases [Pa·s], row-major, from the per-phase viscosities `mu`
/// (liquids first, `n_liquids` of them): `2μ_aμ_b/(μ_a + μ_b)` for two liquids (Eq. 11,
/// Natsui 2021; 0 if both are inviscid), the liquid's `μ` against a solid, 0 between solids.
pub fn viscosity_table(mu: &[f64], n_liquids: usize) -> Vec<f64> {
    let n = mu.len();
    let mut mu_pair = vec![0.0; n * n];
    for a in 0..n {
        for b in a..n {
            let v = match (a < n_liquids, b < n_liquids) {
                (true, true) if mu[a] + mu[b] > 0.0 => 2.0 * mu[a] * mu[b] / (mu[a] + mu[b]),
                (true, true) => 0.0,
                (true, false) => mu[a],
                (false, true) => mu[b],
                (false, false) => 0.0,
            };
            mu_pair[a * n + b] = v;
            mu_pair[b * n + a] = v;
        }
    }
    mu_pair
}
