//! Early detection of a run going wrong, with a diagnosis.
//!
//! After every step the state is checked against the scene's [`crate::scene::Health`] bounds:
//! non-finite values, speed (Mach), compression, liquid inside a wall ([`crate::model::WallSolid`],
//! the rule the harness's invariants use too), and a collapsing adaptive step.
//! A run that fails stops with [`SimError::Unstable`]: the step, the particle (its scene index),
//! the quantity with its value, and the most likely cause with the value it would need.

use crate::error::SimError;
use crate::model::Model;
use crate::state::Particles;
use crate::timestep::StepLimits;
use rayon::prelude::*;

/// The worst particle for each check of one state.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Extremes {
    /// Largest `|v|²` [m²/s²] and its particle.
    pub speed2: (f64, usize),
    /// Largest `|a|²` [m²/s⁴] and its particle.
    pub acc2: (f64, usize),
    /// Largest `ρ/ρ0 − 1` [-] and its particle.
    pub compression: (f64, usize),
    /// First particle (lowest index) with a non-finite position, velocity, acceleration or
    /// density, if any.
    pub non_finite: Option<usize>,
}

/// A value with four significant digits, without an exponent between 1e-3 and 1e5.
fn g(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let mag = v.abs().log10().floor() as i32;
    if (-3..5).contains(&mag) {
        let decimals = (3 - mag).max(0) as usize;
        format!("{v:.decimals$}")
    } else {
        format!("{v:.3e}")
    }
}

fn max_by(a: (f64, usize), b: (f64, usize)) -> (f64, usize) {
    // ties keep the lower index: the result does not depend on the thread count
    if b.0 > a.0 || (b.0 == a.0 && b.1 < a.1) {
        b
    } else {
        a
    }
}

/// Scans the fluid particles (a parallel map-reduce of maxima: exact and order-independent).
pub(crate) fn extremes(p: &Particles, rho0: &[f64]) -> Extremes {
    (0..p.n_fluid)
        .into_par_iter()
        .map(|i| {
            let v2 = p.vel[i].norm_squared();
            let a2 = p.acc[i].norm_squared();
            let comp = p.rho[i] / rho0[p.phase[i] as usize] - 1.0;
            let finite = v2.is_finite()
                && a2.is_finite()
                && comp.is_finite()
                && p.pos[i].iter().all(|x| x.is_finite());
            Extremes {
                speed2: (if finite { v2 } else { 0.0 }, i),
                acc2: (if finite { a2 } else { 0.0 }, i),
                compression: (if finite { comp } else { f64::NEG_INFINITY }, i),
                non_finite: (!finite).then_some(i),
            }
        })
        .reduce(
            || Extremes {
                compression: (f64::NEG_INFINITY, usize::MAX),
                ..Default::default()
            },
            |a, b| Extremes {
                speed2: max_by(a.speed2, b.speed2),
                acc2: max_by(a.acc2, b.acc2),
                compression: max_by(a.compression, b.compression),
                non_finite: match (a.non_finite, b.non_finite) {
                    (Some(x), Some(y)) => Some(x.min(y)),
                    (x, y) => x.or(y),
                },
            },
        )
}

/// What a run knows when it checks its health.
pub(crate) struct Context<'a> {
    pub model: &'a Model,
    pub particles: &'a Particles,
    pub step: u64,
    pub time_s: f64,
    pub extremes: Extremes,
    /// Limits of the state just reached.
    pub limits: StepLimits,
    /// The step just taken [s], and the stable step of the initial state [s].
    pub dt_s: f64,
    pub first_dt_s: f64,
}

/// Checks a state; the first violated bound becomes the error.
pub(crate) fn check(c: &Context) -> Result<(), SimError> {
    let m = c.model;
    let p = c.particles;
    let h = &m.health;
    let fail = |i: usize, quantity: String, cause: String| SimError::Unstable {
        step: c.step,
        time_s: c.time_s,
        particle_id: p.id[i],
        quantity,
        cause,
    };
    let (stable, which) = c.limits.min();
    if let Some(i) = c.extremes.non_finite {
        let cause = match m.time.dt {
            Some(dt) if dt > stable => format!(
                "the fixed step time.dt = {dt:e} s exceeds the {which} limit {stable:e} s of the state reached; lower time.dt or omit it"
            ),
            _ => format!(
                "forces too large for the step {:e} s (now limited by the {which} constraint, {stable:e} s); check the time-step factors and the sound speed",
                c.dt_s
            ),
        };
        return Err(fail(
            i,
            format!(
                "non-finite state (x = {:?} m, v = {:?} m/s, a = {:?} m/s², ρ = {} kg/m³)",
                p.pos[i].as_slice(),
                p.vel[i].as_slice(),
                p.acc[i].as_slice(),
                p.rho[i]
            ),
            cause,
        ));
    }
    let (v2, iv) = c.extremes.speed2;
    let mach = v2.sqrt() / m.c_m_s;
    if mach > h.max_mach {
        return Err(fail(
            iv,
            format!("speed {} m/s = Mach {mach:.2} (health.max_mach = {})", g(v2.sqrt()), h.max_mach),
            format!(
                "the flow is too fast for the weakly compressible model at c = {} m/s: raise discretisation.sound_speed to at least 10 × the fastest speed, {} m/s",
                m.c_m_s,
                g(10.0 * v2.sqrt())
            ),
        ));
    }
    let (comp, ic) = c.extremes.compression;
    if comp > h.max_compression {
        let ph = p.phase[ic] as usize;
        let pressure = p.pressure[ic];
        return Err(fail(
            ic,
            format!(
                "compressed by {:.1} % (ρ = {} kg/m³, p = {} Pa; health.max_compression = {})",
                100.0 * comp,
                g(p.rho[ic]),
                g(pressure),
                h.max_compression
            ),
            format!(
                "the equation of state is too soft for the pressure here: 1 % compression at p = {} Pa needs c ≥ √(p/(0.01 ρ0)) = {} m/s (discretisation.sound_speed = {} m/s)",
                g(pressure),
                g((pressure.max(0.0) / (0.01 * m.rho0[ph])).sqrt()),
                m.c_m_s
            ),
        ));
    }
    if let Some((i, w)) = wall_entry(m, p, h.max_wall_depth_over_l0 * m.l0_m) {
        let x = p.pos[i];
        return Err(fail(
            i,
            format!(
                "liquid particle inside wall '{}' at ({:.4e}, {:.4e}, {:.4e}) m, more than {} l0 past its faces (health.max_wall_depth_over_l0 = {})",
                m.walls[w].name, x.x, x.y, x.z, h.max_wall_depth_over_l0, h.max_wall_depth_over_l0
            ),
            if m.effects.interfacial_tension {
                format!(
                    "the walls' pressure does not hold the liquid out of the gaps between wall particles: with a wide kernel (support {:.2} l0, h = {:.2} l0) the pressure gradient at the nearest-neighbour distance is weak, and the potential's cohesion pulls a wetting liquid in; use a kernel of support ≈ 2.1 l0 (wendland_c2 at h_over_l0 = 1.05, discretisation.setting = \"natsui2021\"), effects.wall_repulsion = true, or raise discretisation.sound_speed (now {} m/s); health.max_wall_depth_over_l0 = inf lets the run go on",
                    m.support_m / m.l0_m,
                    m.h_m / m.l0_m,
                    m.c_m_s
                )
            } else if m.effects.pressure_difference {
                "in the difference form of the pressure force a wall resists only the difference between its extrapolated pressure and the liquid particle's, and where a wall particle's liquid neighbours are less compressed than the particle it pulls the particle in (an impact's spreading edge; docs/model.md §3): take density.pressure_gradient = \"symmetric\" for a scene with impacts; health.max_wall_depth_over_l0 = inf lets the run go on".to_string()
            } else {
                format!(
                    "the walls' pressure does not hold the liquid out (kernel support {:.2} l0, h = {:.2} l0): raise discretisation.sound_speed (now {} m/s) so that the liquid is compressed less where it meets the wall; health.max_wall_depth_over_l0 = inf lets the run go on",
                    m.support_m / m.l0_m,
                    m.h_m / m.l0_m,
                    m.c_m_s
                )
            },
        ));
    }
    if m.time.dt.is_none() && c.first_dt_s > 0.0 && stable < h.min_dt_ratio * c.first_dt_s {
        let (a2, ia) = c.extremes.acc2;
        return Err(fail(
            ia,
            format!(
                "the time step collapsed to {:.3e} s, {:.1e} of the first step {:.3e} s ({which} limit; |a| = {:.3e} m/s²)",
                stable,
                stable / c.first_dt_s,
                c.first_dt_s,
                a2.sqrt()
            ),
            "a particle is being thrown by a force far beyond the others (typically two particles almost on top of each other after an impact too fast for the sound speed); raise discretisation.sound_speed or lower the time-step factors".into(),
        ));
    }
    if let Some(dt) = m.time.dt {
        // the limits carry safety factors (0.25 for CFL): twice the limit is past stability;
        // at step 0 the scene check (time.dt against the initial limits) speaks first
        if c.step > 0 && dt > 2.0 * stable {
            let (v2, iv) = c.extremes.speed2;
            return Err(fail(
                iv,
                format!("the fixed step time.dt = {dt:e} s is more than twice the {which} limit {stable:e} s of the state reached (|v|max = {:.3e} m/s)", v2.sqrt()),
                format!("the state has outgrown the fixed step: set time.dt ≤ {stable:e} s, or omit it for the adaptive step"),
            ));
        }
    }
    Ok(())
}

/// The first fluid particle (lowest index: the same for any thread count) inside a wall deeper
/// than `depth_m` [m], with the wall's index.
fn wall_entry(m: &Model, p: &Particles, depth_m: f64) -> Option<(usize, usize)> {
    if m.walls.is_empty() || !depth_m.is_finite() {
        return None;
    }
    (0..p.n_fluid).into_par_iter().find_map_first(|i| {
        let x = p.pos[i];
        m.walls
            .iter()
            .position(|w| w.holds([x.x, x.y, x.z], depth_m))
            .map(|w| (i, w))
    })
}
