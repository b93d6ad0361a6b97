//! The hard cases' metrics: each invariant of a healthy run against its exact or physical
//! bound.

use super::measure::HardRun;
use super::{SCENES, TRANSIENT};
use crate::suite::{Metric, Tolerance};

/// The metrics of one run of the case `case`.
pub fn run_metrics(case: &str, m: &HardRun) -> Vec<Metric> {
    let (run, sc) = (m.run, &m.run.info.scene);
    let id = &run.id;
    let name = |what: &str| format!("{id}: {what}");
    let metric =
        |what: &str, unit: &str, value: f64| Metric::new(case, name(what), unit, value).run(run);
    let check = |what: &str, ok: bool, source: &str| {
        Metric::check(case, name(what), "yes", ok, source).run(run)
    };
    let kept = m.counts.first().is_some_and(|&c0| {
        m.counts.iter().all(|&c| c == c0) && c0 as usize == run.info.fluid_particles
    });
    let mass = &m.mass_kg;
    let mut out = vec![
        check(
            "completed",
            run.completed(),
            "the run reaches its end time without a blow-up",
        )
        .note(
            run.info
                .error
                .clone()
                .unwrap_or_else(|| format!("{} steps", run.info.steps)),
        ),
        check(
            "particles kept",
            kept,
            "every particle is accounted for at every output",
        ),
        check(
            "mass conserved",
            mass.iter().all(|x| x.to_bits() == mass[0].to_bits()),
            "the total mass is the same bits at every output",
        ),
    ];
    if !sc.walls.is_empty() {
        out.push(
            metric("particles inside walls", "count", m.inside_walls as f64).against(
                0.0,
                Tolerance::exact("no liquid particle deeper than l0/2 inside a wall (final state)"),
            ),
        );
    }
    out.push(
        metric(
            "max compression after the transient",
            "-",
            m.compression_after_transient,
        )
        .against(
            0.0,
            Tolerance::absolute(
                0.1,
                "10 %: ten times the 1 % compression the sound speeds are chosen for",
            ),
        )
        .note(format!(
            "largest ρ/ρ0 − 1 after the first {:.0} % of the run; over the whole run {:.3}",
            TRANSIENT * 100.0,
            m.compression_max
        )),
    );
    if sc.effects.gravity.is_none() && sc.walls.is_empty() {
        out.extend(conservation(case, m));
    }
    out.extend(integrity(case, m));
    out
}

/// Where no external force acts: momentum to round-off, and no energy from nowhere.
fn conservation(case: &str, m: &HardRun) -> [Metric; 2] {
    let (run, sc) = (m.run, &m.run.info.scene);
    let (id, l0) = (&run.id, sc.discretisation.l0);
    let scale = m.mass_kg.first().copied().unwrap_or(0.0) * m.max_speed_m_s;
    // the EOS stores up to p_b²/(2ρc²) per volume at the cohesive pressure p_b ≈ 1.75σ/l0
    // (docs/model.md §4); it is not in kinetic + interfacial energy and may flow into them
    let c2 = sc.discretisation.sound_speed.powi(2);
    let stored: f64 = (sc.liquids.iter().zip(&m.initial_counts))
        .map(|(l, &n)| {
            let pb = 1.75 * l.surface_tension.unwrap_or(0.0) / l0;
            pb * pb / (2.0 * l.density * c2) * n * l0.powi(3)
        })
        .sum();
    [
        Metric::new(case, format!("{id}: momentum drift"), "kg m/s", m.momentum_drift_kg_m_s)
            .against(0.0, Tolerance::absolute(1e-9 * scale, format!("1e-9 of the motion's momentum scale M·|v|max = {scale:.2e} kg m/s: every pair force is antisymmetric, only round-off remains")))
            .run(run),
        Metric::new(case, format!("{id}: energy growth after the transient"), "J", m.energy_growth_j)
            .against(0.0, Tolerance::absolute(2.0 * stored, format!("twice the compression energy the EOS can hold at the cohesive pressure, p_b²/(2ρc²)·V = {stored:.2e} J")))
            .run(run)
            .note("largest rise of kinetic + interfacial energy above its value at 20 % of the run"),
    ]
}

/// The liquid stays whole: bodies at the end, clumping, and for the drop at rest its centroid.
fn integrity(case: &str, m: &HardRun) -> Vec<Metric> {
    let run = m.run;
    let (id, l0) = (&run.id, run.info.scene.discretisation.l0);
    let expected_bodies = SCENES.iter().find(|s| s.0 == id).and_then(|s| s.4);
    let mut bodies = Metric::new(
        case,
        format!("{id}: bodies at the end"),
        "count",
        m.bodies as f64,
    )
    .run(run);
    if let Some(n) = expected_bodies {
        bodies = bodies.against(n as f64, Tolerance::exact("particles within 1.5 l0 of each other form one body (docs/model.md §7's interface distance); no spurious fragments"));
    }
    // clumping is judged on the drop at rest: during a violent relaxation particles pass within
    // l0/2 of each other for a while (the 5³ cube: 29 % at 3 ms, 0 % from 4 ms)
    let resting = id == "resting_drop";
    let mut clumped = Metric::new(case, format!("{id}: clumped particles"), "-", m.clumped)
        .run(run)
        .note("share of particles with a neighbour closer than l0/2 in the final state");
    if resting {
        clumped = clumped.against(
            0.0,
            Tolerance::absolute(
                0.01,
                "1 %: a drop at rest must not pair into clusters (none on the starting lattice)",
            ),
        );
    }
    let mut out = vec![bodies, clumped];
    if resting {
        out.push(
            Metric::new(case, format!("{id}: centroid drift"), "m", m.centroid_drift_m)
                .against(0.0, Tolerance::absolute(1e-6 * l0, "1e-6 l0: with momentum conserved to round-off the centroid cannot move measurably"))
                .run(run)
                .note(format!("over {} steps", run.info.steps)),
        );
    }
    out
}
