//! Particle shifting on a lattice slab: back towards uniformity inside, only along the surface
//! near it (`solver::physics::shifting`).

use solver::kernel::{Kernel, QuinticSpline, WendlandC2};
use solver::lattice::shifting_boundary_sum;
use solver::neighbours::NeighbourSearch;
use solver::physics::shifting::displacements;
use solver::state::Vec3;

/// A slab of `n × n × layers` lattice sites of spacing `l0` [m], unit volume fractions.
fn slab(n: usize, layers: usize, l0: f64) -> Vec<Vec3> {
    let mut pos = Vec::new();
    for z in 0..layers {
        for y in 0..n {
            for x in 0..n {
                pos.push(Vec3::new(x as f64, y as f64, z as f64) * l0);
            }
        }
    }
    pos
}

fn shifts<K: Kernel>(h_over_l0: f64, pos: &[Vec3], perturbed: Option<(usize, Vec3)>) -> Vec<Vec3> {
    let l0 = 1.0;
    let k = K::new(h_over_l0 * l0);
    let mut pos = pos.to_vec();
    if let Some((i, d)) = perturbed {
        pos[i] += d;
    }
    let boundary = shifting_boundary_sum(&k, l0);
    let vol = vec![l0 * l0 * l0; pos.len()];
    let phase = vec![0u8; pos.len()];
    let mut search = NeighbourSearch::new(k.support_m(), k.support_m(), 0.1 * l0);
    // the search wants positions sorted by cell; the shifts are returned in input order
    let perm = search.sort_order(&pos).unwrap();
    let sorted: Vec<Vec3> = perm.iter().map(|&i| pos[i as usize]).collect();
    search.build(&sorted, sorted.len()).unwrap();
    let mut out = vec![Vec3::zeros(); pos.len()];
    displacements(
        &k,
        &sorted,
        &vol,
        &phase,
        &search.lists,
        boundary,
        1.0,
        &mut out,
    );
    let mut back = vec![Vec3::zeros(); pos.len()];
    for (k, &i) in perm.iter().enumerate() {
        back[i as usize] = out[k];
    }
    back
}

#[test]
fn a_slab_is_shifted_only_along_its_surfaces() {
    let (n, layers) = (9, 9);
    let pos = slab(n, layers, 1.0);
    let idx = |x: usize, y: usize, z: usize| (z * n + y) * n + x;
    // the top surface's centre particle, displaced sideways: pushed back towards its site,
    // along the surface (the normal is the neighbourhood's; 10 % of the shift allows for
    // the tilt the displaced particle gives its neighbours' gradients)
    let top = idx(4, 4, layers - 1);
    let out = shifts::<WendlandC2>(1.05, &pos, Some((top, Vec3::new(0.2, 0.0, 0.0))));
    assert!(out[top].x < 0.0, "{:?}", out[top]);
    assert!(out[top].z.abs() < 0.1 * out[top].x.abs(), "{:?}", out[top]);
    // a displaced interior particle (4 planes deep: beyond one support of any surface
    // particle) is pushed back towards its site in every direction
    let mid = idx(4, 4, 4);
    let out = shifts::<WendlandC2>(1.05, &pos, Some((mid, Vec3::new(0.1, 0.0, 0.1))));
    assert!(out[mid].x < 0.0 && out[mid].z < 0.0, "{:?}", out[mid]);
    // the undisturbed slab away from its side faces (4 sites from them, beyond the
    // quintic spline's support of 3.15): no shift at any depth, to round-off — the
    // surface planes' normal gradients are projected out
    let out = shifts::<QuinticSpline>(1.05, &pos, None);
    for z in 0..layers {
        let d = out[idx(4, 4, z)];
        assert!(d.norm() < 1e-12, "plane {z}: {d:?}");
    }
}
