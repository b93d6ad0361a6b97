//! Line/marker charts ([`Plot`]): results as solid lines and markers, theory as dashed lines,
//! reference values as labelled horizontal lines, and a legend in the emptiest corner.

use std::path::Path;

use plotters::coord::Shift;
use plotters::element::DashedPathElement;
use plotters::prelude::*;

use super::axis::Axis;
use super::clip::Bounds;
use super::frame::{chart_builder, draw_mesh, draw_no_data, y_label_area, Chart, MARGIN};
use super::legend::draw_series_legend;
use super::marker::{closed, glyph_parts, marker_shape, MARKER_R};
use super::output::{write_both, DrawResult};
use super::range::{auto_range, given_range, is_finite_point};
use super::reference::draw_reference_lines;
use super::style::palette;
use super::text::page;

/// How a [`Series`] is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SeriesKind {
    /// Solid line through the points: a simulation result sampled densely.
    Line,
    /// Dashed line through the points: theory or another reference curve.
    Dashed,
    /// Markers only: discrete results such as literature values or single simulations.
    Markers,
    /// Solid line with a marker at every point: a simulation result at a few samples.
    LineMarkers,
}

/// One data set of a [`Plot`].
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Legend text; an empty label keeps the series out of the legend.
    pub label: String,
    /// The `(x, y)` points in drawing order; non-finite points are skipped and break lines.
    pub points: Vec<(f64, f64)>,
    /// How the points are drawn.
    pub kind: SeriesKind,
    /// Index into [`PALETTE`](super::PALETTE) (taken modulo its length); it also picks the
    /// marker shape.
    pub color: usize,
}

/// A 2-D line/marker plot, drawn by [`draw`].
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Plot {
    /// Caption above the plot.
    pub title: String,
    /// Label of the horizontal axis, with its unit (e.g. `"c² [m²/s²]"`).
    pub x_label: String,
    /// Label of the vertical axis, with its unit.
    pub y_label: String,
    /// The data sets, drawn in order (later ones on top).
    pub series: Vec<Series>,
    /// Fixed horizontal range `(min, max)`; `None` (or a non-finite pair) fits the data.
    pub x_range: Option<(f64, f64)>,
    /// Fixed vertical range `(min, max)`; `None` (or a non-finite pair) fits the data
    /// (within the horizontal range) and the reference lines.
    pub y_range: Option<(f64, f64)>,
    /// Horizontal reference lines `(y, label)`, drawn dashed in dark grey with the label at
    /// their right end.
    pub hlines: Vec<(f64, String)>,
}

/// Draws `plot` into `STEM.svg` and `STEM.png` (1024×720 px).
///
/// The extensions are appended to `stem` (a stem such as `out/c_10.5` gives `out/c_10.5.svg`);
/// missing parent directories are created.
pub fn draw(plot: &Plot, stem: &Path) -> anyhow::Result<()> {
    write_both(
        stem,
        |root| render_plot(plot, root),
        |root| render_plot(plot, root),
    )
}

/// Draws the plot on `root` (either backend).
fn render_plot<DB: DrawingBackend>(p: &Plot, root: &DrawingArea<DB, Shift>) -> DrawResult<DB> {
    let area = page(root, &p.title)?;

    let finite: Vec<(f64, f64)> = p
        .series
        .iter()
        .flat_map(|s| s.points.iter().copied())
        .filter(is_finite_point)
        .collect();
    let (x_range, y_range) = plot_ranges(p, &finite);
    let xa = Axis::new(x_range, 9);
    let ya = Axis::new(y_range, 7);
    let bounds = Bounds::of(&xa, &ya);

    let mut chart = chart_builder(&area, y_label_area(&area, &ya), 2 * MARGIN)
        .build_cartesian_2d(xa.clone(), ya.clone())?;
    draw_mesh(&mut chart, &xa, &ya, &p.x_label, &p.y_label)?;

    // Normalised positions of what is drawn, for the legend placement. Reference lines go
    // under the data; lines before markers and legend entries, so markers stay on top.
    let mut occupancy = draw_reference_lines(&mut chart, &xa, &ya, &p.hlines)?;
    for s in &p.series {
        draw_line(&mut chart, &bounds, s, &mut occupancy)?;
    }
    let legend = p.series.iter().filter(|s| !s.label.is_empty()).count() > 1;
    for s in &p.series {
        draw_markers(&mut chart, &bounds, s, legend, &mut occupancy)?;
    }
    if legend {
        draw_series_legend(&mut chart, &occupancy, 44)?;
    }

    if finite.is_empty() {
        draw_no_data(&chart, &xa, &ya)?;
    }
    Ok(())
}

/// The x and y ranges of the plot: given by the caller, or fitted to the `finite` points (y
/// to those within a given x range, and to the reference lines), `(0, 1)` without data.
fn plot_ranges(p: &Plot, finite: &[(f64, f64)]) -> ((f64, f64), (f64, f64)) {
    let given_x = given_range(p.x_range);
    let x_range = given_x
        .or_else(|| auto_range(finite.iter().map(|q| q.0)))
        .unwrap_or((0.0, 1.0));
    let y_range = given_range(p.y_range)
        .or_else(|| {
            let in_x = finite
                .iter()
                .filter(|q| given_x.is_none() || (q.0 >= x_range.0 && q.0 <= x_range.1))
                .map(|q| q.1);
            auto_range(in_x.chain(p.hlines.iter().map(|h| h.0)))
        })
        .unwrap_or((0.0, 1.0));
    (x_range, y_range)
}

/// Draws the line of `s` (solid or dashed, clipped to `bounds`; nothing for markers only)
/// and samples it into `occupancy`.
fn draw_line<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    bounds: &Bounds,
    s: &Series,
    occupancy: &mut Vec<(f64, f64)>,
) -> DrawResult<DB> {
    let style = palette(s.color).stroke_width(2);
    let lines = match s.kind {
        SeriesKind::Markers => Vec::new(),
        _ => bounds.polylines(&s.points),
    };
    for line in &lines {
        for w in line.windows(2) {
            let (a, b) = (bounds.normalised(w[0]), bounds.normalised(w[1]));
            occupancy.extend((0..=10).map(|i| {
                let t = f64::from(i) / 10.0;
                (a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1))
            }));
        }
    }
    if s.kind == SeriesKind::Dashed {
        chart.draw_series(
            lines
                .into_iter()
                .map(|l| DashedPathElement::new(l, 10, 6, style)),
        )?;
    } else {
        chart.draw_series(lines.into_iter().map(|l| PathElement::new(l, style)))?;
    }
    Ok(())
}

/// Draws the markers of `s` inside `bounds` (none for lines only), adds them to `occupancy`
/// and, if `legend` and the series has a label, registers its legend entry.
fn draw_markers<'a, DB: DrawingBackend + 'a>(
    chart: &mut Chart<'a, DB>,
    bounds: &Bounds,
    s: &Series,
    legend: bool,
    occupancy: &mut Vec<(f64, f64)>,
) -> DrawResult<DB> {
    let color = palette(s.color);
    let shape = s.color;
    let kind = s.kind;
    let visible: Vec<(f64, f64)> = match kind {
        SeriesKind::Markers | SeriesKind::LineMarkers => s
            .points
            .iter()
            .copied()
            .filter(|q| is_finite_point(q) && bounds.contains(*q))
            .collect(),
        SeriesKind::Line | SeriesKind::Dashed => Vec::new(),
    };
    occupancy.extend(visible.iter().map(|&q| bounds.normalised(q)));
    let (poly, fill, edge_style) = marker_shape(shape, color, MARKER_R);
    let edge = closed(&poly);
    let anno = chart.draw_series(visible.into_iter().map(|q| {
        EmptyElement::at(q)
            + Polygon::new(poly.clone(), fill)
            + PathElement::new(edge.clone(), edge_style)
    }))?;
    if legend && !s.label.is_empty() {
        anno.label(s.label.clone()).legend(move |(x, y)| {
            let g = glyph_parts(kind, color, shape);
            EmptyElement::at((x + 20, y))
                + DashedPathElement::new(g.line, g.dash, g.gap, g.line_style)
                + Polygon::new(g.poly, g.fill)
                + PathElement::new(g.edge, g.edge_style)
        });
    }
    Ok(())
}
