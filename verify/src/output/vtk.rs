//! Particle snapshots as VTK XML unstructured grids (`.vtu`, readable by ParaView): one vertex
//! cell per particle with position, velocity, density, pressure and phase.

use solver::state::Particles;
use std::fmt::Write as _;
use std::path::Path;

/// Writes the fluid particles (and, with `walls`, the wall particles) of `p` to `path`, in the
/// order of their scene index so that snapshots can be compared particle by particle.
pub fn write_vtu(path: &Path, p: &Particles, walls: bool) -> std::io::Result<()> {
    let n_total = if walls { p.len() } else { p.n_fluid };
    let mut order: Vec<usize> = (0..n_total).collect();
    order.sort_by_key(|&i| p.id[i]);
    let n = order.len();
    let mut s = String::with_capacity(200 * n + 1000);
    s.push_str("<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n<UnstructuredGrid>\n");
    let _ = writeln!(s, "<Piece NumberOfPoints=\"{n}\" NumberOfCells=\"{n}\">");
    s.push_str(
        "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n",
    );
    for &i in &order {
        let x = p.pos[i];
        let _ = writeln!(s, "{:e} {:e} {:e}", x.x, x.y, x.z);
    }
    s.push_str("</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
    for k in 0..n {
        let _ = write!(s, "{k} ");
    }
    s.push_str("\n</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
    for k in 1..=n {
        let _ = write!(s, "{k} ");
    }
    s.push_str("\n</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
    for _ in 0..n {
        s.push_str("1 ");
    }
    s.push_str("\n</DataArray>\n</Cells>\n<PointData Scalars=\"density_kg_m3\" Vectors=\"velocity_m_s\">\n");
    s.push_str("<DataArray type=\"Float64\" Name=\"velocity_m_s\" NumberOfComponents=\"3\" format=\"ascii\">\n");
    for &i in &order {
        let v = p.vel[i];
        let _ = writeln!(s, "{:e} {:e} {:e}", v.x, v.y, v.z);
    }
    s.push_str("</DataArray>\n");
    for (name, data) in [("density_kg_m3", &p.rho), ("pressure_Pa", &p.pressure)] {
        let _ = writeln!(
            s,
            "<DataArray type=\"Float64\" Name=\"{name}\" format=\"ascii\">"
        );
        for &i in &order {
            let _ = write!(s, "{:e} ", data[i]);
        }
        s.push_str("\n</DataArray>\n");
    }
    s.push_str("<DataArray type=\"Int32\" Name=\"phase\" format=\"ascii\">\n");
    for &i in &order {
        let _ = write!(s, "{} ", p.phase[i]);
    }
    s.push_str("\n</DataArray>\n</PointData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n");
    crate::output::atomic_write(path, s.as_bytes())
}
