//! The chart frame shared by every plot kind: margins and label areas, the styled mesh (grid,
//! axes, ticks and axis titles) and the "no data" note of an empty chart.

use plotters::chart::MeshStyle;
use plotters::coord::ranged1d::Ranged;
use plotters::coord::Shift;
use plotters::prelude::*;

use super::axis::Axis;
use super::output::DrawResult;
use super::text::{no_data_style, text_style, DESC_PX, NO_DATA, TICK_PX};

/// Margin in pixels around a chart.
pub(super) const MARGIN: i32 = 16;
/// Height in pixels of the area under a chart: tick labels and the x-axis title.
pub(super) const X_LABEL_AREA: i32 = 64;

/// A chart whose two coordinates are the module's [`Axis`].
pub(super) type Chart<'a, DB> = ChartContext<'a, DB, Cartesian2d<Axis, Axis>>;

/// A chart builder on `area` with the module's margins, `right_px` pixels of margin on the
/// right, and a label area of `y_label_px` pixels on the left.
pub(super) fn chart_builder<'a, 'b, DB: DrawingBackend>(
    area: &'a DrawingArea<DB, Shift>,
    y_label_px: i32,
    right_px: i32,
) -> ChartBuilder<'a, 'b, DB> {
    let mut builder = ChartBuilder::on(area);
    builder
        .margin(MARGIN)
        .margin_right(right_px)
        .x_label_area_size(X_LABEL_AREA)
        .y_label_area_size(y_label_px);
    builder
}

/// Width in pixels of the widest tick label of `axis`.
fn tick_label_width<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, axis: &Axis) -> i32 {
    let style = text_style(TICK_PX, BLACK);
    axis.ticks
        .iter()
        .map(|&t| {
            area.estimate_text_size(&axis.label(t), &style)
                .map(|(w, _)| w as i32)
                .unwrap_or(8 * TICK_PX as i32)
        })
        .max()
        .unwrap_or(0)
}

/// Size in pixels of a vertical axis' label area: tick labels, tick marks and the rotated
/// axis title.
pub(super) fn y_label_area<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, axis: &Axis) -> i32 {
    tick_label_width(area, axis) + 20 + DESC_PX as i32 + 14
}

/// Sets the styles every mesh of the module shares: tick labels, axis titles, axis lines and
/// tick marks.
pub(super) fn styled<'m, 'a, 'b, X: Ranged, Y: Ranged, DB: DrawingBackend>(
    mesh: &'m mut MeshStyle<'a, 'b, X, Y, DB>,
) -> &'m mut MeshStyle<'a, 'b, X, Y, DB> {
    mesh.label_style(text_style(TICK_PX, BLACK))
        .axis_desc_style(text_style(DESC_PX, BLACK))
        .axis_style(BLACK.stroke_width(1))
        .set_all_tick_mark_size(6)
}

/// Draws the grid (bold at the ticks, light at the minor positions), the axes with their
/// tick labels and the axis titles.
pub(super) fn draw_mesh<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    xa: &Axis,
    ya: &Axis,
    x_label: &str,
    y_label: &str,
) -> DrawResult<DB> {
    let fx = |v: &f64| xa.label(*v);
    let fy = |v: &f64| ya.label(*v);
    styled(&mut chart.configure_mesh())
        .x_desc(x_label)
        .y_desc(y_label)
        .x_label_formatter(&fx)
        .y_label_formatter(&fy)
        .bold_line_style(RGBColor(0xC8, 0xC8, 0xC8).stroke_width(1))
        .light_line_style(RGBColor(0xEE, 0xEE, 0xEE).stroke_width(1))
        .draw()
}

/// The "no data" note in the middle of the plotting area.
pub(super) fn draw_no_data<DB: DrawingBackend>(
    chart: &Chart<'_, DB>,
    xa: &Axis,
    ya: &Axis,
) -> DrawResult<DB> {
    let style = no_data_style(RGBColor(0x70, 0x70, 0x70));
    chart
        .plotting_area()
        .draw(&Text::new(NO_DATA, (xa.mid(), ya.mid()), style))
}
