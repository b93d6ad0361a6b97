//! Diagnostic: bytes per particle held by each structure after some steps, against the RSS.
//! Usage: `cargo run --release -p solver --example memory_account -- SCENE.toml [steps]`.
fn rss() -> f64 {
    let s = std::fs::read_to_string("/proc/self/status").unwrap();
    let kb = |k: &str| {
        s.lines()
            .find(|l| l.starts_with(k))
            .unwrap()
            .split_whitespace()
            .nth(1)
            .unwrap()
            .parse::<f64>()
            .unwrap()
    };
    kb("VmRSS:") * 1024.0
}
fn main() {
    let text = std::fs::read_to_string(std::env::args().nth(1).unwrap()).unwrap();
    let scene = solver::Scene::from_toml_str(&text).unwrap();
    let base = rss();
    let mut sim = solver::Simulation::new(&scene).unwrap();
    let s = std::fs::read_to_string("/proc/self/status").unwrap();
    println!(
        "after new: RSS {:.0} B/particle, peak {}",
        (rss() - base) / sim.particles.n_fluid as f64,
        s.lines().find(|l| l.starts_with("VmHWM")).unwrap()
    );
    // steps: second argument (default 300; the 160 k bench cube is built for ~85)
    let steps: usize = std::env::args().nth(2).map_or(300, |s| s.parse().unwrap());
    for _ in 0..steps {
        sim.step(f64::INFINITY).unwrap();
    }
    let p = &sim.particles;
    let n = p.n_fluid as f64;
    let v3 = 24.0;
    let parts = (p.pos.capacity() + p.vel.capacity() + p.acc.capacity() + p.x_ref.capacity())
        as f64
        * v3
        + (p.rho.capacity() + p.drho.capacity() + p.pressure.capacity() + p.vol.capacity()) as f64
            * 8.0
        + p.phase.capacity() as f64
        + p.id.capacity() as f64 * 4.0;
    let lists = sim.search.lists.memory_bytes() as f64;
    let index = sim.search.index_memory_bytes() as f64;
    let (entries, words) = (sim.search.lists.entries(), sim.search.lists.words());
    println!("particles {:.0} B, lists {:.0} B, keys and cell tables {:.0} B per particle; list entries {:.1} per particle in {:.1} 16-bit words ({:.0} B used); RSS growth {:.0} B per particle",
        parts / n, lists / n, index / n, entries as f64 / n, words as f64 / n, words as f64 * 2.0 / n, (rss() - base) / n);
}
