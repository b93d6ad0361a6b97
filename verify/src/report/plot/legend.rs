//! Legends: plotters' series-label box placed in the emptiest corner of a chart, and a row of
//! hand-drawn entries (swatch and text) outside the plotting area.

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, VPos};

use super::frame::Chart;
use super::output::{DrawResult, Px};
use super::style::{hatch, rect_fill, NONE_FILL, NONE_HATCH, REF_GREY};
use super::text::{anchored, text_style, LEGEND_PX};

/// Width in pixels of a swatch of a legend row.
const SWATCH_W: i32 = 26;

/// Which corner of the plotting area holds the fewest of `samples` (normalised to `[0, 1]²`).
pub(super) fn emptiest_corner(samples: &[(f64, f64)]) -> SeriesLabelPosition {
    let corners = [
        (SeriesLabelPosition::UpperRight, true, true),
        (SeriesLabelPosition::UpperLeft, false, true),
        (SeriesLabelPosition::LowerRight, true, false),
        (SeriesLabelPosition::LowerLeft, false, false),
    ];
    let mut best = (usize::MAX, SeriesLabelPosition::UpperRight);
    for (pos, right, upper) in corners {
        let n = samples
            .iter()
            .filter(|&&(u, v)| {
                let in_x = if right { u >= 0.55 } else { u <= 0.45 };
                let in_y = if upper { v >= 0.6 } else { v <= 0.4 };
                in_x && in_y
            })
            .count();
        if n < best.0 {
            best = (n, pos);
        }
    }
    best.1
}

/// Draws the labelled series of `chart` in a legend box, in the corner that holds the fewest
/// of the `occupancy` samples (normalised positions of the drawn data); `glyph_px` is the
/// width in pixels reserved for the glyphs.
pub(super) fn draw_series_legend<'a, DB: DrawingBackend + 'a>(
    chart: &mut Chart<'a, DB>,
    occupancy: &[(f64, f64)],
    glyph_px: i32,
) -> DrawResult<DB> {
    chart
        .configure_series_labels()
        .position(emptiest_corner(occupancy))
        .margin(10)
        .legend_area_size(glyph_px)
        .label_font(text_style(LEGEND_PX, BLACK))
        .background_style(WHITE.mix(0.88))
        .border_style(BLACK)
        .draw()
}

/// The graphic of a legend entry.
pub(super) enum Swatch {
    /// A hatched grey box: cells without value.
    Hatched,
    /// A white ring: simulated points on a heat map.
    Ring,
    /// A translucent grey box: a labelled rectangle.
    Box,
    /// A filled dot of the colour: a particle category.
    Dot(RGBColor),
}

/// Draws `swatch` with its left end at `(x, y)` (vertically centred).
fn draw_swatch<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    swatch: &Swatch,
    (x, y): Px,
) -> DrawResult<DB> {
    let corners = [(x, y - 9), (x + SWATCH_W, y + 9)];
    match swatch {
        Swatch::Hatched => {
            root.draw(&Rectangle::new(corners, NONE_FILL.filled()))?;
            hatch(root, corners[0], corners[1])?;
            root.draw(&Rectangle::new(corners, NONE_HATCH))
        }
        Swatch::Ring => draw_ring(root, (x + 13, y)),
        Swatch::Box => {
            root.draw(&Rectangle::new(corners, rect_fill()))?;
            root.draw(&Rectangle::new(corners, REF_GREY))
        }
        Swatch::Dot(color) => root.draw(&Circle::new((x + 13, y), 6, color.filled())),
    }
}

/// A white ring with a black edge centred at `at`: the mark of a simulated point.
pub(super) fn draw_ring<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    at: Px,
) -> DrawResult<DB> {
    root.draw(&Circle::new(at, 7, WHITE.filled()))?;
    root.draw(&Circle::new(at, 7, BLACK.stroke_width(2)))
}

/// Draws legend entries in one row, centred in `area` (a part of `root`).
pub(super) fn legend_row<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    area: &DrawingArea<DB, Shift>,
    entries: &[(Swatch, String)],
) -> DrawResult<DB> {
    const TEXT_GAP: i32 = 8;
    const ENTRY_GAP: i32 = 30;
    let style = anchored(text_style(LEGEND_PX, BLACK), HPos::Left, VPos::Center);
    let widths: Vec<i32> = entries
        .iter()
        .map(|(_, t)| area.estimate_text_size(t, &style).map(|(w, _)| w as i32))
        .collect::<Result<_, _>>()?;
    let total: i32 = widths
        .iter()
        .map(|w| w + SWATCH_W + TEXT_GAP + ENTRY_GAP)
        .sum::<i32>()
        - ENTRY_GAP;
    let (aw, ah) = area.dim_in_pixel();
    let (bx, by) = area.get_base_pixel();
    let mut x = bx + ((aw as i32 - total) / 2).max(4);
    let y = by + ah as i32 / 2;
    for ((swatch, text), w) in entries.iter().zip(widths) {
        draw_swatch(root, swatch, (x, y))?;
        root.draw(&Text::new(
            text.clone(),
            (x + SWATCH_W + TEXT_GAP, y),
            style.clone(),
        ))?;
        x += w + SWATCH_W + TEXT_GAP + ENTRY_GAP;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn emptiest_corner_avoids_data() {
        let upper_right: Vec<(f64, f64)> =
            (0..50).map(|i| (0.6 + f64::from(i) * 0.005, 0.9)).collect();
        assert_eq!(
            emptiest_corner(&upper_right),
            SeriesLabelPosition::UpperLeft
        );
        assert_eq!(emptiest_corner(&[]), SeriesLabelPosition::UpperRight);
    }
}
