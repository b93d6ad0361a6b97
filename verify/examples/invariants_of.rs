//! Runs a scene in memory and prints the shape invariants of its final state (clumped fraction,
//! bodies) and its largest compression: `cargo run --release -p verify --example invariants_of
//! -- SCENE.toml`.
fn main() {
    let path = std::env::args().nth(1).expect("scene file");
    let scene = solver::Scene::from_toml_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    let mut sim = solver::Simulation::new(&scene).unwrap();
    let mut max_comp: f64 = 0.0;
    while sim.time_s < scene.time.end * (1.0 - 1e-12) {
        if let Err(e) = sim.step(scene.time.end - sim.time_s) {
            println!("stopped: {e}");
            break;
        }
        max_comp = max_comp.max(sim.observe().max_compression);
    }
    let p = &sim.particles;
    let pts: Vec<[f64; 3]> = p.pos[..p.n_fluid].iter().map(|x| [x.x, x.y, x.z]).collect();
    let l0 = scene.discretisation.l0;
    println!(
        "steps {}, clumped {:.3}, bodies {}, max compression {:.3}",
        sim.step,
        verify::measure::invariants::clumped_fraction(&pts, l0),
        verify::measure::invariants::components(&pts, 1.5 * l0),
        max_comp
    );
}
