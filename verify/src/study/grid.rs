//! The study's points: problems, variants, resolutions, and their scenes.

use crate::analytic::{lamb, young_laplace};
use crate::cases::scene::{artificial_viscosity_m2_s, SceneBuilder, MATTE};
use serde::{Deserialize, Serialize};
use solver::kernel::KernelKind;
use solver::scene::{BodyShape, Reinit, WallBoundary, WallShape};
use solver::Scene;

/// A problem with an analytic answer.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Problem {
    /// 1 mm matte cube, zero gravity: relative error of the l = 4 period against Lamb.
    CubeDrop,
    /// Matte drop (2 mm diameter) on a θ = 90° plate under gravity: relative error of the
    /// equilibrium height against the axisymmetric Young–Laplace solution.
    SessileDrop,
    /// The cube drop's run again: relative error of the l = 4 amplitude decay rate against
    /// Lamb's with the liquid's ν plus the artificial viscosity's α1 h c/10.
    CubeDamping,
    /// A matte hemisphere on a plate where its contact angle is 30°, zero gravity: relative
    /// error of the static angle (from the height of the spherical cap of the drop's volume).
    ContactAngle30,
    /// The same at 60°.
    ContactAngle60,
}

impl Problem {
    /// Every problem, in report order.
    pub const ALL: [Problem; 5] = [
        Problem::CubeDrop,
        Problem::CubeDamping,
        Problem::SessileDrop,
        Problem::ContactAngle30,
        Problem::ContactAngle60,
    ];

    /// Name used in tables.
    pub fn name(self) -> &'static str {
        match self {
            Problem::CubeDrop => "cube_drop",
            Problem::SessileDrop => "sessile_drop",
            Problem::CubeDamping => "cube_damping",
            Problem::ContactAngle30 => "contact_angle_30",
            Problem::ContactAngle60 => "contact_angle_60",
        }
    }

    /// The folder of its runs: the cube's damping is measured on the cube drop's runs.
    pub fn run_name(self) -> &'static str {
        match self {
            Problem::CubeDamping => Problem::CubeDrop.name(),
            p => p.name(),
        }
    }

    /// The quantity measured, with its unit.
    pub fn quantity(self) -> &'static str {
        match self {
            Problem::CubeDrop => "l = 4 period [s] against Lamb",
            Problem::SessileDrop => "equilibrium height [m] against Young–Laplace",
            Problem::CubeDamping => {
                "l = 4 amplitude decay rate [1/s] against Lamb with ν + α1 h c/10 (the reference \
                 depends on h)"
            }
            Problem::ContactAngle30 | Problem::ContactAngle60 => {
                "static contact angle [°] (spherical cap of the drop's volume and height) against \
                 the typed one"
            }
        }
    }

    /// The liquid model's target for this problem as a relative error [-], with its source
    /// (docs/findings.md, "Targets of the liquid model"); `None` where it sets none.
    pub fn target(self) -> Option<(f64, &'static str)> {
        match self {
            Problem::CubeDrop => Some((0.03, "period within 3 %")),
            Problem::CubeDamping => Some((0.30, "damping within ±30 % of Lamb (ν + ν_AV)")),
            Problem::ContactAngle30 => Some((4.0 / 30.0, "±4° at 30°")),
            Problem::ContactAngle60 => Some((2.0 / 60.0, "±2° for 60–120°")),
            Problem::SessileDrop => None,
        }
    }

    /// The contact angle of the plate [°], for the problems with a plate.
    fn plate_angle_deg(self) -> Option<f64> {
        match self {
            Problem::SessileDrop => Some(90.0),
            Problem::ContactAngle30 => Some(30.0),
            Problem::ContactAngle60 => Some(60.0),
            Problem::CubeDrop | Problem::CubeDamping => None,
        }
    }

    /// Resolutions: particles along the cube side, or drop radius over `l0`.
    pub fn resolutions(self, grid: Grid) -> Vec<usize> {
        match (self.plate_angle_deg().is_some(), grid) {
            (false, Grid::Reduced) => vec![8, 10],
            (false, _) => vec![10, 14, 20, 28],
            (true, Grid::Reduced) => vec![4, 5],
            (true, _) => vec![5, 7, 10, 14],
        }
    }

    /// `l0` [m] at a resolution.
    pub fn l0(self, resolution: usize) -> f64 {
        match self.plate_angle_deg() {
            None => CUBE_SIDE_M / resolution as f64,
            Some(_) => DROP_RADIUS_M / resolution as f64,
        }
    }
}

/// The discretisation choices a variant fixes.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Variant {
    /// Kernel.
    pub kernel: KernelKind,
    /// `h/l0` [-].
    pub h_over_l0: f64,
    /// `r_e/l0` [-].
    pub re_over_l0: f64,
    /// Continuity density with Shepard re-initialisation every 20 steps instead of summation.
    pub continuity: bool,
    /// Order of the potential's zero at `r_e` (1: Kondo 2007).
    #[serde(default = "kondo")]
    pub potential_order: u8,
    /// The short-range liquid–wall repulsion in the problems with a plate (a wide kernel's
    /// pressure does not keep a wetting liquid out of the wall).
    #[serde(default)]
    pub wall_repulsion: bool,
}

fn kondo() -> u8 {
    1
}

impl Variant {
    /// The project's defaults.
    pub const DEFAULT: Variant = Variant {
        kernel: KernelKind::WendlandC2,
        h_over_l0: 1.05,
        re_over_l0: 4.2,
        continuity: false,
        potential_order: 1,
        wall_repulsion: false,
    };

    /// A short label, e.g. `wendland_c2 h1.05 re4.2 sum` (` m2` appended for a potential of
    /// order 2, ` wr` with the wall repulsion).
    pub fn label(&self) -> String {
        let mut order = if self.potential_order == 1 {
            String::new()
        } else {
            format!(" m{}", self.potential_order)
        };
        if self.wall_repulsion {
            order.push_str(" wr");
        }
        format!(
            "{} h{} re{} {}{order}",
            self.kernel.name(),
            self.h_over_l0,
            self.re_over_l0,
            if self.continuity { "cont" } else { "sum" }
        )
    }

    /// A folder-safe label.
    pub fn id(&self) -> String {
        self.label().replace(' ', "_")
    }
}

/// How many points.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, clap::ValueEnum)]
#[serde(rename_all = "snake_case")]
pub enum Grid {
    /// Two variants × two coarse resolutions per problem: the test suite's.
    Reduced,
    /// The default and each single change from it (3 other kernels, h/l0 = 1.3, r_e = 2.1 and
    /// 3.1 l0, continuity density), and the two settings whose lattice has both shear moduli
    /// near zero (quintic spline at h = 1.05 l0 with a smooth potential: r_e = 4.4 l0 of order
    /// 2, r_e = 5.0 l0 of order 3; their support of 3.15 l0 lets a wetting liquid into a wall,
    /// so with the wall repulsion) × four resolutions: 10 variants × 4 × 5 problems.
    Standard,
    /// The full factorial: 4 kernels × h/l0 ∈ {1.05, 1.3} × r_e ∈ {2.1, 3.1, 4.2} × 2 density
    /// schemes × four resolutions × 2 problems (hours).
    Full,
}

impl Grid {
    /// The variants of the grid.
    pub fn variants(self) -> Vec<Variant> {
        let d = Variant::DEFAULT;
        match self {
            Grid::Reduced => vec![
                d,
                Variant {
                    re_over_l0: 2.1,
                    ..d
                },
            ],
            Grid::Standard => {
                let mut v = vec![d];
                for k in KernelKind::ALL.into_iter().filter(|&k| k != d.kernel) {
                    v.push(Variant { kernel: k, ..d });
                }
                v.push(Variant {
                    h_over_l0: 1.3,
                    ..d
                });
                v.push(Variant {
                    re_over_l0: 2.1,
                    ..d
                });
                v.push(Variant {
                    re_over_l0: 3.1,
                    ..d
                });
                v.push(Variant {
                    continuity: true,
                    ..d
                });
                for (re_over_l0, potential_order) in [(4.4, 2), (5.0, 3)] {
                    v.push(Variant {
                        kernel: KernelKind::QuinticSpline,
                        re_over_l0,
                        potential_order,
                        wall_repulsion: true,
                        ..d
                    });
                }
                v
            }
            Grid::Full => {
                let mut v = Vec::new();
                for kernel in KernelKind::ALL {
                    for h_over_l0 in [1.05, 1.3] {
                        for re_over_l0 in [2.1, 3.1, 4.2] {
                            for continuity in [false, true] {
                                v.push(Variant {
                                    kernel,
                                    h_over_l0,
                                    re_over_l0,
                                    continuity,
                                    potential_order: 1,
                                    wall_repulsion: false,
                                });
                            }
                        }
                    }
                }
                v
            }
        }
    }

    /// Every point of the grid, every problem.
    pub fn points(self) -> Vec<Point> {
        let mut out = Vec::new();
        for problem in Problem::ALL {
            for variant in self.variants() {
                for resolution in problem.resolutions(self) {
                    out.push(Point {
                        problem,
                        variant,
                        resolution,
                    });
                }
            }
        }
        out
    }
}

/// One run of the study.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Point {
    /// The problem.
    pub problem: Problem,
    /// The variant.
    pub variant: Variant,
    /// Particles along the cube side, or drop radius over `l0`.
    pub resolution: usize,
}

/// Gravity [m/s²].
const G: f64 = 9.8;
const CUBE_SIDE_M: f64 = 1.0e-3;
const DROP_RADIUS_M: f64 = 1.0e-3;

/// The sessile drop's volume [m³]: a hemisphere of radius 1 mm (its shape at θ = 90° without
/// gravity, which is where it starts).
fn drop_volume() -> f64 {
    2.0 / 3.0 * std::f64::consts::PI * DROP_RADIUS_M.powi(3)
}

impl Point {
    /// Folder name (the cube's damping shares the cube drop's runs).
    pub fn id(&self) -> String {
        format!(
            "{}/{}/n{}",
            self.problem.run_name(),
            self.variant.id(),
            self.resolution
        )
    }

    /// The analytic reference value: period [s], decay rate [1/s], height [m] or angle [°].
    pub fn reference(&self) -> f64 {
        match self.problem {
            Problem::CubeDrop => lamb::lamb_period(
                4,
                MATTE.surface_tension_n_m,
                MATTE.density_kg_m3,
                lamb::cube_equivalent_radius(CUBE_SIDE_M),
            ),
            Problem::CubeDamping => lamb::lamb_damping_rate(
                4,
                MATTE.viscosity_pa_s / MATTE.density_kg_m3
                    + artificial_viscosity_m2_s(&self.scene()),
                lamb::cube_equivalent_radius(CUBE_SIDE_M),
            ),
            Problem::SessileDrop => young_laplace::sessile_drop(
                drop_volume(),
                MATTE.density_kg_m3,
                MATTE.surface_tension_n_m,
                90.0,
                G,
            )
            .map(|d| d.height_m)
            .unwrap_or(f64::NAN),
            Problem::ContactAngle30 => 30.0,
            Problem::ContactAngle60 => 60.0,
        }
    }

    /// `l0` [m].
    pub fn l0(&self) -> f64 {
        self.problem.l0(self.resolution)
    }

    /// Fluid particles, estimated from the shape's volume over l0³: n³ for the cube, the
    /// hemisphere's (2/3)π n³ for the drops of radius n l0 on a plate.
    pub fn estimated_particles(&self) -> usize {
        let n = self.resolution as f64;
        match self.problem.plate_angle_deg() {
            None => (n * n * n) as usize,
            Some(_) => (2.0 / 3.0 * std::f64::consts::PI * n * n * n) as usize,
        }
    }

    /// The scene of the point.
    pub fn scene(&self) -> Scene {
        let v = &self.variant;
        // c² = 150 m²/s² as the paper's cube drop
        let b = SceneBuilder::new(self.l0(), 150f64.sqrt())
            .kernel(v.kernel, v.h_over_l0, v.re_over_l0)
            .potential_order(v.potential_order)
            .paper_effects()
            .liquid(&MATTE);
        let b = if v.continuity {
            b.continuity_density(Reinit::Shepard, 20)
        } else {
            b
        };
        let b = match (self.problem, self.problem.plate_angle_deg()) {
            (_, None) => {
                let h = 0.5 * CUBE_SIDE_M;
                // 3.5 ms ≈ 3 periods
                b.time(3.5e-3, 1.0e-5).body(
                    "cube",
                    MATTE.name,
                    BodyShape::Box {
                        min: [-h; 3],
                        max: [h; 3],
                    },
                )
            }
            // 20 ms ≈ 6 capillary times √(ρR³/σ); the drop starts as the hemisphere it would be
            // without gravity (and the angle problems spread from it, without gravity)
            (problem, Some(theta)) => {
                let b = if problem == Problem::SessileDrop {
                    b.gravity([0.0, 0.0, -G])
                } else {
                    b
                };
                b.time(0.02, 2.0e-4)
                    .wall_repulsion(v.wall_repulsion)
                    .solid("plate", &[(MATTE.name, theta)])
                    .body(
                        "drop",
                        MATTE.name,
                        BodyShape::Hemisphere {
                            center: [0.0; 3],
                            radius: DROP_RADIUS_M,
                            pole: [0.0, 0.0, 1.0],
                        },
                    )
                    .wall(
                        "plate",
                        "plate",
                        WallShape::Disk {
                            center: [0.0; 3],
                            radius: 2.0 * DROP_RADIUS_M,
                        },
                        WallBoundary::FreeSlip,
                    )
            }
        };
        b.build()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_point_builds_a_valid_scene_and_references_are_finite() {
        for p in Grid::Full.points() {
            let s = p.scene();
            assert_eq!(s.discretisation.kernel, p.variant.kernel);
        }
        let reference = |problem| {
            Point {
                problem,
                variant: Variant::DEFAULT,
                resolution: 10,
            }
            .reference()
        };
        assert!(reference(Problem::CubeDrop) > 1e-3 && reference(Problem::CubeDrop) < 1.3e-3);
        assert!(
            reference(Problem::SessileDrop) > 0.8e-3 && reference(Problem::SessileDrop) < 1.0e-3
        );
        assert_eq!(Grid::Standard.variants().len(), 10);
        // the cube's damping is measured on the cube drop's runs: same folder, same scene
        let cube = Grid::Standard.points()[0];
        let damping = Point {
            problem: Problem::CubeDamping,
            ..cube
        };
        assert_eq!((cube.id(), cube.scene()), (damping.id(), damping.scene()));
        // the wide-kernel candidates bring the wall repulsion to the plate, and only there
        let wide = *Grid::Standard.variants().last().expect("variants");
        assert!(wide.wall_repulsion);
        for problem in Problem::ALL {
            let s = Point {
                problem,
                variant: wide,
                resolution: 5,
            }
            .scene();
            assert_eq!(s.effects.wall_repulsion, !s.walls.is_empty(), "{problem:?}");
        }
        // Lamb's l = 4 rate with ν + ν_AV: larger than with ν alone
        assert!(damping.reference() > lamb::lamb_damping_rate(4, 3.13e-3 / 4500.0, 6.2e-4));
        assert_eq!(Grid::Full.variants().len(), 48);
    }
}
