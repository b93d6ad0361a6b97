//! Times `Simulation::step` on a scene: warm-up, then the minimum over repetitions of the time
//! per particle-step. Usage: `cargo run --release -p solver --example step_timing -- SCENE.toml
//! [steps] [repetitions]`.
fn main() {
    let args: Vec<String> = std::env::args().collect();
    let text = std::fs::read_to_string(&args[1]).expect("scene file");
    let steps: usize = args.get(2).map_or(100, |s| s.parse().unwrap());
    let reps: usize = args.get(3).map_or(5, |s| s.parse().unwrap());
    let scene = solver::Scene::from_toml_str(&text).expect("valid scene");
    let mut sim = solver::Simulation::new(&scene).expect("builds");
    for _ in 0..50 {
        sim.step(f64::INFINITY).unwrap();
    }
    let n = sim.particles.n_fluid as f64;
    let mut best = f64::INFINITY;
    for _ in 0..reps {
        let mut s = sim.clone();
        let t0 = std::time::Instant::now();
        for _ in 0..steps {
            s.step(f64::INFINITY).unwrap();
        }
        best = best.min(t0.elapsed().as_secs_f64() / (steps as f64 * n));
    }
    println!(
        "{:.1} ns per particle-step ({:.3e} particle-steps/s), {} particles, {} threads",
        best * 1e9,
        1.0 / best,
        n,
        rayon::current_num_threads()
    );
}
