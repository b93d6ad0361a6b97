//! Text: the font sizes, the text styles built on the embedded font, and the figure title.

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::font::FAMILY;

/// Font size in pixels of the figure title.
pub(super) const TITLE_PX: f64 = 26.0;
/// Font size in pixels of the axis titles.
pub(super) const DESC_PX: f64 = 20.0;
/// Font size in pixels of the tick labels.
pub(super) const TICK_PX: f64 = 16.0;
/// Font size in pixels of the legend entries.
pub(super) const LEGEND_PX: f64 = 16.0;
/// Font size in pixels of notes: reference-line labels and overlay-point labels.
pub(super) const NOTE_PX: f64 = 15.0;
/// Font size in pixels of the "no data" note.
const NO_DATA_PX: f64 = 28.0;
/// The note drawn in the middle of a figure without any finite data.
pub(super) const NO_DATA: &str = "no data";

/// The module's font at `px` pixels in `color`, anchored at its top left corner.
pub(super) fn text_style(px: f64, color: RGBColor) -> TextStyle<'static> {
    TextStyle {
        font: FontDesc::new(FontFamily::Name(FAMILY), px, FontStyle::Normal),
        color: color.to_backend_color(),
        pos: Pos::new(HPos::Left, VPos::Top),
    }
}

/// `style` anchored at the given horizontal and vertical position.
pub(super) fn anchored(style: TextStyle<'static>, h: HPos, v: VPos) -> TextStyle<'static> {
    style.pos(Pos::new(h, v))
}

/// The style of the [`NO_DATA`] note in `color`, centred on its position.
pub(super) fn no_data_style(color: RGBColor) -> TextStyle<'static> {
    anchored(text_style(NO_DATA_PX, color), HPos::Center, VPos::Center)
}

/// Clears `root` to white, draws the title (if any) and returns the area below it.
pub(super) fn page<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    title: &str,
) -> Result<DrawingArea<DB, Shift>, DrawingAreaErrorKind<DB::ErrorType>> {
    root.fill(&WHITE)?;
    let area = root.margin(8, 0, 0, 0);
    if title.trim().is_empty() {
        Ok(area)
    } else {
        area.titled(title, text_style(TITLE_PX, BLACK))
    }
}
