//! Particle dumps: positions, velocities and phase of every particle at one instant, as CSV, so
//! that geometric measurements can be redone without simulating.

use crate::output::atomic_write;
use solver::state::Particles;
use std::fmt::Write as _;
use std::path::Path;

/// The particles of one instant. Walls come last (`wall = true`).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Dump {
    /// Simulated time [s].
    pub time_s: f64,
    /// Positions [m].
    pub pos: Vec<[f64; 3]>,
    /// Velocities [m/s].
    pub vel: Vec<[f64; 3]>,
    /// Phase index (liquids first, then solids).
    pub phase: Vec<u8>,
    /// Wall particle?
    pub wall: Vec<bool>,
}

impl Dump {
    /// Takes the state of `p` at `time_s` [s], in scene order.
    pub fn of(p: &Particles, time_s: f64) -> Dump {
        let mut order: Vec<usize> = (0..p.len()).collect();
        order.sort_by_key(|&i| p.id[i]);
        Dump {
            time_s,
            pos: order.iter().map(|&i| p.pos[i].into()).collect(),
            vel: order.iter().map(|&i| p.vel[i].into()).collect(),
            phase: order.iter().map(|&i| p.phase[i]).collect(),
            wall: order.iter().map(|&i| i >= p.n_fluid).collect(),
        }
    }

    /// The wall particles of `scene` as a dump, rebuilt as the run placed them (walls never
    /// move, so the dumps leave them out); `None` if the scene has no walls.
    pub fn walls_of(scene: &solver::Scene) -> anyhow::Result<Option<Dump>> {
        if scene.walls.is_empty() {
            return Ok(None);
        }
        let model = solver::Model::from_scene(scene)?;
        let (p, _, _) = solver::setup::build_particles(scene, &model)?;
        let n = p.n_wall();
        Ok(Some(Dump {
            time_s: 0.0,
            pos: p.pos[p.n_fluid..].iter().map(|x| [x.x, x.y, x.z]).collect(),
            vel: vec![[0.0; 3]; n],
            phase: p.phase[p.n_fluid..].to_vec(),
            wall: vec![true; n],
        }))
    }

    /// This dump with the particles of `walls` appended (`None`: unchanged).
    pub fn with_walls(mut self, walls: Option<&Dump>) -> Dump {
        if let Some(w) = walls {
            self.pos.extend_from_slice(&w.pos);
            self.vel.extend_from_slice(&w.vel);
            self.phase.extend_from_slice(&w.phase);
            self.wall.extend_from_slice(&w.wall);
        }
        self
    }

    /// The liquid particles as a measurement cloud (walls as neighbours).
    pub fn cloud(&self, l0_m: f64) -> crate::measure::surface::Cloud {
        let mut c = crate::measure::surface::Cloud {
            pos: Vec::new(),
            phase: Vec::new(),
            walls: Vec::new(),
            l0_m,
        };
        for i in 0..self.pos.len() {
            if self.wall[i] {
                c.walls.push(self.pos[i]);
            } else {
                c.pos.push(self.pos[i]);
                c.phase.push(self.phase[i]);
            }
        }
        c
    }

    /// Writes the dump (walls only if `walls`).
    pub fn write(&self, path: &Path, walls: bool) -> std::io::Result<()> {
        let mut s = String::with_capacity(100 * self.pos.len());
        let _ = writeln!(s, "# time_s = {:e}", self.time_s);
        s.push_str("x_m,y_m,z_m,vx_m_s,vy_m_s,vz_m_s,phase,wall\n");
        for i in 0..self.pos.len() {
            if self.wall[i] && !walls {
                continue;
            }
            let (x, v) = (self.pos[i], self.vel[i]);
            // positions to 7 significant digits (1e-7 of a millimetre drop is far below any
            // measured length), velocities to 4
            let _ = writeln!(
                s,
                "{:.6e},{:.6e},{:.6e},{:.3e},{:.3e},{:.3e},{},{}",
                x[0],
                x[1],
                x[2],
                v[0],
                v[1],
                v[2],
                self.phase[i],
                u8::from(self.wall[i])
            );
        }
        atomic_write(path, s.as_bytes())
    }

    /// Reads a dump written by [`Dump::write`].
    pub fn read(path: &Path) -> anyhow::Result<Dump> {
        let text = std::fs::read_to_string(path)?;
        let mut d = Dump::default();
        for line in text.lines() {
            if let Some(t) = line.strip_prefix("# time_s = ") {
                d.time_s = t.trim().parse()?;
                continue;
            }
            if line.starts_with('x') || line.is_empty() {
                continue;
            }
            let f: Vec<&str> = line.split(',').collect();
            anyhow::ensure!(f.len() == 8, "{}: bad line {line:?}", path.display());
            let num = |k: usize| -> anyhow::Result<f64> { Ok(f[k].parse::<f64>()?) };
            d.pos.push([num(0)?, num(1)?, num(2)?]);
            d.vel.push([num(3)?, num(4)?, num(5)?]);
            d.phase.push(f[6].parse()?);
            d.wall.push(f[7] == "1");
        }
        Ok(d)
    }
}
