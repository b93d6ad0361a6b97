//! The surface tension the relaxed particle liquid really has: a periodic slab, relaxed, its
//! tension measured from the pair-force virial (Kirkwood & Buff 1949).
//!
//! The potential's coefficient `C = 2σ l0²/S` is calibrated on the rigid reference lattice:
//! the energy of splitting it between two layers. A real surface relaxes — its layers move
//! apart or together, the bulk compresses under the cohesive pressure until the EOS balances
//! it — and the pressure force, absent from the lattice sum, carries stress there too. The
//! slab measures all of it: a liquid slab periodic along x and y with two free surfaces normal
//! to z, started on the lattice at rest, relaxes under the scene's own forces and viscosities,
//! its velocities damped as `dv/dt = −v/τ` (τ one sound crossing of the slab: the static
//! equilibrium does not depend on how the kinetic energy left); over the last part of the run
//! the mechanical surface tension is averaged: `σ_KB = Σ_i (a_i − a_b) / (2A)`, `a_i =
//! W_i,zz − (W_i,xx + W_i,yy)/2` the anisotropy of particle `i`'s share of the virial
//! ([`crate::observables::particle_virials`]), `a_b` its mean over the slab's middle third and
//! `A` the slab's cross-section. For a liquid `a_b = 0` and this is Kirkwood–Buff's
//! `∫ (p_N − p_T) dz` over both surfaces. The particle lattice is not quite a liquid: the
//! period fixes the slab's lateral spacing while the cohesive pressure compresses its bulk,
//! which then carries an anisotropic elastic stress (thickness × `a_b`/volume); subtracting
//! `a_b` per particle leaves the surfaces' excess (the dividing surface counts particles).
//!
//! With `discretisation.tension_calibration = "relaxed_slab"` a run scales each liquid's
//! coefficients until its slab has the typed σ, then each pair of liquids' coefficient until a
//! two-liquid slab (one layer on the other: two free surfaces and the interface) has the
//! typed σ_ab ([`tension_scales`]); the factors are computed once per process for a given
//! scene (cached in memory). Then each liquid–solid pair's coefficient is scaled until the
//! liquid's slab resting on a plate of the solid has the scene's work of adhesion
//! `σ (1 + cos θ)`, counted as the liquid–wall pair energy per area at the gap and registry
//! the relaxed liquid takes (the lattice calibration assumes the liquid's first layer one
//! spacing above the wall's).

use super::Simulation;
use crate::error::SimError;
use crate::observables::particle_virials;
use crate::scene::{Body, BodyShape, PeriodicAxes, Scene, SceneError, TensionCalibration};
use crate::with_kernel;
use std::sync::Mutex;

/// The slab's design, in spacings `l0` and sound crossings of its thickness.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SlabDesign {
    /// Thickness over the spacing `l0` [-]: two surface zones of a few `r_e` each and a bulk
    /// between them. Measured (matte, l0 = 37 µm, c² = 150 m²/s², Wendland C2,
    /// h = 1.05 l0, r_e = 2.1 l0): σ_KB/σ = 1.152,
    /// 1.037, 1.015, 0.996, 1.003 at 13, 19, 26, 40, 60 l0 — 40 is within 0.5 % of 60.
    pub thickness_over_l0: f64,
    /// Run length in sound crossings of the thickness `T/c` [-].
    pub crossings: f64,
    /// The averaged part: the last this many crossings [-].
    pub averaged_crossings: f64,
    /// The damping time `τ` of the velocities, in crossings [-].
    pub damping_crossings: f64,
}

impl Default for SlabDesign {
    fn default() -> Self {
        SlabDesign {
            thickness_over_l0: 40.0,
            crossings: 32.0,
            averaged_crossings: 8.0,
            damping_crossings: 1.0,
        }
    }
}

/// The measured tension of one liquid's slab.
#[derive(Clone, Debug, PartialEq)]
pub struct SlabTension {
    /// The liquid.
    pub liquid: String,
    /// The surface tension the scene gives [N/m].
    pub sigma_typed_n_m: f64,
    /// The mechanical surface tension of the relaxed slab [N/m].
    pub sigma_measured_n_m: f64,
    /// The standard error of the time average [N/m] (from the spread of block means). It does
    /// not hold the spread between slabs that differ slightly: a floppy setting settles into
    /// different surface structures (measured: 7 % for a 0.04 % change of C, quintic spline,
    /// r_e = 4.4 l0, order 2).
    pub sigma_standard_error_n_m: f64,
    /// The slab's particles.
    pub particles: usize,
    /// Steps taken.
    pub steps: u64,
    /// Mean density of the middle third over `ρ0`, at the end [-].
    pub bulk_density_ratio: f64,
}

/// The slab scene of liquid `liquid` (index into `scene.liquids`): the scene's discretisation,
/// density control, viscosities and tension, no gravity and no walls; periodic along x and y
/// with the shortest period the neighbour search allows.
pub fn slab_scene(scene: &Scene, liquid: usize, design: SlabDesign) -> Result<Scene, SceneError> {
    let l0 = scene.discretisation.l0;
    let skin = scene.discretisation.neighbour_skin_over_l0 * l0;
    let cut = scene.kernel_support().max(scene.r_e()) + skin;
    let n_side = (2.0 * cut / l0 - 1e-9).ceil().max(1.0);
    let n_thick = design.thickness_over_l0.ceil().max(n_side);
    let (side, thick) = (n_side * l0, n_thick * l0);
    let l = scene.liquids.get(liquid).ok_or_else(|| {
        SceneError::invalid("liquid", liquid, "no liquid of this index in the scene")
    })?;
    let mut s = scene.clone();
    s.description = format!("relaxed slab of {} (tension calibration)", l.name);
    s.liquids = vec![l.clone()];
    s.discretisation.tension_calibration = TensionCalibration::Lattice;
    s.solids.clear();
    s.interfaces.clear();
    s.walls.clear();
    s.effects.gravity = None;
    s.effects.wall_repulsion = false;
    s.bodies = vec![Body {
        name: "slab".into(),
        liquid: Some(l.name.clone()),
        shape: BodyShape::Box {
            min: [0.0; 3],
            max: [side, side, thick],
        },
        cut: None,
        velocity: [0.0; 3],
        velocity_wave: None,
    }];
    s.periodic = PeriodicAxes {
        x: Some([0.0, side]),
        y: Some([0.0, side]),
        z: None,
    };
    s.time.end = design.crossings * thick / scene.discretisation.sound_speed;
    s.time.output_interval = s.time.end;
    s.time.dt = None;
    s.validate()?;
    Ok(s)
}

/// Relaxes the slab of liquid `liquid` with the lattice's coefficients times `scale` and
/// measures its tension.
pub fn slab_tension(
    scene: &Scene,
    liquid: usize,
    design: SlabDesign,
    scale: f64,
) -> Result<SlabTension, SimError> {
    let slab = slab_scene(scene, liquid, design)?;
    let r = relax(&slab, design, |m| {
        if scale != 1.0 {
            m.scale_tension(&[scale]);
        }
    })?;
    Ok(SlabTension {
        liquid: slab.liquids[0].name.clone(),
        sigma_typed_n_m: slab.liquids[0].surface_tension.unwrap_or(0.0),
        // two free surfaces
        sigma_measured_n_m: 0.5 * r.excess_n_m,
        sigma_standard_error_n_m: 0.5 * r.excess_standard_error_n_m,
        particles: r.particles,
        steps: r.steps,
        bulk_density_ratio: r.bulk_density_ratio[0],
    })
}

/// The two-liquid slab of liquids `a` and `b` (indices into `scene.liquids`): `a`'s layer
/// below `b`'s, each as thick as a one-liquid slab, so the slab has a free surface of each and
/// the interface between them; otherwise as [`slab_scene`], its run as many crossings of the
/// whole thickness.
pub fn pair_slab_scene(
    scene: &Scene,
    a: usize,
    b: usize,
    design: SlabDesign,
) -> Result<Scene, SceneError> {
    let mut s = slab_scene(scene, a, design)?;
    let lb = scene
        .liquids
        .get(b)
        .ok_or_else(|| SceneError::invalid("liquid", b, "no liquid of this index in the scene"))?;
    if a == b {
        return Err(SceneError::invalid("liquid", b, "a pair of two liquids"));
    }
    let BodyShape::Box { min, max } = s.bodies[0].shape.clone() else {
        unreachable!("the slab is a box")
    };
    let thick = max[2] - min[2];
    s.description = format!(
        "relaxed slab of {} under {} (tension calibration)",
        scene.liquids[a].name, lb.name
    );
    s.liquids.push(lb.clone());
    s.interfaces = scene
        .interfaces
        .iter()
        .filter(|i| {
            let has = |n: &str| i.liquids.iter().any(|l| l == n);
            has(&scene.liquids[a].name) && has(&lb.name)
        })
        .cloned()
        .collect();
    s.bodies[0].name = "lower".into();
    let mut upper = s.bodies[0].clone();
    upper.name = "upper".into();
    upper.liquid = Some(lb.name.clone());
    upper.shape = BodyShape::Box {
        min: [min[0], min[1], max[2]],
        max: [max[0], max[1], max[2] + thick],
    };
    s.bodies.push(upper);
    s.time.end = design.crossings * 2.0 * thick / scene.discretisation.sound_speed;
    s.time.output_interval = s.time.end;
    s.validate()?;
    Ok(s)
}

/// The measured interfacial tension of a two-liquid slab.
#[derive(Clone, Debug, PartialEq)]
pub struct PairSlabTension {
    /// The two liquids (lower, upper).
    pub liquids: [String; 2],
    /// The interfacial tension the scene gives, `σ_a + σ_b − 2σ_pair` [N/m].
    pub sigma_typed_n_m: f64,
    /// The relaxed slab's interfacial tension [N/m]: its total surface excess less the two
    /// free surfaces' tensions given.
    pub sigma_measured_n_m: f64,
    /// The standard error of the slab's time average [N/m] (the free surfaces' own errors
    /// not included).
    pub sigma_standard_error_n_m: f64,
    /// The slab's particles.
    pub particles: usize,
    /// Steps taken.
    pub steps: u64,
}

/// Relaxes the two-liquid slab of liquids `a` (below) and `b` with the liquids' coefficients
/// scaled by `liquid_scales` (`f_a`, `f_b`), the pair's by `pair_scale` on top of `√(f_a f_b)`,
/// and measures the interfacial tension: the slab's total excess less `free_surfaces_n_m`,
/// the two liquids' own surface tensions at those factors [N/m] (their one-liquid slabs').
pub fn pair_slab_tension(
    scene: &Scene,
    (a, b): (usize, usize),
    design: SlabDesign,
    liquid_scales: [f64; 2],
    pair_scale: f64,
    free_surfaces_n_m: [f64; 2],
) -> Result<PairSlabTension, SimError> {
    let slab = pair_slab_scene(scene, a, b, design)?;
    let typed = typed_pair(&slab, 0, 1)?.1;
    let r = relax(&slab, design, |m| {
        m.scale_tension(&liquid_scales);
        if pair_scale != 1.0 {
            m.scale_pair_tension(0, 1, pair_scale);
        }
    })?;
    Ok(PairSlabTension {
        liquids: [slab.liquids[0].name.clone(), slab.liquids[1].name.clone()],
        sigma_typed_n_m: typed,
        sigma_measured_n_m: r.excess_n_m - free_surfaces_n_m[0] - free_surfaces_n_m[1],
        sigma_standard_error_n_m: r.excess_standard_error_n_m,
        particles: r.particles,
        steps: r.steps,
    })
}

/// The typed `σ_a + σ_b` and interfacial tension `σ_ab = σ_a + σ_b − 2σ_pair(a, b)` of liquids
/// `a`, `b` of `scene` as its pair table has them [N/m] (Eq. (18), Natsui 2021).
fn typed_pair(scene: &Scene, a: usize, b: usize) -> Result<(f64, f64), SimError> {
    let m = crate::model::Model::from_scene(scene)?;
    let surfaces = m.pairs.sigma(a, a) + m.pairs.sigma(b, b);
    Ok((surfaces, surfaces - 2.0 * m.pairs.sigma(a, b)))
}

/// The slab of liquid `liquid` resting on a plate of solid `solid` (index into
/// `scene.solids`): a one-liquid slab whose lower face touches the plate's top at the lattice's
/// spacing, the plate spanning the period (so the wall too repeats along x and y), laid as
/// thick as the scene's walls are (the kernel support and `r_e`).
pub fn wall_slab_scene(
    scene: &Scene,
    liquid: usize,
    solid: usize,
    design: SlabDesign,
) -> Result<Scene, SceneError> {
    let mut s = slab_scene(scene, liquid, design)?;
    let sol = scene.solids.get(solid).ok_or_else(|| {
        SceneError::invalid("solid", solid, "no solid of this index in the scene")
    })?;
    let (x, y) = (
        s.periodic.x.unwrap_or_default(),
        s.periodic.y.unwrap_or_default(),
    );
    s.description = format!(
        "relaxed slab of {} on {} (tension calibration)",
        scene.liquids[liquid].name, sol.name
    );
    let mut sol = sol.clone();
    // the slab has this one liquid
    let name = &scene.liquids[liquid].name;
    sol.contact_angles.retain(|l, _| l == name);
    s.solids = vec![sol.clone()];
    s.walls = vec![crate::scene::Wall {
        name: "plate".into(),
        solid: sol.name.clone(),
        shape: crate::scene::WallShape::Plate {
            min: [x[0], y[0]],
            max: [x[1], y[1]],
            top: 0.0,
        },
        layers: None,
        boundary: Default::default(),
    }];
    s.effects.wall_repulsion = scene.effects.wall_repulsion;
    s.validate()?;
    Ok(s)
}

/// The work of adhesion of a liquid on a solid as the relaxed particle liquid has it.
#[derive(Clone, Debug, PartialEq)]
pub struct WallAdhesion {
    /// The liquid and the solid.
    pub pair: [String; 2],
    /// The work of adhesion the scene gives, `2σ_pair = σ (1 + cos θ)` [N/m].
    pub typed_n_m: f64,
    /// The relaxed slab's: its liquid–wall pair energy per area, `Σ C P(r) / A` [N/m].
    pub measured_n_m: f64,
    /// The standard error of the time average [N/m].
    pub standard_error_n_m: f64,
    /// Mean height of the liquid's first layer above the plate's top wall plane, over `l0`
    /// [-] (the lattice calibration assumes 1), at the end.
    pub first_layer_gap_over_l0: f64,
    /// The slab's particles.
    pub particles: usize,
}

/// Relaxes liquid `liquid`'s slab on solid `solid` with the liquid's coefficients scaled by
/// `liquid_scale` and the liquid–solid coefficient by `pair_scale` on top, and measures the
/// work of adhesion: the liquid–wall pair energy per cross-section. Like the lattice's
/// calibration (the energy of the pairs across a plane), it counts the pairs' energy, now at
/// the gap and registry the liquid really takes; the liquid's own restructuring between
/// contact and separation is left out.
pub fn wall_adhesion(
    scene: &Scene,
    (liquid, solid): (usize, usize),
    design: SlabDesign,
    liquid_scale: f64,
    pair_scale: f64,
) -> Result<WallAdhesion, SimError> {
    let slab = wall_slab_scene(scene, liquid, solid, design)?;
    let m0 = crate::model::Model::from_scene(&slab)?;
    let typed = 2.0 * m0.pairs.sigma(0, 1);
    let r = relax_measuring(
        &slab,
        design,
        |m| {
            m.scale_tension(&[liquid_scale]);
            if pair_scale != 1.0 {
                m.scale_pair_tension(0, 1, pair_scale);
            }
        },
        |sim| {
            let (m, p) = (&sim.model, &sim.particles);
            let r_e = m.r_e_m;
            let c = m.pairs.c(0, 1);
            let mut e = 0.0;
            for i in 0..p.n_fluid {
                for j in sim.search.lists.all(i) {
                    if j < p.n_fluid {
                        continue;
                    }
                    let r = sim.search.lists.delta(p.pos[i], p.pos[j]).norm();
                    if r < r_e {
                        e += c * m.potential.p(r); // Eq. (15), Natsui 2021 (its energy)
                    }
                }
            }
            e
        },
    )?;
    Ok(WallAdhesion {
        pair: [slab.liquids[0].name.clone(), slab.solids[0].name.clone()],
        typed_n_m: typed,
        measured_n_m: r.excess_n_m,
        standard_error_n_m: r.excess_standard_error_n_m,
        first_layer_gap_over_l0: r.first_layer_gap_over_l0,
        particles: r.particles,
    })
}

/// What a relaxed slab gives.
struct Relaxed {
    /// The surfaces' excess of the virial's anisotropy per cross-section area, time-averaged
    /// [N/m]: the sum of the tensions of every surface and interface of the slab.
    excess_n_m: f64,
    /// Its standard error [N/m].
    excess_standard_error_n_m: f64,
    particles: usize,
    steps: u64,
    /// Per liquid of the slab, the mean density of the middle third of its layer over `ρ0`.
    bulk_density_ratio: Vec<f64>,
    /// With a wall: the mean height of the liquid particles within 1.5 l0 of the top wall
    /// plane above it, over `l0` [-]; NaN without.
    first_layer_gap_over_l0: f64,
}

/// Relaxes a slab scene (periodic along x and y; layers along z) with its model changed by
/// `adjust` and averages its surface excess ([`surface_excess`]) over the design's last
/// crossings.
fn relax(
    slab: &Scene,
    design: SlabDesign,
    adjust: impl FnOnce(&mut crate::model::Model),
) -> Result<Relaxed, SimError> {
    relax_measuring(slab, design, adjust, |sim| {
        let w = with_kernel!(sim.model.kernel, K => particle_virials::<K>(
            &sim.model,
            &sim.particles,
            &sim.search.lists
        ));
        let p = &sim.particles;
        surface_excess(&w, &p.pos[..w.len()], &p.phase[..w.len()])
    })
}

/// [`relax`] with another measurement: `measure` [J] over the cross-section, time-averaged.
fn relax_measuring(
    slab: &Scene,
    design: SlabDesign,
    adjust: impl FnOnce(&mut crate::model::Model),
    measure: impl Fn(&Simulation) -> f64,
) -> Result<Relaxed, SimError> {
    let mut sim = Simulation::new(slab)?;
    let before = sim.model.pairs.clone();
    adjust(&mut sim.model);
    if sim.model.pairs != before {
        with_kernel!(sim.model.kernel, K => sim.evaluate::<K>());
    }
    let end = slab.time.end;
    let (x, y) = (
        slab.periodic.x.unwrap_or_default(),
        slab.periodic.y.unwrap_or_default(),
    );
    let area = (x[1] - x[0]) * (y[1] - y[0]);
    let crossing = end / design.crossings;
    let tau = design.damping_crossings * crossing;
    let start = end - design.averaged_crossings * crossing;
    // time-weighted means of the excess over 8 blocks of the averaged part
    const BLOCKS: usize = 8;
    let mut block_sum = [0.0; BLOCKS];
    let mut block_time = [0.0; BLOCKS];
    while sim.time_s < end {
        let dt = sim.step(end - sim.time_s)?;
        let keep = (-dt / tau).exp();
        for v in &mut sim.particles.vel[..sim.particles.n_fluid] {
            *v *= keep;
        }
        if sim.time_s > start {
            let excess = measure(&sim) / area;
            let b =
                (((sim.time_s - start) / (end - start) * BLOCKS as f64) as usize).min(BLOCKS - 1);
            block_sum[b] += excess * dt;
            block_time[b] += dt;
        }
    }
    let means: Vec<f64> = (0..BLOCKS)
        .filter(|&b| block_time[b] > 0.0)
        .map(|b| block_sum[b] / block_time[b])
        .collect();
    let n = means.len() as f64;
    let mean = means.iter().sum::<f64>() / n;
    let var = means.iter().map(|m| (m - mean).powi(2)).sum::<f64>() / (n - 1.0).max(1.0);
    let p = &sim.particles;
    let bulk_density_ratio = (0..slab.liquids.len())
        .map(|a| {
            let idx: Vec<usize> = (0..p.n_fluid)
                .filter(|&i| p.phase[i] as usize == a)
                .collect();
            let (lo, hi) = middle_third(idx.iter().map(|&i| p.pos[i].z));
            let middle: Vec<f64> = idx
                .iter()
                .filter(|&&i| p.pos[i].z > lo && p.pos[i].z < hi)
                .map(|&i| p.rho[i])
                .collect();
            middle.iter().sum::<f64>() / middle.len().max(1) as f64 / sim.model.rho0[a]
        })
        .collect();
    let l0 = slab.discretisation.l0;
    let wall_top = p.pos[p.n_fluid..]
        .iter()
        .map(|x| x.z)
        .fold(f64::NEG_INFINITY, f64::max);
    let first: Vec<f64> = p.pos[..p.n_fluid]
        .iter()
        .map(|x| x.z - wall_top)
        .filter(|&d| d < 1.5 * l0)
        .collect();
    let first_layer_gap_over_l0 = if first.is_empty() {
        f64::NAN
    } else {
        first.iter().sum::<f64>() / first.len() as f64 / l0
    };
    Ok(Relaxed {
        first_layer_gap_over_l0,
        excess_n_m: mean,
        excess_standard_error_n_m: (var / n).sqrt(),
        particles: p.n_fluid,
        steps: sim.step,
        bulk_density_ratio,
    })
}

/// `Σ_i (a_i − a_b)` [J] over the particles with virial shares `w`, positions `pos` and
/// phases `phase`: `a_i = w_zz − (w_xx + w_yy)/2`, `a_b` the mean of `a` over the middle third
/// of particle `i`'s phase's extent along z (its layer's bulk).
fn surface_excess(w: &[[f64; 9]], pos: &[crate::state::Vec3], phase: &[u8]) -> f64 {
    let aniso = |w: &[f64; 9]| w[8] - 0.5 * (w[0] + w[4]);
    let n_phases = phase.iter().map(|&p| p as usize + 1).max().unwrap_or(0);
    let mut total = 0.0;
    for a in 0..n_phases {
        let mine = || (0..w.len()).filter(move |&i| phase[i] as usize == a);
        let (lo, hi) = middle_third(mine().map(|i| pos[i].z));
        let (mut sum, mut bulk, mut n_bulk, mut n) = (0.0, 0.0, 0usize, 0usize);
        for i in mine() {
            let v = aniso(&w[i]);
            sum += v;
            n += 1;
            if pos[i].z > lo && pos[i].z < hi {
                bulk += v;
                n_bulk += 1;
            }
        }
        total += sum - n as f64 * bulk / n_bulk.max(1) as f64;
    }
    total
}

/// The bounds [m] of the middle third of the extent of the heights `z` [m].
fn middle_third(z: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = z.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), z| {
        (a.min(z), b.max(z))
    });
    let third = (hi - lo) / 3.0;
    (lo + third, hi - third)
}

/// The relaxed calibration's factors of a scene: per liquid, and per pair of liquids on top of
/// `√(f_a f_b)`.
#[derive(Clone, Debug, PartialEq)]
pub struct TensionScales {
    /// Per liquid, the factor of its coefficients (1 for a liquid without surface tension).
    pub liquids: Vec<f64>,
    /// Per pair of phases `(a, b, f)`, `a < b`, with a non-zero pair strength: for two liquids
    /// the factor of `C_ab` beyond `√(f_a f_b)` that gives the two-liquid slab the scene's
    /// `σ_ab`; for a liquid `a` and a solid `b` (phase index: liquids first) used by a wall,
    /// the factor beyond `f_a` that gives the liquid's slab on the solid the scene's work of
    /// adhesion.
    pub pairs: Vec<(usize, usize, f64)>,
}

/// The factors of `scene`'s liquids ([`calibrate_liquid`]), then of its pairs of liquids
/// ([`calibrate_pair`]) and of its liquids on the solids of its walls ([`calibrate_wall`]),
/// with the liquids' factors applied. Cached per scene and design for the
/// life of the process.
pub fn tension_scales(scene: &Scene, design: SlabDesign) -> Result<TensionScales, SimError> {
    static CACHE: Mutex<Vec<(String, TensionScales)>> = Mutex::new(Vec::new());
    let mut key_scene = scene.clone();
    // what the slabs do not depend on
    key_scene.bodies.clear();
    key_scene.walls.clear();
    key_scene.description.clear();
    key_scene.time.end = 0.0;
    key_scene.time.output_interval = 0.0;
    let key = format!("{key_scene:?} {design:?}");
    if let Some((_, f)) = CACHE.lock().expect("cache").iter().find(|(k, _)| *k == key) {
        return Ok(f.clone());
    }
    let n = scene.liquids.len();
    let mut liquids = vec![1.0; n];
    let mut surfaces = vec![0.0; n];
    for (a, l) in scene.liquids.iter().enumerate() {
        let sigma = l.surface_tension.unwrap_or(0.0);
        if sigma > 0.0 {
            (liquids[a], surfaces[a]) = calibrate_liquid(scene, a, design, sigma)?;
        }
    }
    let table = crate::model::Model::from_scene(scene)?.pairs;
    let mut pairs = Vec::new();
    for a in 0..n {
        for b in a + 1..n {
            if table.sigma(a, b) > 0.0 && surfaces[a] > 0.0 && surfaces[b] > 0.0 {
                let f = calibrate_pair(
                    scene,
                    (a, b),
                    design,
                    [liquids[a], liquids[b]],
                    [surfaces[a], surfaces[b]],
                )?;
                pairs.push((a, b, f));
            }
        }
    }
    for (sol_idx, sol) in scene.solids.iter().enumerate() {
        if !scene.walls.iter().any(|w| w.solid == sol.name) {
            continue; // no wall of it: nothing touches it
        }
        let phase = n + sol_idx;
        for a in 0..n {
            if table.sigma(a, phase) > 0.0 && surfaces[a] > 0.0 {
                let f = calibrate_wall(scene, (a, sol_idx), design, liquids[a])?;
                pairs.push((a, phase, f));
            }
        }
    }
    let scales = TensionScales { liquids, pairs };
    CACHE.lock().expect("cache").push((key, scales.clone()));
    Ok(scales)
}

/// How close the calibrated slab's tension comes to the typed one [-]: 0.5 %, a few times the
/// measurement's standard error at settled settings (0.1–0.3 %), well below what a check can
/// resolve (a period within 3 % needs σ within 6 %).
pub const CALIBRATION_TOLERANCE: f64 = 0.005;

/// Slabs a calibration may relax before it gives up.
const MAX_SLABS: usize = 5;

/// The factor `f` of liquid `a`'s coefficients whose relaxed slab has the typed tension
/// `sigma` [N/m] within [`CALIBRATION_TOLERANCE`] (or within twice the slab's standard error,
/// when the slab is noisier than that). The response is not linear in `C` (the
/// bulk's compression, and the surface sums with it, follow `C`): from `f0 = 1` and
/// `f1 = σ/σ_KB(1)` on, each step fits `σ_KB ∝ f^α` through the last two slabs and sets
/// `f ← f (σ/σ_KB(f))^(1/α)` (a secant step in the logarithms). Refused, with the residual, if
/// [`MAX_SLABS`] slabs do not get there. Returns the factor and the accepted slab's tension
/// [N/m].
pub fn calibrate_liquid(
    scene: &Scene,
    a: usize,
    design: SlabDesign,
    sigma: f64,
) -> Result<(f64, f64), SimError> {
    let found = scale_in_logs(sigma, CALIBRATION_TOLERANCE * sigma, |f| {
        positive_slab_tension(scene, a, design, f)
    })?;
    found.map_err(|(f, s)| {
        SceneError::invalid(
            "discretisation.tension_calibration",
            "relaxed_slab",
            format!(
                "the relaxed slab of {} did not reach the typed σ = {sigma} N/m within {} % in \
                 {MAX_SLABS} slabs (last: {s:e} N/m at f = {f}): use the lattice calibration",
                scene.liquids[a].name,
                CALIBRATION_TOLERANCE * 100.0
            ),
        )
        .into()
    })
}

/// The factor `f` at which `measure(f) = (value, standard error)` is `target` within
/// `tolerance` or twice its standard error (a noisier measurement cannot tell a closer factor
/// apart), for a positive measure growing with `f`: from `f0 = 1` and `f1 = target/value(1)`
/// on, each step fits `value ∝ f^α` through the last two and sets `f ← f (target/value)^(1/α)`
/// (a secant step in the logarithms). `Ok(Ok((f, value)))` when found; `Ok(Err((f, value)))`,
/// the last tried, after [`MAX_SLABS`] measurements.
#[allow(clippy::type_complexity)]
fn scale_in_logs(
    target: f64,
    tolerance: f64,
    mut measure: impl FnMut(f64) -> Result<(f64, f64), SimError>,
) -> Result<Result<(f64, f64), (f64, f64)>, SimError> {
    let close = |(s, se): (f64, f64)| (s - target).abs() < tolerance.max(2.0 * se);
    let first = measure(1.0)?;
    if close(first) {
        return Ok(Ok((1.0, first.0)));
    }
    let (mut f_prev, mut s_prev) = (1.0, first.0);
    let mut f = target / s_prev;
    for _ in 1..MAX_SLABS {
        let m = measure(f)?;
        if close(m) {
            return Ok(Ok((f, m.0)));
        }
        let s = m.0;
        let alpha = if (f / f_prev - 1.0).abs() > 1e-6 {
            ((s / s_prev).ln() / (f / f_prev).ln()).clamp(0.2, 5.0)
        } else {
            1.0
        };
        (f_prev, s_prev) = (f, s);
        f *= (target / s).powf(1.0 / alpha);
    }
    Ok(Err((f_prev, s_prev)))
}

/// The factor of the coefficient of liquid `liquid` on solid `solid` (on top of the liquid's
/// factor `liquid_scale`) whose slab on a plate of the solid has the scene's work of adhesion
/// `σ (1 + cos θ)` within [`CALIBRATION_TOLERANCE`] of it ([`wall_adhesion`]; the same secant
/// steps as [`calibrate_liquid`]). Refused, with the residual, after [`MAX_SLABS`] slabs.
pub fn calibrate_wall(
    scene: &Scene,
    (liquid, solid): (usize, usize),
    design: SlabDesign,
    liquid_scale: f64,
) -> Result<f64, SimError> {
    let first = wall_adhesion(scene, (liquid, solid), design, liquid_scale, 1.0)?;
    let target = first.typed_n_m;
    let mut cached = Some(first);
    let found = scale_in_logs(target, CALIBRATION_TOLERANCE * target, |f| {
        let m = match cached.take() {
            Some(m) if f == 1.0 => m,
            _ => wall_adhesion(scene, (liquid, solid), design, liquid_scale, f)?,
        };
        if m.measured_n_m.is_nan() || m.measured_n_m <= 0.0 {
            return Err(SceneError::invalid(
                "discretisation.tension_calibration",
                "relaxed_slab",
                format!(
                    "the relaxed slab of {} on {} has no adhesion ({:e} N/m)",
                    m.pair[0], m.pair[1], m.measured_n_m
                ),
            )
            .into());
        }
        Ok((m.measured_n_m, m.standard_error_n_m))
    })?;
    found.map(|(f, _)| f).map_err(|(f, w)| {
        SceneError::invalid(
            "discretisation.tension_calibration",
            "relaxed_slab",
            format!(
                "the relaxed slab of {} on {} did not reach the work of adhesion {target} N/m \
                 within {} % in {MAX_SLABS} slabs (last: {w:e} N/m at f = {f}): use the \
                 lattice calibration",
                scene.liquids[liquid].name,
                scene.solids[solid].name,
                CALIBRATION_TOLERANCE * 100.0
            ),
        )
        .into()
    })
}

/// The factor `g` of the coefficient `C_ab` (on top of `√(f_a f_b)`, the liquids' factors
/// `liquid_scales` applied) whose two-liquid slab has the scene's interfacial tension within
/// [`CALIBRATION_TOLERANCE`] of `σ_a + σ_b` (the scale of the sums it is the difference of:
/// an interfacial tension much smaller than the surface tensions cannot be resolved more
/// finely than theirs), or within twice the slab's standard error. `free_surfaces_n_m` are
/// the liquids' slab tensions at their factors [N/m]. `σ_ab` falls as `C_ab` grows: from
/// `g0 = 1`, the first step with the lattice's slope `dσ_ab/dg = −2σ_pair`, then secant steps
/// (the lattice's slope again where a noisy slab gives no falling secant). Refused, with the
/// residual, after [`MAX_SLABS`] slabs.
pub fn calibrate_pair(
    scene: &Scene,
    (a, b): (usize, usize),
    design: SlabDesign,
    liquid_scales: [f64; 2],
    free_surfaces_n_m: [f64; 2],
) -> Result<f64, SimError> {
    let measure =
        |g: f64| pair_slab_tension(scene, (a, b), design, liquid_scales, g, free_surfaces_n_m);
    let first = measure(1.0)?;
    let target = first.sigma_typed_n_m;
    let sum = free_surfaces_n_m[0] + free_surfaces_n_m[1];
    let close = |m: &PairSlabTension| {
        (m.sigma_measured_n_m - target).abs()
            < (CALIBRATION_TOLERANCE * sum).max(2.0 * m.sigma_standard_error_n_m)
    };
    if close(&first) {
        return Ok(1.0);
    }
    let (mut g_prev, mut s_prev) = (1.0, first.sigma_measured_n_m);
    // the first step from the lattice's slope: on the lattice σ_ab = σ_a + σ_b − 2σ_pair g, so
    // dσ_ab/dg = −2σ_pair = −(σ_a + σ_b − σ_ab) of the typed values
    let slope0 = -(typed_pair(scene, a, b)?.0 - target);
    let mut g = 1.0 + (target - s_prev) / slope0;
    let mut slabs = 1;
    while slabs < MAX_SLABS {
        if !(g.is_finite() && g > 0.0) {
            break; // no positive factor on this course
        }
        let m = measure(g)?;
        slabs += 1;
        if close(&m) {
            return Ok(g);
        }
        let s = m.sigma_measured_n_m;
        let slope = (s - s_prev) / (g - g_prev);
        (g_prev, s_prev) = (g, s);
        // not falling (a noisy slab): the lattice's slope instead of the secant
        g += (target - s) / if slope < 0.0 { slope } else { slope0 };
    }
    Err(SceneError::invalid(
        "discretisation.tension_calibration",
        "relaxed_slab",
        format!(
            "the relaxed slab of {} under {} did not reach the interfacial tension {target} \
             N/m within {} % of σ_a + σ_b in {slabs} slab(s) (last: {s_prev:e} N/m at a \
             pair factor {g_prev}; next step {g}): use the lattice calibration",
            scene.liquids[a].name,
            scene.liquids[b].name,
            CALIBRATION_TOLERANCE * 100.0
        ),
    )
    .into())
}

/// The relaxed slab's tension and its standard error [N/m] of liquid `a` at coefficients ×
/// `scale`; refused if not positive (nothing to calibrate).
fn positive_slab_tension(
    scene: &Scene,
    a: usize,
    design: SlabDesign,
    scale: f64,
) -> Result<(f64, f64), SimError> {
    let m = slab_tension(scene, a, design, scale)?;
    if m.sigma_measured_n_m.is_nan() || m.sigma_measured_n_m <= 0.0 {
        return Err(SceneError::invalid(
            "discretisation.tension_calibration",
            "relaxed_slab",
            format!(
                "the relaxed slab of {} has no positive tension ({:e} N/m): this setting has \
                 no surface to calibrate",
                m.liquid, m.sigma_measured_n_m
            ),
        )
        .into());
    }
    Ok((m.sigma_measured_n_m, m.sigma_standard_error_n_m))
}
