//! The force terms of a run, assembled from the model and the current state, and the one place
//! that registers them: [`Simulation::pair_forces`] lists every term with the effect that
//! declares it. Adding a term is its file in `physics/` plus one line there.

use super::Simulation;
use crate::kernel::Kernel;
use crate::physics::forces::Monaghan1994WallRepulsion;
use crate::physics::forces::{
    fluid_forces, ArtificialViscosity, ContinuityRate, LaminarViscosity, LoopInput,
    MonaghanClearyGingold, Neighbourhood, Off, Power, Pressure, PressureDifference,
};
use crate::physics::surface_tension::PairwisePotential;
use crate::scene::LaminarForm;
use crate::state::Vec3;

/// Runs `$run` with `$terms` bound to the list `(A, (B, (…, Off)))` of the declared terms, one
/// monomorphised loop per combination of declared terms. Each line is `if DECLARED => TERM,`
/// (or `always => TERM,`; or `if A => TERM_A, else if B => TERM_B,` for two forms of one
/// term, never both), in loop order: the order in which the terms' parts of a pair sum are
/// added.
macro_rules! with_terms {
    ($terms:ident => $run:expr; $($list:tt)*) => {
        with_terms!(@pick [] $terms $run; $($list)*)
    };
    (@pick [$($built:expr),*] $terms:ident $run:expr; ) => {{
        let $terms = with_terms!(@nest $($built),*);
        $run
    }};
    (@pick [$($built:expr),*] $terms:ident $run:expr; always => $make:expr, $($rest:tt)*) => {
        with_terms!(@pick [$($built,)* $make] $terms $run; $($rest)*)
    };
    (@pick [$($built:expr),*] $terms:ident $run:expr;
        if $on:expr => $make:expr, else if $on2:expr => $make2:expr, $($rest:tt)*) => {
        if $on {
            with_terms!(@pick [$($built,)* $make] $terms $run; $($rest)*)
        } else if $on2 {
            with_terms!(@pick [$($built,)* $make2] $terms $run; $($rest)*)
        } else {
            with_terms!(@pick [$($built,)* Off] $terms $run; $($rest)*)
        }
    };
    (@pick [$($built:expr),*] $terms:ident $run:expr; if $on:expr => $make:expr, $($rest:tt)*) => {
        if $on {
            with_terms!(@pick [$($built,)* $make] $terms $run; $($rest)*)
        } else {
            with_terms!(@pick [$($built,)* Off] $terms $run; $($rest)*)
        }
    };
    (@nest) => { Off };
    (@nest $head:expr $(, $tail:expr)*) => { ($head, with_terms!(@nest $($tail),*)) };
}

impl Simulation {
    /// Accelerations [m/s²] of the fluid particles under every declared term of the current
    /// state (densities, pressures and neighbour lists as they are), and with the continuity
    /// scheme their density rates [kg/(m³ s)] (`drho` empty otherwise); returns the power of
    /// the dissipative terms at the current velocities (the energy budget,
    /// [`crate::physics::forces::ledger`]). The step calls it after the density; public for
    /// tests and benchmarks.
    pub fn pair_forces<K: Kernel>(&self, acc: &mut [Vec3], drho: &mut [f64]) -> Power {
        let e = &self.model.effects;
        let inp = self.loop_input::<K>();
        with_terms!(terms => fluid_forces(&inp, &terms, acc, drho);
            if e.interfacial_tension => self.potential_term(),
            if !e.pressure_difference => self.pressure_term(),
            else if e.pressure_difference => self.pressure_difference_term(),
            if e.artificial_viscosity.is_some() => self.artificial_viscosity_term(),
            if e.explicit_laminar(LaminarForm::HuAdams) => self.laminar_viscosity_term(),
            else if e.explicit_laminar(LaminarForm::MonaghanClearyGingold) => self.mcg_viscosity_term(),
            if e.continuity() => self.continuity_term(),
            if e.wall_repulsion => self.wall_repulsion_term(),
        )
    }

    /// What the force loop reads besides the terms, for the current state.
    pub fn loop_input<K: Kernel>(&self) -> LoopInput<'_, K> {
        let (m, p) = (&self.model, &self.particles);
        LoopInput {
            kernel: m.kernel_of::<K>(),
            state: Neighbourhood {
                n_fluid: p.n_fluid,
                pos: &p.pos,
                vel: &p.vel,
                rho: &p.rho,
                vol: &p.vol,
                phase: &p.phase,
                mass: &m.mass,
            },
            gravity: m.gravity(),
            lists: &self.search.lists,
            active: &self.search.active,
        }
    }

    /// The pressure term of the current state.
    pub fn pressure_term(&self) -> Pressure<'_> {
        Pressure {
            pressure: &self.particles.pressure,
            vol: &self.particles.vol,
        }
    }

    /// The pressure term in its difference form, of the current state.
    pub fn pressure_difference_term(&self) -> PressureDifference<'_> {
        PressureDifference {
            pressure: &self.particles.pressure,
            vol: &self.particles.vol,
        }
    }

    /// The laminar viscosity term of the current state.
    pub fn laminar_viscosity_term(&self) -> LaminarViscosity<'_> {
        LaminarViscosity {
            mu_pair: &self.model.mu_pair,
            n_phases: self.model.pairs.n_phases,
            vol: &self.particles.vol,
            n_fluid: self.particles.n_fluid,
            wall_no_slip: &self.wall_no_slip,
        }
    }

    /// The laminar viscosity term in the Monaghan–Cleary–Gingold form, with `η = 0.1 h`.
    pub fn mcg_viscosity_term(&self) -> MonaghanClearyGingold<'_> {
        let h = self.model.h_m;
        MonaghanClearyGingold {
            base: self.laminar_viscosity_term(),
            eta2_m2: 0.01 * h * h, // (0.1 h)², as Monaghan 2005 and Eq. (13), Natsui 2021
        }
    }

    /// The artificial viscosity term of the current state (coefficients zero if the scene
    /// does not declare it).
    pub fn artificial_viscosity_term(&self) -> ArtificialViscosity<'_> {
        let m = &self.model;
        ArtificialViscosity::new(
            m.effects.artificial_viscosity.unwrap_or((0.0, 0.0)),
            m.c_m_s,
            m.h_m,
            &self.particles.rho,
            &m.mass,
        )
    }

    /// The pairwise-potential (tension and wetting) term of the current state.
    pub fn potential_term(&self) -> PairwisePotential<'_> {
        PairwisePotential {
            potential: self.model.potential,
            coeff: &self.model.pairs.coeff,
            n_phases: self.model.pairs.n_phases,
            pos: &self.particles.pos,
            phase: &self.particles.phase,
            periodic: self.search.lists.periodic,
            spills: &self.far_spills,
        }
    }

    /// The liquid–wall repulsion of the model.
    pub fn wall_repulsion_term(&self) -> Monaghan1994WallRepulsion<'_> {
        Monaghan1994WallRepulsion {
            strength_j: &self.model.wall_repulsion_strength_j,
            range_m: self.model.wall_repulsion_range_m,
        }
    }

    /// The continuity density rate of the current state.
    pub fn continuity_term(&self) -> ContinuityRate<'_> {
        ContinuityRate {
            vol: &self.particles.vol,
        }
    }
}
