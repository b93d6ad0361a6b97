//! Markers and legend glyphs of line/marker charts: six convex marker shapes picked by the
//! series' colour index, and the line-plus-marker glyph of a legend entry.

use plotters::prelude::*;

use super::line::SeriesKind;
use super::output::Px;

/// Marker radius in pixels.
pub(super) const MARKER_R: i32 = 5;

/// The outline of marker shape `shape` (modulo 6) around the origin, `r` pixels in radius,
/// with its fill and edge styles. All shapes are convex polygons so that one element type
/// serves every marker: filled circle, square, triangle, diamond, downward triangle, and a
/// ring (white inside).
///
/// (plotters' `DynElement` cannot be used in `draw_series` with the SVG and bitmap backends,
/// which borrow their output path, hence one concrete element type for all shapes.)
pub(super) fn marker_shape(
    shape: usize,
    color: RGBColor,
    r: i32,
) -> (Vec<Px>, ShapeStyle, ShapeStyle) {
    let rf = f64::from(r);
    let circle = |radius: f64| -> Vec<Px> {
        (0..20)
            .map(|i| {
                let a = std::f64::consts::TAU * f64::from(i) / 20.0;
                (
                    (radius * a.cos()).round() as i32,
                    (radius * a.sin()).round() as i32,
                )
            })
            .collect()
    };
    let solid = (color.filled(), color.stroke_width(1));
    match shape % 6 {
        0 => (circle(rf), solid.0, solid.1),
        1 => {
            let h = (0.9 * rf).round() as i32;
            (vec![(-h, -h), (h, -h), (h, h), (-h, h)], solid.0, solid.1)
        }
        2 => {
            let (d, b) = (r + 1, (0.75 * rf).round() as i32);
            (vec![(0, -d), (d, b), (-d, b)], solid.0, solid.1)
        }
        3 => {
            let d = r + 1;
            (vec![(0, -d), (d, 0), (0, d), (-d, 0)], solid.0, solid.1)
        }
        4 => {
            let (d, b) = (r + 1, (0.75 * rf).round() as i32);
            (vec![(0, d), (d, -b), (-d, -b)], solid.0, solid.1)
        }
        _ => (circle(rf), WHITE.filled(), color.stroke_width(2)),
    }
}

/// The closed outline of a polygon (first vertex repeated at the end).
pub(super) fn closed(poly: &[Px]) -> Vec<Px> {
    let mut v = poly.to_vec();
    if let Some(&first) = poly.first() {
        v.push(first);
    }
    v
}

/// The parts of a legend glyph, relative to its centre: a line (solid, dashed or none) of
/// 30 pixels and a marker (or none).
pub(super) struct GlyphParts {
    /// The line's end points (empty for markers only).
    pub(super) line: Vec<Px>,
    /// Dash length in pixels (the whole line for a solid one).
    pub(super) dash: i32,
    /// Gap between dashes in pixels.
    pub(super) gap: i32,
    /// Stroke of the line.
    pub(super) line_style: ShapeStyle,
    /// The marker polygon (empty for lines only).
    pub(super) poly: Vec<Px>,
    /// Fill of the marker.
    pub(super) fill: ShapeStyle,
    /// The marker's closed outline.
    pub(super) edge: Vec<Px>,
    /// Stroke of the marker's outline.
    pub(super) edge_style: ShapeStyle,
}

/// The legend glyph of a series drawn as `kind` in `color` with marker shape `shape`.
pub(super) fn glyph_parts(kind: SeriesKind, color: RGBColor, shape: usize) -> GlyphParts {
    let none = TRANSPARENT.filled();
    let (line, dash, gap, line_style) = match kind {
        SeriesKind::Line | SeriesKind::LineMarkers => {
            (vec![(-15, 0), (15, 0)], 30, 1, color.stroke_width(2))
        }
        SeriesKind::Dashed => (vec![(-15, 0), (15, 0)], 8, 4, color.stroke_width(2)),
        SeriesKind::Markers => (Vec::new(), 1, 1, none),
    };
    let (poly, fill, edge, edge_style) = match kind {
        SeriesKind::Markers | SeriesKind::LineMarkers => {
            let (poly, fill, edge_style) = marker_shape(shape, color, MARKER_R);
            let edge = closed(&poly);
            (poly, fill, edge, edge_style)
        }
        SeriesKind::Line | SeriesKind::Dashed => (Vec::new(), none, Vec::new(), none),
    };
    GlyphParts {
        line,
        dash,
        gap,
        line_style,
        poly,
        fill,
        edge,
        edge_style,
    }
}
