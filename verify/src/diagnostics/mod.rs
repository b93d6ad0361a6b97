//! Diagnostics of the discretisation itself, independent of any paper check: how far the
//! particle system is from a liquid.

pub mod curvature;
pub mod interface_shear;
pub mod lattice_moduli;
pub mod mode_stiffness;
pub mod slab_tension;
pub mod sphere_cloud;
pub mod surface_stress;
