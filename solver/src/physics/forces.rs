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
use crate::neighbours::NeighbourLists;
use crate::state::Vec3;
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
    let n_fluid = inp.n_fluid;
    let nph = inp.n_phases;
    let (pos, vel, rho, pre, vol, phase) =
        (inp.pos, inp.vel, inp.rho, inp.pressure, inp.vol, inp.phase);

    let body = |i: usize| -> (Vec3, f64) {
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
        for chunk in inp.lists.near(i).chunks(CHUNK) {
            // gather, then the per-pair geometry branch-free over the chunk (vectorisable)
            let (mut dx, mut dy, mut dz, mut c) =
                ([0.0; CHUNK], [0.0; CHUNK], [0.0; CHUNK], [0.0; CHUNK]);
            for (n, &j) in chunk.iter().enumerate() {
                let d = pi - pos[j as usize];
                dx[n] = d.x;
                dy[n] = d.y;
                dz[n] = d.z;
                if IT {
                    c[n] = coeff_row[phase[j as usize] as usize];
                }
            }
            let (mut inv_r, mut dw, mut pot) = ([0.0; CHUNK], [0.0; CHUNK], [0.0; CHUNK]);
            let mut inside = [false; CHUNK];
            for n in 0..CHUNK {
                let r2 = dx[n] * dx[n] + dy[n] * dy[n] + dz[n] * dz[n];
                let r = r2.sqrt();
                let ir = 1.0 / r;
                // coincident particles have no direction: no force (the health check reports them)
                let apart = r2 > 0.0;
                inv_r[n] = if apart { ir } else { 0.0 };
                inside[n] = apart && r2 < support2;
                let d = k.dw_dr_inside(r.min(support));
                dw[n] = if inside[n] { d } else { 0.0 };
                if IT {
                    // Eq. (15), Natsui 2021 (physics.md §4): C_ij (r − l0)(r − r_e) e_ij
                    let v = c[n] * (r - l0) * (r - r_e) * ir;
                    pot[n] = if apart && r2 < re2 { v } else { 0.0 };
                }
            }
            for n in 0..chunk.len() {
                let rij = Vec3::new(dx[n], dy[n], dz[n]);
                if inside[n] {
                    let j = chunk[n] as usize;
                    let e = rij * inv_r[n];
                    let dwn = dw[n];
                    let is_wall = WALL && j >= n_fluid;
                    let v_j = vol[j];
                    if PRES {
                        // Eq. (11), Natsui 2021: −(p_i V_i² + p_j V_j²) ∇_i W_ij
                        f -= e * ((pv_i + pre[j] * v_j * v_j) * dwn);
                    }
                    if AV || VISC || CONT {
                        let vij = vi - vel[j];
                        if AV && !is_wall {
                            let vr = vij.dot(&rij);
                            if vr < 0.0 {
                                let phi = h * vr / (rij.norm_squared() + eta2); // Eq. (13), Natsui 2021
                                let m_j = inp.mass[phase[j] as usize];
                                // Eq. (12), Natsui 2021 with m_i m_j Π_ij (physics.md §3)
                                let pi_ij = (-alpha1 * c_s * phi + alpha2 * phi * phi)
                                    / (0.5 * (rho_i + rho[j]));
                                f -= e * (m_i * m_j * pi_ij * dwn);
                            }
                        }
                        if VISC && (!is_wall || inp.wall_no_slip[j - n_fluid]) {
                            // Eq. (11), Natsui 2021: 2μiμj/(μi+μj) (V_i² + V_j²) (dW/dr / r) v_ij
                            let mu_ij = mu_row[phase[j] as usize];
                            f += vij * (mu_ij * (v2_i + v_j * v_j) * dwn * inv_r[n]);
                        }
                        if CONT {
                            dr += v_j * vij.dot(&e) * dwn; // Σ_j V_j v_ij·∇_i W_ij
                        }
                    }
                }
                if IT {
                    f += rij * pot[n];
                }
            }
        }
        if IT {
            far_potential(&mut f, pi, inp.lists.far(i), pos, phase, coeff_row, l0, r_e);
        }
        (f / m_i + inp.gravity, rho_i * dr)
    };

    if CONT {
        acc.par_iter_mut()
            .zip(drho.par_iter_mut())
            .enumerate()
            .for_each(|(i, (a, d))| {
                let (ai, di) = body(i);
                *a = ai;
                *d = di;
            });
    } else {
        acc.par_iter_mut()
            .enumerate()
            .for_each(|(i, a)| *a = body(i).0);
    }
}

/// Neighbours processed together by [`far_potential`].
const CHUNK: usize = 16;

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
