//! One thread and two threads give bitwise identical particle states: every parallel loop
//! gathers per particle in a fixed neighbour order, and reductions are maxima.

use super::common::{block_scene, ALUMINA_PLATE};
use solver::{Scene, Simulation};

fn run_with_threads(text: &str, threads: usize, steps: usize) -> solver::state::Particles {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap();
    pool.install(|| {
        let mut s = Simulation::new(&Scene::from_toml_str(text).unwrap()).unwrap();
        for _ in 0..steps {
            s.step(f64::INFINITY).unwrap();
        }
        assert!(
            s.search.builds > 1,
            "the test must cover neighbour rebuilds and re-sorting"
        );
        s.particles
    })
}

fn bits(v: &[f64]) -> Vec<u64> {
    v.iter().map(|x| x.to_bits()).collect()
}

#[test]
fn one_and_two_threads_give_identical_bits() {
    let text = block_scene(
        10,
        1e-4,
        "interfacial_tension = true\nlaminar_viscosity = true\nartificial_viscosity = {}\ngravity = [0.0, 0.0, -9.81]",
        ALUMINA_PLATE,
    );
    let a = run_with_threads(&text, 1, 200);
    let b = run_with_threads(&text, 2, 200);
    assert_eq!(a.id, b.id, "same particle order");
    let flat = |p: &solver::state::Particles| -> Vec<f64> {
        p.pos
            .iter()
            .chain(&p.vel)
            .chain(&p.acc)
            .flat_map(|v| v.iter().copied())
            .chain(p.rho.iter().copied())
            .chain(p.pressure.iter().copied())
            .collect()
    };
    assert_eq!(
        bits(&flat(&a)),
        bits(&flat(&b)),
        "states differ between 1 and 2 threads"
    );
}
