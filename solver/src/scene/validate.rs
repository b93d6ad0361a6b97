//! Validation of a parsed scene: ranges of every value and consistency of the references.
//! Checks that need the particles (counts, overlaps) and the time-step limits are made when the
//! simulation is built ([`crate::Simulation::new`]).

use super::{
    shapes::on_lattice_plane, DensityScheme, LaminarForm, PressureGradient, Reinit, Scene,
    SceneError, SurfaceForceWalls, TensionModel, WallBoundary,
};
use std::collections::BTreeSet;

type R = Result<(), SceneError>;

fn positive(field: &str, v: f64, what: &str) -> R {
    if v.is_finite() && v > 0.0 {
        Ok(())
    } else {
        Err(SceneError::invalid(
            field,
            v,
            format!("{what} must be a positive finite number"),
        ))
    }
}

fn non_negative(field: &str, v: f64, what: &str) -> R {
    if v.is_finite() && v >= 0.0 {
        Ok(())
    } else {
        Err(SceneError::invalid(
            field,
            v,
            format!("{what} must be zero or positive and finite"),
        ))
    }
}

fn in_range(field: &str, v: f64, lo: f64, hi: f64, what: &str) -> R {
    if v.is_finite() && v > lo && v <= hi {
        Ok(())
    } else {
        Err(SceneError::invalid(
            field,
            v,
            format!("{what} must lie in ({lo}, {hi}]"),
        ))
    }
}

fn unique_name(field: &str, name: &str, seen: &mut BTreeSet<String>) -> R {
    if name.trim().is_empty() {
        return Err(SceneError::invalid(
            field,
            "\"\"",
            "names must not be empty",
        ));
    }
    // names become column headers of the time series (`water_centroid_x_m`) and keys in the
    // records: a comma, quote or line break would split or shift a CSV column
    if let Some(c) = name.chars().find(|c| matches!(c, ',' | '"' | '\n' | '\r')) {
        return Err(SceneError::invalid(
            field,
            name,
            format!("names must not contain {c:?} (they head CSV columns); use e.g. `slag_FeO`"),
        ));
    }
    if !seen.insert(name.to_string()) {
        return Err(SceneError::invalid(field, name, "this name is used twice"));
    }
    Ok(())
}

pub(super) fn validate(s: &Scene) -> R {
    discretisation(s)?;
    time(s)?;
    effects(s)?;
    materials(s)?;
    bodies(s)?;
    walls(s)?;
    tension_inputs(s)?;
    super::periodic::validate(s)?;
    particle_budget(s)
}

/// Half-width of the domain in spacings: shapes must lie within ±`DOMAIN_SPACINGS`·l0 of the
/// origin (the neighbour grid spans ±2²⁰ cells of at least one spacing; this keeps a margin).
pub(crate) const DOMAIN_SPACINGS: f64 = 524_288.0;

fn inside_domain(field: String, lo: [f64; 3], hi: [f64; 3], l0: f64) -> R {
    let limit = DOMAIN_SPACINGS * l0;
    if (0..3).all(|k| lo[k] >= -limit && hi[k] <= limit) {
        Ok(())
    } else {
        Err(SceneError::invalid(
            field,
            format!("{lo:?} … {hi:?}"),
            format!("shapes must lie within ±{limit:e} m of the origin (2^19 spacings at l0 = {l0:e} m)"),
        ))
    }
}

/// Upper estimate of the particles the bodies and walls will take, from their bounding boxes,
/// refused above `discretisation.max_particles` before anything is allocated.
fn particle_budget(s: &Scene) -> R {
    let l0 = s.discretisation.l0;
    for b in &s.bodies {
        let (lo, hi) = b.shape.bounds();
        inside_domain(format!("body[{}].shape", b.name), lo, hi, l0)?;
    }
    for w in &s.walls {
        let t = s.wall_layers(w) as f64 * l0;
        let (lo, hi) = match w.shape {
            super::WallShape::Disk {
                center: c,
                radius: r,
            } => ([c[0] - r, c[1] - r, c[2] - t], [c[0] + r, c[1] + r, c[2]]),
            super::WallShape::Plate { min, max, top } => {
                ([min[0], min[1], top - t], [max[0], max[1], top])
            }
            super::WallShape::Box { min, max, .. } => (
                [min[0] - t, min[1] - t, min[2] - t],
                [max[0] + t, max[1] + t, max[2] + t],
            ),
        };
        inside_domain(format!("wall[{}].shape", w.name), lo, hi, l0)?;
    }
    let cells = |lo: [f64; 3], hi: [f64; 3]| -> f64 {
        (0..3).map(|k| (hi[k] - lo[k]) / l0 + 2.0).product()
    };
    let mut n: f64 = s
        .bodies
        .iter()
        .map(|b| {
            let (lo, hi) = b.shape.bounds();
            cells(lo, hi)
        })
        .sum();
    for w in &s.walls {
        let t = s.wall_layers(w) as f64 * l0;
        n += match w.shape {
            super::WallShape::Disk {
                center: c,
                radius: r,
            } => cells([c[0] - r, c[1] - r, c[2] - t], [c[0] + r, c[1] + r, c[2]]),
            super::WallShape::Plate { min, max, top } => {
                cells([min[0], min[1], top - t], [max[0], max[1], top])
            }
            super::WallShape::Box { min, max, .. } => cells(
                [min[0] - t, min[1] - t, min[2] - t],
                [max[0] + t, max[1] + t, max[2] + t],
            ),
        };
    }
    let limit = s.discretisation.max_particles;
    let within = n <= limit as f64; // false for NaN
    if !within {
        return Err(SceneError::invalid(
            "discretisation.max_particles",
            limit,
            format!("the bodies and walls would take up to {n:.3e} particles at l0 = {l0:e} m; enlarge l0, shrink the shapes, or raise max_particles"),
        ));
    }
    Ok(())
}

fn discretisation(s: &Scene) -> R {
    let d = &s.discretisation;
    positive("discretisation.l0", d.l0, "the particle spacing l0 [m]")?;
    // Support 2h ≤ l0 would leave a particle without neighbours; beyond h = 6 l0 a particle
    // has tens of thousands of neighbours — certainly a typo.
    in_range("discretisation.h_over_l0", d.h_over_l0, 0.5, 6.0, "h/l0")?;
    // The potential is repulsive below l0 and attractive up to r_e: r_e must exceed l0.
    in_range(
        "discretisation.re_over_l0",
        d.re_over_l0,
        1.0,
        10.0,
        "r_e/l0",
    )?;
    if !(1..=3).contains(&d.potential_order) {
        return Err(SceneError::invalid(
            "discretisation.potential_order",
            d.potential_order,
            "the potential's order must be 1 (Kondo 2007), 2 or 3",
        ));
    }
    positive(
        "discretisation.sound_speed",
        d.sound_speed,
        "the sound speed c [m/s]",
    )?;
    if !(d.neighbour_skin_over_l0.is_finite() && (0.0..=2.0).contains(&d.neighbour_skin_over_l0)) {
        return Err(SceneError::invalid(
            "discretisation.neighbour_skin_over_l0",
            d.neighbour_skin_over_l0,
            "the neighbour-list skin must lie in [0, 2] (in units of l0)",
        ));
    }
    Ok(())
}

fn time(s: &Scene) -> R {
    let t = &s.time;
    positive("time.end", t.end, "the end time [s]")?;
    positive(
        "time.output_interval",
        t.output_interval,
        "the output interval [s]",
    )?;
    if t.output_interval > t.end {
        return Err(SceneError::invalid(
            "time.output_interval",
            t.output_interval,
            format!("the output interval exceeds time.end = {} s", t.end),
        ));
    }
    if let Some(dt) = t.dt {
        positive("time.dt", dt, "a fixed time step [s]")?;
    }
    if t.max_steps == 0 {
        return Err(SceneError::invalid(
            "time.max_steps",
            0,
            "must be at least 1",
        ));
    }
    let f = &t.factors;
    in_range("time.factors.cfl", f.cfl, 0.0, 1.0, "a safety factor")?;
    in_range(
        "time.factors.viscous",
        f.viscous,
        0.0,
        1.0,
        "a safety factor",
    )?;
    in_range(
        "time.factors.capillary",
        f.capillary,
        0.0,
        1.0,
        "a safety factor",
    )?;
    in_range("time.factors.force", f.force, 0.0, 1.0, "a safety factor")?;
    let h = &s.health;
    positive("health.max_mach", h.max_mach, "the largest Mach number")?;
    positive(
        "health.max_compression",
        h.max_compression,
        "the largest compression ρ/ρ0 − 1",
    )?;
    in_range(
        "health.min_dt_ratio",
        h.min_dt_ratio,
        0.0,
        1.0,
        "the smallest step over the first step",
    )?;
    // not NaN (a NaN bound would pass every particle silently); infinity switches the check off
    if h.max_wall_depth_over_l0.is_nan() || h.max_wall_depth_over_l0 < 0.0 {
        return Err(SceneError::invalid(
            "health.max_wall_depth_over_l0",
            h.max_wall_depth_over_l0,
            "a depth in spacings, ≥ 0 (inf switches the check off)",
        ));
    }
    Ok(())
}

fn effects(s: &Scene) -> R {
    let e = &s.effects;
    if let Some(g) = e.gravity {
        if !g.iter().all(|x| x.is_finite()) {
            return Err(SceneError::invalid(
                "effects.gravity",
                format!("{g:?}"),
                "must be finite [m/s²]",
            ));
        }
    }
    if e.wall_repulsion && s.walls.is_empty() {
        return Err(SceneError::invalid(
            "effects.wall_repulsion",
            true,
            "a liquid–wall repulsion needs walls: add a [[wall]] or remove the effect",
        ));
    }
    if e.wall_repulsion && !e.interfacial_tension.is_potential() {
        return Err(SceneError::invalid(
            "effects.wall_repulsion",
            true,
            "its strength scales with the cohesive pressure of the potential: it needs effects.interfacial_tension = true (the potential)",
        ));
    }
    if let Some(ps) = &e.particle_shifting {
        // the shift per step is about A U dt ≤ A × 0.25 h: beyond A = 8 it exceeds 2 h
        if !(ps.coefficient > 0.0 && ps.coefficient <= 8.0) {
            return Err(SceneError::invalid(
                "effects.particle_shifting.coefficient",
                ps.coefficient,
                "A in δr = −A h U dt ∇C: in (0, 8] (4 is Sun et al. 2017's; larger moves a particle more than its spacing per step)",
            ));
        }
    }
    if let Some(na) = &e.nonaffine_viscosity {
        // its step limit 0.125 h/(α c) is the CFL limit's 0.25 h/c at α = 0.5
        if !(na.coefficient > 0.0 && na.coefficient <= 0.5) {
            return Err(SceneError::invalid(
                "effects.nonaffine_viscosity.coefficient",
                na.coefficient,
                "α in μ_na = α ρ c h: in (0, 0.5] (beyond 0.5 its viscous step limit is below the CFL limit; 0.01–0.1 damps particle-scale motion at 0.01–0.1 c/h)",
            ));
        }
    }
    if e.surface_force_walls != SurfaceForceWalls::default()
        && e.interfacial_tension != TensionModel::SurfaceForce
    {
        return Err(SceneError::invalid(
            "effects.surface_force_walls",
            "normal",
            "is how walls take part in the continuum surface force: it needs \
             effects.interfacial_tension = \"surface_force\"",
        ));
    }
    if e.laminar_form != LaminarForm::default() {
        if !e.laminar_viscosity {
            return Err(SceneError::invalid(
                "effects.laminar_form",
                "monaghan_cleary_gingold",
                "is the form of the laminar viscosity: it needs effects.laminar_viscosity = true",
            ));
        }
        if e.implicit_viscosity.is_some() {
            return Err(SceneError::invalid(
                "effects.laminar_form",
                "monaghan_cleary_gingold",
                "the implicit viscous solve integrates the default form (hu_adams) only: drop effects.implicit_viscosity or the form",
            ));
        }
    }
    if let Some(iv) = &e.implicit_viscosity {
        if !e.laminar_viscosity {
            return Err(SceneError::invalid(
                "effects.implicit_viscosity",
                "set",
                "integrates the laminar viscosity: it needs effects.laminar_viscosity = true",
            ));
        }
        if let Some(w) = s.walls.iter().find(|w| w.boundary == WallBoundary::NoSlip) {
            return Err(SceneError::invalid(
                "effects.implicit_viscosity",
                "set",
                format!(
                    "wall \"{}\" is no-slip; the implicit viscous solve supports free-slip walls only (its ghost velocities would make the system non-symmetric): make the wall free-slip or use the explicit viscosity",
                    w.name
                ),
            ));
        }
        if !(iv.relative_tolerance > 0.0 && iv.relative_tolerance <= 1e-3) {
            return Err(SceneError::invalid(
                "effects.implicit_viscosity.relative_tolerance",
                iv.relative_tolerance,
                "the solve's relative residual: in (0, 1e-3] (a looser one leaves a velocity error larger than the step's own)",
            ));
        }
        if iv.max_iterations == 0 {
            return Err(SceneError::invalid(
                "effects.implicit_viscosity.max_iterations",
                0,
                "at least 1",
            ));
        }
    }
    if let Some(av) = &e.artificial_viscosity {
        non_negative("effects.artificial_viscosity.alpha1", av.alpha1, "α1")?;
        non_negative("effects.artificial_viscosity.alpha2", av.alpha2, "α2")?;
    }
    let d = &s.density;
    if d.scheme == DensityScheme::Summation && d.reinit != Reinit::None {
        return Err(SceneError::invalid(
            "density.reinit",
            format!("{:?}", d.reinit).to_lowercase(),
            "re-initialisation applies only to density.scheme = \"continuity\"",
        ));
    }
    if d.reinit_every == 0 {
        return Err(SceneError::invalid(
            "density.reinit_every",
            0,
            "must be at least 1 step",
        ));
    }
    if !d.background_pressure.is_finite() {
        return Err(SceneError::invalid(
            "density.background_pressure",
            d.background_pressure,
            "must be a finite pressure [Pa]",
        ));
    }
    let p = &s.periodic;
    if d.background_pressure != 0.0 && (p.x.is_none() || p.y.is_none() || p.z.is_none()) {
        return Err(SceneError::invalid(
            "density.background_pressure",
            d.background_pressure,
            "only in a scene periodic along x, y and z (a free surface or a wall would feel it \
             as a force)",
        ));
    }
    if d.pressure_gradient == PressureGradient::Difference
        && s.effects.interfacial_tension == TensionModel::Potential
    {
        return Err(SceneError::invalid(
            "density.pressure_gradient",
            "difference",
            "is for the continuum models (effects.interfacial_tension = \"surface_force\" or \
             \"surface_stress\"): the pairwise potential's cohesion is held by the pressure \
             level that the difference form ignores (a cube of water ran to Mach 1 in 531 steps)",
        ));
    }
    Ok(())
}

fn materials(s: &Scene) -> R {
    if s.liquids.is_empty() {
        return Err(SceneError::invalid(
            "liquid",
            "[]",
            "a scene needs at least one [[liquid]]",
        ));
    }
    let mut names = BTreeSet::new();
    for l in &s.liquids {
        unique_name(&format!("liquid[{}].name", l.name), &l.name, &mut names)?;
        let f = |k: &str| format!("liquid[{}].{k}", l.name);
        positive(&f("density"), l.density, "the density ρ0 [kg/m³]")?;
        non_negative(&f("viscosity"), l.viscosity, "the viscosity μ [Pa·s]")?;
        if let Some(sigma) = l.surface_tension {
            positive(&f("surface_tension"), sigma, "the surface tension σ [N/m]")?;
        }
    }
    for so in &s.solids {
        unique_name(&format!("solid[{}].name", so.name), &so.name, &mut names)?;
        for (liquid, &angle) in &so.contact_angles {
            let field = format!("solid[{}].contact_angles.{liquid}", so.name);
            if s.liquid_index(liquid).is_none() {
                return Err(SceneError::invalid(
                    field,
                    liquid,
                    super::names::no_such(
                        "liquid",
                        liquid,
                        s.liquids.iter().map(|l| l.name.as_str()),
                    ),
                ));
            }
            if !(angle.is_finite() && angle > 0.0 && angle < 180.0) {
                return Err(SceneError::invalid(
                    field,
                    angle,
                    "a contact angle must lie strictly between 0 and 180 degrees",
                ));
            }
        }
    }
    let mut pairs = BTreeSet::new();
    for (n, i) in s.interfaces.iter().enumerate() {
        let field = format!("interface[{n}]");
        for name in &i.liquids {
            if s.liquid_index(name).is_none() {
                return Err(SceneError::invalid(
                    format!("{field}.liquids"),
                    name,
                    super::names::no_such(
                        "liquid",
                        name,
                        s.liquids.iter().map(|l| l.name.as_str()),
                    ),
                ));
            }
        }
        if i.liquids[0] == i.liquids[1] {
            return Err(SceneError::invalid(
                format!("{field}.liquids"),
                format!("{:?}", i.liquids),
                "an interface joins two different liquids",
            ));
        }
        positive(
            &format!("{field}.tension"),
            i.tension,
            "the interfacial tension σ_ab [N/m]",
        )?;
        let mut key = i.liquids.clone();
        key.sort();
        if !pairs.insert(key) {
            return Err(SceneError::invalid(
                format!("{field}.liquids"),
                format!("{:?}", i.liquids),
                "this pair of liquids has two [[interface]] entries",
            ));
        }
    }
    Ok(())
}

fn check_shape(prefix: &str, checks: Vec<(&'static str, String, bool)>) -> R {
    for (field, value, ok) in checks {
        if !ok {
            return Err(SceneError::invalid(
                format!("{prefix}.shape.{field}"),
                value,
                "must be finite, with positive sizes (and max > min)",
            ));
        }
    }
    Ok(())
}

fn bodies(s: &Scene) -> R {
    if s.bodies.is_empty() {
        return Err(SceneError::invalid(
            "body",
            "[]",
            "a scene needs at least one [[body]]",
        ));
    }
    let mut names = BTreeSet::new();
    for b in &s.bodies {
        let p = format!("body[{}]", b.name);
        unique_name(&format!("{p}.name"), &b.name, &mut names)?;
        match (&b.liquid, &b.cut) {
            (Some(l), None) => {
                if s.liquid_index(l).is_none() {
                    return Err(SceneError::invalid(
                        format!("{p}.liquid"),
                        l,
                        super::names::no_such(
                            "liquid",
                            l,
                            s.liquids.iter().map(|l| l.name.as_str()),
                        ),
                    ));
                }
            }
            (None, Some(cut)) => {
                for l in &cut.liquids {
                    if s.liquid_index(l).is_none() {
                        return Err(SceneError::invalid(
                            format!("{p}.cut.liquids"),
                            l,
                            super::names::no_such(
                                "liquid",
                                l,
                                s.liquids.iter().map(|l| l.name.as_str()),
                            ),
                        ));
                    }
                }
                let n = cut.normal;
                if !(n.iter().all(|x| x.is_finite()) && n.iter().any(|&x| x != 0.0)) {
                    return Err(SceneError::invalid(
                        format!("{p}.cut.normal"),
                        format!("{n:?}"),
                        "must be a finite non-zero vector",
                    ));
                }
                if !cut.point.iter().all(|x| x.is_finite()) {
                    return Err(SceneError::invalid(
                        format!("{p}.cut.point"),
                        format!("{:?}", cut.point),
                        "must be finite [m]",
                    ));
                }
            }
            (Some(_), Some(_)) => {
                return Err(SceneError::invalid(
                    p,
                    "liquid and cut",
                    "give either `liquid` or `cut`, not both",
                ));
            }
            (None, None) => {
                return Err(SceneError::invalid(
                    p,
                    "neither liquid nor cut",
                    "give the body's `liquid` (or a `cut` into two liquids)",
                ));
            }
        }
        check_shape(&p, b.shape.checks())?;
        if !b.velocity.iter().all(|x| x.is_finite()) {
            return Err(SceneError::invalid(
                format!("{p}.velocity"),
                format!("{:?}", b.velocity),
                "must be finite [m/s]",
            ));
        }
    }
    Ok(())
}

fn walls(s: &Scene) -> R {
    let mut names: BTreeSet<String> = s.bodies.iter().map(|b| b.name.clone()).collect();
    let l0 = s.discretisation.l0;
    for w in &s.walls {
        let p = format!("wall[{}]", w.name);
        unique_name(&format!("{p}.name"), &w.name, &mut names)?;
        if s.solid_index(&w.solid).is_none() {
            return Err(SceneError::invalid(
                format!("{p}.solid"),
                &w.solid,
                super::names::no_such("solid", &w.solid, s.solids.iter().map(|x| x.name.as_str())),
            ));
        }
        check_shape(&p, w.shape.checks())?;
        for (field, x) in w.shape.lattice_planes() {
            if !on_lattice_plane(x, l0) {
                return Err(SceneError::invalid(
                    format!("{p}.shape.{field}"),
                    x,
                    format!("wall surfaces must lie on lattice planes: a multiple of l0 = {l0} m"),
                ));
            }
        }
        let needed = s.kernel_support().max(s.r_e());
        if let Some(layers) = w.layers {
            if layers == 0 || (layers as f64) * l0 < needed * (1.0 - 1e-9) {
                return Err(SceneError::invalid(
                    format!("{p}.layers"),
                    layers,
                    format!(
                        "a wall must be at least as thick as the kernel support and the potential \
                         cut-off ({needed:e} m = {:.2} l0), or density and wetting come out wrong",
                        needed / l0
                    ),
                ));
            }
        }
    }
    Ok(())
}

/// With interfacial tension on, every pair of liquids present needs σ_ab; with the potential
/// every liquid also needs σ, and a contact angle on every solid that a wall is made of (with
/// the surface force, every liquid that has a σ). The continuum models act between liquids
/// only: they need two of them ([`continuum_inputs`]).
fn tension_inputs(s: &Scene) -> R {
    let model = s.effects.interfacial_tension;
    if !model.is_on() {
        return Ok(());
    }
    let mut used: BTreeSet<&str> = BTreeSet::new();
    for b in &s.bodies {
        if let Some(l) = &b.liquid {
            used.insert(l);
        }
        if let Some(c) = &b.cut {
            used.insert(&c.liquids[0]);
            used.insert(&c.liquids[1]);
        }
    }
    if model.is_continuum() {
        continuum_inputs(s, model, used.len())?;
    }
    for l in s.liquids.iter().filter(|_| model.is_potential()) {
        if l.surface_tension.is_none() {
            return Err(SceneError::invalid(
                format!("liquid[{}].surface_tension", l.name),
                "missing",
                "effects.interfacial_tension needs every liquid's surface tension [N/m]",
            ));
        }
    }
    let used: Vec<&str> = used.into_iter().collect();
    for (n, a) in used.iter().enumerate() {
        for b in &used[n + 1..] {
            if s.interface_tension(a, b).is_none() {
                return Err(SceneError::invalid(
                    "interface",
                    format!("missing for liquids [\"{a}\", \"{b}\"]"),
                    "these liquids can touch: add [[interface]] with their interfacial tension [N/m]",
                ));
            }
        }
    }
    for w in &s.walls {
        let solid = &s.solids[s.solid_index(&w.solid).expect("checked in walls()")];
        for l in &used {
            let has_sigma = s
                .liquids
                .iter()
                .any(|x| x.name == *l && x.surface_tension.is_some());
            let has_angle = solid.contact_angles.contains_key(*l);
            if !has_sigma && has_angle && model == TensionModel::SurfaceForce {
                // only the potential can reach here with a liquid without σ otherwise
                return Err(SceneError::invalid(
                    format!("solid[{}].contact_angles.{l}", solid.name),
                    "given",
                    format!(
                        "liquid '{l}' has no surface tension, so its contact angle takes no \
                         part in the surface force (Young: σ_lS = σ_S − σ_l cos θ): remove the \
                         angle, or give liquid[{l}].surface_tension"
                    ),
                ));
            }
            if !has_sigma && model == TensionModel::SurfaceForce {
                continue;
            }
            if !has_angle {
                return Err(SceneError::invalid(
                    format!("solid[{}].contact_angles.{l}", solid.name),
                    "missing",
                    format!(
                        "liquid '{l}' can touch wall '{}': give its contact angle [degrees]",
                        w.name
                    ),
                ));
            }
        }
    }
    Ok(())
}

/// The continuum models' own limits (the surface stress and the surface force): they act
/// across interfaces between liquid phases, so a scene needs at least two liquids in its
/// bodies (a liquid's free surface against empty space carries no tension: the surrounding gas
/// is declared as a liquid). The surface force splits the tensions among at most three phases:
/// three liquids, or, with the shares' walls, two and the one solid its walls are made of (the
/// wall normal's walls are no phase: three liquids on them). Contact angles on walls are not
/// built for the surface stress.
fn continuum_inputs(s: &Scene, model: TensionModel, liquids_used: usize) -> R {
    let name = match model {
        TensionModel::SurfaceForce => "surface_force",
        _ => "surface_stress",
    };
    if liquids_used < 2 {
        return Err(SceneError::invalid(
            "effects.interfacial_tension",
            format!("\"{name}\""),
            format!(
                "the {} acts across interfaces between liquid phases and a free surface \
                 against empty space carries none: declare the surrounding fluid as a second \
                 liquid and give the pair's [[interface]] tension",
                name.replace('_', " ")
            ),
        ));
    }
    if model == TensionModel::SurfaceForce && liquids_used > 3 {
        return Err(SceneError::invalid(
            "effects.interfacial_tension",
            format!("\"{name}\" with {liquids_used} liquids"),
            "the surface force splits each pair's tension into the liquids' shares \
             (σ_ab = σ_a + σ_b), which is exact for up to three liquids: use at most three, or \
             the potential (true)",
        ));
    }
    let Some(first) = s.walls.first() else {
        return Ok(());
    };
    if model != TensionModel::SurfaceForce {
        return Err(SceneError::invalid(
            format!("wall[{}]", first.name),
            "present",
            format!(
                "contact angles are not built for effects.interfacial_tension = \"{name}\": \
                 use \"surface_force\" or the potential (true) for scenes with walls"
            ),
        ));
    }
    if let Some(w) = s.walls.iter().find(|w| w.solid != first.solid) {
        return Err(SceneError::invalid(
            format!("wall[{}].solid", w.name),
            &w.solid,
            format!(
                "the surface force's walls are one phase of its split of the tensions: make \
                 every wall of one solid (wall[{}] is of '{}')",
                first.name, first.solid
            ),
        ));
    }
    if liquids_used > 2 && s.effects.surface_force_walls == SurfaceForceWalls::Shares {
        return Err(SceneError::invalid(
            "effects.interfacial_tension",
            format!("\"{name}\" with {liquids_used} liquids and walls"),
            "the surface force splits the tensions among at most three phases, and the shares' \
             walls make their solid one of them: use at most two liquids with walls, \
             effects.surface_force_walls = \"normal\" (whose walls are no phase) for three, or \
             the potential (true)",
        ));
    }
    Ok(())
}
