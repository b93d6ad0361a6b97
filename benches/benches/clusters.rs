//! How fast can the potential's pair loop be? A probe, not the solver's code path: the
//! potential's pair force (Kondo's `P'(r) = (r − l0)(r − r_e)`, Eq. (15), Natsui 2021, one unit
//! coefficient for every pair) summed over every neighbour within `r_e`, on the seeded,
//! perturbed 20 k cube, by six loops:
//!
//! - `clusters/list/re{2.1,4.2}`: the solver's layout — each particle's own list of neighbour
//!   indices (here plain `u32`, in index order), positions gathered through it, one particle's
//!   sum at a time;
//! - `clusters/list_r2/re{2.1,4.2}`: the same loop with a force polynomial in `r²` (same zeros,
//!   not the solver's force): no square root and no division per pair — what those cost;
//! - `clusters/lanes_f64/re{2.1,4.2}`: the list loop with its arithmetic in 8 lanes (the
//!   neighbours gathered 8 at a time, the force computed over the lanes as vector operations,
//!   summed per lane, the lanes added at the end): the fastest exact loop of the solver's
//!   force written here;
//! - `clusters/lanes_r2/re{2.1,4.2}`: the lanes with the force polynomial in `r²` of
//!   `list_r2` — what a sqrt-free potential would cost in lanes;
//! - `clusters/lanes_f32/re{2.1,4.2}`: the same in single precision (positions from the cube's
//!   corner, each particle's lanes added in `f64`) — what reduced precision would buy (its
//!   largest force error is printed at set-up);
//! - `clusters/cluster4/re{2.1,4.2}`: the list's arithmetic, with the particles grouped in
//!   clusters of 4 (columns 2 l0 × 2 l0 across, sorted by height, padded with far-away dummies
//!   to a multiple of 4) and one list of neighbouring clusters per cluster (bounding boxes
//!   closer than `r_e`); each entry is 4 × 4 pairs, the cluster's 4 particles in the vector
//!   lanes and each neighbour broadcast against them, the pairs beyond `r_e` masked.
//!
//! All evaluate each pair from both sides (no scattered writes). Throughput is in pairs within
//! `r_e` (both directions), so criterion's elements/s are useful pair evaluations per second;
//! the cluster layout also evaluates masked pairs (its efficiency is printed at set-up). The
//! forces of the clusters and of the `f64` lanes are compared with the list's before timing
//! (another summation order: within 1e-12 of the largest force).
//!
//! Run: `cargo bench -p benches --bench clusters [-- FILTER]`.

mod common;

use benches::{fixture, re_label, sampling, SIZES};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use solver::physics::surface_tension::Kondo2007Potential;
use std::hint::black_box;

/// Particles per cluster.
const W: usize = 4;

/// Positions in structure-of-arrays form [m].
struct Soa {
    x: Vec<f64>,
    y: Vec<f64>,
    z: Vec<f64>,
}

/// Each particle's neighbours within `r_e` (both directions, index order).
struct Lists {
    start: Vec<u32>,
    ids: Vec<u32>,
}

/// Particles regrouped in clusters of [`W`], and each cluster's neighbouring clusters.
struct Clusters {
    pos: Soa,
    /// The original index of each slot (`u32::MAX` for a dummy).
    origin: Vec<u32>,
    start: Vec<u32>,
    ids: Vec<u32>,
}

fn neighbour_lists(p: &Soa, r_e_m: f64) -> Lists {
    let n = p.x.len();
    let lo = [min(&p.x), min(&p.y), min(&p.z)];
    let cell = |v: f64, k: usize| ((v - lo[k]) / r_e_m) as i64;
    let mut grid: std::collections::HashMap<(i64, i64, i64), Vec<u32>> = Default::default();
    for i in 0..n {
        let key = (cell(p.x[i], 0), cell(p.y[i], 1), cell(p.z[i], 2));
        grid.entry(key).or_default().push(i as u32);
    }
    let (mut start, mut ids) = (vec![0u32], Vec::new());
    for i in 0..n {
        let (cx, cy, cz) = (cell(p.x[i], 0), cell(p.y[i], 1), cell(p.z[i], 2));
        let mut row = Vec::new();
        for dz in -1..=1 {
            for dy in -1..=1 {
                for dx in -1..=1 {
                    for &j in grid.get(&(cx + dx, cy + dy, cz + dz)).into_iter().flatten() {
                        let j_ = j as usize;
                        let r2 = (p.x[i] - p.x[j_]).powi(2)
                            + (p.y[i] - p.y[j_]).powi(2)
                            + (p.z[i] - p.z[j_]).powi(2);
                        if j_ != i && r2 < r_e_m * r_e_m {
                            row.push(j);
                        }
                    }
                }
            }
        }
        row.sort_unstable();
        ids.extend(row);
        start.push(ids.len() as u32);
    }
    Lists { start, ids }
}

fn min(v: &[f64]) -> f64 {
    v.iter().copied().fold(f64::INFINITY, f64::min)
}

fn clusters(p: &Soa, l0_m: f64, r_e_m: f64) -> Clusters {
    let n = p.x.len();
    let (x0, y0) = (min(&p.x), min(&p.y));
    let column = |i: usize| {
        (
            ((p.y[i] - y0) / (2.0 * l0_m)) as i64,
            ((p.x[i] - x0) / (2.0 * l0_m)) as i64,
        )
    };
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by(|&a, &b| column(a).cmp(&column(b)).then(p.z[a].total_cmp(&p.z[b])));
    let far = 1e3 * r_e_m;
    let (mut pos, mut origin) = (
        Soa {
            x: vec![],
            y: vec![],
            z: vec![],
        },
        Vec::new(),
    );
    let mut k = 0;
    while k < n {
        let col = column(order[k]);
        let end = (k..n).find(|&m| column(order[m]) != col).unwrap_or(n);
        for &i in &order[k..end] {
            pos.x.push(p.x[i]);
            pos.y.push(p.y[i]);
            pos.z.push(p.z[i]);
            origin.push(i as u32);
        }
        // dummies far apart from everything (and from each other)
        while origin.len() % W != 0 {
            let d = far * (1.0 + origin.len() as f64);
            pos.x.push(d);
            pos.y.push(d);
            pos.z.push(d);
            origin.push(u32::MAX);
        }
        k = end;
    }
    let nc = origin.len() / W;
    let bbox = |c: usize| {
        let real = (c * W..c * W + W).filter(|&s| origin[s] != u32::MAX);
        let mut b = [
            f64::INFINITY,
            -f64::INFINITY,
            f64::INFINITY,
            -f64::INFINITY,
            f64::INFINITY,
            -f64::INFINITY,
        ];
        for s in real {
            for (k, v) in [pos.x[s], pos.y[s], pos.z[s]].into_iter().enumerate() {
                b[2 * k] = b[2 * k].min(v);
                b[2 * k + 1] = b[2 * k + 1].max(v);
            }
        }
        b
    };
    let boxes: Vec<_> = (0..nc).map(bbox).collect();
    let gap = |a: &[f64; 6], b: &[f64; 6]| {
        (0..3)
            .map(|k| {
                (a[2 * k] - b[2 * k + 1])
                    .max(b[2 * k] - a[2 * k + 1])
                    .max(0.0)
                    .powi(2)
            })
            .sum::<f64>()
    };
    let (mut start, mut ids) = (vec![0u32], Vec::new());
    for a in &boxes {
        for (j, b) in boxes.iter().enumerate() {
            if gap(a, b) < r_e_m * r_e_m {
                ids.push(j as u32);
            }
        }
        start.push(ids.len() as u32);
    }
    Clusters {
        pos,
        origin,
        start,
        ids,
    }
}

/// The force on every particle through its own list, with `s(r²)` the pair's force over its
/// distance [N/m per unit coefficient] (called for every entry, masked beyond `r_e`).
fn sum_lists(p: &Soa, l: &Lists, r_e_m: f64, s_of_r2: impl Fn(f64) -> f64, f: &mut [[f64; 3]]) {
    let r_e2 = r_e_m * r_e_m;
    for (i, fi) in f.iter_mut().enumerate() {
        let (xi, yi, zi) = (p.x[i], p.y[i], p.z[i]);
        let mut acc = [0.0; 3];
        for &j in &l.ids[l.start[i] as usize..l.start[i + 1] as usize] {
            let j = j as usize;
            let (dx, dy, dz) = (xi - p.x[j], yi - p.y[j], zi - p.z[j]);
            let r2 = dx * dx + dy * dy + dz * dz;
            let s = s_of_r2(r2);
            let s = if r2 < r_e2 { s } else { 0.0 };
            acc[0] += s * dx;
            acc[1] += s * dy;
            acc[2] += s * dz;
        }
        *fi = acc;
    }
}

/// Lanes of the lane-wise loops.
const L: usize = 8;

/// The list loop with its arithmetic in [`L`] lanes: each particle's neighbours gathered
/// [`L`] at a time into local arrays (the tail padded with a distance beyond `r_e`), the
/// force over the lanes (one vector operation per stage), summed per lane and the lanes
/// added in lane order at the end — another summation order than [`sum_lists`]. Generic
/// over the float type `T` of the positions, the arithmetic and the lanes' sums (`f64` or
/// `f32`); the lanes are added in `f64`.
fn sum_lists_lanes<T: Lane>(
    p: &[Vec<T>; 3],
    l: &Lists,
    r_e_m: f64,
    s_of_r2: impl Fn(T) -> T,
    f: &mut [[f64; 3]],
) {
    let r_e2 = T::from_f64(r_e_m * r_e_m);
    let pad = T::from_f64(2.0 * r_e_m);
    let zero = T::from_f64(0.0);
    for (i, fi) in f.iter_mut().enumerate() {
        let xi = [p[0][i], p[1][i], p[2][i]];
        let mut acc = [[zero; L]; 3];
        for ch in l.ids[l.start[i] as usize..l.start[i + 1] as usize].chunks(L) {
            let mut d = [[pad; L]; 3];
            for (n, &j) in ch.iter().enumerate() {
                for k in 0..3 {
                    d[k][n] = xi[k] - p[k][j as usize];
                }
            }
            let r2: [T; L] =
                std::array::from_fn(|n| d[0][n] * d[0][n] + d[1][n] * d[1][n] + d[2][n] * d[2][n]);
            let s: [T; L] = std::array::from_fn(|n| {
                let s = s_of_r2(r2[n]);
                if r2[n] < r_e2 {
                    s
                } else {
                    zero
                }
            });
            for k in 0..3 {
                for n in 0..L {
                    acc[k][n] = acc[k][n] + s[n] * d[k][n];
                }
            }
        }
        *fi = std::array::from_fn(|k| acc[k].iter().map(|v| v.to_f64()).sum());
    }
}

/// A float type of the lane-wise loop.
trait Lane:
    Copy
    + PartialOrd
    + std::ops::Add<Output = Self>
    + std::ops::Sub<Output = Self>
    + std::ops::Mul<Output = Self>
    + std::ops::Div<Output = Self>
{
    fn from_f64(v: f64) -> Self;
    fn to_f64(self) -> f64;
    fn sqrt(self) -> Self;
}

impl Lane for f64 {
    fn from_f64(v: f64) -> Self {
        v
    }
    fn to_f64(self) -> f64 {
        self
    }
    fn sqrt(self) -> Self {
        f64::sqrt(self)
    }
}

impl Lane for f32 {
    fn from_f64(v: f64) -> Self {
        v as f32
    }
    fn to_f64(self) -> f64 {
        self as f64
    }
    fn sqrt(self) -> Self {
        f32::sqrt(self)
    }
}

/// `P'(r)/r = (r² − l0²)(r² − r_e²) / (r (r + l0)(r + r_e))` with the denominator replaced by
/// the constant `(l0 + r_e)³`: the same zeros, not the same force (not the solver's physics);
/// no square root and no division — what those cost.
fn polynomial_in_r2<T: Lane>(pot: &Kondo2007Potential) -> impl Fn(T) -> T + Copy {
    let (l02, re2) = (
        T::from_f64(pot.l0_m * pot.l0_m),
        T::from_f64(pot.r_e_m * pot.r_e_m),
    );
    let scale = T::from_f64(1.0 / (pot.l0_m + pot.r_e_m).powi(3));
    move |r2: T| (r2 - l02) * (r2 - re2) * scale
}

/// Kondo's `P'(r)/r = (r − l0)(r − r_e)/r` from `r²`: a square root and a division.
fn kondo_over_r<T: Lane>(pot: &Kondo2007Potential) -> impl Fn(T) -> T + Copy {
    let (l0, re) = (T::from_f64(pot.l0_m), T::from_f64(pot.r_e_m));
    move |r2: T| {
        let r = r2.sqrt();
        (r - l0) * (r - re) / r
    }
}

/// The force on every slot through the cluster lists [N per unit coefficient].
fn sum_clusters(c: &Clusters, r_e_m: f64, s_of_r2: impl Fn(f64) -> f64, f: &mut [[f64; 3]]) {
    let r_e2 = r_e_m * r_e_m;
    let p = &c.pos;
    let lanes = |v: &[f64], k: usize| -> [f64; W] { v[k..k + W].try_into().expect("W slots") };
    for (ci, fc) in f.chunks_exact_mut(W).enumerate() {
        let i0 = ci * W;
        let (xi, yi, zi) = (lanes(&p.x, i0), lanes(&p.y, i0), lanes(&p.z, i0));
        // the 4 particles of cluster `ci` in the lanes; each neighbour broadcast against them
        let mut acc = [[0.0; W]; 3];
        for &cj in &c.ids[c.start[ci] as usize..c.start[ci + 1] as usize] {
            let j0 = cj as usize * W;
            let (xj, yj, zj) = (lanes(&p.x, j0), lanes(&p.y, j0), lanes(&p.z, j0));
            for b in 0..W {
                // stage by stage over the 4 lanes, so that each stage is one vector operation
                let dx: [f64; W] = std::array::from_fn(|a| xi[a] - xj[b]);
                let dy: [f64; W] = std::array::from_fn(|a| yi[a] - yj[b]);
                let dz: [f64; W] = std::array::from_fn(|a| zi[a] - zj[b]);
                let r2: [f64; W] =
                    std::array::from_fn(|a| dx[a] * dx[a] + dy[a] * dy[a] + dz[a] * dz[a]);
                let s: [f64; W] = std::array::from_fn(|a| s_of_r2(r2[a]));
                // beyond r_e, and the particle itself (r = 0: s is NaN there)
                let s: [f64; W] = std::array::from_fn(|a| {
                    if (r2[a] < r_e2) & (r2[a] > 0.0) {
                        s[a]
                    } else {
                        0.0
                    }
                });
                for a in 0..W {
                    acc[0][a] += s[a] * dx[a];
                    acc[1][a] += s[a] * dy[a];
                    acc[2][a] += s[a] * dz[a];
                }
            }
        }
        for (a, fa) in fc.iter_mut().enumerate() {
            *fa = [acc[0][a], acc[1][a], acc[2][a]];
        }
    }
}

fn probe(c: &mut Criterion) {
    let mut group = c.benchmark_group("clusters");
    let (_, n_side) = SIZES[0]; // the 20 k cube
    common::configure(&mut group, sampling(n_side, false));
    for re in [2.1, 4.2] {
        let sim = fixture(n_side, re, false);
        let m = &sim.model;
        let pp = &sim.particles;
        let n = pp.n_fluid;
        let soa = Soa {
            x: pp.pos[..n].iter().map(|v| v.x).collect(),
            y: pp.pos[..n].iter().map(|v| v.y).collect(),
            z: pp.pos[..n].iter().map(|v| v.z).collect(),
        };
        let pot = m.potential;
        let (kondo, kondo32) = (kondo_over_r::<f64>(&pot), kondo_over_r::<f32>(&pot));
        let poly = polynomial_in_r2::<f64>(&pot);
        let lists = neighbour_lists(&soa, m.r_e_m);
        let cl = clusters(&soa, m.l0_m, m.r_e_m);
        let pairs = lists.ids.len();
        let evaluated = cl.ids.len() * W * W;
        // the same forces from both layouts before anything is timed
        let mut f_list = vec![[0.0; 3]; n];
        let mut f_cl = vec![[0.0; 3]; cl.origin.len()];
        sum_lists(&soa, &lists, m.r_e_m, kondo, &mut f_list);
        sum_clusters(&cl, m.r_e_m, kondo, &mut f_cl);
        let largest = f_list.iter().flatten().fold(0.0f64, |a, v| a.max(v.abs()));
        for (s, &o) in cl.origin.iter().enumerate() {
            if o != u32::MAX {
                for k in 0..3 {
                    let d = (f_cl[s][k] - f_list[o as usize][k]).abs();
                    assert!(d <= 1e-12 * largest, "layouts disagree at {o}: {d:e}");
                }
            }
        }
        // the lane-wise loops: f64 on the same positions; f32 on positions from the cube's
        // corner (a 1 mm cube: f32 spacing of at most 1.2e-10 m there, 3e-6 l0)
        let p64 = [soa.x.clone(), soa.y.clone(), soa.z.clone()];
        let corner = [min(&soa.x), min(&soa.y), min(&soa.z)];
        let p32: [Vec<f32>; 3] =
            std::array::from_fn(|k| p64[k].iter().map(|v| (v - corner[k]) as f32).collect());
        let mut f_lanes = vec![[0.0; 3]; n];
        sum_lists_lanes(&p64, &lists, m.r_e_m, kondo, &mut f_lanes);
        let mut f_32 = vec![[0.0; 3]; n];
        sum_lists_lanes(&p32, &lists, m.r_e_m, kondo32, &mut f_32);
        let worst = |g: &[[f64; 3]]| {
            g.iter()
                .zip(&f_list)
                .flat_map(|(a, b)| (0..3).map(move |k| (a[k] - b[k]).abs()))
                .fold(0.0f64, f64::max)
                / largest
        };
        // another summation order in f64: rounding of ~300 terms, far below 1e-12
        assert!(worst(&f_lanes) <= 1e-12, "f64 lanes disagree");
        // f32: rounding of 6e-8 per operation over ~30–260 terms that largely cancel; 1e-4
        // only catches a wrong loop (off by the order of the force), the error is printed
        assert!(worst(&f_32) <= 1e-4, "f32 lanes disagree");
        println!(
            "r_e = {re} l0: the f32 lanes' largest force error {:.2e} of the largest force",
            worst(&f_32)
        );
        println!(
            "r_e = {re} l0: {n} particles, {:.1} neighbours each; {} clusters ({} slots), {:.1} neighbouring clusters each, {:.0} % of the evaluated pairs within r_e",
            pairs as f64 / n as f64,
            cl.origin.len() / W,
            cl.origin.len(),
            cl.ids.len() as f64 / (cl.origin.len() / W) as f64,
            100.0 * pairs as f64 / evaluated as f64
        );
        group.throughput(Throughput::Elements(pairs as u64));
        let mut time = |name: &str, run: &mut dyn FnMut()| {
            group.bench_function(BenchmarkId::new(name, re_label(re)), |b| b.iter(&mut *run));
        };
        // the inputs through `black_box` at every iteration: nothing is hoisted out of the timing
        time("list", &mut || {
            sum_lists(black_box(&soa), &lists, m.r_e_m, kondo, &mut f_list)
        });
        time("list_r2", &mut || {
            sum_lists(black_box(&soa), &lists, m.r_e_m, poly, &mut f_list)
        });
        time("lanes_f64", &mut || {
            sum_lists_lanes(black_box(&p64), &lists, m.r_e_m, kondo, &mut f_lanes)
        });
        time("lanes_r2", &mut || {
            sum_lists_lanes(black_box(&p64), &lists, m.r_e_m, poly, &mut f_lanes)
        });
        time("lanes_f32", &mut || {
            sum_lists_lanes(black_box(&p32), &lists, m.r_e_m, kondo32, &mut f_32)
        });
        time("cluster4", &mut || {
            sum_clusters(black_box(&cl), m.r_e_m, kondo, &mut f_cl)
        });
    }
    group.finish();
}

criterion_group!(benches, probe);
criterion_main!(benches);
