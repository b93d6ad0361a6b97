//! A full time step: `Simulation::step(f64::INFINITY)` (kick, drift, density, EOS, all forces,
//! kick, health check).
//!
//! - `step/{20k,160k}/re{2.1,4.2}`: the matte cube with interfacial tension, laminar and
//!   artificial viscosity; `r_e` = 2.1 l0 is the performance-target scene, 4.2 l0 the
//!   solver's default cut-off.
//!
//! Each iteration steps a fresh clone of the seeded, perturbed state of `benches::fixture`
//! (the clone is made outside the timed region), so every sample times the same step. The
//! lists were just built, so the step does not rebuild them: this is the common step, the
//! amortised search cost is in `neighbours/rebuild`. Throughput is in fluid particles, so
//! criterion's elements/s are particle-steps per second.
//!
//! Run: `cargo bench -p benches --bench step [-- FILTER]` (e.g. `-- 20k`). Reports go to
//! `target/criterion/`.

mod common;

use benches::{fixture, re_label, sampling, CUTOFFS, SIZES};
use criterion::{criterion_group, criterion_main, BatchSize, BenchmarkId, Criterion, Throughput};
use std::cell::OnceCell;

fn step(c: &mut Criterion) {
    let mut group = c.benchmark_group("step");
    for (size, n_side) in SIZES {
        common::configure(&mut group, sampling(n_side, true));
        for re in CUTOFFS {
            group.throughput(Throughput::Elements(n_side.pow(3) as u64));
            // built on first use, so that a filtered run builds only what it measures (criterion
            // calls the closure once per warm-up round and sample)
            let sim = OnceCell::new();
            group.bench_function(BenchmarkId::new(size, re_label(re)), |b| {
                let sim = sim.get_or_init(|| {
                    let sim = fixture(n_side, re, false);
                    // the timed step must be the common one, without a list rebuild
                    let mut probe = sim.clone();
                    probe.step(f64::INFINITY).expect("benchmark step");
                    assert_eq!(probe.search.builds, sim.search.builds);
                    sim
                });
                b.iter_batched_ref(
                    || sim.clone(),
                    |s| s.step(f64::INFINITY).expect("benchmark step"),
                    BatchSize::PerIteration,
                )
            });
        }
    }
    group.finish();
}

criterion_group!(benches, step);
criterion_main!(benches);
