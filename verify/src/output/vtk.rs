//! Particle snapshots for ParaView: VTK XML unstructured grids (`.vtu`) with the data appended
//! as base64 of little-endian binary (about 115 bytes per particle, against ~200 as text; base64
//! rather than raw so that plain XML readers parse it too), one vertex
//! cell per particle with position, velocity, density, pressure and phase, and the simulated
//! time as the grid's `TimeValue`; and a `.pvd` collection that ties the snapshots into one
//! time series. Walls do not move: they are written once.

use solver::state::Particles;
use std::fmt::Write as _;
use std::path::Path;

/// One data array of a grid: its XML attributes (type, name, components) and its bytes.
struct Array {
    attributes: String,
    bytes: Vec<u8>,
}

fn f64s(values: impl Iterator<Item = f64>) -> Vec<u8> {
    values.flat_map(f64::to_le_bytes).collect()
}

/// Writes particles `range` of `p` (fluid first, walls after; written in the order of their
/// scene index so that snapshots compare particle by particle) to `path`, at simulated time
/// `time_s` [s].
pub fn write_vtu(
    path: &Path,
    p: &Particles,
    range: std::ops::Range<usize>,
    time_s: f64,
) -> std::io::Result<()> {
    let mut order: Vec<usize> = range.collect();
    order.sort_by_key(|&i| p.id[i]);
    let n = order.len();
    let vec3 =
        |v: &[solver::state::Vec3]| f64s(order.iter().flat_map(|&i| [v[i].x, v[i].y, v[i].z]));
    let scalar = |v: &[f64]| f64s(order.iter().map(|&i| v[i]));
    let array = |attributes: &str, bytes: Vec<u8>| Array {
        attributes: attributes.to_string(),
        bytes,
    };
    let points = [array(
        r#"type="Float64" Name="position_m" NumberOfComponents="3""#,
        vec3(&p.pos),
    )];
    let cells = [
        array(
            r#"type="Int64" Name="connectivity""#,
            (0..n as i64).flat_map(i64::to_le_bytes).collect(),
        ),
        array(
            r#"type="Int64" Name="offsets""#,
            (1..=n as i64).flat_map(i64::to_le_bytes).collect(),
        ),
        // VTK_VERTEX
        array(r#"type="UInt8" Name="types""#, vec![1u8; n]),
    ];
    let point_data = [
        array(
            r#"type="Float64" Name="velocity_m_s" NumberOfComponents="3""#,
            vec3(&p.vel),
        ),
        array(r#"type="Float64" Name="density_kg_m3""#, scalar(&p.rho)),
        array(r#"type="Float64" Name="pressure_Pa""#, scalar(&p.pressure)),
        array(
            r#"type="Int32" Name="phase""#,
            order
                .iter()
                .flat_map(|&i| i32::from(p.phase[i]).to_le_bytes())
                .collect(),
        ),
    ];
    let mut xml = String::new();
    let mut data: Vec<u8> = Vec::new();
    let mut section = |xml: &mut String, arrays: &[Array]| {
        for a in arrays {
            let _ = writeln!(
                xml,
                r#"<DataArray {} format="appended" offset="{}"/>"#,
                a.attributes,
                data.len()
            );
            // each array: base64 of its byte count (UInt32) followed by its bytes
            let mut block = (a.bytes.len() as u32).to_le_bytes().to_vec();
            block.extend_from_slice(&a.bytes);
            data.extend_from_slice(base64(&block).as_bytes());
        }
    };
    xml.push_str("<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\" header_type=\"UInt32\">\n<UnstructuredGrid>\n");
    let _ = writeln!(
        xml,
        "<FieldData>\n<DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" format=\"ascii\">{time_s:e}</DataArray>\n</FieldData>"
    );
    let _ = writeln!(xml, "<Piece NumberOfPoints=\"{n}\" NumberOfCells=\"{n}\">");
    xml.push_str("<Points>\n");
    section(&mut xml, &points);
    xml.push_str("</Points>\n<Cells>\n");
    section(&mut xml, &cells);
    xml.push_str("</Cells>\n<PointData Scalars=\"density_kg_m3\" Vectors=\"velocity_m_s\">\n");
    section(&mut xml, &point_data);
    xml.push_str(
        "</PointData>\n</Piece>\n</UnstructuredGrid>\n<AppendedData encoding=\"base64\">\n_",
    );
    let mut bytes = xml.into_bytes();
    bytes.extend_from_slice(&data);
    bytes.extend_from_slice(b"\n</AppendedData>\n</VTKFile>\n");
    crate::output::atomic_write(path, &bytes)
}

/// Standard base64 (RFC 4648, with padding) of `bytes`.
fn base64(bytes: &[u8]) -> String {
    const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let b = [
            chunk[0],
            *chunk.get(1).unwrap_or(&0),
            *chunk.get(2).unwrap_or(&0),
        ];
        let n = (u32::from(b[0]) << 16) | (u32::from(b[1]) << 8) | u32::from(b[2]);
        for k in 0..4 {
            if k <= chunk.len() {
                out.push(ALPHABET[((n >> (18 - 6 * k)) & 63) as usize] as char);
            } else {
                out.push('=');
            }
        }
    }
    out
}

/// Writes the `.pvd` collection `path` of the snapshots `(time [s], file name)`, each with the
/// `walls` file (if any) as a second part at every time.
pub fn write_pvd(
    path: &Path,
    snapshots: &[(f64, String)],
    walls: Option<&str>,
) -> std::io::Result<()> {
    let mut s = String::from("<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n<Collection>\n");
    for (t, file) in snapshots {
        let _ = writeln!(
            s,
            "<DataSet timestep=\"{t:e}\" part=\"0\" file=\"{file}\"/>"
        );
        if let Some(w) = walls {
            let _ = writeln!(s, "<DataSet timestep=\"{t:e}\" part=\"1\" file=\"{w}\"/>");
        }
    }
    s.push_str("</Collection>\n</VTKFile>\n");
    crate::output::atomic_write(path, s.as_bytes())
}

#[cfg(test)]
mod tests {
    #[test]
    fn base64_of_the_rfc_4648_examples() {
        let cases = [
            ("", ""),
            ("f", "Zg=="),
            ("fo", "Zm8="),
            ("foo", "Zm9v"),
            ("foobar", "Zm9vYmFy"),
        ];
        for (plain, coded) in cases {
            assert_eq!(super::base64(plain.as_bytes()), coded);
        }
    }
}
