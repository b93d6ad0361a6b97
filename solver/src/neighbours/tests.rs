//! The search must return exactly the pairs a brute-force search finds — no missing pair (a
//! force left out) and no extra one (the near/far split mislabelled).

use super::*;
use crate::periodic::PeriodicBox;
use std::collections::BTreeSet;

/// A deterministic pseudo-random generator (64-bit LCG, Knuth's constants).
struct Lcg(u64);
impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

fn random_points(n: usize, box_m: f64, offset: f64, seed: u64) -> Vec<Vec3> {
    let mut g = Lcg(seed);
    (0..n)
        .map(|_| {
            Vec3::new(
                g.next() * box_m + offset,
                g.next() * box_m - offset,
                g.next() * box_m,
            )
        })
        .collect()
}

fn check(n_fluid: usize, n_wall: usize, near: f64, far: f64, skin: f64, seed: u64) {
    check_in(PeriodicBox::OPEN, n_fluid, n_wall, (near, far, skin), seed);
}

/// [`check_in`], and the same points again with walls that reach the far cut-off.
fn check_in(
    periodic: PeriodicBox,
    n_fluid: usize,
    n_wall: usize,
    radii: (f64, f64, f64),
    seed: u64,
) {
    for walls_reach_far in [false, true] {
        check_lists(periodic, n_fluid, n_wall, radii, seed, walls_reach_far);
    }
}

/// All pairs `(i, j)`, `i ≠ j`, closer than `radius_m` under the minimum image of `b`.
fn brute_force_pairs(b: &PeriodicBox, pos: &[Vec3], radius_m: f64) -> Vec<(u32, u32)> {
    let r2 = radius_m * radius_m;
    let mut pairs = Vec::new();
    for i in 0..pos.len() {
        for j in 0..pos.len() {
            if i != j && b.delta(pos[i], pos[j]).norm_squared() < r2 {
                pairs.push((i as u32, j as u32));
            }
        }
    }
    pairs
}

fn check_lists(
    periodic: PeriodicBox,
    n_fluid: usize,
    n_wall: usize,
    (near, far, skin): (f64, f64, f64),
    seed: u64,
    walls_reach_far: bool,
) {
    let box_m = 1e-3;
    let mut fluid = random_points(n_fluid, box_m, -3e-4, seed);
    let mut walls = random_points(n_wall, box_m, -3e-4, seed + 7);
    let mut s = NeighbourSearch::new(near, far, skin);
    s.set_periodic(periodic);
    s.walls_reach_far = walls_reach_far;
    let perm = s.sort_order(&fluid).unwrap();
    fluid = perm.iter().map(|&i| fluid[i as usize]).collect();
    let permw = s.sort_order(&walls).unwrap();
    walls = permw.iter().map(|&i| walls[i as usize]).collect();
    let mut pos = fluid.clone();
    pos.extend_from_slice(&walls);
    s.build(&pos, n_fluid).unwrap();

    let near_cut = near + skin;
    let far_cut = far.max(near) + skin;
    let expected_near: BTreeSet<(u32, u32)> = brute_force_pairs(&periodic, &pos, near_cut)
        .into_iter()
        .filter(|&(i, j)| (i as usize) < n_fluid || (j as usize) < n_fluid)
        .collect();
    // a fluid particle lists its near neighbours and its far ones of higher index (each far
    // pair once)
    let expected_all: BTreeSet<(u32, u32)> = brute_force_pairs(&periodic, &pos, far_cut)
        .into_iter()
        .filter(|&(i, j)| (i as usize) < n_fluid && (j > i || expected_near.contains(&(i, j))))
        .collect();
    // with `walls_reach_far` a wall lists, beyond its near fluid neighbours, every fluid
    // particle within the far cut-off
    let expected_wall_far: BTreeSet<(u32, u32)> = brute_force_pairs(&periodic, &pos, far_cut)
        .into_iter()
        .filter(|&(i, j)| {
            walls_reach_far
                && (i as usize) >= n_fluid
                && (j as usize) < n_fluid
                && !expected_near.contains(&(i, j))
        })
        .collect();
    let mut got_near = BTreeSet::new();
    let mut got_all = BTreeSet::new();
    let mut got_wall_far = BTreeSet::new();
    for i in 0..pos.len() {
        for j in s.lists.near(i) {
            assert!(got_near.insert((i as u32, j as u32)), "pair listed twice");
        }
        if i < n_fluid {
            for j in s.lists.all(i) {
                assert!(got_all.insert((i as u32, j as u32)), "pair listed twice");
            }
            assert!(s.lists.far(i).all(|j| j > i), "far pairs once");
        } else {
            for j in s.lists.far(i) {
                assert!(
                    got_wall_far.insert((i as u32, j as u32)),
                    "pair listed twice"
                );
            }
            assert!(s.lists.all(i).all(|j| j < n_fluid), "walls list fluid only");
        }
    }
    assert_eq!(
        got_near, expected_near,
        "near pairs differ from brute force"
    );
    assert_eq!(got_all, expected_all, "all pairs differ from brute force");
    assert_eq!(
        got_wall_far, expected_wall_far,
        "walls' far pairs differ from brute force"
    );
}

#[test]
fn search_returns_exactly_the_brute_force_pairs() {
    // equal radii (r_e = support), a larger potential cut-off, a skin; fluid only and with walls
    check(800, 0, 1.2e-4, 1.2e-4, 0.0, 1);
    check(800, 0, 1.0e-4, 2.0e-4, 0.0, 2);
    check(600, 300, 1.0e-4, 2.0e-4, 2e-5, 3);
    check(500, 500, 1.5e-4, 1.0e-4, 1e-5, 4);
}

#[test]
fn periodic_search_returns_exactly_the_minimum_image_pairs() {
    // the random points fill x ∈ [−0.3, 0.7) mm, y ∈ [0.3, 1.3) mm, z ∈ [0, 1) mm
    let (x, y, z) = ([-3e-4, 7e-4], [3e-4, 1.3e-3], [0.0, 1e-3]);
    let all = PeriodicBox::new([Some(x), Some(y), Some(z)]);
    let only_x = PeriodicBox::new([Some(x), None, None]);
    // a period of 1 mm against cut-offs of 0.22 mm (2 to 4 cells per axis) and 0.41 mm (2:
    // the cells around a cell wrap onto each other and must be visited once)
    check_in(all, 800, 0, (1.0e-4, 2.0e-4, 2e-5), 5);
    check_in(all, 600, 300, (1.0e-4, 2.0e-4, 2e-5), 6);
    check_in(only_x, 600, 300, (1.5e-4, 1.0e-4, 1e-5), 7);
    check_in(all, 500, 100, (1.0e-4, 4.0e-4, 1e-5), 8);
}

/// `n_fluid` random fluid points in a 1 mm box from −0.3 mm and `n_walls` wall points from
/// 0.2 mm (seeds `seed` and `seed + 1`).
fn fluid_and_walls(n_fluid: usize, n_walls: usize, seed: u64) -> (Vec<Vec3>, Vec<Vec3>) {
    (
        random_points(n_fluid, 1e-3, -3e-4, seed),
        random_points(n_walls, 1e-3, 2e-4, seed + 1),
    )
}

/// Every particle's (near, all) lists.
type AllLists = Vec<(Vec<usize>, Vec<usize>)>;

/// Every particle's (near, all) lists of `fluid` and `walls` (sorted by cell first) for a
/// search with cut-offs 0.1/0.2 mm and a 10 µm skin, after `configure`; and the search.
fn lists_of(
    fluid: &[Vec3],
    walls: &[Vec3],
    configure: impl Fn(&mut NeighbourSearch),
) -> (AllLists, NeighbourSearch) {
    let mut s = NeighbourSearch::new(1.0e-4, 2.0e-4, 1e-5);
    configure(&mut s);
    let perm = s.sort_order(fluid).unwrap();
    let mut pos: Vec<Vec3> = perm.iter().map(|&i| fluid[i as usize]).collect();
    let permw = s.sort_order(walls).unwrap();
    pos.extend(permw.iter().map(|&i| walls[i as usize]));
    s.build(&pos, fluid.len()).unwrap();
    let lists = (0..pos.len())
        .map(|i| (s.lists.near(i).collect(), s.lists.all(i).collect()))
        .collect();
    (lists, s)
}

#[test]
fn dense_tables_and_galloping_give_identical_lists() {
    // the two ways of finding a cell's rows must agree entry for entry (same order: the
    // results of a run must not depend on which one a scene's extent selects)
    let (fluid, walls) = fluid_and_walls(700, 400, 11);
    let lists = |dense: bool| {
        let (lists, s) = lists_of(&fluid, &walls, |s| {
            s.dense_tables = dense;
        });
        assert_eq!(s.fluid_table.is_built(), dense);
        assert_eq!(s.wall_table.is_built(), dense);
        lists
    };
    let dense = lists(true);
    assert_eq!(dense, lists(false));
    assert!(dense.iter().map(|l| l.1.len()).sum::<usize>() > 10_000);
}

#[test]
fn clipped_and_whole_rows_give_identical_lists() {
    // clipping the rows to the cells within reach only skips candidates beyond the cut-off:
    // the lists must be the same entry for entry whichever way a scene's density selects
    let (fluid, walls) = fluid_and_walls(900, 500, 13);
    // (walls clip their rows at the far cut-off when they reach it)
    for walls_reach_far in [false, true] {
        let lists = |min_per_cell: usize| {
            lists_of(&fluid, &walls, |s| {
                s.clip_min_per_cell = min_per_cell;
                s.walls_reach_far = walls_reach_far;
            })
            .0
        };
        let clipped = lists(0);
        assert_eq!(clipped, lists(usize::MAX));
        assert!(clipped.iter().map(|l| l.1.len()).sum::<usize>() > 10_000);
    }
}

#[test]
fn keys_order_rows_along_x() {
    let inv = 1.0 / 1e-4;
    let a = cell_key(&Vec3::new(0.5e-4, 0.0, 0.0), inv).unwrap();
    let b = cell_key(&Vec3::new(1.5e-4, 0.0, 0.0), inv).unwrap();
    let c = cell_key(&Vec3::new(-0.5e-4, 0.0, 0.0), inv).unwrap();
    assert_eq!(b, a + 1);
    assert_eq!(c + 1, a);
    assert_eq!(cells::offset_key(a, 1, 0, 0), b);
    assert!(cell_key(&Vec3::new(1e9, 0.0, 0.0), inv).is_err());
    assert!(cell_key(&Vec3::new(f64::NAN, 0.0, 0.0), inv).is_err());
}
