//! The colour bar of heat maps: the viridis scale as a vertical bar with the value axis and
//! its title on the right.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::axis::Axis;
use super::frame::{styled, MARGIN, X_LABEL_AREA};
use super::output::DrawResult;
use super::style::viridis;

/// Number of colour steps of the bar.
const STEPS: u32 = 128;

/// Draws the colour bar of the value axis `za` in `area`, with a label area of `label_px`
/// pixels on its right titled `z_label`; the margins align it with the map's plotting area.
pub(super) fn draw_colour_bar<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    za: &Axis,
    label_px: i32,
    z_label: &str,
) -> DrawResult<DB> {
    let mut bar_chart = ChartBuilder::on(area)
        .margin(MARGIN)
        .x_label_area_size(X_LABEL_AREA)
        .right_y_label_area_size(label_px)
        .build_cartesian_2d(0.0..1.0, za.clone())?;
    let dz = (za.hi - za.lo) / f64::from(STEPS);
    bar_chart.draw_series((0..STEPS).map(|i| {
        let z0 = za.lo + f64::from(i) * dz;
        let c = viridis(z0 + 0.5 * dz, za.lo, za.hi);
        Rectangle::new([(0.0, z0), (1.0, z0 + dz)], c.filled())
    }))?;
    bar_chart.draw_series(std::iter::once(Rectangle::new(
        [(0.0, za.lo), (1.0, za.hi)],
        BLACK.stroke_width(1),
    )))?;
    // The axis and its ticks after the bar, so that the bar does not cover them.
    let fz = |v: &f64| za.label(*v);
    styled(&mut bar_chart.configure_mesh())
        .disable_mesh()
        .disable_x_axis()
        .x_labels(0)
        .y_desc(z_label)
        .y_label_formatter(&fz)
        .draw()
}
