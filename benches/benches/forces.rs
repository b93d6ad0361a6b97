//! Forces: each term of the fused pair loop `physics::forces::fluid_forces` on its own.
//!
//! The loop is instantiated with one effect flag set, so the time is that of one term (plus the
//! shared gather of the neighbour positions):
//!
//! - `forces/pressure/{20k,160k}`: `PRES` (Eq. 11 pressure), cube, lists of `r_e` = 2.1 l0;
//! - `forces/laminar/{20k,160k}`: `VISC` only (laminar viscosity), same input;
//! - `forces/artificial/{20k,160k}`: `AV` only (artificial viscosity), same input;
//! - `forces/tension/{20k,160k}/re{2.1,4.2}`: `IT` only (the Kondo potential over near and far
//!   neighbours), with the lists of the matching `r_e`;
//! - `forces/walls/{20k,160k}`: `PRES` + `WALL` on the cube resting on a disk wall (compare
//!   with `pressure` for the cost of the wall particles).
//!
//! Inputs: the seeded, perturbed matte cubes of `benches::fixture`; `ForceInput` is built from
//! the simulation's model and particles as `Simulation::evaluate` builds it. Throughput is in
//! fluid particles, so criterion's elements/s are particle-updates per second.
//!
//! Run: `cargo bench -p benches --bench forces [-- FILTER]` (e.g. `-- tension`). Reports go
//! to `target/criterion/`.

mod common;

use benches::{fixture, force_input, re_label, sampling, CUTOFFS, K, SIZES};
use criterion::measurement::WallTime;
use criterion::{
    criterion_group, criterion_main, BenchmarkGroup, BenchmarkId, Criterion, Throughput,
};
use solver::physics::forces::{fluid_forces, ForceInput};
use solver::state::Vec3;
use solver::Simulation;
use std::cell::OnceCell;
use std::hint::black_box;

/// A force-loop instance: `fluid_forces::<K, PRES, VISC, AV, IT, WALL, CONT>`.
type Loop = fn(&ForceInput<K>, &mut [Vec3], &mut [f64]);

/// Times `f` on the state in `sim`, built by `make` on first use (so that a filtered run
/// builds only the inputs it measures).
fn bench(
    group: &mut BenchmarkGroup<'_, WallTime>,
    name: &str,
    id: &str,
    sim: &OnceCell<Simulation>,
    make: impl Fn() -> Simulation,
    f: Loop,
) {
    group.bench_function(BenchmarkId::new(name, id), |b| {
        let inp = force_input(sim.get_or_init(&make));
        let mut acc = vec![Vec3::zeros(); inp.n_fluid];
        let mut drho = Vec::new();
        b.iter(|| {
            f(&inp, &mut acc, &mut drho);
            black_box(&acc);
        })
    });
}

fn forces(c: &mut Criterion) {
    let mut group = c.benchmark_group("forces");
    for (size, n_side) in SIZES {
        common::configure(&mut group, sampling(n_side, false));
        group.throughput(Throughput::Elements(n_side.pow(3) as u64));
        for re in CUTOFFS {
            let sim = OnceCell::new();
            let make = || fixture(n_side, re, false);
            if re == CUTOFFS[0] {
                let pres = fluid_forces::<K, true, false, false, false, false, false>;
                let visc = fluid_forces::<K, false, true, false, false, false, false>;
                let av = fluid_forces::<K, false, false, true, false, false, false>;
                bench(&mut group, "pressure", size, &sim, make, pres);
                bench(&mut group, "laminar", size, &sim, make, visc);
                bench(&mut group, "artificial", size, &sim, make, av);
            }
            let it = fluid_forces::<K, false, false, false, true, false, false>;
            let id = format!("{size}/{}", re_label(re));
            // the potential over the r_e = 4.2 l0 lists is the slowest term: sampled as a heavy
            // routine (flat), the others as light ones
            common::configure(&mut group, sampling(n_side, re > 3.0));
            bench(&mut group, "tension", &id, &sim, make, it);
            common::configure(&mut group, sampling(n_side, false));
        }
        let plate = OnceCell::new();
        let make = || fixture(n_side, CUTOFFS[0], true);
        let walls = fluid_forces::<K, true, false, false, false, true, false>;
        bench(&mut group, "walls", size, &plate, make, walls);
    }
    group.finish();
}

criterion_group!(benches, forces);
criterion_main!(benches);
