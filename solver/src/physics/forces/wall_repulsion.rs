//! A short-range liquid–wall repulsion that does not depend on the kernel: Monaghan (1994)'s
//! boundary force, `F_i = Σ_w D_i [(r0/r)¹² − (r0/r)⁴] x_iw / r²` [N] over wall particles `w`
//! closer than `r0`, zero at `r0` and repulsive inside.
//!
//! Why: with a wide kernel (paper B's h = 2 l0) the pressure gradient at one spacing is weak and
//! the potential's cohesion pulls a wetting liquid through the gaps between wall particles. A
//! liquid particle entering the square gap of a wall layer passes within `l0/√2` of four wall
//! particles. With `r0 = 0.8 l0` (below the 0.9–1.1 l0 at which the first liquid layer rests on
//! a wall, so resting liquid does not feel it) the barrier of the gap is
//! `4 D [((r0/r)¹² − 1)/12 − ((r0/r)⁴ − 1)/4] = 0.495 D` at `r = l0/√2`; `D = 10 p_b l0³` makes it
//! five times the work `p_b l0³` the cohesive background pressure `p_b` of the liquid does in
//! pushing one particle one layer in (docs/scene-reference.md).

use super::term::{Lane, Lanes, Neighbour, PairKinematics, PairSums, PairTerm, Particle, CHUNK};

/// The range of the repulsion over the spacing, `r0/l0` [-].
pub const RANGE_OVER_L0: f64 = 0.8;
/// `D / (p_b l0³)` [-]: the gap's barrier is five times the cohesive work (module doc).
pub const STRENGTH_OVER_PB_L03: f64 = 10.0;

/// The liquid–wall repulsion term (Monaghan 1994).
#[derive(Clone, Copy, Debug)]
pub struct Monaghan1994WallRepulsion<'a> {
    /// Strength `D` per phase [J] (the liquid's; zero for solids).
    pub strength_j: &'a [f64],
    /// Range `r0` [m].
    pub range_m: f64,
}

/// Per neighbour: whether it is a wall particle.
pub struct RepulsionLanes {
    wall: Lane<bool>,
}

impl Lanes for RepulsionLanes {
    fn new() -> Self {
        RepulsionLanes {
            wall: [false; CHUNK],
        }
    }
}

impl Monaghan1994WallRepulsion<'_> {
    /// The pair energy [J] of a liquid particle of strength `d_j` [J] at `r_m` [m] from a wall
    /// particle: `Φ(r) = D [((r0/r)¹² − 1)/12 − ((r0/r)⁴ − 1)/4]` for `0 < r < r0`, else zero;
    /// `−dΦ/dr` is the force of [`PairTerm::pair`] (`D [(r0/r)¹² − (r0/r)⁴]/r`), and `Φ(r0) = 0`.
    pub fn pair_energy(&self, d_j: f64, r_m: f64) -> f64 {
        if r_m <= 0.0 || r_m >= self.range_m {
            return 0.0;
        }
        let q4 = (self.range_m / r_m).powi(4);
        d_j * ((q4 * q4 * q4 - 1.0) / 12.0 - (q4 - 1.0) / 4.0) // integral of Monaghan 1994
    }
}

impl PairTerm for Monaghan1994WallRepulsion<'_> {
    /// `D` of particle `i` [J].
    type Own = f64;
    type Lanes = RepulsionLanes;

    #[inline(always)]
    fn own(&self, i: Particle) -> f64 {
        self.strength_j[i.phase]
    }
    #[inline(always)]
    fn gather(&self, _own: &f64, l: &mut RepulsionLanes, n: usize, nb: Neighbour) {
        l.wall[n] = nb.is_wall;
    }
    #[inline(always)]
    fn pair(&self, s: &mut PairSums, d: &f64, l: &RepulsionLanes, n: usize, k: &PairKinematics) {
        let q2 = self.range_m * self.range_m / k.r2; // (r0/r)²
        let q4 = q2 * q2;
        let v = d * (q4 * q4 * q4 - q4) / k.r2; // Monaghan 1994: D[(r0/r)¹² − (r0/r)⁴]/r²
        s.central += if l.wall[n] & k.apart & (q2 > 1.0) {
            v
        } else {
            0.0
        };
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The central coefficient [N/m] on a liquid particle `r` [m] from a wall (or liquid)
    /// neighbour.
    fn coefficient(r: f64, wall: bool) -> f64 {
        let t = Monaghan1994WallRepulsion {
            strength_j: &[1e-9],
            range_m: 0.8e-4,
        };
        let mut lanes = RepulsionLanes::new();
        let nb = Neighbour {
            j: 1,
            phase: 0,
            is_wall: wall,
        };
        t.gather(&1e-9, &mut lanes, 0, nb);
        let k = PairKinematics {
            r2: r * r,
            r,
            ir: 1.0 / r,
            apart: true,
            inside: true,
            dw_r: 0.0,
            vr: 0.0,
        };
        let mut s = PairSums::default();
        t.pair(&mut s, &1e-9, &lanes, 0, &k);
        s.central
    }

    #[test]
    fn repulsive_inside_the_range_zero_beyond_and_between_liquid_particles() {
        let l0 = 1e-4;
        // at r = l0/√2 (the gap of a wall layer): D[(r0/r)¹² − (r0/r)⁴]/r² with r0/r = 1.1314
        let r = l0 / 2f64.sqrt();
        let q = 0.8 * l0 / r;
        let expected = 1e-9 * (q.powi(12) - q.powi(4)) / (r * r);
        let c = coefficient(r, true);
        assert!(
            c > 0.0,
            "repulsive: the force points from the wall to the liquid"
        );
        assert!((c / expected - 1.0).abs() < 1e-12, "{c} vs {expected}");
        // continuous at r0 (zero there) and nothing beyond, nor between two liquid particles
        assert!(coefficient(0.8 * l0 * (1.0 - 1e-9), true).abs() < 1e-6 * expected);
        assert_eq!(coefficient(0.9 * l0, true), 0.0);
        assert_eq!(coefficient(r, false), 0.0);
    }

    #[test]
    fn the_pair_energy_is_the_potential_of_the_force() {
        // −dΦ/dr by a central difference (relative error ~ (δ/r)² ≈ 1e-10 for this smooth
        // function, plus the round-off ε Φ/δ ≈ 1e-8 relative to the force: 1e-6 is safe)
        // equals the force magnitude r·coefficient; Φ vanishes at r0 and beyond
        let t = Monaghan1994WallRepulsion {
            strength_j: &[1e-9],
            range_m: 0.8e-4,
        };
        for r in [0.5e-4, 0.7e-4, 0.79e-4] {
            let d = 1e-5 * r;
            let force = -(t.pair_energy(1e-9, r + d) - t.pair_energy(1e-9, r - d)) / (2.0 * d);
            let expected = r * coefficient(r, true);
            assert!(
                (force / expected - 1.0).abs() < 1e-6,
                "{force} vs {expected}"
            );
        }
        assert!(t.pair_energy(1e-9, 0.8e-4 * (1.0 - 1e-9)).abs() < 1e-24);
        assert_eq!(t.pair_energy(1e-9, 0.9e-4), 0.0);
    }
}
