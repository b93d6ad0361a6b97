//! The measures' plots: height and wetted radius against time, and the contact angle, with the
//! Young–Laplace equilibrium as dashed reference lines where it is defined.

use super::Measures;
use crate::report::plot::{self, Plot, Series, SeriesKind};
use std::path::Path;

/// Draws `measures_size` and `measures_angle` into `dir`.
pub fn plots(m: &Measures, dir: &Path) -> anyhow::Result<()> {
    let series = |f: &dyn Fn(&super::Row) -> f64, what: &str, color0: usize| -> Vec<Series> {
        m.liquids
            .iter()
            .enumerate()
            .map(|(k, name)| Series {
                label: format!("{name}: {what}"),
                points: m
                    .rows
                    .iter()
                    .filter(|r| r.liquid == k)
                    .map(|r| (r.time_s * 1e3, f(r)))
                    .collect(),
                kind: SeriesKind::Line,
                color: color0 + k,
            })
            .collect()
    };
    let mut size = series(&|r| r.height_m * 1e3, "height", 1);
    size.extend(series(
        &|r| r.wetted_radius_m * 1e3,
        "wetted radius",
        1 + m.liquids.len(),
    ));
    let (mut size_lines, mut angle_lines) = (Vec::new(), Vec::new());
    if let Some((h, a, theta)) = m.equilibrium {
        size_lines.push((h * 1e3, "Young–Laplace height".to_string()));
        size_lines.push((a * 1e3, "Young–Laplace wetted radius".to_string()));
        angle_lines.push((theta, "typed angle".to_string()));
    }
    plot::draw(
        &Plot {
            title: "Height above the wall and wetted radius".into(),
            x_label: "t [ms]".into(),
            y_label: "[mm]".into(),
            series: size,
            x_range: None,
            y_range: None,
            hlines: size_lines,
        },
        &dir.join("measures_size"),
    )?;
    plot::draw(
        &Plot {
            title: "Side-view contact angle".into(),
            x_label: "t [ms]".into(),
            y_label: "contact angle [deg]".into(),
            series: series(&|r| r.angle_deg, "contact angle", 1),
            x_range: None,
            y_range: None,
            hlines: angle_lines,
        },
        &dir.join("measures_angle"),
    )
}
