//! Laminar viscosity integrated implicitly: each half kick of the step solves the viscous
//! term by backward Euler, by conjugate gradients (docs/model.md §3, "Implicit viscosity").
//!
//! The laminar term (Eq. (11), Natsui 2021) is linear in the velocities,
//! `F_i = −Σ_j c_ij (v_i − v_j)` [N] with `c_ij = μ_ij (V_i² + V_j²) (−(dW/dr)/r) ≥ 0` [N·s/m]
//! (`c_ij = c_ji`): a weighted graph Laplacian `K`, symmetric and positive semi-definite. A
//! half kick of `τ` [s] from `u` with the other forces `M a` becomes
//! `(M/τ + K) u' = (M/τ)(u + τ a)`, whose matrix is symmetric positive definite: stable for
//! any `τ`.
//!
//! The solve is matrix-free over the pairs within the kernel support (the explicit term's
//! pairs), with the Jacobi preconditioner, starting from the explicit kick's velocities; each
//! product is a gather per particle and each inner product is summed in fixed blocks in
//! particle order, so the result is the same to the bit for any number of threads. Wall
//! particles take no part (walls are free-slip for the viscosity; validation rejects no-slip
//! walls with this solver).

use crate::kernel::Kernel;
use crate::neighbours::NeighbourLists;
/// Particles per block of the inner products: the pair loop's fixed blocks (the sums do not
/// depend on threads).
pub use crate::physics::forces::fused::BLOCK;
use crate::state::Vec3;
use rayon::prelude::*;

/// The coefficients `c_ij` of one set of positions, row by row.
#[derive(Clone, Debug, Default)]
pub struct ViscousOperator {
    /// Start of each fluid particle's row in `j`/`c` (length `n + 1`).
    start: Vec<usize>,
    /// Neighbour index (fluid) per entry.
    j: Vec<u32>,
    /// `c_ij` [N·s/m] per entry.
    c: Vec<f64>,
    /// `Σ_j c_ij` [N·s/m] per row.
    sum_c: Vec<f64>,
    /// Particle mass `m_i` [kg].
    mass: Vec<f64>,
}

/// What [`ViscousOperator::build`] reads of the state.
#[derive(Clone, Copy, Debug)]
pub struct ViscousInput<'a> {
    /// Positions [m] (fluid first).
    pub pos: &'a [Vec3],
    /// Volumes `m/ρ` [m³].
    pub vol: &'a [f64],
    /// Phase per particle.
    pub phase: &'a [u8],
    /// Mass per phase [kg].
    pub mass: &'a [f64],
    /// Pair viscosity [Pa·s], row-major by phase.
    pub mu_pair: &'a [f64],
    /// Number of phases (row length of `mu_pair`).
    pub n_phases: usize,
    /// Number of fluid particles.
    pub n_fluid: usize,
    /// The neighbour lists (near lists hold every pair within the support).
    pub lists: &'a NeighbourLists,
}

/// The outcome of one solve.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Solve {
    /// Conjugate-gradient iterations taken.
    pub iterations: u32,
    /// `‖b − A v‖ / ‖b‖` at the end (0 when `b = 0`).
    pub relative_residual: f64,
    /// Whether it reached the tolerance.
    pub converged: bool,
}

impl ViscousOperator {
    /// Fills the operator of the current state.
    pub fn build<K: Kernel>(&mut self, k: &K, s: &ViscousInput) {
        let n = s.n_fluid;
        let support2 = k.support_m() * k.support_m();
        // each block's rows, then concatenated in block order
        let blocks: Vec<(Vec<usize>, Vec<u32>, Vec<f64>)> = (0..n.div_ceil(BLOCK))
            .into_par_iter()
            .map(|b| {
                let (mut len, mut js, mut cs) = (Vec::new(), Vec::new(), Vec::new());
                for i in b * BLOCK..((b + 1) * BLOCK).min(n) {
                    let before = js.len();
                    let (xi, vi2) = (s.pos[i], s.vol[i] * s.vol[i]);
                    let row = &s.mu_pair[s.phase[i] as usize * s.n_phases..][..s.n_phases];
                    for j in s.lists.near(i).filter(|&j| j < n) {
                        let r2 = s.lists.delta(xi, s.pos[j]).norm_squared();
                        if !(r2 > 0.0 && r2 < support2) {
                            continue;
                        }
                        let r = r2.sqrt();
                        let vj2 = s.vol[j] * s.vol[j];
                        // Eq. (11), Natsui 2021: μ_ij (V_i² + V_j²) (dW/dr / r), here negated
                        let c = -(row[s.phase[j] as usize] * (vi2 + vj2) * (k.dw_dr_inside(r) / r));
                        if c > 0.0 {
                            js.push(j as u32);
                            cs.push(c);
                        }
                    }
                    len.push(js.len() - before);
                }
                (len, js, cs)
            })
            .collect();
        self.start.clear();
        self.j.clear();
        self.c.clear();
        self.start.push(0);
        for (len, js, cs) in blocks {
            for l in len {
                let last = *self.start.last().unwrap();
                self.start.push(last + l);
            }
            self.j.extend_from_slice(&js);
            self.c.extend_from_slice(&cs);
        }
        let (start, c) = (&self.start, &self.c);
        self.sum_c.clear();
        self.sum_c
            .extend((0..n).map(|i| c[start[i]..start[i + 1]].iter().sum::<f64>()));
        self.mass.clear();
        self.mass
            .extend((0..n).map(|i| s.mass[s.phase[i] as usize]));
    }

    /// Number of rows (fluid particles).
    pub fn len(&self) -> usize {
        self.sum_c.len()
    }

    /// Whether the operator has no rows.
    pub fn is_empty(&self) -> bool {
        self.sum_c.is_empty()
    }

    /// Particle masses [kg], one per row.
    pub fn mass(&self) -> &[f64] {
        &self.mass
    }

    /// `y = diag ∘ x − Σ_j c_ij x_j` [N] (with `diag = m/τ + Σ_j c_ij`: `(M/τ + K) x`);
    /// returns `x·y`, summed in blocks of [`BLOCK`] in particle order.
    fn apply(&self, diag: &[f64], x: &[Vec3], y: &mut [Vec3]) -> f64 {
        let partial: Vec<f64> = (y.par_chunks_mut(BLOCK).enumerate())
            .map(|(b, ys)| {
                let mut xy = 0.0;
                for (k, yi) in ys.iter_mut().enumerate() {
                    let i = b * BLOCK + k;
                    let (lo, hi) = (self.start[i], self.start[i + 1]);
                    let mut off = Vec3::zeros();
                    for (&j, &c) in self.j[lo..hi].iter().zip(&self.c[lo..hi]) {
                        off += x[j as usize] * c;
                    }
                    *yi = x[i] * diag[i] - off;
                    xy += x[i].dot(yi);
                }
                xy
            })
            .collect();
        partial.iter().sum()
    }

    /// The viscous force `−K v` [N] on each fluid particle (for tests and diagnostics).
    pub fn force(&self, v: &[Vec3]) -> Vec<Vec3> {
        let mut y = vec![Vec3::zeros(); v.len()];
        let _ = self.apply(&self.sum_c, v, &mut y);
        y.iter().map(|y| -y).collect()
    }

    /// Replaces `v` — the velocities [m/s] the kick of `tau_s` [s] gives without viscosity,
    /// `u + τ a` — by the solution `u'` of `(M/τ + K) u' = (M/τ) v`, to
    /// `‖residual‖ ≤ tolerance ‖(M/τ) v‖` or `max_iterations`.
    pub fn solve(&self, v: &mut [Vec3], tau_s: f64, tolerance: f64, max_iterations: u32) -> Solve {
        let n = self.len();
        assert_eq!(v.len(), n, "one velocity per fluid particle");
        let diag: Vec<f64> = (self.mass.par_iter().zip(&self.sum_c))
            .map(|(m, c)| m / tau_s + c)
            .collect();
        let b: Vec<Vec3> = (v.par_iter().zip(&self.mass))
            .map(|(u, m)| u * (m / tau_s))
            .collect();
        let b_norm = dot(&b, &b).sqrt();
        let mut ap = vec![Vec3::zeros(); n];
        self.apply(&diag, v, &mut ap);
        let mut r: Vec<Vec3> = b.par_iter().zip(&ap).map(|(b, a)| b - a).collect();
        let mut z: Vec<Vec3> = r.par_iter().zip(&diag).map(|(r, d)| r / *d).collect();
        let mut p = z.clone();
        let mut rz = dot(&r, &z);
        let mut res = dot(&r, &r).sqrt();
        let mut iterations = 0;
        while res > tolerance * b_norm && iterations < max_iterations {
            let alpha = rz / self.apply(&diag, &p, &mut ap);
            // v += αp, r −= α Ap, z = r/diag, and the sums r·z, r·r: one pass, fixed blocks
            let sums: Vec<(f64, f64)> = (v.par_chunks_mut(BLOCK))
                .zip(r.par_chunks_mut(BLOCK))
                .zip(z.par_chunks_mut(BLOCK))
                .zip(p.par_chunks(BLOCK).zip(ap.par_chunks(BLOCK)))
                .zip(diag.par_chunks(BLOCK))
                .map(|((((v, r), z), (p, ap)), d)| {
                    let (mut rz, mut rr) = (0.0, 0.0);
                    for k in 0..v.len() {
                        v[k] += p[k] * alpha;
                        r[k] -= ap[k] * alpha;
                        z[k] = r[k] / d[k];
                        rz += r[k].dot(&z[k]);
                        rr += r[k].dot(&r[k]);
                    }
                    (rz, rr)
                })
                .collect();
            let rz_next: f64 = sums.iter().map(|s| s.0).sum();
            res = sums.iter().map(|s| s.1).sum::<f64>().sqrt();
            let beta = rz_next / rz;
            rz = rz_next;
            p.par_iter_mut()
                .zip(&z)
                .for_each(|(p, z)| *p = z + *p * beta);
            iterations += 1;
        }
        Solve {
            iterations,
            relative_residual: if b_norm > 0.0 { res / b_norm } else { 0.0 },
            converged: res <= tolerance * b_norm,
        }
    }
}

/// `Σ_i a_i·b_i`, summed in blocks of [`BLOCK`] in particle order (thread-independent).
pub fn dot(a: &[Vec3], b: &[Vec3]) -> f64 {
    let partial: Vec<f64> = a
        .par_chunks(BLOCK)
        .zip(b.par_chunks(BLOCK))
        .map(|(a, b)| a.iter().zip(b).map(|(a, b)| a.dot(b)).sum::<f64>())
        .collect();
    partial.iter().sum()
}
