//! Heat maps ([`Heatmap`]): a scalar field on a rectilinear grid as viridis-coloured cells,
//! cells without value hatched grey, simulated points on top as labelled rings, a colour bar
//! on the right and a legend row underneath.

use std::path::Path;

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, VPos};

use super::axis::Axis;
use super::colorbar::draw_colour_bar;
use super::frame::{chart_builder, draw_mesh, y_label_area, Chart, MARGIN};
use super::legend::{draw_ring, legend_row, Swatch};
use super::output::{write_both, DrawResult};
use super::range::{is_finite_point, tight_range, widen};
use super::style::{hatch, viridis, NONE_FILL, REF_GREY};
use super::text::{anchored, no_data_style, page, text_style, NOTE_PX, NO_DATA};

/// Legend text of the overlay points.
pub(super) const OVERLAY_LEGEND: &str = "simulated points";
/// Width in pixels of the colour bar itself (without its labels).
const BAR_W: i32 = 28;
/// Height in pixels of the legend row under the map.
const LEGEND_ROW_H: i32 = 40;

/// A scalar field on a rectilinear grid, drawn as coloured cells by [`draw_heatmap`].
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Heatmap {
    /// Caption above the map.
    pub title: String,
    /// Label of the horizontal axis, with its unit.
    pub x_label: String,
    /// Label of the vertical axis, with its unit.
    pub y_label: String,
    /// Cell centres along x (ascending); cell edges lie halfway between neighbours.
    pub x: Vec<f64>,
    /// Cell centres along y (ascending).
    pub y: Vec<f64>,
    /// Values `z[iy][ix]`; `None`, non-finite values and missing entries mean "no value" and
    /// are drawn as hatched grey cells.
    pub z: Vec<Vec<Option<f64>>>,
    /// Legend text of the cells without value (e.g. `"droplet detached"`).
    pub none_label: String,
    /// Label of the colour bar, with its unit.
    pub z_label: String,
    /// Values mapped to the ends of the colour scale; values outside are clamped.
    pub z_range: (f64, f64),
    /// Simulated points `(x, y, label)`, drawn as rings with their label beside them.
    pub overlay: Vec<(f64, f64, String)>,
}

/// Draws `map` with a colour bar into `STEM.svg` and `STEM.png` (1024×720 px).
///
/// The file names are formed as in [`draw`](super::draw).
pub fn draw_heatmap(map: &Heatmap, stem: &Path) -> anyhow::Result<()> {
    write_both(
        stem,
        |root| render_heatmap(map, root),
        |root| render_heatmap(map, root),
    )
}

/// One heat-map cell: x interval, y interval, value.
type Cell = ((f64, f64), (f64, f64), Option<f64>);

/// An overlay point `(x, y, label)`.
type Overlay = (f64, f64, String);

/// Draws the map, its colour bar and legend row on `root` (either backend).
fn render_heatmap<DB: DrawingBackend>(
    m: &Heatmap,
    root: &DrawingArea<DB, Shift>,
) -> DrawResult<DB> {
    let area = page(root, &m.title)?;

    let cells = cells(m);
    let overlay: Vec<&Overlay> = m
        .overlay
        .iter()
        .filter(|o| is_finite_point(&(o.0, o.1)))
        .collect();
    let any_value = cells.iter().any(|c| c.2.is_some());
    let any_none = cells.iter().any(|c| c.2.is_none());
    let (x_range, y_range) = map_ranges(&cells, &overlay);
    let z_range = if m.z_range.0.is_finite() && m.z_range.1.is_finite() {
        widen(m.z_range.0, m.z_range.1)
    } else {
        tight_range(cells.iter().filter_map(|c| c.2))
    };

    let entries = legend_entries(m, any_none, !overlay.is_empty());
    let (area, legend_area) = if entries.is_empty() {
        (area, None)
    } else {
        let h = area.dim_in_pixel().1 as i32;
        let (a, b) = area.split_vertically(h - LEGEND_ROW_H);
        (a, Some(b))
    };

    let xa = Axis::new(x_range, 9);
    let ya = Axis::new(y_range, 7);
    let za = Axis::new(z_range, 7);

    let bar_labels = y_label_area(&area, &za);
    let strip = BAR_W + bar_labels + 2 * MARGIN;
    let aw = area.dim_in_pixel().0 as i32;
    let (main, bar) = area.split_horizontally(aw - strip);

    let mut chart = chart_builder(&main, y_label_area(&main, &ya), MARGIN)
        .build_cartesian_2d(xa.clone(), ya.clone())?;
    draw_mesh(&mut chart, &xa, &ya, &m.x_label, &m.y_label)?;
    draw_cells(&mut chart, root, &cells, z_range)?;
    // Frame again on top of the cells.
    chart.draw_series(std::iter::once(Rectangle::new(
        [(xa.lo, ya.lo), (xa.hi, ya.hi)],
        BLACK.stroke_width(1),
    )))?;
    draw_overlay(&chart, root, &overlay)?;
    if !any_value {
        draw_boxed_no_data(&chart, root, &xa, &ya)?;
    }

    draw_colour_bar(&bar, &za, bar_labels, &m.z_label)?;
    if let Some(legend) = legend_area {
        legend_row(root, &legend, &entries)?;
    }
    Ok(())
}

/// Cell edges from cell centres: halfway between neighbours, the outer edges mirrored.
fn cell_edges(centres: &[f64]) -> Vec<f64> {
    match centres.len() {
        0 => Vec::new(),
        1 => {
            let (lo, hi) = widen(centres[0], centres[0]);
            let half = 0.5 * (hi - lo);
            vec![centres[0] - half, centres[0] + half]
        }
        n => {
            let mut e = Vec::with_capacity(n + 1);
            e.push(centres[0] - 0.5 * (centres[1] - centres[0]));
            e.extend(centres.windows(2).map(|w| 0.5 * (w[0] + w[1])));
            e.push(centres[n - 1] + 0.5 * (centres[n - 1] - centres[n - 2]));
            e
        }
    }
}

/// The `(lo, hi)` interval of cell `i`, if both edges are finite and distinct.
fn cell_span(edges: &[f64], i: usize) -> Option<(f64, f64)> {
    let (a, b) = (*edges.get(i)?, *edges.get(i + 1)?);
    (a.is_finite() && b.is_finite() && a != b).then(|| (a.min(b), a.max(b)))
}

/// The cells of the map with usable edges, row by row, with their finite values.
fn cells(m: &Heatmap) -> Vec<Cell> {
    let xe = cell_edges(&m.x);
    let ye = cell_edges(&m.y);
    let value = |ix: usize, iy: usize| -> Option<f64> {
        m.z.get(iy)
            .and_then(|row| row.get(ix))
            .copied()
            .flatten()
            .filter(|v| v.is_finite())
    };
    (0..m.y.len())
        .flat_map(|iy| (0..m.x.len()).map(move |ix| (ix, iy)))
        .filter_map(|(ix, iy)| Some((cell_span(&xe, ix)?, cell_span(&ye, iy)?, value(ix, iy))))
        .collect()
}

/// The x and y ranges of the map: the cells and the overlay points, with room around the
/// points on the border.
fn map_ranges(cells: &[Cell], overlay: &[&Overlay]) -> ((f64, f64), (f64, f64)) {
    let x_range = tight_range(
        cells
            .iter()
            .flat_map(|c| [c.0 .0, c.0 .1])
            .chain(overlay.iter().map(|o| o.0)),
    );
    let y_range = tight_range(
        cells
            .iter()
            .flat_map(|c| [c.1 .0, c.1 .1])
            .chain(overlay.iter().map(|o| o.1)),
    );
    let pad = |(lo, hi): (f64, f64), vals: &mut dyn Iterator<Item = f64>| {
        let margin = 0.03 * (hi - lo);
        let (mut a, mut b) = (lo, hi);
        for v in vals {
            if v - margin < a {
                a = v - margin;
            }
            if v + margin > b {
                b = v + margin;
            }
        }
        (a, b)
    };
    (
        pad(x_range, &mut overlay.iter().map(|o| o.0)),
        pad(y_range, &mut overlay.iter().map(|o| o.1)),
    )
}

/// The legend row: cells without value (if any) and overlay points (if any).
fn legend_entries(m: &Heatmap, any_none: bool, any_overlay: bool) -> Vec<(Swatch, String)> {
    let mut entries: Vec<(Swatch, String)> = Vec::new();
    if any_none {
        let label = if m.none_label.is_empty() {
            "no value".to_string()
        } else {
            m.none_label.clone()
        };
        entries.push((Swatch::Hatched, label));
    }
    if any_overlay {
        entries.push((Swatch::Ring, OVERLAY_LEGEND.to_string()));
    }
    entries
}

/// Draws the cells: values in viridis over `z_range` (clamped), then the cells without value
/// in hatched grey (the hatch drawn on `root` in pixels).
fn draw_cells<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    root: &DrawingArea<DB, Shift>,
    cells: &[Cell],
    (z0, z1): (f64, f64),
) -> DrawResult<DB> {
    let colored = cells.iter().filter_map(|&((x0, x1), (y0, y1), v)| {
        let c = viridis(v?.clamp(z0, z1), z0, z1);
        Some(Rectangle::new([(x0, y0), (x1, y1)], c.filled()))
    });
    chart.draw_series(colored)?;
    for &((x0, x1), (y0, y1), v) in cells {
        if v.is_none() {
            chart.draw_series(std::iter::once(Rectangle::new(
                [(x0, y0), (x1, y1)],
                NONE_FILL.filled(),
            )))?;
            let a = chart.backend_coord(&(x0, y1));
            let b = chart.backend_coord(&(x1, y0));
            hatch(root, a, b)?;
        }
    }
    Ok(())
}

/// Draws the overlay points as rings, each label on a translucent white box to its right.
fn draw_overlay<DB: DrawingBackend>(
    chart: &Chart<'_, DB>,
    root: &DrawingArea<DB, Shift>,
    overlay: &[&Overlay],
) -> DrawResult<DB> {
    for (x, y, label) in overlay {
        let at = chart.backend_coord(&(*x, *y));
        draw_ring(root, at)?;
        if !label.is_empty() {
            let style = anchored(text_style(NOTE_PX, BLACK), HPos::Left, VPos::Center);
            let (w, h) = root.estimate_text_size(label, &style)?;
            let (w, h) = (w as i32, h as i32);
            let x0 = at.0 + 11;
            root.draw(&Rectangle::new(
                [(x0, at.1 - h / 2 - 3), (x0 + w + 8, at.1 + h / 2 + 3)],
                WHITE.mix(0.8).filled(),
            ))?;
            root.draw(&Text::new(label.clone(), (x0 + 4, at.1), style))?;
        }
    }
    Ok(())
}

/// The "no data" note on a white box in the middle of the map (over any hatched cells).
fn draw_boxed_no_data<DB: DrawingBackend>(
    chart: &Chart<'_, DB>,
    root: &DrawingArea<DB, Shift>,
    xa: &Axis,
    ya: &Axis,
) -> DrawResult<DB> {
    let style = no_data_style(REF_GREY);
    let c = chart.backend_coord(&(xa.mid(), ya.mid()));
    let (w, h) = root.estimate_text_size(NO_DATA, &style)?;
    let (w, h) = (w as i32, h as i32);
    root.draw(&Rectangle::new(
        [
            (c.0 - w / 2 - 10, c.1 - h / 2 - 8),
            (c.0 + w / 2 + 10, c.1 + h / 2 + 8),
        ],
        WHITE.filled(),
    ))?;
    root.draw(&Text::new(NO_DATA, c, style))
}
