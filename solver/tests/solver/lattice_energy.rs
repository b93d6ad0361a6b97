//! Exact lattice identities of the pairwise potential (docs/model.md §4): with `C_ij = 2σ_pair
//! l0²/S`, cutting a periodic slab of the reference lattice costs `σ` per unit area of each new
//! surface; an a|b interface costs `σ_ab`; separating a liquid from a solid costs the work of
//! adhesion `σ(1 + cos θ)` (Young–Dupré). These hold to round-off for any cut-off `r_e`.

use solver::model::Model;

/// A slab of lattice sites `(x, y, z, phase)`: `nxy × nxy` columns, layers at `z = (k + ½) l0`
/// for each `(k, phase)` in `layers`.
fn slab(nxy: i64, layers: &[(i64, usize)], l0: f64) -> Vec<([f64; 3], usize)> {
    let mut v = Vec::new();
    for &(k, ph) in layers {
        for j in 0..nxy {
            for i in 0..nxy {
                v.push(([i as f64 * l0, j as f64 * l0, (k as f64 + 0.5) * l0], ph));
            }
        }
    }
    v
}

/// Potential energy `U = −Σ_{pairs} C_ij P(r_ij)` [J] with periodic images in x and y (box
/// `nxy l0`, larger than `2 r_e` so the minimum image is the only one in range). Pairs of two
/// solid sites are skipped (solids are fixed; `C = 0` there anyway).
fn energy(model: &Model, sites: &[([f64; 3], usize)], nxy: i64) -> f64 {
    let l = nxy as f64 * model.l0_m;
    assert!(l > 2.0 * model.r_e_m);
    let mut u = 0.0;
    for a in 0..sites.len() {
        for b in a + 1..sites.len() {
            let (pa, qa) = sites[a];
            let (pb, qb) = sites[b];
            let mut d = [pa[0] - pb[0], pa[1] - pb[1], pa[2] - pb[2]];
            for dk in d.iter_mut().take(2) {
                *dk -= l * (*dk / l).round();
            }
            let r = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
            u -= model.pairs.c(qa, qb) * model.potential.p(r);
        }
    }
    u
}

fn model(re_over_l0: f64, potential_order: u8) -> Model {
    let text = format!(
        r#"
[discretisation]
l0 = 1.0e-4
re_over_l0 = {re_over_l0}
potential_order = {potential_order}
sound_speed = 10.0
[time]
end = 1.0
output_interval = 0.1
[effects]
interfacial_tension = true
[[liquid]]
name = "a"
density = 1000.0
viscosity = 0.0
surface_tension = 0.4
[[liquid]]
name = "b"
density = 1000.0
viscosity = 0.0
surface_tension = 0.25
[[solid]]
name = "s"
contact_angles = {{ a = 70.0, b = 120.0 }}
[[interface]]
liquids = ["a", "b"]
tension = 0.3
[[body]]
name = "x"
liquid = "a"
shape = {{ kind = "sphere", center = [0, 0, 0], radius = 1e-3 }}
"#
    );
    let scene = solver::Scene::from_toml_str(&text).unwrap();
    Model::from_scene(&scene).unwrap()
}

/// Round-off of summing a few thousand pair energies of similar size: 1e-11 relative is
/// generous (ε = 2.2e-16 times ~1e4 terms is 2e-12).
const TOL: f64 = 1e-11;

fn check(re: f64, order: u8, tol: f64) {
    let m = model(re, order);
    let l0 = m.l0_m;
    let nxy = (2.0 * re).ceil() as i64 + 2;
    let area = (nxy as f64 * l0).powi(2);
    let gap = (re + 2.0).ceil() as i64; // layers of empty space: wider than r_e
    let (a, b, s) = (0usize, 1usize, 2usize);
    let thick = (re.ceil() as i64) + 2; // each slab thicker than r_e

    // σ: cut a slab of a once; two new surfaces
    let joined: Vec<(i64, usize)> = (0..2 * thick).map(|k| (k, a)).collect();
    let cut: Vec<(i64, usize)> = (0..thick)
        .map(|k| (k, a))
        .chain((thick..2 * thick).map(|k| (k + gap, a)))
        .collect();
    let sigma = (energy(&m, &slab(nxy, &cut, l0), nxy) - energy(&m, &slab(nxy, &joined, l0), nxy))
        / (2.0 * area);
    assert!(
        (sigma / 0.4 - 1.0).abs() < tol,
        "r_e = {re} l0: surface energy {sigma} J/m², expected σ = 0.4"
    );

    // σ_ab: an a|b interface replaces one a surface and one b surface
    let ab: Vec<(i64, usize)> = (0..thick)
        .map(|k| (k, a))
        .chain((thick..2 * thick).map(|k| (k, b)))
        .collect();
    let a_b_apart: Vec<(i64, usize)> = (0..thick)
        .map(|k| (k, a))
        .chain((thick..2 * thick).map(|k| (k + gap, b)))
        .collect();
    let d = energy(&m, &slab(nxy, &ab, l0), nxy) - energy(&m, &slab(nxy, &a_b_apart, l0), nxy);
    let sigma_ab = d / area + 0.4 + 0.25;
    assert!(
        (sigma_ab / 0.3 - 1.0).abs() < tol,
        "r_e = {re} l0: a|b interface energy {sigma_ab}, expected σ_ab = 0.3"
    );

    // work of adhesion of a (θ = 70°) and b (θ = 120°) to the solid
    for (liquid, sigma_l, theta_deg) in [(a, 0.4, 70.0f64), (b, 0.25, 120.0)] {
        let on: Vec<(i64, usize)> = (0..thick)
            .map(|k| (k, s))
            .chain((thick..2 * thick).map(|k| (k, liquid)))
            .collect();
        let off: Vec<(i64, usize)> = (0..thick)
            .map(|k| (k, s))
            .chain((thick..2 * thick).map(|k| (k + gap, liquid)))
            .collect();
        let w =
            (energy(&m, &slab(nxy, &off, l0), nxy) - energy(&m, &slab(nxy, &on, l0), nxy)) / area;
        let expected = sigma_l * (1.0 + theta_deg.to_radians().cos());
        assert!(
            (w / expected - 1.0).abs() < tol,
            "r_e = {re} l0: work of adhesion {w} J/m², expected σ(1 + cos θ) = {expected}"
        );
    }
}

#[test]
fn surface_interface_and_adhesion_energies_at_short_cutoff() {
    check(2.1, 1, TOL);
}

#[test]
fn surface_interface_and_adhesion_energies_at_long_cutoff() {
    check(4.2, 1, TOL);
}

#[test]
fn surface_interface_and_adhesion_energies_of_the_smoother_potentials() {
    // the same surface sum calibrates every order (order 2's sign included). At r_e = 5 l0
    // the slabs hold about four times the pair energies of r_e = 4.2 l0, and σ_ab is a
    // difference of sums of ~2σ: the round-off bound grows to 1e-10 (measured: 2.7e-11)
    check(4.4, 2, TOL);
    check(5.0, 3, 1e-10);
}

#[test]
fn interfacial_energy_observable_of_a_lattice_block_is_sigma_times_area() {
    // The observable counts missing bonds against the bulk: for a free lattice cube of side
    // L = n l0 it is σ·6L² less the deficit of its 12 edges and 8 corners, which shrinks
    // relative to the faces as 1/n. With n = 16 the edge correction is about 3/n ≈ 19 %, so
    // the value must lie between 0.75 and 1.0 of σ·6L², and approach it from below as n grows.
    let mut last = 0.0;
    for n in [8usize, 16] {
        let l0 = 1e-4;
        let text = super::common::block_scene(n, l0, "interfacial_tension = true", "");
        let sim = super::common::sim(&text);
        let e = sim.observe().interfacial_energy_j;
        let ideal = 0.4 * 6.0 * (n as f64 * l0).powi(2);
        let ratio = e / ideal;
        assert!(ratio < 1.0 && ratio > 0.6, "n = {n}: E/(σA) = {ratio}");
        assert!(
            ratio > last,
            "approaches σA from below as the cube is refined"
        );
        last = ratio;
    }
}
