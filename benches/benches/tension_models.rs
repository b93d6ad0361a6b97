//! A full time step per tension model on the same scene: `tension_models/20k/{potential,
//! surface_stress, surface_force}`, a water drop in a host liquid filling a periodic cube of
//! 27³ = 19,683 particles ([`benches::drop_in_host_toml`]). The potential at its default
//! setting (h = 1.05 l0), the continuum models at the convergence case's h = 1.3 l0; all with
//! r_e = 4.2 l0, and the surface force again with its colour kernel reaching 3.6 l0
//! (`surface_force@re3.6`: 0.62 times the neighbours; docs/findings.md, the colour kernel's
//! reach).
//!
//! Throughput is in fluid particles (host included), so criterion's elements/s are
//! particle-steps per second. The three are measured in one session, one after another; run
//! it twice and compare the ratios. A continuum model needs the host, the potential does not:
//! a free drop under the potential has only the drop's particles to step.
//!
//! Run: `cargo bench -p benches --bench tension_models`.

mod common;

use benches::{drop_in_host, sampling};
use criterion::{criterion_group, criterion_main, BatchSize, BenchmarkId, Criterion, Throughput};
use std::cell::OnceCell;

/// The tension models compared.
const MODELS: [&str; 4] = [
    "potential",
    "surface_stress",
    "surface_force",
    "surface_force@re3.6",
];

fn tension_models(c: &mut Criterion) {
    let n_side = 27;
    let mut group = c.benchmark_group("tension_models");
    common::configure(&mut group, sampling(n_side, true));
    group.throughput(Throughput::Elements(n_side.pow(3) as u64));
    for model in MODELS {
        let sim = OnceCell::new();
        group.bench_function(BenchmarkId::new("20k", model), |b| {
            let sim = sim.get_or_init(|| drop_in_host(n_side, model));
            b.iter_batched_ref(
                || sim.clone(),
                |s| s.step(f64::INFINITY).expect("benchmark step"),
                BatchSize::PerIteration,
            )
        });
    }
    group.finish();
}

criterion_group!(benches, tension_models);
criterion_main!(benches);
