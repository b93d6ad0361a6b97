//! Diagnostic: surface/interface classification statistics of a saved particle dump.
fn main() {
    let a: Vec<String> = std::env::args().collect();
    let dump = verify::output::dump::Dump::read(std::path::Path::new(&a[1])).unwrap();
    let l0: f64 = a[2].parse().unwrap();
    let cloud = dump.cloud(l0);
    let c = verify::measure::surface::classify(&cloud);
    let n = cloud.pos.len();
    let mut hist = std::collections::BTreeMap::new();
    for &k in &c.neighbours {
        *hist.entry(k).or_insert(0) += 1;
    }
    let fs = c.free_surface.iter().filter(|&&b| b).count();
    let iface = c.interface.iter().filter(|&&b| b).count();
    let both = (0..n)
        .filter(|&i| c.free_surface[i] && c.interface[i])
        .count();
    println!("n {n}, free surface {fs}, interface {iface}, both {both}");
    println!("neighbour histogram: {hist:?}");
}
