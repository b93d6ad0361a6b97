//! Particle views ([`ParticleView`]): side or top views of particles as dots coloured by
//! category, with equal scales on both axes and labelled rectangles (e.g. a wall section)
//! underneath.

use std::collections::BTreeSet;
use std::path::Path;

use plotters::coord::Shift;
use plotters::prelude::*;

use super::axis::Axis;
use super::clip::Bounds;
use super::frame::{chart_builder, draw_mesh, draw_no_data, y_label_area, Chart, MARGIN};
use super::legend::{draw_series_legend, Swatch};
use super::output::{write_both, DrawResult};
use super::range::{auto_range, is_finite_point};
use super::style::{palette, rect_fill, REF_GREY};
use super::text::page;

/// An axis-aligned rectangle `((x0, y0), (x1, y1), label)` of a [`ParticleView`].
pub type LabelledRect = ((f64, f64), (f64, f64), String);

/// A side view of particles, drawn with equal scales on both axes by [`draw_particles`].
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ParticleView {
    /// Caption above the view.
    pub title: String,
    /// Label of the horizontal axis, with its unit.
    pub x_label: String,
    /// Label of the vertical axis, with its unit.
    pub y_label: String,
    /// Particles `(x, y, category)`; the category indexes [`ParticleView::categories`] and
    /// [`PALETTE`](super::PALETTE). Later categories are drawn on top of earlier ones.
    pub points: Vec<(f64, f64, usize)>,
    /// Legend names of the categories.
    pub categories: Vec<String>,
    /// Rectangles `((x0, y0), (x1, y1), label)` drawn under the particles in translucent grey
    /// (e.g. a wall cross-section); equal labels share one legend entry.
    pub rects: Vec<LabelledRect>,
    /// Marker diameter in pixels (at least 1 is used).
    pub marker_px: u32,
}

/// Draws `view` with equal x and y scales into `STEM.svg` and `STEM.png` (1024×720 px).
///
/// The file names are formed as in [`draw`](super::draw).
pub fn draw_particles(view: &ParticleView, stem: &Path) -> anyhow::Result<()> {
    write_both(
        stem,
        |root| render_particles(view, root),
        |root| render_particles(view, root),
    )
}

/// Expands the smaller of two spans so that one data unit has the same length in pixels on
/// both axes of a `pw` × `ph` pixel plotting area.
fn equal_aspect(
    (x0, x1): (f64, f64),
    (y0, y1): (f64, f64),
    (pw, ph): (u32, u32),
) -> ((f64, f64), (f64, f64)) {
    let (pw, ph) = (f64::from(pw.max(1)), f64::from(ph.max(1)));
    let per_px = ((x1 - x0) / pw).max((y1 - y0) / ph);
    let (hx, hy) = (0.5 * per_px * pw, 0.5 * per_px * ph);
    let (cx, cy) = (0.5 * (x0 + x1), 0.5 * (y0 + y1));
    ((cx - hx, cx + hx), (cy - hy, cy + hy))
}

/// Draws the view on `root` (either backend).
fn render_particles<DB: DrawingBackend>(
    v: &ParticleView,
    root: &DrawingArea<DB, Shift>,
) -> DrawResult<DB> {
    let area = page(root, &v.title)?;

    let points: Vec<(f64, f64, usize)> = v
        .points
        .iter()
        .copied()
        .filter(|p| is_finite_point(&(p.0, p.1)))
        .collect();
    let rects: Vec<&LabelledRect> = v
        .rects
        .iter()
        .filter(|r| {
            [r.0 .0, r.0 .1, r.1 .0, r.1 .1]
                .iter()
                .all(|c| c.is_finite())
        })
        .collect();
    let (x_range, y_range) = data_ranges(&points, &rects);

    // The label area is sized from the unexpanded range; equal scales only add room.
    let provisional = Axis::new(y_range, 7);
    let mut builder = chart_builder(&area, y_label_area(&area, &provisional) + 8, 2 * MARGIN);
    let pixels = builder
        .build_cartesian_2d(0.0..1.0, 0.0..1.0)?
        .plotting_area()
        .dim_in_pixel();
    let (x_range, y_range) = equal_aspect(x_range, y_range, pixels);
    let xa = Axis::new(x_range, (pixels.0 / 100).max(2) as usize);
    let ya = Axis::new(y_range, (pixels.1 / 100).max(2) as usize);
    // The ticks stay inside the ranges, so the scales stay equal.
    let mut chart = builder.build_cartesian_2d(xa.clone(), ya.clone())?;
    draw_mesh(&mut chart, &xa, &ya, &v.x_label, &v.y_label)?;
    let bounds = Bounds::of(&xa, &ya);

    // Rectangles under the particles, their legend entries after the categories'.
    let rect_entries = draw_rects(&mut chart, &rects)?;
    let mut entries = draw_points(&mut chart, &bounds, v, &points)?;
    entries.extend(rect_entries);

    if entries.len() > 1 {
        add_legend_entries(&mut chart, entries)?;
        draw_series_legend(&mut chart, &occupancy(&bounds, &points, &rects), 36)?;
    }

    if points.is_empty() {
        draw_no_data(&chart, &xa, &ya)?;
    }
    Ok(())
}

/// The x and y ranges of the particles and rectangles with a 5 % margin, `(0, 1)` without.
fn data_ranges(points: &[(f64, f64, usize)], rects: &[&LabelledRect]) -> ((f64, f64), (f64, f64)) {
    let xs = points
        .iter()
        .map(|p| p.0)
        .chain(rects.iter().flat_map(|r| [r.0 .0, r.1 .0]));
    let ys = points
        .iter()
        .map(|p| p.1)
        .chain(rects.iter().flat_map(|r| [r.0 .1, r.1 .1]));
    (
        auto_range(xs).unwrap_or((0.0, 1.0)),
        auto_range(ys).unwrap_or((0.0, 1.0)),
    )
}

/// Draws the rectangles in translucent grey with a dark grey outline and returns one legend
/// entry per distinct non-empty label.
fn draw_rects<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    rects: &[&LabelledRect],
) -> Result<Vec<(Swatch, String)>, DrawingAreaErrorKind<DB::ErrorType>> {
    for r in rects {
        let ((x0, y0), (x1, y1), _) = **r;
        chart.draw_series(std::iter::once(Rectangle::new(
            [(x0, y0), (x1, y1)],
            rect_fill(),
        )))?;
        chart.draw_series(std::iter::once(Rectangle::new(
            [(x0, y0), (x1, y1)],
            REF_GREY.stroke_width(1),
        )))?;
    }
    let mut labels: Vec<&str> = Vec::new();
    for r in rects {
        if !r.2.is_empty() && !labels.contains(&r.2.as_str()) {
            labels.push(r.2.as_str());
        }
    }
    Ok(labels
        .into_iter()
        .map(|l| (Swatch::Box, l.to_string()))
        .collect())
}

/// Draws the particles inside `bounds` category by category (every named category and every
/// one that occurs) and returns the legend entries of the named ones.
fn draw_points<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    bounds: &Bounds,
    v: &ParticleView,
    points: &[(f64, f64, usize)],
) -> Result<Vec<(Swatch, String)>, DrawingAreaErrorKind<DB::ErrorType>> {
    let radius = (v.marker_px.max(1) as f64 / 2.0).round().max(1.0) as i32;
    // Every named category (for a stable legend) and every category that occurs.
    let cats: BTreeSet<usize> = (0..v.categories.len())
        .chain(points.iter().map(|p| p.2))
        .collect();
    let mut entries = Vec::new();
    for cat in cats {
        let color = palette(cat);
        let elems = points
            .iter()
            .filter(|p| p.2 == cat && bounds.contains((p.0, p.1)))
            .map(|p| Circle::new((p.0, p.1), radius, color.filled()));
        chart.draw_series(elems)?;
        let name = v
            .categories
            .get(cat)
            .cloned()
            .unwrap_or_else(|| format!("category {cat}"));
        if !name.is_empty() {
            entries.push((Swatch::Dot(color), name));
        }
    }
    Ok(entries)
}

/// Registers `entries` as labelled (empty) series of `chart`, for plotters' legend box.
fn add_legend_entries<'a, DB: DrawingBackend + 'a>(
    chart: &mut Chart<'a, DB>,
    entries: Vec<(Swatch, String)>,
) -> DrawResult<DB> {
    for (swatch, name) in entries {
        let anno = chart.draw_series(std::iter::empty::<Circle<(f64, f64), i32>>())?;
        match swatch {
            Swatch::Dot(color) => {
                anno.label(name)
                    .legend(move |(x, y)| Circle::new((x + 15, y), 6, color.filled()));
            }
            _ => {
                anno.label(name).legend(|(x, y)| {
                    EmptyElement::at((x + 2, y))
                        + Rectangle::new([(0, -8), (26, 8)], rect_fill())
                        + Rectangle::new([(0, -8), (26, 8)], REF_GREY)
                });
            }
        }
    }
    Ok(())
}

/// Normalised positions of the particles and of an 11 × 11 grid over each rectangle.
fn occupancy(
    bounds: &Bounds,
    points: &[(f64, f64, usize)],
    rects: &[&LabelledRect],
) -> Vec<(f64, f64)> {
    points
        .iter()
        .map(|p| bounds.normalised((p.0, p.1)))
        .chain(
            rects
                .iter()
                .flat_map(|r| {
                    let (a, b) = (r.0, r.1);
                    (0..=10).flat_map(move |i| {
                        (0..=10).map(move |j| {
                            (
                                a.0 + (b.0 - a.0) * i as f64 / 10.0,
                                a.1 + (b.1 - a.1) * j as f64 / 10.0,
                            )
                        })
                    })
                })
                .map(|q| bounds.normalised(q)),
        )
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn equal_aspect_gives_equal_scales() {
        let (xr, yr) = equal_aspect((0.0, 4.0), (0.0, 1.0), (800, 400));
        assert!(((xr.1 - xr.0) / 800.0 - (yr.1 - yr.0) / 400.0).abs() < 1e-12);
        assert_eq!(xr, (0.0, 4.0));
        assert!((yr.0 + 0.5).abs() < 1e-12 && (yr.1 - 1.5).abs() < 1e-12);
    }
}
