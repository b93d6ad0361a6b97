//! Builds the initial particles of a scene: lattice sites inside each body and wall.

use crate::model::Model;
use crate::scene::{Scene, SceneError, WallBoundary};
use crate::state::{Particles, Vec3};

/// Fewest particles a body may have: below 2×2×2 a body cannot carry a surface with a kernel
/// that reaches two spacings.
pub const MIN_BODY_PARTICLES: usize = 8;

/// Where the particles of each body and wall went.
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize)]
pub struct Inventory {
    /// `(name, particle count)` of each liquid body, in scene order.
    pub bodies: Vec<(String, usize)>,
    /// `(name, particle count, layers)` of each wall, in scene order.
    pub walls: Vec<(String, usize, u32)>,
}

/// The initial particles (unsorted; the simulation sorts them), per-wall-particle no-slip
/// flags, and the inventory.
pub fn build_particles(
    scene: &Scene,
    model: &Model,
) -> Result<(Particles, Vec<bool>, Inventory), SceneError> {
    let l0 = scene.discretisation.l0;
    // every claimed lattice site with its owner (bodies, then walls); sorted afterwards, a
    // site claimed twice is an overlap — 28 bytes a site, freed when the check is done
    let mut claims: Vec<([i64; 3], u32)> = Vec::new();
    let mut fluid = FluidSites::default();
    let mut counts = vec![0; scene.bodies.len()];
    for (body_index, b) in scene.bodies.iter().enumerate() {
        if !b.shape.is_surrounding() {
            counts[body_index] = fill_body(scene, body_index, None, &mut claims, &mut fluid)?;
        }
    }
    let mut inventory = Inventory::default();
    let mut wall_pos = Vec::new();
    let mut wall_phase = Vec::new();
    let mut no_slip = Vec::new();
    for (wall_index, w) in scene.walls.iter().enumerate() {
        let layers = scene.wall_layers(w);
        let solid = model.n_liquids + scene.solid_index(&w.solid).expect("validated");
        let before = wall_pos.len();
        let mut err = None;
        w.shape.for_sites(l0, layers, |idx, p| {
            if err.is_some() {
                return;
            }
            if let Err(e) = claim_site(scene, &mut claims, idx, scene.bodies.len() + wall_index, p)
            {
                err = Some(e);
                return;
            }
            wall_pos.push(Vec3::from(p));
            wall_phase.push(solid as u8);
            no_slip.push(w.boundary == WallBoundary::NoSlip);
        });
        if let Some(e) = err {
            return Err(e);
        }
        inventory
            .walls
            .push((w.name.clone(), wall_pos.len() - before, layers));
    }

    // the surrounding bodies take the sites of their boxes that nothing else took
    if scene.bodies.iter().any(|b| b.shape.is_surrounding()) {
        let mut taken: Vec<[i64; 3]> = claims.iter().map(|c| c.0).collect();
        taken.sort_unstable();
        for (body_index, b) in scene.bodies.iter().enumerate() {
            if b.shape.is_surrounding() {
                counts[body_index] =
                    fill_body(scene, body_index, Some(&taken), &mut claims, &mut fluid)?;
            }
        }
    }
    check_overlaps(scene, &mut claims)?;
    drop(claims);
    for (b, count) in scene.bodies.iter().zip(counts) {
        inventory.bodies.push((b.name.clone(), count));
    }
    let FluidSites {
        pos: fluid_pos,
        vel: fluid_vel,
        phase: fluid_phase,
    } = fluid;

    let n_fluid = fluid_pos.len();
    let n = n_fluid + wall_pos.len();
    let mut pos = fluid_pos;
    pos.extend(wall_pos);
    let mut vel = fluid_vel;
    vel.resize(n, Vec3::zeros());
    let mut phase = fluid_phase;
    phase.extend(wall_phase);
    pos.shrink_to_fit();
    vel.shrink_to_fit();
    phase.shrink_to_fit();
    let rho: Vec<f64> = phase.iter().map(|&p| model.rho0[p as usize]).collect();
    // the continuity rate is state only with that scheme
    let continuity = scene.density.scheme == crate::scene::DensityScheme::Continuity;
    let particles = Particles {
        n_fluid,
        x_ref: pos[..n_fluid].to_vec(),
        pos,
        vel,
        acc: vec![Vec3::zeros(); n_fluid],
        vol: vec![model.rest_volume_m3; n],
        pressure: vec![0.0; n],
        rho,
        drho: if continuity {
            vec![0.0; n_fluid]
        } else {
            Vec::new()
        },
        phase,
        id: (0..n as u32).collect(),
    };
    Ok((particles, no_slip, inventory))
}

/// The fluid particles' sites, velocities [m/s] and phases, in the order they are built.
#[derive(Default)]
struct FluidSites {
    pos: Vec<Vec3>,
    vel: Vec<Vec3>,
    phase: Vec<u8>,
}

/// Records that `owner` (a body's index, or the bodies' count plus a wall's) takes the lattice
/// site `idx` at `p` [m]; refuses a site outside a periodic range, which would overlap one of
/// its own images.
fn claim_site(
    scene: &Scene,
    claims: &mut Vec<([i64; 3], u32)>,
    idx: [i64; 3],
    owner: usize,
    p: [f64; 3],
) -> Result<(), SceneError> {
    for (k, range) in scene.periodic.ranges().iter().enumerate() {
        if let Some([lo, hi]) = *range {
            if !(lo..hi).contains(&p[k]) {
                let name = match scene.bodies.get(owner) {
                    Some(b) => format!("body[{}]", b.name),
                    None => format!("wall[{}]", scene.walls[owner - scene.bodies.len()].name),
                };
                return Err(SceneError::invalid(
                    name,
                    format!("a particle at {:?} m", p),
                    format!(
                        "every particle must lie within the periodic range [{lo:e}, {hi:e}) \
                         m along {}",
                        ["x", "y", "z"][k]
                    ),
                ));
            }
        }
    }
    claims.push((idx, owner as u32));
    Ok(())
}

/// Fills body `body_index` with particles on the lattice sites inside its shape, less the
/// sites in `taken` (sorted; given for a surrounding body), and returns their count.
fn fill_body(
    scene: &Scene,
    body_index: usize,
    taken: Option<&[[i64; 3]]>,
    claims: &mut Vec<([i64; 3], u32)>,
    fluid: &mut FluidSites,
) -> Result<usize, SceneError> {
    let l0 = scene.discretisation.l0;
    let b = &scene.bodies[body_index];
    let (lo, hi) = b.shape.bounds();
    let before = fluid.pos.len();
    let mut err = None;
    crate::scene::shapes_for_sites(lo, hi, l0, |idx, p| {
        if err.is_some() || !b.shape.contains(p) {
            return;
        }
        if taken.is_some_and(|t| t.binary_search(&idx).is_ok()) {
            return;
        }
        if let Err(e) = claim_site(scene, claims, idx, body_index, p) {
            err = Some(e);
            return;
        }
        let liquid = match (&b.liquid, &b.cut) {
            (Some(l), _) => l.as_str(),
            (None, Some(cut)) => cut.liquids[cut.side(p)].as_str(),
            (None, None) => unreachable!("validated"),
        };
        fluid.pos.push(Vec3::from(p));
        let wave = b.velocity_wave.as_ref().map_or([0.0; 3], |w| w.at(p));
        fluid.vel.push(Vec3::from(b.velocity) + Vec3::from(wave));
        fluid
            .phase
            .push(scene.liquid_index(liquid).expect("validated") as u8);
    });
    if let Some(e) = err {
        return Err(e);
    }
    let count = fluid.pos.len() - before;
    if count < MIN_BODY_PARTICLES {
        return Err(SceneError::invalid(
            format!("body[{}].shape", b.name),
            format!("{count} particles"),
            format!(
                "a body needs at least {MIN_BODY_PARTICLES} particles at l0 = {l0:e} m; \
                 make it larger or l0 smaller"
            ),
        ));
    }
    Ok(count)
}

/// Refuses a lattice site claimed by two bodies or walls, naming both.
fn check_overlaps(scene: &Scene, claims: &mut [([i64; 3], u32)]) -> Result<(), SceneError> {
    claims.sort_unstable();
    let name = |k: u32| -> &str {
        let k = k as usize;
        if k < scene.bodies.len() {
            &scene.bodies[k].name
        } else {
            &scene.walls[k - scene.bodies.len()].name
        }
    };
    for w in claims.windows(2) {
        if w[0].0 == w[1].0 {
            let l0 = scene.discretisation.l0;
            let p = w[0].0.map(|i| (i as f64 + 0.5) * l0);
            let (a, b) = (w[0].1.min(w[1].1), w[0].1.max(w[1].1));
            let kind = if (b as usize) < scene.bodies.len() {
                "body"
            } else {
                "wall"
            };
            return Err(SceneError::invalid(
                format!("{kind}[{}]", name(b)),
                format!("overlaps '{}'", name(a)),
                format!(
                    "both claim the lattice site ({:e}, {:e}, {:e}) m; move or shrink one of them",
                    p[0], p[1], p[2]
                ),
            ));
        }
    }
    Ok(())
}
