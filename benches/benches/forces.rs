//! Forces: each term of the fused pair loop `physics::forces::fluid_forces` on its own.
//!
//! The loop is instantiated with one term, so the time is that of one term (plus the shared
//! gather of the neighbour positions and the pair geometry):
//!
//! - `forces/pressure/{20k,160k}`: `Pressure` (Eq. 11), cube, lists of `r_e` = 2.1 l0;
//! - `forces/laminar/{20k,160k}`: `LaminarViscosity` only, same input;
//! - `forces/artificial/{20k,160k}`: `ArtificialViscosity` only, same input;
//! - `forces/tension/{20k,160k}/re{2.1,4.2}`: `PairwisePotential` only (the Kondo potential
//!   over near and far neighbours), with the lists of the matching `r_e`;
//! - `forces/walls/{20k,160k}`: `Pressure` on the cube resting on a disk wall (compare with
//!   `pressure` for the cost of the wall particles).
//!
//! Inputs: the seeded, perturbed matte cubes of `benches::fixture`; the loop input and the
//! terms come from the simulation's public constructors (`Simulation::loop_input`,
//! `Simulation::pressure_term`, …), as the step assembles them. Throughput is in fluid
//! particles, so criterion's elements/s are particle-updates per second.
//!
//! Run: `cargo bench -p benches --bench forces [-- FILTER]` (e.g. `-- tension`). Reports go
//! to `target/criterion/`.

mod common;

use benches::{fixture, re_label, sampling, CUTOFFS, K, SIZES};
use criterion::measurement::WallTime;
use criterion::{
    criterion_group, criterion_main, BenchmarkGroup, BenchmarkId, Criterion, Throughput,
};
use solver::physics::forces::{fluid_forces, Off};
use solver::state::Vec3;
use solver::Simulation;
use std::cell::OnceCell;
use std::hint::black_box;

/// Which term a benchmark runs.
#[derive(Clone, Copy)]
enum Term {
    Pressure,
    Laminar,
    Artificial,
    Tension,
}

/// Runs the loop with the single term `term` on the state of `sim`.
fn run(sim: &Simulation, term: Term, acc: &mut [Vec3]) {
    let inp = sim.loop_input::<K>();
    let drho = &mut [];
    // the booked power (energy budget) is part of the work measured, not of the result
    let _power = match term {
        Term::Pressure => fluid_forces(&inp, &(sim.pressure_term(), Off), acc, drho),
        Term::Laminar => fluid_forces(&inp, &(sim.laminar_viscosity_term(), Off), acc, drho),
        Term::Artificial => fluid_forces(&inp, &(sim.artificial_viscosity_term(), Off), acc, drho),
        Term::Tension => fluid_forces(&inp, &(sim.potential_term(), Off), acc, drho),
    };
}

/// Times `term` on the state in `sim`, built by `make` on first use (so that a filtered run
/// builds only the inputs it measures).
fn bench(
    group: &mut BenchmarkGroup<'_, WallTime>,
    name: &str,
    id: &str,
    sim: &OnceCell<Simulation>,
    make: impl Fn() -> Simulation,
    term: Term,
) {
    group.bench_function(BenchmarkId::new(name, id), |b| {
        let sim = sim.get_or_init(&make);
        let mut acc = vec![Vec3::zeros(); sim.particles.n_fluid];
        b.iter(|| {
            run(sim, term, &mut acc);
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
                bench(&mut group, "pressure", size, &sim, make, Term::Pressure);
                bench(&mut group, "laminar", size, &sim, make, Term::Laminar);
                bench(&mut group, "artificial", size, &sim, make, Term::Artificial);
            }
            let id = format!("{size}/{}", re_label(re));
            // the potential over the r_e = 4.2 l0 lists is the slowest term: sampled as a heavy
            // routine (flat), the others as light ones
            common::configure(&mut group, sampling(n_side, re > 3.0));
            bench(&mut group, "tension", &id, &sim, make, Term::Tension);
            common::configure(&mut group, sampling(n_side, false));
        }
        let plate = OnceCell::new();
        let make = || fixture(n_side, CUTOFFS[0], true);
        bench(&mut group, "walls", size, &plate, make, Term::Pressure);
    }
    group.finish();
}

criterion_group!(benches, forces);
criterion_main!(benches);
