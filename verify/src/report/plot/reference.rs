//! Reference lines of line charts: dashed horizontal lines in dark grey across the plotting
//! area, each labelled at one end without overlapping the labels placed before it.

use plotters::element::DashedPathElement;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, VPos};

use super::axis::Axis;
use super::frame::Chart;
use super::style::REF_GREY;
use super::text::{anchored, text_style, NOTE_PX};

/// Draws the reference lines `(y, label)` that lie within `ya` and returns samples of them in
/// normalised plotting-area coordinates (their right part, where the labels go).
///
/// A label goes above the right end of its line, or below it, or to the left end, whichever
/// does not overlap a label placed before.
pub(super) fn draw_reference_lines<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    xa: &Axis,
    ya: &Axis,
    hlines: &[(f64, String)],
) -> Result<Vec<(f64, f64)>, DrawingAreaErrorKind<DB::ErrorType>> {
    let mut occupancy: Vec<(f64, f64)> = Vec::new();
    let mut placed: Vec<Placed> = Vec::new();
    for (y, label) in hlines {
        if !y.is_finite() || *y < ya.lo || *y > ya.hi {
            continue;
        }
        chart.draw_series(std::iter::once(DashedPathElement::new(
            vec![(xa.lo, *y), (xa.hi, *y)],
            10,
            6,
            REF_GREY.stroke_width(2),
        )))?;
        occupancy.extend((0..=20).map(|i| {
            (
                0.55 + 0.45 * f64::from(i) / 20.0,
                (y - ya.lo) / (ya.hi - ya.lo),
            )
        }));
        if label.is_empty() {
            continue;
        }
        let py = chart.backend_coord(&(xa.hi, *y)).1;
        let (right, above) = place_label(&mut placed, py);
        let (x, dx, h) = if right {
            (xa.hi, -8, HPos::Right)
        } else {
            (xa.lo, 8, HPos::Left)
        };
        let (dy, v) = if above {
            (-4, VPos::Bottom)
        } else {
            (4, VPos::Top)
        };
        let style = anchored(text_style(NOTE_PX, REF_GREY), h, v);
        chart.draw_series(std::iter::once(
            EmptyElement::at((x, *y)) + Text::new(label.clone(), (dx, dy), style),
        ))?;
    }
    Ok(occupancy)
}

/// A placed label: at the right end (or the left), and its vertical pixel band `[top, bottom)`.
type Placed = (bool, i32, i32);

/// Where the label of a line at pixel row `py` goes, as `(at the right end, above the line)`:
/// the first position whose band does not overlap one in `placed` (above right when none is
/// free); the chosen band is added to `placed`.
fn place_label(placed: &mut Vec<Placed>, py: i32) -> (bool, bool) {
    let label_h = NOTE_PX as i32 + 2;
    let candidates = [(true, true), (true, false), (false, true), (false, false)];
    let band = |above: bool| {
        if above {
            (py - 4 - label_h, py - 4)
        } else {
            (py + 4, py + 4 + label_h)
        }
    };
    let free = |&(right, above): &(bool, bool)| {
        let (a, b) = band(above);
        !placed
            .iter()
            .any(|&(r, pa, pb)| r == right && a < pb && pa < b)
    };
    let (right, above) = candidates
        .iter()
        .copied()
        .find(free)
        .unwrap_or((true, true));
    let (a, b) = band(above);
    placed.push((right, a, b));
    (right, above)
}
