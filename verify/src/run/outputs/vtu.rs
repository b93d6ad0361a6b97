//! `particles_NNNNNN.vtu`: a particle snapshot every so many output times.

use crate::output::{vtk, RunError};
use crate::run::observer::{Observer, RunView};

/// Writes a `.vtu` snapshot at every `every`-th output time (the initial state included).
pub(super) struct Vtu {
    every: u64,
}

impl Vtu {
    /// A snapshot every `every` output times.
    pub(super) fn every(every: u32) -> Vtu {
        Vtu {
            every: every.into(),
        }
    }
}

impl Observer for Vtu {
    fn on_output(&mut self, run: &RunView) -> Result<(), RunError> {
        if run.output % self.every != 0 {
            return Ok(());
        }
        let path = run.out_dir.join(format!("particles_{:06}.vtu", run.output));
        let p = &run.sim.particles;
        vtk::write_vtu(&path, p, p.n_wall() > 0).map_err(|e| RunError::io("cannot write", &path, e))
    }
}
