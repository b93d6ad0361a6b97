//! The pair forces on fluid particles, in one gather loop per particle.
//!
//! `m_i dv_i/dt = − Σ_j (p_i V_i² + p_j V_j² + m_i m_j Π_ij) ∇_i W_ij`            (pressure, AV)
//! `            + Σ_j 2μ_iμ_j/(μ_i+μ_j) (V_i² + V_j²) (dW/dr / r) v_ij`          (laminar)
//! `            + Σ_j C_ij P'(r_ij) e_ij + m_i g`                                (tension, gravity)
//!
//! — Eqs. (11)–(13) and (15) of Natsui 2021 as corrected in physics.md §3–4 (Hu & Adams 2006
//! pressure and viscous forms; `m_i m_j Π_ij` for units; the viscous term is the scalar
//! `dW/dr / r` times `v_ij`). The continuity rate `dρ_i/dt = ρ_i Σ_j V_j v_ij·∇_i W_ij` is
//! accumulated in the same loop when that scheme is used.
//!
//! Each effect is a const generic flag: an effect the scene does not declare is compiled out of
//! the loop. Every pair term is written so that the `j`-on-`i` term is the exact bitwise
//! negative of the `i`-on-`j` one (commutative products and sums), which conserves momentum to
//! round-off. Artificial viscosity acts between fluid particles only; laminar viscosity reaches
//! walls only when they are no-slip (free-slip walls are left out of the viscous sum,
//! physics.md §3).

use crate::kernel::Kernel;
use crate::model::Model;
use crate::neighbours::{NeighbourLists, NeighbourSearch, ACTIVE_BITS};
use crate::state::{Particles, Vec3};
use rayon::prelude::*;

/// Inputs of the force loop, borrowed from the state and the model.
pub struct ForceInput<'a, K: Kernel> {
    /// The kernel.
    pub kernel: K,
    /// Smoothing length `h` [m].
    pub h_m: f64,
    /// Initial spacing `l0` [m] (zero-force distance of the potential).
    pub l0_m: f64,
    /// Potential cut-off `r_e` [m].
    pub r_e_m: f64,
    /// Sound speed `c` [m/s] (the mean `c̄_ij` of Eq. 12: one `c` for all phases).
    pub c_m_s: f64,
    /// Artificial-viscosity coefficients `(α1, α2)` [-].
    pub alpha: (f64, f64),
    /// Gravity [m/s²] (zero when the effect is off; added outside the pair loop).
    pub gravity: Vec3,
    /// Particle mass per phase [kg].
    pub mass: &'a [f64],
    /// Viscosity of each pair of phases [Pa·s], row-major: the harmonic mean
    /// `2μ_aμ_b/(μ_a + μ_b)` for two liquids, the liquid's own `μ` against a (no-slip) wall.
    pub mu_pair: &'a [f64],
    /// Potential coefficients `C_ab` [N/m²], row-major by phase.
    pub coeff: &'a [f64],
    /// Number of phases (row length of `coeff`).
    pub n_phases: usize,
    /// Number of fluid particles.
    pub n_fluid: usize,
    /// Positions [m] (all particles).
    pub pos: &'a [Vec3],
    /// Velocities [m/s] (all particles; walls: ghost velocity).
    pub vel: &'a [Vec3],
    /// Densities [kg/m³] (all).
    pub rho: &'a [f64],
    /// Pressures [Pa] (all).
    pub pressure: &'a [f64],
    /// Volumes [m³] (all).
    pub vol: &'a [f64],
    /// Phase indices (all).
    pub phase: &'a [u8],
    /// Per wall particle: no-slip?
    pub wall_no_slip: &'a [bool],
    /// Neighbour lists.
    pub lists: &'a NeighbourLists,
    /// Per fluid particle: which of its first near entries interact
    /// ([`NeighbourSearch::active`]).
    pub active: &'a [u64],
}

impl<'a, K: Kernel> ForceInput<'a, K> {
    /// The inputs of the state `p` under `model`: the one place they are gathered (the
    /// simulation's step and the benchmarks both use it).
    pub fn new(
        kernel: K,
        model: &'a Model,
        p: &'a Particles,
        wall_no_slip: &'a [bool],
        search: &'a NeighbourSearch,
    ) -> Self {
        let m = model;
        ForceInput {
            kernel,
            h_m: m.h_m,
            l0_m: m.l0_m,
            r_e_m: m.r_e_m,
            c_m_s: m.c_m_s,
            alpha: m.effects.artificial_viscosity.unwrap_or((0.0, 0.0)),
            gravity: m.gravity(),
            mass: &m.mass,
            mu_pair: &m.mu_pair,
            coeff: &m.pairs.coeff,
            n_phases: m.pairs.n_phases,
            n_fluid: p.n_fluid,
            pos: &p.pos,
            vel: &p.vel,
            rho: &p.rho,
            pressure: &p.pressure,
            vol: &p.vol,
            phase: &p.phase,
            wall_no_slip,
            lists: &search.lists,
            active: &search.active,
        }
    }
}

/// Evaluates accelerations [m/s²] (and, with `CONT`, density rates [kg/(m³ s)]) of all fluid
/// particles. The flags switch the terms: `PRES` pressure, `VISC` laminar viscosity, `AV`
/// artificial viscosity, `IT` interfacial tension, `WALL` wall particles present, `CONT`
/// continuity density rate.
#[allow(clippy::too_many_arguments)]
pub fn fluid_forces<
    K: Kernel,
    const PRES: bool,
    const VISC: bool,
    const AV: bool,
    const IT: bool,
    const WALL: bool,
    const CONT: bool,
>(
    inp: &ForceInput<K>,
    acc: &mut [Vec3],
    drho: &mut [f64],
) {
    let k = inp.kernel;
    let support = k.support_m();
    let support2 = support * support;
    let r_e = inp.r_e_m;
    let re2 = r_e * r_e;
    let l0 = inp.l0_m;
    let h = inp.h_m;
    let eta2 = 0.01 * h * h; // (0.1 h)², Eq. (13), Natsui 2021
    let (alpha1, alpha2) = inp.alpha;
    let c_s = inp.c_m_s;
    let nph = inp.n_phases;
    let (pos, vel, rho, pre, vol, phase) =
        (inp.pos, inp.vel, inp.rho, inp.pressure, inp.vol, inp.phase);

    let body = |(g, idx): &mut Buffers, i: usize| -> (Vec3, f64) {
        let pi = pos[i];
        let vi = vel[i];
        let ph_i = phase[i] as usize;
        let m_i = inp.mass[ph_i];
        let v_i = vol[i];
        let pv_i = pre[i] * v_i * v_i;
        let v2_i = v_i * v_i;
        let rho_i = rho[i];
        let coeff_row = &inp.coeff[ph_i * nph..(ph_i + 1) * nph];
        let mu_row = &inp.mu_pair[ph_i * nph..(ph_i + 1) * nph];
        let mut f = Vec3::zeros();
        let mut dr = 0.0;
        // the interacting entries among the first ACTIVE_BITS (in list order), then the rest;
        // when all of them interact (r_e beyond the support), the list itself
        let near = inp.lists.near(i);
        let (masked, rest) = near.split_at(near.len().min(ACTIVE_BITS));
        let mut n_active = 0;
        let all = low_bits(masked.len());
        let mut bits = inp.active[i] & all;
        let visit: &[u32] = if bits == all {
            masked
        } else {
            while bits != 0 {
                idx[n_active] = masked[bits.trailing_zeros() as usize];
                n_active += 1;
                bits &= bits - 1;
            }
            &idx[..n_active]
        };
        for chunk in visit.chunks(CHUNK).chain(rest.chunks(CHUNK)) {
            g.fill::<VISC, AV, IT, WALL, CONT>(chunk, pi, vi, inp, coeff_row, mu_row);
            // every pair term of the chunk, branch-free (the compiler vectorises this loop);
            // lanes past the chunk's end hold a previous chunk's values: computed, never added
            let (mut ca, mut cb, mut cd) = ([0.0; CHUNK], [0.0; CHUNK], [0.0; CHUNK]);
            for n in 0..CHUNK {
                let r2 = g.dx[n] * g.dx[n] + g.dy[n] * g.dy[n] + g.dz[n] * g.dz[n];
                let r = r2.sqrt();
                let ir = 1.0 / r;
                // coincident particles have no direction: no force (the health check reports them)
                let apart = r2 > 0.0;
                let inside = apart && r2 < support2;
                let dw_r = k.dw_dr_inside(r.min(support)) * ir; // dW/dr / r [1/m⁵]
                                                                // the pair force is a · r_ij + b · v_ij: pressure, artificial viscosity and
                                                                // tension act along r_ij, laminar viscosity along v_ij; both coefficients are
                                                                // symmetric in i and j, so F_ji = −F_ij to the last bit
                let mut a = 0.0;
                if IT {
                    // Eq. (15), Natsui 2021 (physics.md §4): C_ij (r − l0)(r − r_e) e_ij
                    let v = g.c[n] * (r - l0) * (r - r_e) * ir;
                    a = if apart && r2 < re2 { v } else { 0.0 };
                }
                if PRES {
                    // Eq. (11), Natsui 2021: −(p_i V_i² + p_j V_j²) ∇_i W_ij
                    let v = (pv_i + g.pv[n]) * dw_r;
                    a -= if inside { v } else { 0.0 };
                }
                let vr = g.vx[n] * g.dx[n] + g.vy[n] * g.dy[n] + g.vz[n] * g.dz[n];
                if AV {
                    // Eq. (13), Natsui 2021
                    let phi = h * vr / (r2 + eta2);
                    // Eq. (12), Natsui 2021 with m_i m_j Π_ij (physics.md §3)
                    let pi_ij =
                        (-alpha1 * c_s * phi + alpha2 * phi * phi) / (0.5 * (rho_i + g.rho[n]));
                    let v = m_i * g.m[n] * pi_ij * dw_r;
                    a -= if inside && g.av[n] && vr < 0.0 {
                        v
                    } else {
                        0.0
                    };
                }
                ca[n] = a;
                if VISC {
                    // Eq. (11), Natsui 2021: 2μiμj/(μi+μj) (V_i² + V_j²) (dW/dr / r) v_ij
                    let v = g.mu[n] * (v2_i + g.v2[n]) * dw_r;
                    cb[n] = if inside { v } else { 0.0 };
                }
                if CONT {
                    let v = g.vol[n] * vr * dw_r; // V_j v_ij·∇_i W_ij
                    cd[n] = if inside { v } else { 0.0 };
                }
            }
            for n in 0..chunk.len() {
                f.x += g.dx[n] * ca[n] + g.vx[n] * cb[n];
                f.y += g.dy[n] * ca[n] + g.vy[n] * cb[n];
                f.z += g.dz[n] * ca[n] + g.vz[n] * cb[n];
                if CONT {
                    dr += cd[n];
                }
            }
        }
        if IT {
            far_potential(&mut f, pi, inp.lists.far(i), pos, phase, coeff_row, l0, r_e);
        }
        (f / m_i + inp.gravity, rho_i * dr)
    };

    // one set of buffers per rayon job, not per chunk or particle (zeroing the gather buffer per
    // chunk cost 4 % of a step)
    type Buffers = (Gather<CHUNK>, [u32; ACTIVE_BITS]);
    let buffers = || (Gather::new(), [0u32; ACTIVE_BITS]);
    if CONT {
        acc.par_iter_mut()
            .zip(drho.par_iter_mut())
            .enumerate()
            .for_each_init(buffers, |b, (i, (a, d))| {
                let (ai, di) = body(b, i);
                *a = ai;
                *d = di;
            });
    } else {
        acc.par_iter_mut()
            .enumerate()
            .for_each_init(buffers, |b, (i, a)| *a = body(b, i).0);
    }
}

/// The mask of the lowest `n` bits (`n ≤ 64`).
#[inline(always)]
fn low_bits(n: usize) -> u64 {
    if n >= 64 {
        u64::MAX
    } else {
        (1u64 << n) - 1
    }
}

/// Neighbours processed together by the pair loops (measured, per step of the 20 k cube at
/// r_e = 2.1 and 4.2 l0: 16 is 3–6 % faster than 8, 32 slower than 16).
const CHUNK: usize = 16;

/// One chunk of a particle's neighbours, gathered into arrays: the pair arithmetic then runs
/// over the arrays without indirection or branches.
struct Gather<const N: usize> {
    /// `x_i − x_j` [m].
    dx: [f64; N],
    dy: [f64; N],
    dz: [f64; N],
    /// `v_i − v_j` [m/s] (zero for a free-slip wall: it takes no part in the viscous terms).
    vx: [f64; N],
    vy: [f64; N],
    vz: [f64; N],
    /// `p_j V_j²` [N·m].
    pv: [f64; N],
    /// `V_j²` [m⁶].
    v2: [f64; N],
    /// `V_j` [m³].
    vol: [f64; N],
    /// `ρ_j` [kg/m³].
    rho: [f64; N],
    /// `m_j` [kg].
    m: [f64; N],
    /// Pair viscosity [Pa·s] (zero against a free-slip wall).
    mu: [f64; N],
    /// Potential coefficient `C_ij` [N/m²].
    c: [f64; N],
    /// Artificial viscosity applies (a fluid pair).
    av: [bool; N],
}

impl<const N: usize> Gather<N> {
    /// An empty buffer (lanes not filled by the current chunk are computed but never added).
    fn new() -> Self {
        Gather {
            dx: [0.0; N],
            dy: [0.0; N],
            dz: [0.0; N],
            vx: [0.0; N],
            vy: [0.0; N],
            vz: [0.0; N],
            pv: [0.0; N],
            v2: [0.0; N],
            vol: [0.0; N],
            rho: [1.0; N],
            m: [0.0; N],
            mu: [0.0; N],
            c: [0.0; N],
            av: [false; N],
        }
    }

    /// Gathers the neighbours `chunk` (at most `N`) of a particle at `pi` [m] moving at `vi`
    /// [m/s] into lanes `0..chunk.len()`.
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn fill<
        const VISC: bool,
        const AV: bool,
        const IT: bool,
        const WALL: bool,
        const CONT: bool,
    >(
        &mut self,
        chunk: &[u32],
        pi: Vec3,
        vi: Vec3,
        inp: &ForceInput<impl Kernel>,
        coeff_row: &[f64],
        mu_row: &[f64],
    ) {
        let g = self;
        for (n, &j) in chunk.iter().enumerate() {
            let j = j as usize;
            let d = pi - inp.pos[j];
            g.dx[n] = d.x;
            g.dy[n] = d.y;
            g.dz[n] = d.z;
            let is_wall = WALL && j >= inp.n_fluid;
            let vj = inp.vol[j];
            g.pv[n] = inp.pressure[j] * vj * vj;
            g.v2[n] = vj * vj;
            g.vol[n] = vj;
            let ph = inp.phase[j] as usize;
            if AV || VISC || CONT {
                let v = vi - inp.vel[j];
                g.vx[n] = v.x;
                g.vy[n] = v.y;
                g.vz[n] = v.z;
            }
            if AV {
                g.rho[n] = inp.rho[j];
                g.m[n] = inp.mass[ph];
                g.av[n] = !is_wall;
            }
            if VISC {
                let coupled = !is_wall || inp.wall_no_slip[j - inp.n_fluid];
                g.mu[n] = if coupled { mu_row[ph] } else { 0.0 };
            }
            if IT {
                g.c[n] = coeff_row[ph];
            }
        }
    }
}

/// Adds the potential force of the far neighbours (beyond the kernel support, within `r_e`) to
/// `f`: Eq. (15), Natsui 2021, `C_ij (r − l0)(r − r_e) e_ij`.
///
/// The neighbours are gathered in chunks; the per-pair factors are computed branch-free over a
/// whole chunk (a loop the compiler vectorises: `sqrt` and division are exact IEEE operations),
/// then added to `f` one by one in list order — the same operations in the same order as a
/// scalar loop, hence the same bits.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn far_potential(
    f: &mut Vec3,
    pi: Vec3,
    far: &[u32],
    pos: &[Vec3],
    phase: &[u8],
    coeff_row: &[f64],
    l0: f64,
    r_e: f64,
) {
    let re2 = r_e * r_e;
    for chunk in far.chunks(CHUNK) {
        let (mut dx, mut dy, mut dz, mut c) =
            ([0.0; CHUNK], [0.0; CHUNK], [0.0; CHUNK], [0.0; CHUNK]);
        for (k, &j) in chunk.iter().enumerate() {
            let j = j as usize;
            let d = pi - pos[j];
            dx[k] = d.x;
            dy[k] = d.y;
            dz[k] = d.z;
            c[k] = coeff_row[phase[j] as usize];
        }
        let mut s = [0.0; CHUNK];
        for k in 0..CHUNK {
            let r2 = dx[k] * dx[k] + dy[k] * dy[k] + dz[k] * dz[k];
            let r = r2.sqrt();
            let v = c[k] * (r - l0) * (r - r_e) / r;
            s[k] = if r2 < re2 && r2 > 0.0 { v } else { 0.0 };
        }
        for k in 0..chunk.len() {
            f.x += dx[k] * s[k];
            f.y += dy[k] * s[k];
            f.z += dz[k] * s[k];
        }
    }
}

/// Selects the [`fluid_forces`] instance for run-time flags (pressure always on).
#[allow(clippy::too_many_arguments)]
pub fn dispatch<K: Kernel>(
    inp: &ForceInput<K>,
    visc: bool,
    av: bool,
    it: bool,
    wall: bool,
    cont: bool,
    acc: &mut [Vec3],
    drho: &mut [f64],
) {
    macro_rules! pick {
        ([$($done:tt)*], []) => { fluid_forces::<K, true, $($done)*>(inp, acc, drho) };
        ([$($done:tt)*], [$b:expr $(, $rest:expr)*]) => {
            if $b { pick!([$($done)* true,], [$($rest),*]) }
            else { pick!([$($done)* false,], [$($rest),*]) }
        };
    }
    pick!([], [visc, av, it, wall, cont])
}
