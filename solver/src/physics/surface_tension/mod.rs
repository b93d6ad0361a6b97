//! Surface and interfacial tension: by a pairwise interparticle potential (the paper's model),
//! or by a continuum model between liquid phases: the surface stress ([`surface_stress`]) or
//! the surface force ([`surface_force`]).
//!
//! The potential is Kondo et al. (2007)'s, used in 3D SPH by Natsui et al. (2016, 2021): a pair
//! force `C_ij P'(r_ij) e_ij`, repulsive below `l0`, attractive between `l0` and `r_e`
//! ([`potential`]), in the force loop as the term [`force::PairwisePotential`]. Pair strengths
//! follow the Fowkes hypothesis ([`fowkes`]): users give σ, σ_ab and contact angles, and the
//! coefficients `C_ab` follow.

pub mod force;
pub mod fowkes;
pub mod lattice_cloud;
pub mod potential;
pub mod surface_force;
pub mod surface_stress;
#[cfg(test)]
mod test_cloud;

pub use force::{far_pair_forces, PairwisePotential};
pub use fowkes::PairTable;
pub use potential::Kondo2007Potential;
