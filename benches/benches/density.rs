//! Density: `physics::density::summation` (number-density summation over the near lists).
//!
//! - `density/summation/{20k,160k}`: the summation density of every fluid particle, on the
//!   seeded, perturbed matte cube with the lists of `r_e` = 2.1 l0 (the summation reads only
//!   the near part of the lists).
//!
//! Throughput is in fluid particles, so criterion's elements/s are particle-updates per second.
//!
//! Run: `cargo bench -p benches --bench density [-- FILTER]`. Reports go to
//! `target/criterion/`.

mod common;

use benches::{fixture, sampling, K, SIZES};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use solver::physics::density;
use std::cell::OnceCell;
use std::hint::black_box;

fn summation(c: &mut Criterion) {
    let mut group = c.benchmark_group("density");
    for (size, n_side) in SIZES {
        common::configure(&mut group, sampling(n_side, false));
        group.throughput(Throughput::Elements(n_side.pow(3) as u64));
        // built on first use, so that a filtered run builds only what it measures (criterion
        // calls the closure once per warm-up round and sample)
        let sim = OnceCell::new();
        group.bench_function(BenchmarkId::new("summation", size), |b| {
            let sim = sim.get_or_init(|| fixture(n_side, 2.1, false));
            let m = &sim.model;
            let p = &sim.particles;
            let kernel = m.kernel_of::<K>();
            let mut rho = vec![0.0; p.n_fluid];
            let mut active = vec![0; p.n_fluid];
            let active_radius = m.support_m.max(m.r_e_m);
            b.iter(|| {
                density::summation(
                    &kernel,
                    &p.pos,
                    &p.phase,
                    &m.rho0,
                    &sim.search.lists,
                    m.lattice_kernel_sum,
                    active_radius,
                    &mut rho,
                    &mut active,
                );
                black_box(&rho);
            })
        });
    }
    group.finish();
}

criterion_group!(benches, summation);
criterion_main!(benches);
