//! Figures of the verification reports: line plots, heat maps and particle snapshots.
//!
//! Every figure is written twice, as `STEM.svg` (vector, for the report) and `STEM.png`
//! ([`WIDTH`] × [`HEIGHT`] pixels, for quick viewing), from the same drawing code.
//!
//! # Conventions
//!
//! - **Colours** come from a fixed palette, [`PALETTE`] (Okabe & Ito's colour-blind-safe
//!   set); a series picks one by index ([`Series::color`], taken modulo the palette length).
//!   The marker shape follows the colour index as well (circle, square, triangle, diamond,
//!   cross, ring), so that series stay distinguishable in grey-scale print.
//! - **Dashed lines are theory or reference values**: analytic curves ([`SeriesKind::Dashed`])
//!   and the horizontal reference lines of [`Plot::hlines`] (dark grey, labelled at their
//!   right end).
//! - **Solid lines and markers are results**: simulations ([`SeriesKind::Line`],
//!   [`SeriesKind::LineMarkers`]) and discrete points such as literature values
//!   ([`SeriesKind::Markers`]).
//! - Heat maps use the viridis colour scale with a colour bar; cells without a value are
//!   light grey with a diagonal hatch and get a legend entry; simulated points on top of a
//!   map are white rings with a black edge and a text label.
//! - A legend box is drawn whenever a figure has more than one labelled entry (and on heat
//!   maps whenever there are cells without value or overlay points); line plots put it in the
//!   corner of the plotting area that holds the least data.
//!
//! # Robustness
//!
//! Non-finite points (NaN, ±inf) are ignored; a line is broken where they occur. Ranges not
//! given by the caller are taken from the data with a 5 % margin; ranges of zero width are
//! widened. Lines are clipped to the plotting area. A figure without any finite data point is
//! still drawn: an empty frame with the text "no data". Tick labels are chosen by the module
//! (steps of 1, 2 or 5 times a power of ten) and printed compactly: fixed-point with as many
//! decimals as the step needs, or `1.5e-3` style when the values are below 1e-2 or above 1e5.
//!
//! # Fonts
//!
//! Text is rendered with DejaVu Sans embedded in the binary (`assets/DejaVuSans.ttf`),
//! registered once as the `sans-serif` family of plotters' `ab_glyph` text backend, so no
//! system font is needed. The SVG files name the family `sans-serif` and leave the choice of
//! glyphs to the viewer.
//!
//! # Layout of the module
//!
//! One file per kind of figure, each with its data type and its `draw…` function:
//! `line` (line/marker charts, with `reference` for the labelled horizontal lines and
//! `marker` for marker shapes and legend glyphs), `heatmap` (with `colorbar`) and
//! `particles`. The pieces they share: `output` (SVG + PNG files), `font` (the embedded
//! font), `text` (text styles, title), `style` (palette, fills, hatch), `range` (data
//! ranges), `axis` (ticks and tick labels), `clip` (the plotting box: clipping and
//! normalised positions), `frame` (margins, mesh, "no data" note) and `legend`.

mod axis;
mod clip;
mod colorbar;
mod font;
mod frame;
mod heatmap;
mod legend;
mod line;
mod marker;
mod output;
mod particles;
mod range;
mod reference;
mod style;
mod text;

#[cfg(test)]
mod tests;

pub use heatmap::{draw_heatmap, Heatmap};
pub use line::{draw, Plot, Series, SeriesKind};
pub use output::{HEIGHT, WIDTH};
pub use particles::{draw_particles, LabelledRect, ParticleView};
pub use style::PALETTE;
