//! Neighbour search: building the lists and querying them.
//!
//! - `neighbours/rebuild/{20k,160k}/re{2.1,4.2}`: what `Simulation` does when a particle has
//!   moved half the skin — the permutation sorting the fluid particles by cell, the permutation
//!   of the particle arrays, and the build of the near/far Verlet lists (one search for the
//!   kernel support and `r_e`). Repeated on the same state, which stays sorted: as in a run,
//!   where particles move at most half the skin between builds, the sort sees nearly sorted
//!   keys.
//! - `neighbours/query/{20k,160k}/re{2.1,4.2}`: one pass over every fluid particle's lists
//!   with the distance test against the largest interaction radius
//!   (`Simulation::mean_neighbours`) — the traversal cost every pair loop pays, without
//!   physics.
//!
//! Inputs: the seeded, perturbed matte cubes of `benches::fixture`. Throughput is in fluid
//! particles, so criterion's elements/s are particle-updates per second.
//!
//! Run: `cargo bench -p benches --bench neighbours [-- FILTER]` (e.g. `-- rebuild/20k`).
//! Reports go to `target/criterion/`.

mod common;

use benches::{fixture, re_label, sampling, CUTOFFS, SIZES};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use std::cell::OnceCell;
use std::hint::black_box;

fn neighbours(c: &mut Criterion) {
    let mut group = c.benchmark_group("neighbours");
    for (size, n_side) in SIZES {
        for re in CUTOFFS {
            // built on first use, so that a filtered run builds only what it measures (criterion
            // calls the closure once per warm-up round and sample)
            let mut sim = OnceCell::new();
            let make = || fixture(n_side, re, false);
            group.throughput(Throughput::Elements(n_side.pow(3) as u64));
            let id = format!("{size}/{}", re_label(re));
            common::configure(&mut group, sampling(n_side, false));
            group.bench_function(BenchmarkId::new("query", &id), |b| {
                let sim = sim.get_or_init(make);
                b.iter(|| black_box(sim.mean_neighbours()))
            });
            // up to a second per rebuild at 160k: flat sampling with a longer target
            common::configure(&mut group, sampling(n_side, true));
            group.bench_function(BenchmarkId::new("rebuild", &id), |b| {
                sim.get_or_init(make);
                let sim = sim.get_mut().expect("initialised");
                b.iter(|| {
                    sim.rebuild_neighbours()
                        .expect("benchmark particles stay on the cell grid");
                    black_box(sim.search.lists.entries())
                })
            });
        }
    }
    group.finish();
}

criterion_group!(benches, neighbours);
criterion_main!(benches);
