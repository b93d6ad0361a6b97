//! Colours and fills shared by the plot kinds: the palette, the viridis scale, the grey of
//! reference elements, the translucent grey of rectangles and the hatched grey of cells
//! without value.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::output::{DrawResult, Px};

/// The fixed colour palette indexed by [`Series::color`](super::Series::color) and by
/// particle categories: Okabe & Ito's colour-blind-safe colours as `(r, g, b)`, ordered blue,
/// vermillion, bluish green, reddish purple, orange, sky blue, black, yellow.
pub const PALETTE: [(u8, u8, u8); 8] = [
    (0x00, 0x72, 0xB2),
    (0xD5, 0x5E, 0x00),
    (0x00, 0x9E, 0x73),
    (0xCC, 0x79, 0xA7),
    (0xE6, 0x9F, 0x00),
    (0x56, 0xB4, 0xE9),
    (0x00, 0x00, 0x00),
    (0xF0, 0xE4, 0x42),
];

/// Dark grey of reference lines, their labels and rectangle outlines.
pub(super) const REF_GREY: RGBColor = RGBColor(0x50, 0x50, 0x50);
/// Fill of heat-map cells without value.
pub(super) const NONE_FILL: RGBColor = RGBColor(0xD9, 0xD9, 0xD9);
/// Colour of the hatch lines (and swatch outline) of cells without value.
pub(super) const NONE_HATCH: RGBColor = RGBColor(0x8C, 0x8C, 0x8C);
/// Distance in pixels between hatch lines, measured along the axes.
const HATCH_SPACING: i32 = 8;

/// Palette colour number `i` (modulo the palette length).
pub(super) fn palette(i: usize) -> RGBColor {
    let (r, g, b) = PALETTE[i % PALETTE.len()];
    RGBColor(r, g, b)
}

/// The translucent grey fill of labelled rectangles (e.g. a wall cross-section) and of their
/// legend entries.
pub(super) fn rect_fill() -> ShapeStyle {
    RGBColor(0x9A, 0x9A, 0x9A).mix(0.55).filled()
}

/// The viridis colour of `v` on the scale from `lo` to `hi`.
pub(super) fn viridis(v: f64, lo: f64, hi: f64) -> RGBColor {
    ViridisRGB.get_color_normalized(v, lo, hi)
}

/// Draws 45° hatch lines, aligned on a global pixel grid, inside the pixel rectangle.
pub(super) fn hatch<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    (ax, ay): Px,
    (bx, by): Px,
) -> DrawResult<DB> {
    let (x0, x1) = (ax.min(bx), ax.max(bx));
    let (y0, y1) = (ay.min(by), ay.max(by));
    let style = NONE_HATCH.stroke_width(1);
    let first = (x0 + y0).div_euclid(HATCH_SPACING) * HATCH_SPACING;
    let mut k = first;
    while k <= x1 + y1 {
        // Points on x + y = k inside the rectangle.
        let xa = x0.max(k - y1);
        let xb = x1.min(k - y0);
        if xa < xb {
            root.draw(&PathElement::new(vec![(xa, k - xa), (xb, k - xb)], style))?;
        }
        k += HATCH_SPACING;
    }
    Ok(())
}
