//! Particle views shared by the cases on a plate.

use crate::output::dump::Dump;

/// The particles of `dump` in the slice |y| < `l0_m` [m], seen from the side as (x, z) [mm],
/// each with its liquid's phase as class, and the wall particles within |x| < `wall_half_m`
/// [m] with class `wall_class`.
pub fn phase_slice(
    dump: &Dump,
    l0_m: f64,
    wall_half_m: f64,
    wall_class: usize,
) -> Vec<(f64, f64, usize)> {
    vertical_slice(dump, [0.0, 0.0], [1.0, 0.0], l0_m, wall_half_m, wall_class)
}

/// The particles of `dump` within `l0_m` [m] of the vertical plane through `origin` (x, y) [m]
/// along the horizontal unit vector `along`, seen from the side as (distance along `along`
/// from `origin`, z) [mm], each with its liquid's phase as class, and the wall particles
/// within `wall_half_m` [m] of `origin` along it with class `wall_class`.
pub fn vertical_slice(
    dump: &Dump,
    origin: [f64; 2],
    along: [f64; 2],
    l0_m: f64,
    wall_half_m: f64,
    wall_class: usize,
) -> Vec<(f64, f64, usize)> {
    let plane = |p: &[f64; 3]| {
        let (dx, dy) = (p[0] - origin[0], p[1] - origin[1]);
        // (along the plane, across it)
        (
            dx * along[0] + dy * along[1],
            -dx * along[1] + dy * along[0],
        )
    };
    (0..dump.pos.len())
        .filter_map(|i| {
            let (u, w) = plane(&dump.pos[i]);
            let keep = w.abs() < l0_m && (!dump.wall[i] || u.abs() < wall_half_m);
            keep.then(|| {
                let class = if dump.wall[i] {
                    wall_class
                } else {
                    dump.phase[i] as usize
                };
                (u * 1e3, dump.pos[i][2] * 1e3, class)
            })
        })
        .collect()
}

/// The liquid particles of `dump` seen from above as (x, y) [mm], each with its phase as class,
/// in order of height (the highest drawn last, on top).
pub fn top_view(dump: &Dump) -> Vec<(f64, f64, usize)> {
    let mut liquid: Vec<usize> = (0..dump.pos.len()).filter(|&i| !dump.wall[i]).collect();
    liquid.sort_by(|&a, &b| dump.pos[a][2].total_cmp(&dump.pos[b][2]));
    liquid
        .into_iter()
        .map(|i| {
            (
                dump.pos[i][0] * 1e3,
                dump.pos[i][1] * 1e3,
                dump.phase[i] as usize,
            )
        })
        .collect()
}

/// The horizontal centroid (x, y) [m] of the liquid particles of phase `phase` in `dump`
/// (NaN if it has none).
pub fn phase_centroid_xy(dump: &Dump, phase: u8) -> [f64; 2] {
    let (mut sum, mut n) = ([0.0; 2], 0usize);
    for (p, (&ph, &wall)) in dump.pos.iter().zip(dump.phase.iter().zip(&dump.wall)) {
        if ph == phase && !wall {
            sum[0] += p[0];
            sum[1] += p[1];
            n += 1;
        }
    }
    [sum[0] / n as f64, sum[1] / n as f64]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_vertical_slice_keeps_the_particles_near_its_plane_in_its_coordinates() {
        let dump = Dump {
            time_s: 0.0,
            // on the diagonal through (1, 1), off it, and a wall particle far along it
            pos: vec![[2.0, 2.0, 0.5], [1.0, 3.0, 0.5], [9.0, 9.0, 0.0]],
            vel: vec![[0.0; 3]; 3],
            phase: vec![1, 0, 2],
            wall: vec![false, false, true],
        };
        let s = std::f64::consts::FRAC_1_SQRT_2;
        let v = vertical_slice(&dump, [1.0, 1.0], [s, s], 0.1, 5.0, 7);
        assert_eq!(v.len(), 1);
        let (u, z, class) = v[0];
        assert!((u - 2f64.sqrt() * 1e3).abs() < 1e-9 && z == 500.0 && class == 1);
        // the wall particle is kept once the wall half-width reaches it
        assert_eq!(
            vertical_slice(&dump, [1.0, 1.0], [s, s], 0.1, 12.0, 7).len(),
            2
        );
        assert_eq!(phase_centroid_xy(&dump, 0), [1.0, 3.0]);
        // seen from above, the highest drawn last
        assert_eq!(top_view(&dump).len(), 2);
    }
}
