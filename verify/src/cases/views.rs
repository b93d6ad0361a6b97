//! Particle views shared by the cases on a plate.

use crate::suite::dump::Dump;

/// The particles of `dump` in the slice |y| < `l0_m` [m], seen from the side as (x, z) [mm],
/// each with its liquid's phase as class, and the wall particles within |x| < `wall_half_m`
/// [m] with class `wall_class`.
pub fn phase_slice(
    dump: &Dump,
    l0_m: f64,
    wall_half_m: f64,
    wall_class: usize,
) -> Vec<(f64, f64, usize)> {
    (0..dump.pos.len())
        .filter(|&i| {
            dump.pos[i][1].abs() < l0_m && (!dump.wall[i] || dump.pos[i][0].abs() < wall_half_m)
        })
        .map(|i| {
            (
                dump.pos[i][0] * 1e3,
                dump.pos[i][2] * 1e3,
                if dump.wall[i] {
                    wall_class
                } else {
                    dump.phase[i] as usize
                },
            )
        })
        .collect()
}
