//! Seeded inputs shared by the criterion benchmarks in `benches/benches/`.
//!
//! Every benchmark runs on a cube of copper matte (ρ = 4500 kg/m³, μ = 3.13 mPa·s,
//! σ = 0.40 N/m, c = 12.25 m/s, Wendland C2, h = 1.05 l0) of 1 mm edge at two resolutions:
//! 27³ = 19,683 particles (l0 = 1 mm/27, "20k") and 54³ = 157,464 particles (l0 = 1 mm/54,
//! "160k"). The walls benchmark uses the same cube resting on a disk wall.
//!
//! A lattice is a special input (every pair distance repeats), so [`fixture`] displaces each
//! fluid particle by a deterministic pseudo-random amount of up to ±0.05 l0 per axis and gives
//! it a velocity of up to ±0.05 m/s per axis ([`Lcg`], fixed seed: the inputs are the same in
//! every run), rebuilds the neighbour lists as `Simulation` does (sort by cell, permute,
//! build), and takes one time step so that density, pressure, wall values and accelerations
//! are those of the perturbed state. The result is a mid-run state.
//!
//! Run the benchmarks with `cargo bench -p benches [-- FILTER]`; criterion writes its reports
//! under `target/criterion/`.

use solver::kernel::{KernelKind, WendlandC2};
use solver::state::Vec3;
use solver::{Scene, Simulation};
use std::time::Duration;

/// The kernel of every benchmark scene.
pub type K = WendlandC2;

/// Particles per cube edge, with the label used in benchmark ids.
pub const SIZES: [(&str, usize); 2] = [("20k", 27), ("160k", 54)];

/// The two potential cut-offs `r_e / l0` of the issue (the paper's 2.1 and the default 4.2).
pub const CUTOFFS: [f64; 2] = [2.1, 4.2];

/// Cube edge [m].
const EDGE_M: f64 = 1.0e-3;

/// Seed of the perturbation.
const SEED: u64 = 0x5eed_2024_0bad_cafe;

/// Benchmark label of a cut-off, e.g. `re2.1`.
pub fn re_label(re_over_l0: f64) -> String {
    format!("re{re_over_l0}")
}

/// Sampling settings. Criterion's default (100 samples, 5 s, linear sampling of at least 5050
/// iterations) would take hours here; instead, to keep the whole `cargo bench -p benches`
/// within about ten minutes on two cores:
/// - 20k, light routines (≤ 40 ms): 20 samples in 6 s after a 1 s warm-up;
/// - 20k heavy, and 160k light: 10 flat samples (every sample the same number of
///   iterations, criterion's mode for long routines) in 5 s;
/// - 160k heavy routines (a time step, a list rebuild: 0.2–1 s): 10 flat samples in 12 s
///   after a 2 s warm-up, i.e. at least 10 timed iterations.
#[derive(Clone, Copy, Debug)]
pub struct Sampling {
    /// Samples per benchmark.
    pub sample_size: usize,
    /// Warm-up time.
    pub warm_up: Duration,
    /// Target measurement time.
    pub measurement: Duration,
    /// Whether every sample runs the same number of iterations (criterion's `Flat` mode, for
    /// long routines).
    pub flat: bool,
}

/// Sampling for a cube of `n_side³` particles; `heavy` for a time step or a list rebuild.
pub fn sampling(n_side: usize, heavy: bool) -> Sampling {
    match (n_side > 30, heavy) {
        (false, false) => Sampling {
            sample_size: 20,
            warm_up: Duration::from_secs(1),
            measurement: Duration::from_secs(6),
            flat: false,
        },
        (false, true) => Sampling {
            sample_size: 10,
            warm_up: Duration::from_secs(1),
            measurement: Duration::from_secs(5),
            flat: true,
        },
        (true, false) => Sampling {
            sample_size: 10,
            warm_up: Duration::from_secs(1),
            measurement: Duration::from_secs(5),
            flat: true,
        },
        (true, true) => Sampling {
            sample_size: 10,
            warm_up: Duration::from_secs(2),
            measurement: Duration::from_secs(12),
            flat: true,
        },
    }
}

/// Scene text: the matte cube of `n_side³` particles with the potential cut-off
/// `re_over_l0`, laminar and artificial viscosity; with `plate`, the cube rests on a disk wall
/// (z = 0) under gravity instead of floating free.
pub fn scene_toml(n_side: usize, re_over_l0: f64, plate: bool) -> String {
    let l0 = EDGE_M / n_side as f64;
    let half = 0.5 * EDGE_M;
    let (zmin, zmax) = if plate { (0.0, EDGE_M) } else { (-half, half) };
    let mut s = format!(
        r#"description = "benchmark: matte cube, {n_side}^3 particles, r_e = {re_over_l0} l0"

[discretisation]
l0 = {l0:?}
kernel = "wendland_c2"
h_over_l0 = 1.05
re_over_l0 = {re_over_l0:?}
sound_speed = 12.247448713915890

[time]
end = 1.0e-4
output_interval = 1.0e-5

[effects]
interfacial_tension = true
laminar_viscosity = true
artificial_viscosity = {{ alpha1 = 0.01, alpha2 = 0.01 }}
{gravity}
[[liquid]]
name = "matte"
density = 4500.0
viscosity = 3.13e-3
surface_tension = 0.40

[[body]]
name = "cube"
liquid = "matte"
shape = {{ kind = "box", min = [{nh:?}, {nh:?}, {zmin:?}], max = [{half:?}, {half:?}, {zmax:?}] }}
"#,
        gravity = if plate {
            "gravity = [0.0, 0.0, -9.81]\n"
        } else {
            ""
        },
        nh = -half,
    );
    if plate {
        s.push_str(
            r#"
[[solid]]
name = "alumina"
contact_angles = { matte = 90.0 }

[[wall]]
name = "plate"
solid = "alumina"
shape = { kind = "disk", center = [0.0, 0.0, 0.0], radius = 8.0e-4 }
"#,
        );
    }
    s
}

/// A 64-bit linear congruential generator (Knuth's MMIX constants): deterministic, no
/// dependencies; good enough to break the symmetry of a lattice.
#[derive(Clone, Debug)]
pub struct Lcg(u64);

impl Lcg {
    /// A generator with the given seed.
    pub fn new(seed: u64) -> Self {
        Lcg(seed)
    }

    /// Uniform in `[-1, 1)`, from the 53 high bits of the state.
    pub fn symmetric(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        2.0 * (self.0 >> 11) as f64 / (1u64 << 53) as f64 - 1.0
    }

    /// A vector with components uniform in `[-a, a)`.
    pub fn vec(&mut self, a: f64) -> Vec3 {
        Vec3::new(
            a * self.symmetric(),
            a * self.symmetric(),
            a * self.symmetric(),
        )
    }
}

/// The benchmark state: the scene of [`scene_toml`] built, its fluid perturbed (seeded), the
/// lists rebuilt and one time step taken.
pub fn fixture(n_side: usize, re_over_l0: f64, plate: bool) -> Simulation {
    let sim = perturbed(&scene_toml(n_side, re_over_l0, plate), n_side);
    assert_eq!(sim.model.kernel, KernelKind::WendlandC2);
    sim
}

/// The scene `text` of `n_side³` fluid particles built, its fluid perturbed (seeded by
/// `n_side`), the lists rebuilt and one time step taken.
fn perturbed(text: &str, n_side: usize) -> Simulation {
    let scene = Scene::from_toml_str(text).expect("benchmark scene parses");
    let mut sim = Simulation::new(&scene).expect("benchmark scene builds");
    assert_eq!(sim.particles.n_fluid, n_side.pow(3));
    let l0 = sim.model.l0_m;
    let mut rng = Lcg::new(SEED ^ ((n_side as u64) << 32));
    let p = &mut sim.particles;
    for i in 0..p.n_fluid {
        p.pos[i] += rng.vec(0.05 * l0);
        p.vel[i] = rng.vec(0.05);
    }
    sim.rebuild_neighbours()
        .expect("benchmark particles stay on the cell grid");
    sim.step(f64::INFINITY)
        .expect("one step of the benchmark scene");
    sim
}

/// Scene text for the tension models' comparison: a water drop of radius 0.3 mm (R/l0 = 8.1)
/// in a host liquid of the same density and viscosity filling a periodic cube of 1 mm edge,
/// `n_side³` particles, σ_ab = 0.0728 N/m, laminar and artificial viscosity, under the tension
/// model `model` (`"potential"`, `"surface_stress"` or `"surface_force"`). The potential runs at
/// the default setting (h = 1.05 l0, r_e = 4.2 l0, each liquid's σ = 0.0728 N/m with the pair's
/// through Fowkes), the continuum models at the convergence case's h = 1.3 l0 (their colour
/// kernel reaches r_e = 4.2 l0, or `R` l0 for a model named `"NAME@reR"`, e.g.
/// `"surface_force@re3.6"`).
pub fn drop_in_host_toml(n_side: usize, model: &str) -> String {
    let l0 = EDGE_M / n_side as f64;
    let half = 0.5 * EDGE_M;
    let (model, re) = model
        .split_once("@re")
        .map_or((model, None), |(m, r)| (m, Some(r)));
    let h = match (model, re) {
        ("potential", _) => String::new(),
        (_, None) => "h_over_l0 = 1.3\n".into(),
        (_, Some(re)) => format!("h_over_l0 = 1.3\nre_over_l0 = {re}\n"),
    };
    format!(
        r#"description = "benchmark: water drop in a host, {n_side}^3 particles, {model}"

[discretisation]
l0 = {l0:?}
{h}sound_speed = 3.82

[time]
end = 1.0e-4
output_interval = 1.0e-5

[effects]
interfacial_tension = "{model}"
laminar_viscosity = true
artificial_viscosity = {{ alpha1 = 0.01, alpha2 = 0.01 }}

[[liquid]]
name = "water"
density = 997.0
viscosity = 1.0e-3
surface_tension = 0.0728

[[liquid]]
name = "host"
density = 997.0
viscosity = 1.0e-3
surface_tension = 0.0728

[[interface]]
liquids = ["water", "host"]
tension = 0.0728

[[body]]
name = "drop"
liquid = "water"
shape = {{ kind = "ellipsoid", center = [{half:?}, {half:?}, {half:?}], semi_axes = [3.0e-4, 3.0e-4, 3.0e-4] }}

[[body]]
name = "host"
liquid = "host"
shape = {{ kind = "box_around_ellipsoid", min = [0.0, 0.0, 0.0], max = [{edge:?}, {edge:?}, {edge:?}], center = [{half:?}, {half:?}, {half:?}], semi_axes = [3.0e-4, 3.0e-4, 3.0e-4] }}

[periodic]
x = [0.0, {edge:?}]
y = [0.0, {edge:?}]
z = [0.0, {edge:?}]
"#,
        edge = EDGE_M,
    )
}

/// The state of [`drop_in_host_toml`], perturbed as [`fixture`]'s (seeded), lists rebuilt, one
/// time step taken.
pub fn drop_in_host(n_side: usize, model: &str) -> Simulation {
    perturbed(&drop_in_host_toml(n_side, model), n_side)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_model_named_with_a_reach_sets_the_colour_kernels() {
        let scene = |m: &str| Scene::from_toml_str(&drop_in_host_toml(12, m)).unwrap();
        let (plain, narrow) = (scene("surface_force"), scene("surface_force@re3.6"));
        assert_eq!(plain.discretisation.re_over_l0, 4.2); // the default
        assert_eq!(narrow.discretisation.re_over_l0, 3.6);
        assert_eq!(narrow.discretisation.h_over_l0, 1.3);
        assert_eq!(
            narrow.effects.interfacial_tension,
            plain.effects.interfacial_tension
        );
    }
}
