//! A user's run, measured like the cases measure theirs (`verify measure RUN_DIR`): per liquid
//! and snapshot, the height above the wall, the wetted radius and its rate of change, the
//! side-view contact angle with its error bound, the l = 2 and l = 4 shape moments and the
//! centroid → `measures.csv` and two plots, with the Young–Laplace equilibrium drawn in where one
//! liquid rests on one horizontal wall. The snapshots are the run's `.vtu` series (`run --vtk N`);
//! a run without one is measured at its end, from `particles_final.csv`.
//! The same functions of [`crate::measure`] as the cases use. Under a continuum tension model a
//! liquid declared without a surface tension is the gas around the others: it is left out of
//! the measures, and the others' surfaces against it are their free surfaces.

mod draw;

use crate::analytic::{lamb, young_laplace};
use crate::measure::geometry::{self, sessile_angle_error_deg};
use crate::measure::shape::{axial_quadrupole_q2, cubic_harmonic_q4};
use crate::measure::surface::{self, Cloud};
use crate::output::dump::Dump;
use crate::output::run_info::RunInfo;
use crate::output::vtk_read::{read_pvd, read_vtu};
use crate::run::FINAL;
use solver::scene::WallShape;
use std::fmt::Write as _;
use std::path::Path;

/// One liquid at one snapshot.
#[derive(Clone, Debug)]
pub struct Row {
    /// Simulated time [s].
    pub time_s: f64,
    /// Liquid index.
    pub liquid: usize,
    /// Particles of the liquid.
    pub particles: usize,
    /// Centroid [m].
    pub centroid_m: [f64; 3],
    /// Height above the wall's top, or the z extent without a wall [m].
    pub height_m: f64,
    /// Radius of the wetted disc, `l0 √(N₁/π)` for N₁ particles in the first layer [m] (NaN
    /// without a wall).
    pub wetted_radius_m: f64,
    /// d(wetted radius)/dt by central differences over the snapshots [m/s].
    pub spreading_rate_m_s: f64,
    /// Side-view contact angle [deg] (NaN where the fit fails or without a wall).
    pub angle_deg: f64,
    /// Its tested error bound [deg] (NaN where none is tested).
    pub angle_bound_deg: f64,
    /// Axial l = 2 moment Q2 and the cubic l = 4 moment Q4 [-].
    pub q2: f64,
    /// See `q2`.
    pub q4: f64,
}

/// A run's measures, and the Young–Laplace equilibrium where it is defined.
pub struct Measures {
    /// Liquid names, by index.
    pub liquids: Vec<String>,
    /// One row per liquid and snapshot, in time order.
    pub rows: Vec<Row>,
    /// `(height [m], wetted radius [m], angle [deg])` of the Young–Laplace drop with the scene's
    /// volume, σ, θ and gravity, for one liquid on one horizontal wall.
    pub equilibrium: Option<(f64, f64, f64)>,
}

/// The top `z` [m] of the scene's only horizontal wall (a disk or a plate).
fn wall_top(scene: &solver::Scene) -> Option<f64> {
    match scene.walls.as_slice() {
        [w] => match &w.shape {
            WallShape::Disk { center, .. } => Some(center[2]),
            WallShape::Plate { top, .. } => Some(*top),
            _ => None,
        },
        _ => None,
    }
}

/// Calls `each` with the run's snapshots in turn, `(time [s], particles)` with the walls as the
/// particles' neighbours: one in memory at a time.
fn for_each_snapshot(
    dir: &Path,
    scene: &solver::Scene,
    mut each: impl FnMut(f64, Cloud),
) -> anyhow::Result<()> {
    let l0 = scene.discretisation.l0;
    let pvd = dir.join("particles.pvd");
    if !pvd.exists() {
        let last = dir.join(FINAL);
        if !last.exists() {
            anyhow::bail!(
                "{}: no snapshots (particles.pvd) and no final state ({FINAL}); run the scene \
                 with `--vtk N` to measure it over time",
                dir.display()
            );
        }
        let dump = Dump::read(&last)?.with_walls(Dump::walls_of(scene)?.as_ref());
        each(dump.time_s, dump.cloud(l0));
        return Ok(());
    }
    let walls = match read_vtu(&dir.join("walls.vtu")) {
        Ok(w) => w.pos,
        Err(_) => Vec::new(),
    };
    for (t, file) in read_pvd(&pvd).map_err(anyhow::Error::msg)? {
        let s = read_vtu(&dir.join(&file)).map_err(anyhow::Error::msg)?;
        let cloud = Cloud {
            pos: s.pos,
            phase: s.phase.iter().map(|&p| p as u8).collect(),
            walls: walls.clone(),
            l0_m: l0,
        };
        each(t, cloud);
    }
    Ok(())
}

/// Measures the run in `dir` from its `.vtu` snapshots, or at its end from its final state.
pub fn measure(dir: &Path) -> anyhow::Result<Measures> {
    let info = RunInfo::read(dir)?;
    let scene = &info.scene;
    let z_w = wall_top(scene);
    let n_liquids = scene.liquids.len();
    let gas = gases(scene);
    let mut rows = Vec::new();
    for_each_snapshot(dir, scene, |t, mut cloud| {
        cloud.retain_phases(|p| !gas[p as usize]);
        let classes = surface::classify(&cloud);
        for k in (0..n_liquids).filter(|&k| !gas[k]) {
            let pts: Vec<[f64; 3]> = (0..cloud.pos.len())
                .filter(|&i| cloud.phase[i] == k as u8)
                .map(|i| cloud.pos[i])
                .collect();
            rows.push(row(t, k, &pts, &cloud, &classes, z_w));
        }
    })?;
    spreading_rates(&mut rows, n_liquids);
    Ok(Measures {
        liquids: scene.liquids.iter().map(|l| l.name.clone()).collect(),
        equilibrium: equilibrium(scene, rows.last().map_or(0, |r| r.particles)),
        rows,
    })
}

fn row(
    time_s: f64,
    liquid: usize,
    pts: &[[f64; 3]],
    cloud: &Cloud,
    classes: &surface::Classes,
    z_w: Option<f64>,
) -> Row {
    let l0 = cloud.l0_m;
    let n = pts.len().max(1) as f64;
    let mut c = [0.0; 3];
    for p in pts {
        for a in 0..3 {
            c[a] += p[a] / n;
        }
    }
    let (lo, hi) = pts
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
            (a.min(p[2]), b.max(p[2]))
        });
    let (height_m, wetted_radius_m, angle_deg, angle_bound_deg) = match z_w {
        Some(z) => {
            let first = pts.iter().filter(|p| (p[2] - z).abs() < l0).count() as f64;
            let angle = geometry::sessile_contact_angle(cloud, classes, liquid as u8, z)
                .unwrap_or(f64::NAN);
            let radius = lamb::sphere_radius_from_volume(pts.len() as f64 * l0 * l0 * l0);
            let bound = sessile_angle_error_deg(radius / l0, angle).unwrap_or(f64::NAN);
            (
                hi + 0.5 * l0 - z,
                l0 * (first / std::f64::consts::PI).sqrt(),
                angle,
                bound,
            )
        }
        None => (hi - lo + l0, f64::NAN, f64::NAN, f64::NAN),
    };
    Row {
        time_s,
        liquid,
        particles: pts.len(),
        centroid_m: c,
        height_m,
        wetted_radius_m,
        spreading_rate_m_s: f64::NAN,
        angle_deg,
        angle_bound_deg,
        q2: axial_quadrupole_q2(pts),
        q4: cubic_harmonic_q4(pts),
    }
}

/// d(wetted radius)/dt per liquid: central differences inside, one-sided at the ends.
fn spreading_rates(rows: &mut [Row], n_liquids: usize) {
    for k in 0..n_liquids {
        let idx: Vec<usize> = (0..rows.len()).filter(|&i| rows[i].liquid == k).collect();
        for (j, &i) in idx.iter().enumerate() {
            let a = idx[j.saturating_sub(1)];
            let b = idx[(j + 1).min(idx.len() - 1)];
            let dt = rows[b].time_s - rows[a].time_s;
            if dt > 0.0 {
                rows[i].spreading_rate_m_s =
                    (rows[b].wetted_radius_m - rows[a].wetted_radius_m) / dt;
            }
        }
    }
}

/// Per liquid: whether it is the gas around the others, a liquid without a surface tension
/// under a continuum tension model (docs/model.md §4b).
fn gases(scene: &solver::Scene) -> Vec<bool> {
    let continuum = scene.effects.interfacial_tension.is_continuum();
    scene
        .liquids
        .iter()
        .map(|l| continuum && l.surface_tension.is_none())
        .collect()
}

/// The Young–Laplace drop of one liquid of `particles` particles on the scene's only wall: in
/// empty space, or in one gas (docs/model.md §4b), where the tension is the pair's, the
/// density the difference, and the angle Eq. 23's with the gas's σ zero:
/// `cos θ = σ cos θ_S / σ_ag`.
fn equilibrium(scene: &solver::Scene, particles: usize) -> Option<(f64, f64, f64)> {
    wall_top(scene)?;
    let gas = gases(scene);
    let (liquids, gases): (Vec<_>, Vec<_>) = scene.liquids.iter().zip(&gas).partition(|p| !*p.1);
    let ([(liquid, _)], [solid]) = (liquids.as_slice(), scene.solids.as_slice()) else {
        return None;
    };
    let typed = *solid.contact_angles.get(&liquid.name)?;
    let (theta, sigma, density) = match gases.as_slice() {
        [] => (typed, liquid.surface_tension?, liquid.density),
        [(g, _)] => {
            let s = scene.interface_tension(&liquid.name, &g.name)?;
            let cos = liquid.surface_tension? * typed.to_radians().cos() / s;
            (cos.acos().to_degrees(), s, liquid.density - g.density)
        }
        _ => return None,
    };
    if !theta.is_finite() {
        return None; // |cos θ| > 1: no equilibrium angle
    }
    let g = match scene.effects.gravity {
        Some([gx, gy, gz]) if gx == 0.0 && gy == 0.0 && gz <= 0.0 => -gz,
        Some(_) => return None, // tilted: not an axisymmetric drop
        None => 0.0,
    };
    let l0 = scene.discretisation.l0;
    let volume = particles as f64 * l0 * l0 * l0;
    // a gas as dense as the liquid takes its weight: the drop is as in zero gravity
    let (density, g) = match density > 0.0 {
        true => (density, g),
        false if density == 0.0 || g == 0.0 => (liquid.density, 0.0),
        false => return None, // the liquid would float
    };
    let d = young_laplace::sessile_drop(volume, density, sigma, theta, g).ok()?;
    Some((d.height_m, d.contact_radius_m, theta))
}

impl Measures {
    /// `measures.csv`: one row per liquid and snapshot.
    pub fn csv(&self) -> String {
        let mut s = String::from(
            "time_s,liquid,particles,centroid_x_m,centroid_y_m,centroid_z_m,height_m,wetted_radius_m,spreading_rate_m_s,contact_angle_deg,contact_angle_bound_deg,q2,q4\n",
        );
        for r in &self.rows {
            let _ = writeln!(
                s,
                "{:e},{},{},{:e},{:e},{:e},{:e},{:e},{:e},{},{},{:e},{:e}",
                r.time_s,
                self.liquids[r.liquid],
                r.particles,
                r.centroid_m[0],
                r.centroid_m[1],
                r.centroid_m[2],
                r.height_m,
                r.wetted_radius_m,
                r.spreading_rate_m_s,
                r.angle_deg,
                r.angle_bound_deg,
                r.q2,
                r.q4
            );
        }
        s
    }
}

/// Measures the run in `dir` and writes `measures.csv` and the plots into it; the paths written.
pub fn write(dir: &Path) -> anyhow::Result<Measures> {
    let m = measure(dir)?;
    crate::output::atomic_write(&dir.join("measures.csv"), m.csv().as_bytes())?;
    draw::plots(&m, dir)?;
    Ok(m)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A matte hemisphere on a plate in a gas (no surface tension) under the surface force,
    /// with the pair's tension `sigma_ag` [N/m].
    fn cap_in_gas(sigma_ag: f64) -> solver::Scene {
        solver::Scene::from_toml_str(&format!(
            r#"
            [discretisation]
            l0 = 1e-4
            h_over_l0 = 1.3
            sound_speed = 5.0
            [time]
            end = 1e-3
            output_interval = 1e-4
            [effects]
            interfacial_tension = "surface_force"
            [[liquid]]
            name = "matte"
            density = 4500.0
            viscosity = 3e-3
            surface_tension = 0.4
            [[liquid]]
            name = "gas"
            density = 4500.0
            viscosity = 3e-3
            [[interface]]
            liquids = ["matte", "gas"]
            tension = {sigma_ag}
            [[solid]]
            name = "plate"
            contact_angles = {{ matte = 60.0 }}
            [[body]]
            name = "cap"
            liquid = "matte"
            shape = {{ kind = "hemisphere", center = [0.0, 0.0, 0.0], radius = 1e-3, pole = [0.0, 0.0, 1.0] }}
            [[body]]
            name = "gas"
            liquid = "gas"
            shape = {{ kind = "surrounding", min = [-2e-3, -2e-3, 0.0], max = [2e-3, 2e-3, 2e-3] }}
            [[wall]]
            name = "plate"
            solid = "plate"
            shape = {{ kind = "plate", min = [-2e-3, -2e-3], max = [2e-3, 2e-3], top = 0.0 }}
            "#
        ))
        .unwrap()
    }

    #[test]
    fn a_liquid_in_a_declared_gas_has_the_equilibrium_of_eq_23() {
        assert_eq!(gases(&cap_in_gas(0.4)), vec![false, true]);
        // the hemisphere's volume, 2/3 π R³, in particles of l0 = 0.1 mm
        let n = (2.0 / 3.0 * std::f64::consts::PI * 1e-9 / 1e-12).round() as usize;
        // σ_ag = σ: the typed angle; 2σ: cos θ = cos 60°/2
        let (_, _, theta) = equilibrium(&cap_in_gas(0.4), n).unwrap();
        assert!((theta - 60.0).abs() < 1e-9, "{theta}");
        let (h, _, theta) = equilibrium(&cap_in_gas(0.8), n).unwrap();
        assert!(
            (theta - 0.25f64.acos().to_degrees()).abs() < 1e-9,
            "{theta}"
        );
        // zero gravity: the spherical cap of that volume and angle
        let cap = young_laplace::spherical_cap(n as f64 * 1e-12, theta);
        assert!(
            (h / cap.height_m - 1.0).abs() < 1e-6,
            "{h} {}",
            cap.height_m
        );
    }
}
