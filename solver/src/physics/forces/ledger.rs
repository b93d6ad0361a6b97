//! The energy ledger of the forces that are the gradient of no energy: what the pair loop
//! books apart, and how the time step turns it into energy taken out of the liquid.
//!
//! Such a term declares a [`Booking`]: the viscosities (dissipative; laminar viscosity at a
//! no-slip wall couples the liquid to the wall's ghost velocity instead, so its liquid and
//! wall neighbours are booked apart) and the pressure for the walls' own part
//! `−p_w V_w² ∇_i W_iw` (the extrapolated wall pressure has no energy) and, in its difference
//! form, for the liquid pairs' departure from the symmetric form. The fused loop then
//! also sums the booked force on each fluid particle `i` on its own, `f_i^t` [N], and returns,
//! per channel, `P = Σ_i f_i^t·v_i` [W] and `Q = Σ_i f_i^t·a_i` [W/s], with `v_i` the
//! velocity the forces were evaluated with and `a_i` the total acceleration.
//!
//! Why both: a kick `u → u' = u + τ a` (τ = dt/2) changes the kinetic energy by exactly
//! `Σ_i m_i ū_i·(u'_i − u_i) = τ Σ_i f_i·ū_i` with the mean velocity `ū = u + (τ/2) a` of the
//! kick, and `f_i = Σ_t f_i^t + m_i g`. So the work of term `t` in a kick is
//! `W^t = τ (P^t + (τ/2) Q^t)`, after which `P^t` (at the new velocity) is `P^t + τ Q^t`; the
//! kinetic energy of the kick–drift–kick step is then the sum of the terms' works to
//! round-off, whatever `dt` does, and the dissipated energy is `−Σ W^t` over the kicks
//! ([`Dissipation::kick`]).
//!
//! Which velocity: not the half-step velocity `v_{n+½}` the viscous forces are evaluated
//! with — booking `dt Σ f·v_{n+½}` misses `(τ²/2) Q` per kick, and the budget of the test cube
//! then drifts 2.3 times more, that of a drop on a plate 20 times — but the mean velocity of
//! each kick. Over the two kicks that use one acceleration, with a constant step, that sums
//! to `dt Σ f·v_{n+1}`: the power at the full-step velocity, synchronous with the positions
//! the force was evaluated at.

use serde::{Deserialize, Serialize};

/// A ledger a booked term's work goes to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Ledger {
    /// Laminar viscosity.
    Laminar = 0,
    /// Artificial viscosity.
    Artificial = 1,
    /// The pressure force's work that is the gradient of no energy: the walls' own part (wall
    /// channel) and, with the difference form, its liquid pairs' departure from the symmetric
    /// form (liquid channel).
    Pressure = 2,
}

impl Ledger {
    /// Number of ledgers.
    pub const COUNT: usize = 3;
}

/// Which coefficient of the pair force a booked term books: what its booked coefficient
/// multiplies.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Part {
    /// The central coefficient `a_ij` (force along `x_i − x_j`).
    Central,
    /// The shear coefficient `b_ij` (force along `v_i − v_j`).
    Shear,
}

/// How a term is booked: which coefficient it books, and for which neighbours.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Booking {
    /// Its ledger.
    pub ledger: Ledger,
    /// The coefficient it books.
    pub part: Part,
    /// Whether its pairs with liquid neighbours are booked (the liquid channel).
    pub liquid: bool,
    /// Whether its pairs with wall neighbours are booked (the wall channel).
    pub walls: bool,
}

/// Per ledger, the booking of the term booked to it, if any.
pub type Bookings = [Option<Booking>; Ledger::COUNT];

/// No term booked.
pub const NO_BOOKINGS: Bookings = [None; Ledger::COUNT];

/// The bookings of a single term.
pub const fn single(b: Option<Booking>) -> Bookings {
    let mut out = NO_BOOKINGS;
    if let Some(b) = b {
        out[b.ledger as usize] = Some(b);
    }
    out
}

/// The bookings of two lists of terms (`a` first where both book the same ledger).
pub const fn merge(a: Bookings, b: Bookings) -> Bookings {
    let mut out = a;
    let mut k = 0;
    while k < Ledger::COUNT {
        if out[k].is_none() {
            out[k] = b[k];
        }
        k += 1;
    }
    out
}

/// Whether some ledger is booked.
pub const fn any(b: Bookings) -> bool {
    let mut k = 0;
    while k < Ledger::COUNT {
        if b[k].is_some() {
            return true;
        }
        k += 1;
    }
    false
}

/// Whether some term books its pairs with wall neighbours.
pub const fn any_walls(b: Bookings) -> bool {
    let mut k = 0;
    while k < Ledger::COUNT {
        if let Some(x) = b[k] {
            if x.walls {
                return true;
            }
        }
        k += 1;
    }
    false
}

/// Number of channels: per ledger, liquid neighbours and wall neighbours.
pub const CHANNELS: usize = 2 * Ledger::COUNT;

/// The channel of `ledger` for liquid (`wall` false) or wall neighbours.
pub const fn channel(ledger: usize, wall: bool) -> usize {
    2 * ledger + wall as usize
}

/// Per channel, `P = Σ_i f_i·v_i` [W] and `Q = Σ_i f_i·a_i` [W/s] of one force evaluation
/// (module doc); between kicks, `P` follows the velocity ([`Dissipation::kick`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Power {
    /// `Σ_i f_i·v_i` [W] per channel.
    pub velocity_w: [f64; CHANNELS],
    /// `Σ_i f_i·a_i` [W/s] per channel.
    pub acceleration_w_s: [f64; CHANNELS],
}

impl Power {
    /// Adds `o` channel by channel.
    #[inline]
    pub fn add(&mut self, o: &Power) {
        for c in 0..CHANNELS {
            self.velocity_w[c] += o.velocity_w[c];
            self.acceleration_w_s[c] += o.acceleration_w_s[c];
        }
    }
}

/// The energy the booked terms and the density re-initialisation have taken out of the
/// liquid since the start [J], and the booked power of the current acceleration.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Dissipation {
    /// Per channel, `−Σ W` over the kicks so far [J] (module doc).
    pub dissipated_j: [f64; CHANNELS],
    /// Compression energy removed by the density re-initialisations so far [J]
    /// (`E(before) − E(after)`; either sign).
    pub density_reinit_j: f64,
    /// Energy the particle shifting took out so far [J] (either sign): the work of the
    /// forces along each step's shift, `Σ_i m_i a_i·δr_i` — first order in the shift, and
    /// counting the viscous part of `a_i` too, so the budget closes only to that order.
    #[serde(default)]
    pub shifting_j: f64,
    /// The booked power of the current accelerations at the current velocities.
    pub power: Power,
    /// The work of the continuum models' interfacial force so far, booked apart: not in
    /// [`Dissipation::total_j`] ([`InterfacialWork`]).
    #[serde(default)]
    pub interfacial: InterfacialWork,
    /// The work of the non-affine viscosity so far (≤ 0; its negative is in
    /// [`Dissipation::total_j`]).
    #[serde(default)]
    pub nonaffine: ForceWork,
}

/// The work of a force computed outside the pair loop, booked per kick at the kick's mean
/// velocity as the loop's terms' are (module doc): the continuum models' interfacial force
/// ([`InterfacialWork`]) and the non-affine viscosity
/// ([`crate::physics::nonaffine_viscosity`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct ForceWork {
    /// `Σ W` over the kicks so far [J].
    pub work_j: f64,
    /// `P = Σ_i F_i·v_i` [W] of the current force `F` at the current velocities.
    pub velocity_w: f64,
    /// `Q = Σ_i F_i·a_i` [W/s] of the current force and accelerations.
    pub acceleration_w_s: f64,
}

impl ForceWork {
    /// Books a kick of `tau_s` [s] and moves `P` to the new velocities.
    fn kick(&mut self, tau_s: f64) {
        self.work_j += tau_s * (self.velocity_w + 0.5 * tau_s * self.acceleration_w_s);
        self.velocity_w += tau_s * self.acceleration_w_s;
    }
}

/// The work of the continuum models' interfacial force on the liquid (docs/model.md §4a,
/// §4b).
///
/// It is kept out of the budget, which counts the models' interfacial energy estimate `E`
/// instead: the force is the gradient of no energy, and `W + ΔE` is the energy it put into
/// the liquid that `E` does not hold (the budget's drift where every other force derives from
/// an energy). Zero under the pairwise potential, whose force is `−∇` of the interfacial
/// energy the budget counts.
pub type InterfacialWork = ForceWork;

impl Dissipation {
    /// Books a kick `v ← v + τ a` of `tau_s` [s] with the current accelerations, and moves
    /// `P` to the new velocities.
    pub fn kick(&mut self, tau_s: f64) {
        let p = &mut self.power;
        for c in 0..CHANNELS {
            let q = p.acceleration_w_s[c];
            // the work τ Σ f·ū with ū = u + (τ/2) a, the kick's mean velocity
            self.dissipated_j[c] -= tau_s * (p.velocity_w[c] + 0.5 * tau_s * q);
            p.velocity_w[c] += tau_s * q;
        }
        self.interfacial.kick(tau_s);
        self.nonaffine.kick(tau_s);
    }

    /// Energy dissipated by `ledger` so far [J]: liquid pairs (`wall` false) or pairs with
    /// wall particles.
    pub fn of(&self, ledger: Ledger, wall: bool) -> f64 {
        self.dissipated_j[channel(ledger as usize, wall)]
    }

    /// Everything taken out of the liquid so far [J]: every channel, the re-initialisations,
    /// the shifting and the non-affine viscosity (not the interfacial force's work,
    /// [`InterfacialWork`]).
    pub fn total_j(&self) -> f64 {
        self.dissipated_j.iter().sum::<f64>() + self.density_reinit_j + self.shifting_j
            - self.nonaffine.work_j
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_kicks_book_the_kinetic_energy_change_of_one_particle() {
        // one particle of mass 2 kg, force f = (3, −1, 0.5) N from one term, velocity
        // (1, 2, −1) m/s: after two kicks of τ its kinetic energy changed by exactly the
        // booked work (everything here is exact in binary up to a few roundings: 1e-14)
        let (m, f, v0) = (2.0, [3.0, -1.0, 0.5], [1.0, 2.0, -1.0]);
        let a: Vec<f64> = f.iter().map(|x| x / m).collect();
        let dot = |x: &[f64], y: &[f64]| x.iter().zip(y).map(|(p, q)| p * q).sum::<f64>();
        let mut d = Dissipation::default();
        d.power.velocity_w[0] = dot(&f, &v0);
        d.power.acceleration_w_s[0] = dot(&f, &a);
        // the same force as the continuum tension's, booked apart
        d.interfacial.velocity_w = dot(&f, &v0);
        d.interfacial.acceleration_w_s = dot(&f, &a);
        let tau = 0.125;
        d.kick(tau);
        d.kick(0.5 * tau);
        let v1: Vec<f64> = v0.iter().zip(&a).map(|(v, a)| v + 1.5 * tau * a).collect();
        let dk = 0.5 * m * (dot(&v1, &v1) - dot(&v0, &v0));
        assert!(
            (d.of(Ledger::Laminar, false) + dk).abs() < 1e-14,
            "{d:?} vs {dk}"
        );
        assert!((d.power.velocity_w[0] - dot(&f, &v1)).abs() < 1e-14);
        assert!((d.interfacial.work_j - dk).abs() < 1e-14, "{d:?} vs {dk}");
        assert!((d.interfacial.velocity_w - dot(&f, &v1)).abs() < 1e-14);
        // the interfacial force's work is not in the total taken out
        assert_eq!(d.total_j(), d.dissipated_j[0]);
    }

    #[test]
    fn bookings_merge_by_ledger() {
        let lam = Booking {
            ledger: Ledger::Laminar,
            part: Part::Shear,
            liquid: true,
            walls: true,
        };
        let art = Booking {
            ledger: Ledger::Artificial,
            part: Part::Central,
            liquid: true,
            walls: false,
        };
        let both = merge(single(Some(art)), single(Some(lam)));
        assert_eq!(both, [Some(lam), Some(art), None]);
        assert_eq!(merge(single(None), NO_BOOKINGS), NO_BOOKINGS);
        assert_eq!(channel(Ledger::Artificial as usize, true), 3);
        assert!(any(both) && any_walls(both) && !any_walls(single(Some(art))));
    }
}
