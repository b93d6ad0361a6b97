//! The continuum surface force (CSF) between liquid phases: Brackbill et al. 1992's force
//! density `σ_ab κ ∇c`, normal to the interface, with the curvature `κ` from a renormalised
//! divergence of the normals (Adami et al. 2010's idea, here in 3D; docs/model.md §4b). It
//! has the surface stress's inputs and colour gradients, but no tangential tension: the 2D
//! prototypes' flat capillary wave paired under the stress and not under this force.
//!
//! For each interface term ([`interface_terms`]: the pair of liquids `a | b` with its `σ_ab`, or
//! with three liquids each liquid against the other two with its share `σ_k`), on the
//! particles of its two sides `a` and `b`:
//! - the colour gradient `g_i = ∇c_b` [1/m], pointing into `b`: `G_i^b` on `a`'s particles and
//!   `−G_i^a` on `b`'s ([`StressInput::colour_gradient`]);
//! - where `|g_i| > 0.01/r_e` (the band: nearly all of the colour kernel's reach), the normal
//!   `n_i = g_i/|g_i|` and the curvature
//!   `κ_i = −Σ_j V_j (n_j − n_i)·∇_i W_c / Σ_j V_j ½(r² − (n_i·r_ij)²) |W_c'|/r`
//!   over band neighbours `j` of `a` or `b` whose normals are within 120° of `n_i` (a film's
//!   opposite face is no neighbour): the divergence of `n` with the kernel's moment in
//!   the tangent plane as its normalisation (the band truncates the moment along `n`, along
//!   which `n` does not change), positive for a drop of `b` in `a`;
//! - the force `F_i = V_i σ_ab κ_i g_i` [N].
//!
//! Walls take part in one of two ways ([`Walls`]). In the shares' (the default), their solid
//! is a third phase of the split (two liquids and one solid): each liquid's share comes from
//! the tensions of its interfaces with the other liquid and with the solid, the latter from
//! Young's relation with the liquid's contact angle, and the solid's own share is no term (a
//! rigid wall's area does not change). Wall particles take part in the colour gradients,
//! normals and curvatures of the liquids' terms; no force acts on them. In the wall normal's
//! ([`wall_normal`]), the walls are no phase: the pair's term runs over the fluid, and its
//! normals near a wall are turned to the contact angle's.
//!
//! Not a pair form: linear momentum is conserved only as far as `κ` is uniform on a closed
//! interface; each term of the three-liquid split is made to conserve it
//! (`momentum_correction`). The fluid's passes visit each pair once ([`each_pair_once`]),
//! the walls' pass gathers over each wall particle's list: the bits do not depend on the
//! thread count.

pub mod contact_line;
pub mod wall_normal;

use super::surface_stress::StressInput;
use crate::kernel::Kernel;
use crate::physics::forces::pairs_once::{each_pair_once, Reactions, Spills};
use crate::state::Vec3;
use nalgebra::Matrix3;
use rayon::prelude::*;
use wall_normal::WallNormal;

/// The band's threshold on `|∇c| r_e` [-]. The 2D prototypes' `|∇c| h_c > 0.1` (0.2 here)
/// left about 4 % of a sphere's `∫|∇c|` out at every resolution, and the convergence case's
/// l = 2 error did not fall with it (+4.1, +7.9, +7.5 % at R/l0 = 10, 14.1, 20); at 0.01 it
/// falls (+8.7, +4.6, +2.8 %; docs/findings.md). Only isolated particles at the colour
/// kernel's edge, whose normals are noise, stay out.
pub const BAND_GRADIENT_TIMES_R_E: f64 = 0.01;

/// The cosine below which two band particles' normals are taken for opposite faces of a film
/// and left out of each other's curvature [-]: normals more than 120° apart. A 90° fold's
/// normals, perpendicular up to round-off, stay in (docs/model.md §4b, *Opposite faces*).
pub const OPPOSITE_FACES_COSINE: f64 = -0.5;

/// Scratch of the surface force, kept between steps.
#[derive(Clone, Debug)]
pub struct ForceScratch {
    /// The band's threshold on `|∇c| r_e` [-] ([`BAND_GRADIENT_TIMES_R_E`] by default; the
    /// diagnostics vary it).
    pub band_gradient_times_r_e: f64,
    /// Whether each term of the three-liquid split is made to conserve linear momentum
    /// (`momentum_correction`; on by default, the tests turn it off to measure what it
    /// removes).
    pub split_momentum_correction: bool,
    /// `∇c_b` per particle [1/m] (zero off the phases `a` and `b`; walls: zero unless they
    /// take part).
    gradient: Vec<Vec3>,
    /// The unit normal in the band (zero outside it) per particle.
    normal: Vec<Vec3>,
    /// The curvature's sums `(numerator [1/m], denominator [-], 0)` per fluid particle.
    sums: Vec<Vec3>,
    /// The curvature [1/m] of the last pair evaluated, per fluid particle (zero outside the
    /// band).
    pub curvature: Vec<f64>,
    /// The force per fluid particle [N].
    pub force: Vec<Vec3>,
    /// One split term's force per fluid particle [N] (the momentum correction's input).
    term_force: Vec<Vec3>,
    /// The interfacial energy estimate `Σ_i V_i σ_ab |∇c_b|` [J] of the last evaluation.
    pub interface_energy_j: f64,
    /// Its share per fluid particle [J].
    energy: Vec<f64>,
    /// The wall's normal and distance [m] per fluid particle (the wall normal's treatment).
    wall_geometry: Vec<(Vec3, f64)>,
    /// The wall particles' colour fractions of the two sides (the wall normal's treatment).
    wall_colour: Vec<(f64, f64)>,
    spills: Spills,
}

/// How the walls take part in the surface force (docs/model.md §4b).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Walls {
    /// They take none (no walls, or walls that only hold the fluid).
    Absent,
    /// Their solid, this phase, is a third phase of the split: Young's shares.
    Shares(usize),
    /// They turn the interface's normal to the contact angle ([`wall_normal`]).
    Normal(WallNormal),
}

impl Default for ForceScratch {
    fn default() -> Self {
        ForceScratch {
            band_gradient_times_r_e: BAND_GRADIENT_TIMES_R_E,
            split_momentum_correction: true,
            gradient: Vec::new(),
            normal: Vec::new(),
            sums: Vec::new(),
            curvature: Vec::new(),
            force: Vec::new(),
            term_force: Vec::new(),
            interface_energy_j: 0.0,
            energy: Vec::new(),
            wall_geometry: Vec::new(),
            wall_colour: Vec::new(),
            spills: Spills::default(),
        }
    }
}

impl ForceScratch {
    /// Evaluates the forces of the current state: `sigma(a, b)` [N/m] is the tension of the
    /// pair of liquid phases `a ≠ b` (zero: no interface term), `n_liquids` the number of
    /// liquid phases; `walls` how the walls take part, with `sigma(a, S)` the liquid `a`'s
    /// tension against their solid `S` relative to the solid's own ([`interface_terms`];
    /// the wall normal's contact angles come from the same tensions, [`contact_cosine`]).
    /// Walls take part only with lists that reach the colour kernel's support from the wall
    /// side ([`crate::neighbours::NeighbourSearch::walls_reach_far`]).
    pub fn evaluate<K: Kernel>(
        &mut self,
        inp: &StressInput<K>,
        n_liquids: usize,
        sigma: impl Fn(usize, usize) -> f64 + Sync,
        walls: Walls,
    ) {
        let wall = match walls {
            Walls::Shares(solid) => Some(solid),
            Walls::Absent | Walls::Normal(_) => None,
        };
        let normal_walls = match walls {
            Walls::Normal(w) => {
                wall_normal::wall_geometry(inp, &mut self.wall_geometry);
                Some(w)
            }
            Walls::Absent | Walls::Shares(_) => None,
        };
        let blend_m = wall_normal::BLEND_OVER_SUPPORT * inp.kernel.support_m();
        let n = inp.n_fluid;
        let n_all = if wall.is_some() { inp.pos.len() } else { n };
        self.gradient.resize(n_all, Vec3::zeros());
        self.normal.resize(n_all, Vec3::zeros());
        self.sums.resize(n, Vec3::zeros());
        self.curvature.clear();
        self.curvature.resize(n, 0.0);
        self.force.clear();
        self.force.resize(n, Vec3::zeros());
        self.energy.clear();
        self.energy.resize(n_all, 0.0);
        let band = self.band_gradient_times_r_e / inp.kernel.support_m();
        let level = normal_walls.and_then(|w| split_wall_level(n_liquids, &sigma, w.solid));
        for (sides, s) in interface_terms(n_liquids, &sigma, wall) {
            interface_gradient(inp, sides, &self.spills, &mut self.gradient);
            // the walls' contact angles for this term, if they turn its normals
            let turn = normal_walls
                .and_then(|w| turn_cosine(sides, &sigma, w.solid, s, level).map(|c| (c, w.l0_m)));
            // the wall's side of the colour's jump, as of the pressure's
            if turn.is_some() {
                wall_normal::complete_with_wall_colour(
                    inp,
                    |p| sides.of(p),
                    &mut self.wall_colour,
                    &mut self.gradient,
                );
            }
            let geometry = &self.wall_geometry;
            // the normal in the band
            self.normal
                .par_iter_mut()
                .zip(self.gradient.par_iter())
                .enumerate()
                .for_each(|(i, (nrm, g))| {
                    let m = g.norm();
                    *nrm = if m > band { *g / m } else { Vec3::zeros() };
                    let Some((cos_theta, l0_m)) = turn.filter(|_| m > band) else {
                        return;
                    };
                    let (nw, dist_m) = geometry[i];
                    *nrm = wall_normal::turned(*nrm, nw, dist_m, cos_theta, l0_m, blend_m);
                });
            curvature_sums(inp, &self.normal, &self.spills, &mut self.sums);
            // the walls' share of the energy (their side of the liquid's faces on them)
            self.energy[n..]
                .par_iter_mut()
                .zip(self.gradient[n..].par_iter())
                .zip(inp.vol[n..n_all].par_iter())
                .for_each(|((e, g), v)| *e += v * s * g.norm());
            let (grad, sums) = (&self.gradient, &self.sums);
            // a term of the three liquids' split collects its own force first, to be corrected
            let corrected = self.split_momentum_correction
                && wall.is_none()
                && matches!(sides, Sides::Phase(_));
            if corrected {
                self.term_force.clear();
                self.term_force.resize(n, Vec3::zeros());
            }
            let target = if corrected {
                &mut self.term_force
            } else {
                &mut self.force
            };
            target
                .par_iter_mut()
                .zip(self.curvature.par_iter_mut())
                .zip(self.energy[..n].par_iter_mut())
                .enumerate()
                .for_each(|(i, ((f, k), e))| {
                    let g = grad[i];
                    if g == Vec3::zeros() {
                        return;
                    }
                    *e += inp.vol[i] * s * g.norm();
                    let [num, den, _] = [sums[i].x, sums[i].y, sums[i].z];
                    if den <= 0.0 {
                        return;
                    }
                    *k = -num / den; // κ = −∇·n, renormalised in the tangent plane
                    *f += g * (inp.vol[i] * s * *k); // Brackbill et al. 1992: σ κ ∇c
                });
            if corrected {
                let geometry = normal_walls.map(|w| Facing {
                    geometry: self.wall_geometry.as_slice(),
                    l0_m: w.l0_m,
                    blend_m,
                });
                momentum_correction(inp, &self.gradient[..n], geometry, &mut self.term_force);
                self.force
                    .par_iter_mut()
                    .zip(self.term_force.par_iter())
                    .for_each(|(f, t)| *f += t);
            }
        }
        // a fixed-order sum: the same bits for any thread count
        self.interface_energy_j = self.energy.iter().sum();
    }
}

/// Below this fraction of the largest eigenvalue of the walls' normal moment
/// `Σ w_i n_w ⊗ n_w` (over a term's band particles within the wall normal's blend, weighted as
/// it turns them), a direction is one no wall faces ([`momentum_correction`]). The discrete
/// wall normal of a particle over a lattice plate leans by up to 2.6e-3 rad within 3 l0 of it
/// at any offset along the plate (8e-4 rms; Wendland C2 at r_e = 4.2 l0; 0.15 rad at 3–4 l0,
/// outside the blend), so a plate's moment along itself is below ~1e-5 of the largest; a
/// direction counts as faced from 1e-3 (walls leaning by ~2° rms along it).
const UNFACED_EIGENVALUE_FRACTION: f64 = 1e-3;

/// The wall normal's geometry as [`momentum_correction`] reads it.
#[derive(Clone, Copy)]
struct Facing<'a> {
    /// The wall's unit normal and distance [m] per fluid particle (zero normal: no wall near).
    geometry: &'a [(Vec3, f64)],
    /// The lattice spacing [m] and the blend [m] of [`wall_normal::turned`].
    l0_m: f64,
    blend_m: f64,
}

/// Makes one term of the three-liquid split conserve linear momentum (docs/model.md §4b):
/// subtracts from its force `force` [N] (one per fluid particle) the net `N = Σ_i F_i` as a
/// uniform traction over the term's interface, `ΔF_i = −P N V_i|g_i| / Σ_j V_j|g_j|`, with
/// `g` the term's colour gradient [1/m]. Each share's interface is closed, so its continuum
/// force `σ_k ∮ κ n dA` vanishes whatever its shape; the discrete one does not where the share's
/// interface folds at a triple line (a 90° fold pulls 1.05 of its line force, a sphere's face
/// 0.99 of its Laplace force, lattice unit tests), and off Neumann's balance the folds of the
/// shares do not cancel. `P` projects on the directions that no wall faces: without walls
/// (`walls = None`, or no band particle near one) every direction; under the wall normal
/// (`walls`), those along which the wall normals of the band particles it turns have almost no
/// moment ([`UNFACED_EIGENVALUE_FRACTION`]) — along a plate, the plate's two directions —
/// since a share turned at one angle along its whole boundary on a plane pushes that boundary
/// evenly (no net along it) while the wall takes the push across. The sums run in particle
/// order (the same bits for any thread count).
fn momentum_correction<K: Kernel>(
    inp: &StressInput<K>,
    gradient: &[Vec3],
    walls: Option<Facing>,
    force: &mut [Vec3],
) {
    let mut net = Vec3::zeros();
    let mut area = 0.0; // Σ V|g| [m²]
    let mut faced = Matrix3::zeros();
    for (i, (f, g)) in force.iter().zip(gradient).enumerate() {
        if *g == Vec3::zeros() {
            continue;
        }
        net += f;
        area += inp.vol[i] * g.norm();
        if let Some(w) = walls {
            let (nw, dist_m) = w.geometry[i];
            if nw != Vec3::zeros() {
                let weight = wall_normal::turned_weight(dist_m, w.l0_m, w.blend_m);
                faced += nw * nw.transpose() * weight;
            }
        }
    }
    if area == 0.0 {
        return;
    }
    let eigen = faced.symmetric_eigen();
    let largest = eigen.eigenvalues.max();
    let mut free = Matrix3::zeros();
    for (k, lambda) in eigen.eigenvalues.iter().enumerate() {
        if *lambda <= UNFACED_EIGENVALUE_FRACTION * largest {
            let v = eigen.eigenvectors.column(k);
            free += v * v.transpose();
        }
    }
    let traction = free * net / area; // [N/m²]
    force
        .par_iter_mut()
        .zip(gradient.par_iter())
        .zip(inp.vol.par_iter())
        .for_each(|((f, g), v)| {
            if *g != Vec3::zeros() {
                *f -= traction * (v * g.norm());
            }
        });
}

/// The cosine of the contact angle, measured in side A, at which the interface term `sides`
/// (tension `s` [N/m]) meets the walls of solid `solid`: Young's
/// `cos θ = (σ_BS − σ_AS)/σ_AB`, clipped to [−1, 1] (`sigma(a, solid)` holds each liquid's
/// tension against the solid up to the solid's own, which cancels). `None` for a liquid
/// against all the others (the three-liquid split: each share's angle comes from the split's
/// common level, [`split_wall_level`]).
pub fn contact_cosine(
    sides: Sides,
    sigma: &impl Fn(usize, usize) -> f64,
    solid: usize,
    s: f64,
) -> Option<f64> {
    match sides {
        Sides::Pair(a, b) => {
            let (a, b) = (a as usize, b as usize);
            Some(((sigma(b, solid) - sigma(a, solid)) / s).clamp(-1.0, 1.0))
        }
        Sides::Phase(_) => None,
    }
}

/// The cosine [-], measured in side A, of the angle at which the wall normal turns the
/// normals of the interface term `sides` (tension `s` [N/m]) at the walls of solid `solid`:
/// a pair's Young angle ([`contact_cosine`]); for a liquid `k` against the other two (the
/// three-liquid split, share `σ_k = s`), one angle along its whole interface,
/// `σ_k cos φ_k = C − σ_kS`, from the split's common level `C` ([`split_wall_level`]).
/// Where two liquids `k | l` meet the wall their shares' pushes then add to
/// `(C − σ_kS) − (C − σ_lS) = σ_lS − σ_kS = σ_kl cos θ_kl`, Young's (Eq. 23 for two liquids),
/// and since each share's push is the same all along its closed boundary on the wall, the
/// pushes leave no net force along it, whatever the drop's shape (docs/model.md §4b). Clipped
/// to [−1, 1]; `None` for a liquid of the split without a level.
fn turn_cosine(
    sides: Sides,
    sigma: &impl Fn(usize, usize) -> f64,
    solid: usize,
    s: f64,
    level: Option<f64>,
) -> Option<f64> {
    match sides {
        Sides::Pair(..) => contact_cosine(sides, sigma, solid, s),
        Sides::Phase(k) => level.map(|c| ((c - sigma(k as usize, solid)) / s).clamp(-1.0, 1.0)),
    }
}

/// The common level `C` [N/m] of the three-liquid split at walls under the wall normal
/// (`turn_cosine`), given the pair tensions `sigma(a, b)` and each liquid's tension against
/// the solid `sigma(a, solid)` up to the solid's own: any `C` gives each pair Young's push, and
/// a share `σ_k` can turn its normals only as far as `|C − σ_kS| ≤ |σ_k|`. Those intervals
/// meet wherever every pair has a Young angle (`|σ_kS − σ_lS| ≤ σ_kl = σ_k + σ_l`, and
/// intervals on a line that meet pairwise meet all together); `C` is the middle of their
/// common part, which keeps the shares' angles as far from 0° and 180° as it can (a liquid
/// with no share, `σ_k = 0`, fixes `C = σ_kS`). `None` unless the liquids with tensions are
/// three.
pub fn split_wall_level(
    n_liquids: usize,
    sigma: &impl Fn(usize, usize) -> f64,
    solid: usize,
) -> Option<f64> {
    let liquids: Vec<usize> = (0..n_liquids)
        .filter(|&a| (0..n_liquids).any(|b| b != a && sigma(a, b) != 0.0))
        .collect();
    if liquids.len() != 3 {
        return None;
    }
    let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
    for (i, &k) in liquids.iter().enumerate() {
        let (l, m) = (liquids[(i + 1) % 3], liquids[(i + 2) % 3]);
        let share = 0.5 * (sigma(k, l) + sigma(k, m) - sigma(l, m));
        let s_ks = sigma(k, solid);
        lo = lo.max(s_ks - share.abs());
        hi = hi.min(s_ks + share.abs());
    }
    Some(0.5 * (lo + hi))
}

/// The two sides of an interface term: a pair of liquids `a | b`, or one liquid against all
/// the others.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Sides {
    /// Liquid `a` (side A) against liquid `b` (side B).
    Pair(u8, u8),
    /// Liquid `k` (side A) against every other phase, liquid or wall (side B).
    Phase(u8),
}

impl Sides {
    /// `+1` for a phase on side A, `−1` on side B, `0` on neither.
    #[inline(always)]
    fn of(self, phase: u8) -> f64 {
        match self {
            Sides::Pair(a, _) | Sides::Phase(a) if phase == a => 1.0,
            Sides::Pair(_, b) if phase == b => -1.0,
            Sides::Phase(_) => -1.0,
            Sides::Pair(..) => 0.0,
        }
    }
}

/// The interface terms of the force with their tensions [N/m], given the tension
/// `sigma(a, b)` [N/m] of each pair of the `n_liquids` liquid phases (zero: none), and, if the
/// walls take part, their solid's phase `wall` with `sigma(a, wall)` the liquid `a`'s tension
/// against it up to a constant common to the liquids (Young: `σ_aS = σ_S − σ_a cos θ_a`).
///
/// With one pair of liquids and no wall, that pair `a | b` and its `σ_ab`. With three phases
/// (three liquids, or two and the walls' solid), each liquid against the other two with its
/// own share `σ_k = ½(σ_kl + σ_km − σ_lm)`, so that `σ_ab = σ_a + σ_b` on every interface
/// (docs/model.md §4b): each liquid's interface is closed, and at a triple line the three terms
/// meet as the tensions balance, where a pair's colour gradient would end at an open edge. The
/// solid's share is no term (a rigid wall's area is fixed), so the constant in its tensions
/// drops out. Four or more phases are refused by the scene's validation (the split is
/// overdetermined); here they keep their pairs.
pub fn interface_terms(
    n_liquids: usize,
    sigma: &impl Fn(usize, usize) -> f64,
    wall: Option<usize>,
) -> Vec<(Sides, f64)> {
    let mut pairs = Vec::new();
    let mut liquids = Vec::new();
    for a in 0..n_liquids {
        for b in a + 1..n_liquids {
            let s = sigma(a, b);
            if s != 0.0 {
                pairs.push((Sides::Pair(a as u8, b as u8), s));
                for k in [a, b] {
                    if !liquids.contains(&k) {
                        liquids.push(k);
                    }
                }
            }
        }
    }
    liquids.sort_unstable();
    liquids.extend(wall);
    if liquids.len() != 3 {
        return pairs;
    }
    let [k, l, m] = [liquids[0], liquids[1], liquids[2]];
    let share = |k, l, m| 0.5 * (sigma(k, l) + sigma(k, m) - sigma(l, m));
    [
        (k, share(k, l, m)),
        (l, share(l, k, m)),
        (m, share(m, k, l)),
    ]
    .into_iter()
    .filter(|&(k, s)| s != 0.0 && Some(k) != wall)
    .map(|(k, s)| (Sides::Phase(k as u8), s))
    .collect()
}

/// The colour gradient [1/m] of an interface term at the particles of its two sides, into
/// `out` (zero elsewhere), pointing from side A into side B, in one pass over the pairs across
/// the interface: `∇c_B` on A's particles and `−∇c_A` on B's ([`StressInput::colour_gradient`]'s
/// sums, here both at once). A pair `i, j` across adds `s V_j ∇_i W_c` to `i` and
/// `s V_i ∇_i W_c` to `j`, with `s = +1` if `i` is on side A and `−1` if on side B. If `out`
/// holds the walls too (they take part: side B of a liquid's term), a fluid particle's sum
/// takes its wall neighbours, and each wall particle then gathers its own over its fluid
/// neighbours.
fn interface_gradient<K: Kernel>(
    inp: &StressInput<K>,
    sides: Sides,
    spills: &Spills,
    out: &mut [Vec3],
) {
    out.fill(Vec3::zeros());
    let phase = inp.phase;
    let (fluid, walls) = out.split_at_mut(inp.n_fluid);
    let with_walls = !walls.is_empty();
    each_pair_once(fluid, spills, |i, reactions: &mut Reactions| {
        let mut g = Vec3::zeros();
        let sign = sides.of(phase[i]);
        if sign == 0.0 {
            return g;
        }
        let across = |j: usize| sides.of(phase[j]) == -sign;
        let mut add = |j: usize, grad_w: Vec3, _| {
            g += grad_w * (sign * inp.vol[j]);
            reactions.subtract(j, grad_w * (-sign * inp.vol[i]));
        };
        if with_walls {
            inp.each_later_neighbour_or_wall(i, across, &mut add);
        } else {
            inp.each_later_neighbour(i, across, &mut add);
        }
        g
    });
    walls.par_iter_mut().enumerate().for_each(|(k, g)| {
        let w = inp.n_fluid + k;
        let sign = sides.of(phase[w]);
        if sign == 0.0 {
            return;
        }
        inp.each_fluid_neighbour_of_wall(
            w,
            |j| sides.of(phase[j]) == -sign,
            |j, grad_w| *g += grad_w * (sign * inp.vol[j]),
        );
    });
}

/// The curvature's sums `(Σ_j V_j (n_j − n_i)·∇_i W_c, Σ_j V_j ½(r² − (n_i·r)²)|W_c'|/r, 0)`
/// over pairs of band particles (nonzero `normal`), into `out` (one per fluid particle); wall
/// particles in the band (if `normal` holds them) count as neighbours of fluid ones.
fn curvature_sums<K: Kernel>(
    inp: &StressInput<K>,
    normal: &[Vec3],
    spills: &Spills,
    out: &mut [Vec3],
) {
    out.fill(Vec3::zeros());
    let in_band = |j: usize| j < normal.len() && normal[j] != Vec3::zeros();
    let with_walls = normal.len() > inp.n_fluid;
    each_pair_once(out, spills, |i, reactions: &mut Reactions| {
        let ni = normal[i];
        let mut sum = Vec3::zeros();
        if ni == Vec3::zeros() {
            return sum;
        }
        let mut add = |j: usize, grad_w: Vec3, d: Vec3| {
            let nj = normal[j];
            // a neighbour whose normal is more than 120° from i's is on another face of a
            // film thinner than the colour kernel, not on i's interface (docs/model.md §4b,
            // *Opposite faces*)
            if ni.dot(&nj) < OPPOSITE_FACES_COSINE {
                return;
            }
            // grad_w = ∇_i W_c = r_ij W'/r, with d = r_ij = x_i − x_j
            let div = (nj - ni).dot(&grad_w);
            let r2 = d.norm_squared();
            let abs_dw_over_r = grad_w.norm() / r2.sqrt();
            let ti = 0.5 * (r2 - ni.dot(&d).powi(2)) * abs_dw_over_r;
            let tj = 0.5 * (r2 - nj.dot(&d).powi(2)) * abs_dw_over_r;
            sum += Vec3::new(inp.vol[j] * div, inp.vol[j] * ti, 0.0);
            // j's sums: (n_i − n_j)·∇_j W_c = (n_j − n_i)·∇_i W_c (a wall takes none)
            reactions.subtract(j, -Vec3::new(inp.vol[i] * div, inp.vol[i] * tj, 0.0));
        };
        if with_walls {
            inp.each_later_neighbour_or_wall(i, in_band, &mut add);
        } else {
            inp.each_later_neighbour(i, in_band, &mut add);
        }
        sum
    });
}

#[cfg(test)]
mod tests;

#[cfg(test)]
mod wall_tests;
