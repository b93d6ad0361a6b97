//! Reading back what [`super::vtk`] writes: the `.pvd` collection and the positions and phases
//! of a `.vtu` snapshot (appended base64 arrays, each a UInt32 byte count and its bytes). Only
//! this project's own files are read; anything else is an error, never a panic.

use std::path::Path;

/// One snapshot: its simulated time and, per particle, position and phase.
#[derive(Clone, Debug, PartialEq)]
pub struct Snapshot {
    /// Simulated time [s] (the grid's `TimeValue`).
    pub time_s: f64,
    /// Positions [m].
    pub pos: Vec<[f64; 3]>,
    /// Phase index per particle (liquids 0.., walls after).
    pub phase: Vec<i32>,
}

/// The fluid snapshots `(time [s], file name)` of a `.pvd` collection (part 0), in file order.
pub fn read_pvd(path: &Path) -> Result<Vec<(f64, String)>, String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let mut out = Vec::new();
    for line in text.lines().filter(|l| l.contains("<DataSet")) {
        if attr(line, "part").as_deref() != Some("0") {
            continue;
        }
        let t = attr(line, "timestep").and_then(|t| t.parse::<f64>().ok());
        match (t, attr(line, "file")) {
            (Some(t), Some(f)) => out.push((t, f)),
            _ => {
                return Err(format!(
                    "{}: a DataSet without time or file",
                    path.display()
                ))
            }
        }
    }
    Ok(out)
}

/// Reads a `.vtu` written by [`super::vtk::write_vtu`]: positions, phases (0 where the file has
/// none, as the walls' file) and the time.
pub fn read_vtu(path: &Path) -> Result<Snapshot, String> {
    let bytes = std::fs::read(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let text = String::from_utf8_lossy(&bytes);
    let err = |what: &str| format!("{}: {what}", path.display());
    let start = text
        .find("<AppendedData")
        .ok_or_else(|| err("no appended data"))?;
    let data = &text[start..];
    let data = &data[data.find('_').ok_or_else(|| err("no appended data"))? + 1..];
    let header = &text[..start];
    let array = |name: &str| -> Result<Vec<u8>, String> {
        let line = header
            .lines()
            .find(|l| l.contains("<DataArray") && attr(l, "Name").as_deref() == Some(name))
            .ok_or_else(|| err(&format!("no array {name}")))?;
        let offset: usize = attr(line, "offset")
            .and_then(|o| o.parse().ok())
            .ok_or_else(|| err(&format!("array {name} without offset")))?;
        let block = data
            .get(offset..)
            .ok_or_else(|| err("offset beyond the data"))?;
        let head = decode(block.get(..8).ok_or_else(|| err("truncated data"))?)?;
        let len = u32::from_le_bytes([head[0], head[1], head[2], head[3]]) as usize;
        let chars = (4 + len).div_ceil(3) * 4;
        let all = decode(block.get(..chars).ok_or_else(|| err("truncated data"))?)?;
        Ok(all[4..4 + len].to_vec())
    };
    let pos: Vec<[f64; 3]> = array("position_m")?
        .chunks_exact(24)
        .map(|c| {
            let f = |k: usize| f64::from_le_bytes(c[8 * k..8 * k + 8].try_into().expect("8 bytes"));
            [f(0), f(1), f(2)]
        })
        .collect();
    let phase = match array("phase") {
        Ok(b) => b
            .chunks_exact(4)
            .map(|c| i32::from_le_bytes(c.try_into().expect("4 bytes")))
            .collect(),
        Err(_) => vec![0; pos.len()],
    };
    if phase.len() != pos.len() {
        return Err(err("positions and phases differ in length"));
    }
    let time_s = header
        .find("Name=\"TimeValue\"")
        .and_then(|i| {
            let rest = &header[i..];
            let a = rest.find('>')? + 1;
            let b = rest.find("</DataArray>")?;
            rest[a..b].trim().parse().ok()
        })
        .unwrap_or(f64::NAN);
    Ok(Snapshot { time_s, pos, phase })
}

/// The value of attribute `name` in an XML tag line.
fn attr(line: &str, name: &str) -> Option<String> {
    let key = format!(" {name}=\"");
    let i = line.find(&key)? + key.len();
    let j = line[i..].find('"')?;
    Some(line[i..i + j].to_string())
}

/// Standard base64 (RFC 4648, with padding) decoded.
fn decode(text: &str) -> Result<Vec<u8>, String> {
    let value = |c: u8| -> Result<u32, String> {
        Ok(match c {
            b'A'..=b'Z' => c - b'A',
            b'a'..=b'z' => c - b'a' + 26,
            b'0'..=b'9' => c - b'0' + 52,
            b'+' => 62,
            b'/' => 63,
            _ => return Err(format!("not base64: {:?}", c as char)),
        } as u32)
    };
    let mut out = Vec::with_capacity(text.len() / 4 * 3);
    for chunk in text.as_bytes().chunks(4) {
        if chunk.len() != 4 {
            return Err("base64 of a length not a multiple of 4".into());
        }
        let pad = chunk.iter().rev().take_while(|&&c| c == b'=').count();
        let mut n = 0u32;
        for &c in &chunk[..4 - pad] {
            n = (n << 6) | value(c)?;
        }
        n <<= 6 * pad as u32;
        let b = [(n >> 16) as u8, (n >> 8) as u8, n as u8];
        out.extend_from_slice(&b[..3 - pad]);
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_round_trips_the_rfc_4648_examples() {
        for (plain, coded) in [
            ("", ""),
            ("f", "Zg=="),
            ("fo", "Zm8="),
            ("foobar", "Zm9vYmFy"),
        ] {
            assert_eq!(decode(coded).unwrap(), plain.as_bytes());
        }
        assert!(decode("Zg=").is_err() && decode("Z!==").is_err());
    }

    #[test]
    fn a_written_snapshot_reads_back_bit_for_bit() {
        let scene = solver::Scene::from_toml_str(include_str!("../../../scenes/cube_drop.toml"))
            .expect("scene");
        let sim = solver::Simulation::new(&scene).expect("built");
        let p = &sim.particles;
        let dir = std::env::temp_dir().join(format!("vtk-read-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("s.vtu");
        super::super::vtk::write_vtu(&path, p, 0..p.n_fluid, 1.25e-3).unwrap();
        let s = read_vtu(&path).unwrap();
        assert_eq!(s.time_s, 1.25e-3);
        let mut order: Vec<usize> = (0..p.n_fluid).collect();
        order.sort_by_key(|&i| p.id[i]);
        let expected: Vec<[f64; 3]> = order
            .iter()
            .map(|&i| [p.pos[i].x, p.pos[i].y, p.pos[i].z])
            .collect();
        assert_eq!(s.pos, expected);
        assert!(s.phase.iter().all(|&k| k == 0));
        super::super::vtk::write_pvd(
            &dir.join("p.pvd"),
            &[(0.0, "a.vtu".into()), (1e-3, "b.vtu".into())],
            Some("w.vtu"),
        )
        .unwrap();
        assert_eq!(
            read_pvd(&dir.join("p.pvd")).unwrap(),
            vec![(0.0, "a.vtu".to_string()), (1e-3, "b.vtu".to_string())]
        );
        let _ = std::fs::remove_dir_all(&dir);
    }
}
