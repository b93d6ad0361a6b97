//! The pair loop's booking of the dissipative terms, of the walls' own pressure and of the
//! pressure's difference form's departure from the compression energy's gradient
//! (`physics::forces::ledger`): it reports each term's power exactly, and it leaves the
//! accelerations bitwise alone. Its cost is measured by an ignored test.

use super::common::{advance, sim};
use super::energy_budget::{drop_on_plate, SUMMATION_CLIP};
use solver::kernel::WendlandC2;
use solver::physics::forces::ledger::{channel, Bookings, Ledger, Power, NO_BOOKINGS};
use solver::physics::forces::term::{Neighbour, PairKinematics, PairSums, Particle};
use solver::physics::forces::{fluid_forces, Off, PairTerm};
use solver::state::Vec3;
use solver::Simulation;
use std::time::Instant;

/// A term with its booking switched off: the loop sums nothing apart for it.
#[derive(Clone, Copy)]
struct Unbooked<T>(T);

impl<T: PairTerm> PairTerm for Unbooked<T> {
    const ON: bool = T::ON;
    const USES_VELOCITY: bool = T::USES_VELOCITY;
    const RATE: bool = T::RATE;
    const FAR: bool = T::FAR;
    const BOOKINGS: Bookings = NO_BOOKINGS;
    type Own = T::Own;
    type Lanes = T::Lanes;
    fn own(&self, i: Particle) -> T::Own {
        self.0.own(i)
    }
    #[inline(always)]
    fn gather(&self, own: &T::Own, l: &mut T::Lanes, n: usize, nb: Neighbour) {
        self.0.gather(own, l, n, nb)
    }
    #[inline(always)]
    fn pair(&self, s: &mut PairSums, own: &T::Own, l: &T::Lanes, n: usize, k: &PairKinematics) {
        self.0.pair(s, own, l, n, k)
    }
    #[inline(always)]
    fn far_forces(&self, lists: &solver::neighbours::NeighbourLists, out: &mut [Vec3]) {
        self.0.far_forces(lists, out)
    }
}

/// `(Σ_i f_i·v_i [W], Σ_i f_i·a_i [W/s], Σ_i |f_i·v_i| [W])` of the forces `f_i = m_i (acc_i
/// − g)` at the current velocities and the accelerations `a`.
fn power_of(s: &Simulation, acc: &[Vec3], a: &[Vec3]) -> (f64, f64, f64) {
    let p = &s.particles;
    let g = s.model.gravity();
    let (mut pv, mut pa, mut abs) = (0.0, 0.0, 0.0);
    for i in 0..p.n_fluid {
        let f = (acc[i] - g) * s.model.mass[p.phase[i] as usize];
        pv += f.dot(&p.vel[i]);
        pa += f.dot(&a[i]);
        abs += f.dot(&p.vel[i]).abs();
    }
    (pv, pa, abs)
}

/// The accelerations [m/s²] of the state of `s` under `term` alone (and gravity).
fn alone<T: PairTerm>(s: &Simulation, term: T) -> Vec<Vec3> {
    let mut acc = vec![Vec3::zeros(); s.particles.n_fluid];
    let _ = fluid_forces(
        &s.loop_input::<WendlandC2>(),
        &(term, Off),
        &mut acc,
        &mut [],
    );
    acc
}

/// The booked power of `ledger`, both sides.
fn booked(p: &Power, ledger: Ledger) -> (f64, f64) {
    let (l, w) = (
        channel(ledger as usize, false),
        channel(ledger as usize, true),
    );
    (
        p.velocity_w[l] + p.velocity_w[w],
        p.acceleration_w_s[l] + p.acceleration_w_s[w],
    )
}

/// Asserts that the power `power` booked to `ledger` is that of the forces `alone` gives,
/// at the velocities of `s` and the accelerations `acc`.
fn assert_booked(
    s: &Simulation,
    power: &Power,
    acc: &[Vec3],
    name: &str,
    alone: &[Vec3],
    ledger: Ledger,
) {
    let n = s.particles.n_fluid;
    let (pv, pa, abs) = power_of(s, alone, acc);
    let (bv, ba) = booked(power, ledger);
    assert!(abs > 0.0, "{name}: no power at all");
    // the same products summed in another order: round-off of ~1e-16 per term, over
    // some 10⁴ terms; 1e-10 of Σ|f·v| leaves a wide margin and still catches a single
    // pair booked twice or not at all (of order 1e-3 of it)
    assert!(
        (bv - pv).abs() <= 1e-10 * abs,
        "{name}: booked {bv:e} W, own {pv:e} W"
    );
    let scale = abs * acc.iter().map(|a| a.norm()).fold(0.0, f64::max)
        / s.particles.vel[..n]
            .iter()
            .map(|v| v.norm())
            .fold(0.0, f64::max);
    assert!(
        (ba - pa).abs() <= 1e-10 * scale,
        "{name}: booked {ba:e} W/s, own {pa:e} W/s"
    );
}

#[test]
fn the_central_laminar_form_is_booked_with_its_own_power() {
    let text = drop_on_plate("lattice", SUMMATION_CLIP, "no_slip").replace(
        "laminar_viscosity = true",
        "laminar_viscosity = true\nlaminar_form = \"monaghan_cleary_gingold\"",
    );
    let mut s = sim(&text);
    assert!(s
        .model
        .effects
        .names()
        .iter()
        .any(|e| e.contains("Gingold")));
    advance(&mut s, 200); // on the plate: the no-slip wall's pairs take part
    let mut acc = vec![Vec3::zeros(); s.particles.n_fluid];
    let power = s.pair_forces::<WendlandC2>(&mut acc, &mut []);
    let mcg = alone(&s, s.mcg_viscosity_term());
    assert_booked(&s, &power, &acc, "central laminar", &mcg, Ledger::Laminar);
    assert!(power.velocity_w[channel(Ledger::Laminar as usize, true)] != 0.0);
}

#[test]
fn the_loop_books_each_terms_own_power_and_leaves_the_accelerations_alone() {
    let mut s = sim(&drop_on_plate("lattice", SUMMATION_CLIP, "no_slip"));
    advance(&mut s, 200); // the drop is on the plate: wall pairs take part
    let n = s.particles.n_fluid;
    let mut acc = vec![Vec3::zeros(); n];
    let power = s.pair_forces::<WendlandC2>(&mut acc, &mut []);
    let inp = s.loop_input::<WendlandC2>();
    // the same list of terms, nothing booked: bitwise the same accelerations
    let mut plain = vec![Vec3::zeros(); n];
    let unbooked = (
        Unbooked(s.potential_term()),
        (
            Unbooked(s.pressure_term()),
            (
                Unbooked(s.artificial_viscosity_term()),
                (Unbooked(s.laminar_viscosity_term()), Off),
            ),
        ),
    );
    assert_eq!(
        fluid_forces(&inp, &unbooked, &mut plain, &mut []),
        Power::default()
    );
    assert_eq!(acc, plain, "booking changed the accelerations");

    // each booked term alone: its force is m (a − g), its power Σ f·v and Σ f·a
    let check = |name: &str, alone: &[Vec3], ledger: Ledger| {
        assert_booked(&s, &power, &acc, name, alone, ledger)
    };
    check(
        "laminar",
        &alone(&s, s.laminar_viscosity_term()),
        Ledger::Laminar,
    );
    let av = s.artificial_viscosity_term();
    check("artificial", &alone(&s, av), Ledger::Artificial);
    // the walls' own pressure: the pressure term with the liquid's pressures zeroed
    let mut walls_only = s.clone();
    walls_only.particles.pressure[..n].fill(0.0);
    let pressure = walls_only.pressure_term();
    check(
        "wall pressure",
        &alone(&walls_only, pressure),
        Ledger::Pressure,
    );
    // the no-slip plate's share of laminar viscosity is booked on its own channel
    let walls = channel(Ledger::Laminar as usize, true);
    assert!(power.velocity_w[walls] != 0.0);
}

/// The cost of the booking in the pair loop, on the state of the 20 k cube benchmark
/// (`scenes/bench_cube_20k.toml`, no walls): every term booked, none, and one at a time,
/// interleaved; prints the quartiles. Run with
/// `cargo test -p solver --test solver booking_cost -- --ignored --nocapture`.
#[test]
#[ignore]
fn booking_cost() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../scenes/bench_cube_20k.toml");
    let mut s = sim(&std::fs::read_to_string(path).unwrap());
    advance(&mut s, 20);
    let inp = s.loop_input::<WendlandC2>();
    let n = s.particles.n_fluid;
    let (pot, pr) = (s.potential_term(), s.pressure_term());
    let (av, lam) = (s.artificial_viscosity_term(), s.laminar_viscosity_term());
    let (upot, upr, uav, ulam) = (Unbooked(pot), Unbooked(pr), Unbooked(av), Unbooked(lam));
    let mut acc = vec![Vec3::zeros(); n];
    let mut time: Vec<Vec<f64>> = vec![Vec::new(); 5];
    let reps = 101;
    for k in 0..reps {
        for v in 0..5 {
            let w = (k + v) % 5;
            let t0 = Instant::now();
            let _ = match w {
                0 => fluid_forces(&inp, &(pot, (pr, (av, (lam, Off)))), &mut acc, &mut []),
                1 => fluid_forces(&inp, &(upot, (upr, (uav, (ulam, Off)))), &mut acc, &mut []),
                2 => fluid_forces(&inp, &(upot, (upr, (av, (ulam, Off)))), &mut acc, &mut []),
                3 => fluid_forces(&inp, &(upot, (upr, (uav, (lam, Off)))), &mut acc, &mut []),
                _ => fluid_forces(&inp, &(upot, (pr, (uav, (ulam, Off)))), &mut acc, &mut []),
            };
            time[w].push(t0.elapsed().as_secs_f64());
        }
    }
    let names = ["all booked", "none", "artificial", "laminar", "pressure"];
    for (name, mut t) in names.into_iter().zip(time) {
        t.sort_by(f64::total_cmp);
        let q = |f: usize| t[f * reps / 4] * 1e3;
        println!("{name:12} quartiles {:.3} {:.3} {:.3} ms", q(1), q(2), q(3));
    }
}

#[test]
fn the_difference_form_books_its_departure_from_the_compression_energys_gradient() {
    // a hemisphere under the surface force on a plate, in motion: liquid and wall pairs
    let text =
        super::surface_force_walls::cap(120.0, "[density]\npressure_gradient = \"difference\"");
    let mut s = sim(&text);
    advance(&mut s, 30);
    let mut acc = vec![Vec3::zeros(); s.particles.n_fluid];
    let power = s.pair_forces::<WendlandC2>(&mut acc, &mut []);
    // the departure is the difference form's force less the compression energy's gradient,
    // which is the symmetric form's force less its booked walls' own part
    let difference = alone(&s, s.pressure_difference_term());
    let symmetric = alone(&s, s.pressure_term());
    let mut own = vec![Vec3::zeros(); s.particles.n_fluid];
    let walls_own = fluid_forces(
        &s.loop_input::<WendlandC2>(),
        &(s.pressure_term(), Off),
        &mut own,
        &mut [],
    );
    let departure: Vec<Vec3> = difference
        .iter()
        .zip(&symmetric)
        .map(|(d, y)| d - y + s.model.gravity())
        .collect();
    let (pv, _, abs) = power_of(&s, &departure, &acc);
    let expected = pv + booked(&walls_own, Ledger::Pressure).0;
    let (bv, _) = booked(&power, Ledger::Pressure);
    assert!(abs > 0.0, "no departure at all");
    // the same products summed in another order (round-off, as in `assert_booked`)
    assert!(
        (bv - expected).abs() <= 1e-10 * (abs + expected.abs()),
        "booked {bv:e} W, expected {expected:e} W"
    );
}
