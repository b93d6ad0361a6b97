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
    let periodic = scene.periodic.ranges();
    let mut claim = |idx: [i64; 3], owner: usize, p: [f64; 3]| -> Result<(), SceneError> {
        // a particle outside a periodic range would overlap one of its own images
        for (k, range) in periodic.iter().enumerate() {
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
                            "every particle must lie within the periodic range [{lo:e}, {hi:e})                              m along {}",
                            ["x", "y", "z"][k]
                        ),
                    ));
                }
            }
        }
        claims.push((idx, owner as u32));
        Ok(())
    };

    let mut fluid_pos = Vec::new();
    let mut fluid_vel = Vec::new();
    let mut fluid_phase = Vec::new();
    let mut inventory = Inventory::default();
    for (body_index, b) in scene.bodies.iter().enumerate() {
        let (lo, hi) = b.shape.bounds();
        let before = fluid_pos.len();
        let mut err = None;
        crate::scene::shapes_for_sites(lo, hi, l0, |idx, p| {
            if err.is_some() || !b.shape.contains(p) {
                return;
            }
            if let Err(e) = claim(idx, body_index, p) {
                err = Some(e);
                return;
            }
            let liquid = match (&b.liquid, &b.cut) {
                (Some(l), _) => l.as_str(),
                (None, Some(cut)) => cut.liquids[cut.side(p)].as_str(),
                (None, None) => unreachable!("validated"),
            };
            fluid_pos.push(Vec3::from(p));
            let wave = b.velocity_wave.as_ref().map_or([0.0; 3], |w| w.at(p));
            fluid_vel.push(Vec3::from(b.velocity) + Vec3::from(wave));
            fluid_phase.push(scene.liquid_index(liquid).expect("validated") as u8);
        });
        if let Some(e) = err {
            return Err(e);
        }
        let count = fluid_pos.len() - before;
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
        inventory.bodies.push((b.name.clone(), count));
    }

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
            if let Err(e) = claim(idx, scene.bodies.len() + wall_index, p) {
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

    check_overlaps(scene, &mut claims)?;
    drop(claims);

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
