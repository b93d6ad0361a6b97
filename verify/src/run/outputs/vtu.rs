//! `particles_NNNNNN.vtu`: the fluid particles every so many output times; `walls.vtu` once;
//! `particles.pvd`: the collection ParaView opens as one time series (walls at every time).

use crate::output::{vtk, RunError};
use crate::run::observer::{Observer, RunView};

/// The collection file.
pub const PVD: &str = "particles.pvd";
/// The walls' file.
pub const WALLS: &str = "walls.vtu";

/// Writes a `.vtu` snapshot at every `every`-th output time (the initial state included).
pub(super) struct Vtu {
    every: u64,
    /// The snapshots written: (time [s], file name).
    written: Vec<(f64, String)>,
}

impl Vtu {
    /// A snapshot every `every` output times.
    pub(super) fn every(every: u32) -> Vtu {
        Vtu {
            every: every.into(),
            written: Vec::new(),
        }
    }

    /// The snapshot of output `k`: its file name and simulated time [s] (`k` output intervals).
    fn snapshot(run: &RunView, k: u64) -> (f64, String) {
        (
            k as f64 * run.sim.scene.time.output_interval,
            format!("particles_{k:06}.vtu"),
        )
    }

    fn walls(run: &RunView) -> Option<&'static str> {
        (run.sim.particles.n_wall() > 0).then_some(WALLS)
    }
}

impl Observer for Vtu {
    fn on_resume(&mut self, run: &RunView) -> Result<(), RunError> {
        // the snapshots up to the checkpoint exist; later ones are written again
        self.written = (0..=run.output)
            .filter(|k| k % self.every == 0)
            .map(|k| Vtu::snapshot(run, k))
            .filter(|(_, f)| run.out_dir.join(f).exists())
            .collect();
        Ok(())
    }

    fn on_output(&mut self, run: &RunView) -> Result<(), RunError> {
        if run.output % self.every != 0 {
            return Ok(());
        }
        let p = &run.sim.particles;
        let (t, file) = Vtu::snapshot(run, run.output);
        let path = run.out_dir.join(&file);
        vtk::write_vtu(&path, p, 0..p.n_fluid, t)
            .map_err(|e| RunError::io("cannot write", &path, e))?;
        if let Some(w) = Vtu::walls(run) {
            let path = run.out_dir.join(w);
            // once: at the start, or on resuming a run whose folder lost it
            if run.output == 0 || !path.exists() {
                vtk::write_vtu(&path, p, p.n_fluid..p.len(), 0.0)
                    .map_err(|e| RunError::io("cannot write", &path, e))?;
            }
        }
        self.written.push((t, file));
        let path = run.out_dir.join(PVD);
        vtk::write_pvd(&path, &self.written, Vtu::walls(run))
            .map_err(|e| RunError::io("cannot write", &path, e))
    }
}
