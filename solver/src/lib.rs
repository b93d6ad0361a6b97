//! A 3D weakly compressible SPH solver for droplets with surface and interfacial tension.
//!
//! Tension comes from a pairwise interparticle potential (Kondo et al. 2007) whose strength
//! between unlike phases follows the Fowkes hypothesis, as in Natsui et al., ISIJ Int. 56
//! (2016) 1297 and Chem. Eng. Sci. 229 (2021) 116035: users give σ [N/m], σ_ab and contact
//! angles, never tuned coefficients. The equations are those of `docs/model.md` (the papers'
//! printed equations, corrected, and the choices the code makes where the papers leave one
//! open); every implementing line cites its equation.
//!
//! The key design decision: effects are declared by the scene, and each force term is a type
//! ([`physics::forces::PairTerm`]) passed to one fused pair loop; a term the scene does not
//! declare is the empty type [`physics::forces::Off`] and compiles away, and the kernel is a
//! type parameter ([`kernel::Kernel`]), so an absent effect costs nothing. All parallel work gathers per
//! particle in a fixed neighbour order, so results are bitwise identical for any thread count.
//!
//! ```no_run
//! let scene = solver::Scene::from_toml_str(&std::fs::read_to_string("scenes/cube_drop.toml")?)?;
//! let mut sim = solver::Simulation::new(&scene)?;
//! while sim.time_s < scene.time.end {
//!     sim.step(scene.time.end - sim.time_s)?;
//! }
//! println!("{:?}", sim.observe());
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
#![deny(missing_docs)]

pub mod checkpoint;
pub mod error;
pub mod health;
pub mod kernel;
pub mod lattice;
pub mod model;
pub mod neighbours;
pub mod observables;
pub mod periodic;
pub mod physics;
pub mod scene;
pub mod setup;
pub mod simulation;
pub mod state;
pub mod timestep;

pub use checkpoint::Checkpoint;
pub use error::SimError;
pub use model::Model;
pub use observables::Observables;
pub use scene::{Scene, SceneError};
pub use simulation::Simulation;
