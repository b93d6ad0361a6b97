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

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Once;

use anyhow::{anyhow, bail, Context};
use std::ops::Range;

use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint, Ranged};
use plotters::coord::Shift;
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// Width in pixels of every PNG written by this module (the SVG has the same size in user units).
pub const WIDTH: u32 = 1024;
/// Height in pixels of every PNG written by this module.
pub const HEIGHT: u32 = 720;

/// The fixed colour palette indexed by [`Series::color`] and by particle categories:
/// Okabe & Ito's colour-blind-safe colours as `(r, g, b)`, ordered blue, vermillion,
/// bluish green, reddish purple, orange, sky blue, black, yellow.
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

/// The embedded font (DejaVu Sans, see `assets/DejaVuSans-LICENSE.txt`).
static FONT_BYTES: &[u8] = include_bytes!("../../assets/DejaVuSans.ttf");

const FAMILY: &str = "sans-serif";
const TITLE_PX: f64 = 26.0;
const DESC_PX: f64 = 20.0;
const TICK_PX: f64 = 16.0;
const LEGEND_PX: f64 = 16.0;
const NOTE_PX: f64 = 15.0;
const MARGIN: i32 = 16;
const X_LABEL_AREA: i32 = 64;
const MARKER_R: i32 = 5;
const REF_GREY: RGBColor = RGBColor(0x50, 0x50, 0x50);
const NONE_FILL: RGBColor = RGBColor(0xD9, 0xD9, 0xD9);
const NONE_HATCH: RGBColor = RGBColor(0x8C, 0x8C, 0x8C);
const HATCH_SPACING: i32 = 8;
const NO_DATA: &str = "no data";
const OVERLAY_LEGEND: &str = "simulated points";

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
    /// Index into [`PALETTE`] (taken modulo its length); it also picks the marker shape.
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

/// A scalar field on a rectilinear grid, drawn as coloured cells by [`draw_heatmap`].
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Heatmap {
    /// Caption above the map.
    pub title: String,
    /// Label of the horizontal axis, with its unit.
    pub x_label: String,
    /// Label of the vertical axis, with its unit.
    pub y_label: String,
    /// Cell centres along x (ascending); cell edges lie halfway between neighbours.
    pub x: Vec<f64>,
    /// Cell centres along y (ascending).
    pub y: Vec<f64>,
    /// Values `z[iy][ix]`; `None`, non-finite values and missing entries mean "no value" and
    /// are drawn as hatched grey cells.
    pub z: Vec<Vec<Option<f64>>>,
    /// Legend text of the cells without value (e.g. `"droplet detached"`).
    pub none_label: String,
    /// Label of the colour bar, with its unit.
    pub z_label: String,
    /// Values mapped to the ends of the colour scale; values outside are clamped.
    pub z_range: (f64, f64),
    /// Simulated points `(x, y, label)`, drawn as rings with their label beside them.
    pub overlay: Vec<(f64, f64, String)>,
}

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
    /// [`PALETTE`]. Later categories are drawn on top of earlier ones.
    pub points: Vec<(f64, f64, usize)>,
    /// Legend names of the categories.
    pub categories: Vec<String>,
    /// Rectangles `((x0, y0), (x1, y1), label)` drawn under the particles in translucent grey
    /// (e.g. a wall cross-section); equal labels share one legend entry.
    pub rects: Vec<LabelledRect>,
    /// Marker diameter in pixels (at least 1 is used).
    pub marker_px: u32,
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

/// Draws `map` with a colour bar into `STEM.svg` and `STEM.png` (1024×720 px).
///
/// The file names are formed as in [`draw`].
pub fn draw_heatmap(map: &Heatmap, stem: &Path) -> anyhow::Result<()> {
    write_both(
        stem,
        |root| render_heatmap(map, root),
        |root| render_heatmap(map, root),
    )
}

/// Draws `view` with equal x and y scales into `STEM.svg` and `STEM.png` (1024×720 px).
///
/// The file names are formed as in [`draw`].
pub fn draw_particles(view: &ParticleView, stem: &Path) -> anyhow::Result<()> {
    write_both(
        stem,
        |root| render_particles(view, root),
        |root| render_particles(view, root),
    )
}

// ---------------------------------------------------------------------------------------------
// Output
// ---------------------------------------------------------------------------------------------

/// A pixel position of the backend.
type Px = (i32, i32);

type DrawResult<DB> = Result<(), DrawingAreaErrorKind<<DB as DrawingBackend>::ErrorType>>;

/// Registers the embedded font once; fails if the font could not be parsed.
fn ensure_font() -> anyhow::Result<()> {
    static REGISTER: Once = Once::new();
    static OK: AtomicBool = AtomicBool::new(false);
    REGISTER.call_once(|| {
        let ok = plotters::style::register_font(FAMILY, FontStyle::Normal, FONT_BYTES).is_ok();
        OK.store(ok, Ordering::SeqCst);
    });
    if OK.load(Ordering::SeqCst) {
        Ok(())
    } else {
        bail!("the embedded font DejaVuSans.ttf could not be registered")
    }
}

/// `stem` with `.ext` appended (not replacing any dot already in the file name).
fn with_suffix(stem: &Path, ext: &str) -> PathBuf {
    let mut name = stem.as_os_str().to_owned();
    name.push(".");
    name.push(ext);
    PathBuf::from(name)
}

/// Renders one figure with both backends (the renderer is passed twice because a closure
/// cannot be generic over the backend).
fn write_both<S, B>(stem: &Path, render_svg: S, render_png: B) -> anyhow::Result<()>
where
    S: for<'a> Fn(&DrawingArea<SVGBackend<'a>, Shift>) -> DrawResult<SVGBackend<'a>>,
    B: for<'a> Fn(&DrawingArea<BitMapBackend<'a>, Shift>) -> DrawResult<BitMapBackend<'a>>,
{
    ensure_font()?;
    if let Some(parent) = stem.parent().filter(|p| !p.as_os_str().is_empty()) {
        std::fs::create_dir_all(parent)
            .with_context(|| format!("creating directory {}", parent.display()))?;
    }

    let svg = with_suffix(stem, "svg");
    {
        let root = SVGBackend::new(&svg, (WIDTH, HEIGHT)).into_drawing_area();
        render_svg(&root).map_err(|e| anyhow!("drawing {}: {e}", svg.display()))?;
        root.present()
            .map_err(|e| anyhow!("writing {}: {e}", svg.display()))?;
    }

    let png = with_suffix(stem, "png");
    {
        let root = BitMapBackend::new(&png, (WIDTH, HEIGHT)).into_drawing_area();
        render_png(&root).map_err(|e| anyhow!("drawing {}: {e}", png.display()))?;
        root.present()
            .map_err(|e| anyhow!("writing {}: {e}", png.display()))?;
    }
    Ok(())
}

// ---------------------------------------------------------------------------------------------
// Styles, colours and markers
// ---------------------------------------------------------------------------------------------

fn text_style(px: f64, color: RGBColor) -> TextStyle<'static> {
    TextStyle {
        font: FontDesc::new(FontFamily::Name(FAMILY), px, FontStyle::Normal),
        color: color.to_backend_color(),
        pos: Pos::new(HPos::Left, VPos::Top),
    }
}

fn anchored(style: TextStyle<'static>, h: HPos, v: VPos) -> TextStyle<'static> {
    style.pos(Pos::new(h, v))
}

/// Palette colour number `i` (modulo the palette length).
fn palette(i: usize) -> RGBColor {
    let (r, g, b) = PALETTE[i % PALETTE.len()];
    RGBColor(r, g, b)
}

/// The outline of marker shape `shape` (modulo 6) around the origin, `r` pixels in radius,
/// with its fill and edge styles. All shapes are convex polygons so that one element type
/// serves every marker: filled circle, square, triangle, diamond, downward triangle, and a
/// ring (white inside).
///
/// (plotters' `DynElement` cannot be used in `draw_series` with the SVG and bitmap backends,
/// which borrow their output path, hence one concrete element type for all shapes.)
fn marker_shape(shape: usize, color: RGBColor, r: i32) -> (Vec<Px>, ShapeStyle, ShapeStyle) {
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
fn closed(poly: &[Px]) -> Vec<Px> {
    let mut v = poly.to_vec();
    if let Some(&first) = poly.first() {
        v.push(first);
    }
    v
}

/// The parts of a legend glyph, relative to its centre: a line (solid, dashed or none) of
/// 30 pixels and a marker (or none).
struct GlyphParts {
    line: Vec<Px>,
    dash: i32,
    gap: i32,
    line_style: ShapeStyle,
    poly: Vec<Px>,
    fill: ShapeStyle,
    edge: Vec<Px>,
    edge_style: ShapeStyle,
}

fn glyph_parts(kind: SeriesKind, color: RGBColor, shape: usize) -> GlyphParts {
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

// ---------------------------------------------------------------------------------------------
// Ranges, ticks and labels
// ---------------------------------------------------------------------------------------------

/// Widens a range of (nearly) zero width around its centre.
fn widen(lo: f64, hi: f64) -> (f64, f64) {
    let (lo, hi) = if lo <= hi { (lo, hi) } else { (hi, lo) };
    let mag = lo.abs().max(hi.abs());
    if hi - lo > mag * 1e-9 && hi - lo > 0.0 {
        return (lo, hi);
    }
    let c = 0.5 * (lo + hi);
    let half = if mag > 0.0 { 0.05 * mag } else { 1.0 };
    (c - half, c + half)
}

/// A caller-given range if it is usable: both ends finite (put in order and widened).
fn given_range(r: Option<(f64, f64)>) -> Option<(f64, f64)> {
    match r {
        Some((a, b)) if a.is_finite() && b.is_finite() => Some(widen(a, b)),
        _ => None,
    }
}

/// The range of the finite values with a 5 % margin on each side, `None` if there is none.
fn auto_range(values: impl IntoIterator<Item = f64>) -> Option<(f64, f64)> {
    let (lo, hi) = finite_extent(values)?;
    let (lo, hi) = widen(lo, hi);
    let pad = 0.05 * (hi - lo);
    let (plo, phi) = (lo - pad, hi + pad);
    if plo.is_finite() && phi.is_finite() {
        Some((plo, phi))
    } else {
        Some((lo, hi))
    }
}

fn finite_extent(values: impl IntoIterator<Item = f64>) -> Option<(f64, f64)> {
    values
        .into_iter()
        .filter(|v| v.is_finite())
        .fold(None, |acc, v| match acc {
            None => Some((v, v)),
            Some((lo, hi)) => Some((lo.min(v), hi.max(v))),
        })
}

fn is_finite_point(&(x, y): &(f64, f64)) -> bool {
    x.is_finite() && y.is_finite()
}

/// One axis: its range, the labelled ticks and the minor grid positions.
#[derive(Debug, Clone)]
struct Axis {
    lo: f64,
    hi: f64,
    ticks: Vec<f64>,
    minor: Vec<f64>,
    step: f64,
    max_abs: f64,
}

impl Axis {
    /// Ticks at multiples of 1, 2 or 5 × 10ⁿ, about `target` of them over `[lo, hi]`.
    fn new((lo, hi): (f64, f64), target: usize) -> Self {
        let (lo, hi) = widen(lo, hi);
        let span = hi - lo;
        let raw = span / target.max(1) as f64;
        let mag = 10f64.powf(raw.log10().floor());
        let norm = raw / mag;
        let (nice, minor_div) = if norm <= 1.0 {
            (1.0, 5.0)
        } else if norm <= 2.0 {
            (2.0, 4.0)
        } else if norm <= 5.0 {
            (5.0, 5.0)
        } else {
            (10.0, 5.0)
        };
        let step = nice * mag;
        let ticks = multiples(lo, hi, step);
        let minor = multiples(lo, hi, step / minor_div);
        let (ticks, step) = match ticks {
            Some(t) if !t.is_empty() => (t, step),
            _ => (vec![lo, hi], span),
        };
        let minor = minor.unwrap_or_default();
        let max_abs = ticks.iter().fold(0f64, |m, t| m.max(t.abs()));
        Self {
            lo,
            hi,
            ticks,
            minor,
            step,
            max_abs,
        }
    }

    fn label(&self, v: f64) -> String {
        format_tick(v, self.step, self.max_abs)
    }

    fn mid(&self) -> f64 {
        0.5 * (self.lo + self.hi)
    }
}

/// The axis is its own coordinate: linear, with the module's ticks as bold mesh lines and
/// labels and the minor positions as light mesh lines.
impl Ranged for Axis {
    type FormatOption = DefaultFormatting;
    type ValueType = f64;

    fn map(&self, value: &f64, limit: (i32, i32)) -> i32 {
        let t = (value - self.lo) / (self.hi - self.lo);
        let p = f64::from(limit.0) + f64::from(limit.1 - limit.0) * t;
        if p.is_nan() {
            limit.0
        } else {
            // Far outside the area (only reachable for unclipped elements): keep i32 safe.
            p.clamp(-1e7, 1e7).round() as i32
        }
    }

    fn key_points<H: KeyPointHint>(&self, hint: H) -> Vec<f64> {
        if hint.weight().allow_light_points() {
            self.minor.clone()
        } else {
            self.ticks.clone()
        }
    }

    fn range(&self) -> Range<f64> {
        self.lo..self.hi
    }
}

/// The multiples of `step` within `[lo, hi]`, `None` if the step is unusable or gives too many.
fn multiples(lo: f64, hi: f64, step: f64) -> Option<Vec<f64>> {
    if !(step.is_finite() && step > 0.0) {
        return None;
    }
    let first = (lo / step - 1e-9).ceil();
    let last = (hi / step + 1e-9).floor();
    if !(first.is_finite() && last.is_finite()) || last - first > 1000.0 {
        return None;
    }
    let mut out = Vec::new();
    let mut k = first;
    while k <= last {
        let v = k * step;
        out.push(if v.abs() < step * 1e-9 { 0.0 } else { v });
        k += 1.0;
    }
    Some(out)
}

/// A compact tick label: fixed-point with the decimals the step needs, or `1.5e-3` style
/// when the largest tick magnitude is below 1e-2 or at least 1e5.
fn format_tick(v: f64, step: f64, max_abs: f64) -> String {
    if !v.is_finite() {
        return String::new();
    }
    if v == 0.0 || (step > 0.0 && v.abs() < step * 1e-6) {
        return "0".to_string();
    }
    let step_exp = if step > 0.0 && step.is_finite() {
        (step.log10() + 1e-9).floor() as i32
    } else {
        v.abs().log10().floor() as i32 - 2
    };
    if !(1e-2..1e5).contains(&max_abs) {
        let exp = (v.abs().log10() + 1e-9).floor() as i32;
        let digits = (exp - step_exp).clamp(0, 10) as usize;
        let s = format!("{v:.digits$e}");
        match s.split_once('e') {
            Some((mantissa, e)) if mantissa.contains('.') => {
                format!(
                    "{}e{e}",
                    mantissa.trim_end_matches('0').trim_end_matches('.')
                )
            }
            _ => s,
        }
    } else {
        let digits = (-step_exp).clamp(0, 10) as usize;
        format!("{v:.digits$}")
    }
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

/// Size of the label area left of the plot: tick labels, tick marks and the rotated axis title.
fn y_label_area<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, axis: &Axis) -> i32 {
    tick_label_width(area, axis) + 20 + DESC_PX as i32 + 14
}

/// Draws the title (if any) and returns the area below it.
fn titled<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    title: &str,
) -> Result<DrawingArea<DB, Shift>, DrawingAreaErrorKind<DB::ErrorType>> {
    if title.trim().is_empty() {
        Ok(root.margin(8, 0, 0, 0))
    } else {
        let area = root.margin(8, 0, 0, 0);
        area.titled(title, text_style(TITLE_PX, BLACK))
    }
}

/// Which corner of the plotting area holds the fewest of `samples` (normalised to `[0, 1]²`).
fn emptiest_corner(samples: &[(f64, f64)]) -> SeriesLabelPosition {
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

/// Normalises `p` to the box of the two axes.
fn normalised(p: (f64, f64), xa: &Axis, ya: &Axis) -> (f64, f64) {
    (
        (p.0 - xa.lo) / (xa.hi - xa.lo),
        (p.1 - ya.lo) / (ya.hi - ya.lo),
    )
}

// ---------------------------------------------------------------------------------------------
// Clipping
// ---------------------------------------------------------------------------------------------

#[derive(Debug, Clone, Copy)]
struct Bounds {
    x0: f64,
    x1: f64,
    y0: f64,
    y1: f64,
}

impl Bounds {
    fn of(xa: &Axis, ya: &Axis) -> Self {
        Self {
            x0: xa.lo,
            x1: xa.hi,
            y0: ya.lo,
            y1: ya.hi,
        }
    }

    fn contains(&self, (x, y): (f64, f64)) -> bool {
        let ex = (self.x1 - self.x0) * 1e-9;
        let ey = (self.y1 - self.y0) * 1e-9;
        x >= self.x0 - ex && x <= self.x1 + ex && y >= self.y0 - ey && y <= self.y1 + ey
    }

    /// Liang–Barsky clipping of the segment `a`–`b`; the ends that need no clipping are
    /// returned unchanged so that consecutive segments can be joined again.
    fn clip(&self, a: (f64, f64), b: (f64, f64)) -> Option<((f64, f64), (f64, f64))> {
        let (dx, dy) = (b.0 - a.0, b.1 - a.1);
        let mut t0 = 0.0f64;
        let mut t1 = 1.0f64;
        let checks = [
            (-dx, a.0 - self.x0),
            (dx, self.x1 - a.0),
            (-dy, a.1 - self.y0),
            (dy, self.y1 - a.1),
        ];
        for (p, q) in checks {
            if p == 0.0 {
                if q < 0.0 {
                    return None;
                }
            } else {
                let r = q / p;
                if p < 0.0 {
                    t0 = t0.max(r);
                } else {
                    t1 = t1.min(r);
                }
                if t0 > t1 {
                    return None;
                }
            }
        }
        let start = if t0 > 0.0 {
            (a.0 + t0 * dx, a.1 + t0 * dy)
        } else {
            a
        };
        let end = if t1 < 1.0 {
            (a.0 + t1 * dx, a.1 + t1 * dy)
        } else {
            b
        };
        Some((start, end))
    }

    /// The visible polylines of `points`: broken at non-finite points and at the box edges.
    fn polylines(&self, points: &[(f64, f64)]) -> Vec<Vec<(f64, f64)>> {
        let mut out: Vec<Vec<(f64, f64)>> = Vec::new();
        let mut current: Vec<(f64, f64)> = Vec::new();
        for pair in points.windows(2) {
            let (a, b) = (pair[0], pair[1]);
            let clipped = if is_finite_point(&a) && is_finite_point(&b) {
                self.clip(a, b)
            } else {
                None
            };
            match clipped {
                Some((s, e)) => {
                    if current.last() != Some(&s) {
                        if current.len() > 1 {
                            out.push(std::mem::take(&mut current));
                        }
                        current.clear();
                        current.push(s);
                    }
                    current.push(e);
                }
                None => {
                    if current.len() > 1 {
                        out.push(std::mem::take(&mut current));
                    }
                    current.clear();
                }
            }
        }
        if current.len() > 1 {
            out.push(current);
        }
        out
    }
}

// ---------------------------------------------------------------------------------------------
// Line plots
// ---------------------------------------------------------------------------------------------

fn render_plot<DB: DrawingBackend>(p: &Plot, root: &DrawingArea<DB, Shift>) -> DrawResult<DB> {
    root.fill(&WHITE)?;
    let area = titled(root, &p.title)?;

    let finite: Vec<(f64, f64)> = p
        .series
        .iter()
        .flat_map(|s| s.points.iter().copied())
        .filter(is_finite_point)
        .collect();
    let has_data = !finite.is_empty();

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

    let xa = Axis::new(x_range, 9);
    let ya = Axis::new(y_range, 7);
    let bounds = Bounds::of(&xa, &ya);

    let mut chart = ChartBuilder::on(&area)
        .margin(MARGIN)
        .margin_right(2 * MARGIN)
        .x_label_area_size(X_LABEL_AREA)
        .y_label_area_size(y_label_area(&area, &ya))
        .build_cartesian_2d(xa.clone(), ya.clone())?;
    draw_mesh(&mut chart, &xa, &ya, &p.x_label, &p.y_label)?;

    // Reference lines, under the data. A label goes above the right end of its line, or
    // below it, or to the left end, whichever does not overlap a label placed before.
    let mut occupancy: Vec<(f64, f64)> = Vec::new();
    let mut placed: Vec<(bool, i32, i32)> = Vec::new();
    let label_h = NOTE_PX as i32 + 2;
    for (y, label) in &p.hlines {
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

    // Lines first, then markers and legend entries, so markers stay on top.
    for s in &p.series {
        let style = palette(s.color).stroke_width(2);
        let lines = match s.kind {
            SeriesKind::Markers => Vec::new(),
            _ => bounds.polylines(&s.points),
        };
        for line in &lines {
            for w in line.windows(2) {
                let (a, b) = (normalised(w[0], &xa, &ya), normalised(w[1], &xa, &ya));
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
    }

    let labelled = p.series.iter().filter(|s| !s.label.is_empty()).count();
    for s in &p.series {
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
        occupancy.extend(visible.iter().map(|&q| normalised(q, &xa, &ya)));
        let (poly, fill, edge_style) = marker_shape(shape, color, MARKER_R);
        let edge = closed(&poly);
        let anno = chart.draw_series(visible.into_iter().map(|q| {
            EmptyElement::at(q)
                + Polygon::new(poly.clone(), fill)
                + PathElement::new(edge.clone(), edge_style)
        }))?;
        if labelled > 1 && !s.label.is_empty() {
            anno.label(s.label.clone()).legend(move |(x, y)| {
                let g = glyph_parts(kind, color, shape);
                EmptyElement::at((x + 20, y))
                    + DashedPathElement::new(g.line, g.dash, g.gap, g.line_style)
                    + Polygon::new(g.poly, g.fill)
                    + PathElement::new(g.edge, g.edge_style)
            });
        }
    }

    if labelled > 1 {
        chart
            .configure_series_labels()
            .position(emptiest_corner(&occupancy))
            .margin(10)
            .legend_area_size(44)
            .label_font(text_style(LEGEND_PX, BLACK))
            .background_style(WHITE.mix(0.88))
            .border_style(BLACK)
            .draw()?;
    }

    if !has_data {
        draw_no_data(&chart, &xa, &ya)?;
    }
    Ok(())
}

type Chart<'a, DB> = ChartContext<'a, DB, Cartesian2d<Axis, Axis>>;

fn draw_mesh<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    xa: &Axis,
    ya: &Axis,
    x_label: &str,
    y_label: &str,
) -> DrawResult<DB> {
    let fx = |v: &f64| xa.label(*v);
    let fy = |v: &f64| ya.label(*v);
    chart
        .configure_mesh()
        .x_desc(x_label)
        .y_desc(y_label)
        .x_label_formatter(&fx)
        .y_label_formatter(&fy)
        .label_style(text_style(TICK_PX, BLACK))
        .axis_desc_style(text_style(DESC_PX, BLACK))
        .bold_line_style(RGBColor(0xC8, 0xC8, 0xC8).stroke_width(1))
        .light_line_style(RGBColor(0xEE, 0xEE, 0xEE).stroke_width(1))
        .axis_style(BLACK.stroke_width(1))
        .set_all_tick_mark_size(6)
        .draw()
}

/// The "no data" note in the middle of the plotting area.
fn draw_no_data<DB: DrawingBackend>(chart: &Chart<'_, DB>, xa: &Axis, ya: &Axis) -> DrawResult<DB> {
    let style = anchored(
        text_style(28.0, RGBColor(0x70, 0x70, 0x70)),
        HPos::Center,
        VPos::Center,
    );
    chart
        .plotting_area()
        .draw(&Text::new(NO_DATA, (xa.mid(), ya.mid()), style))
}

// ---------------------------------------------------------------------------------------------
// Heat maps
// ---------------------------------------------------------------------------------------------

/// Cell edges from cell centres: halfway between neighbours, the outer edges mirrored.
fn cell_edges(centres: &[f64]) -> Vec<f64> {
    match centres.len() {
        0 => Vec::new(),
        1 => {
            let (lo, hi) = widen(centres[0], centres[0]);
            let half = 0.5 * (hi - lo);
            vec![centres[0] - half, centres[0] + half]
        }
        n => {
            let mut e = Vec::with_capacity(n + 1);
            e.push(centres[0] - 0.5 * (centres[1] - centres[0]));
            e.extend(centres.windows(2).map(|w| 0.5 * (w[0] + w[1])));
            e.push(centres[n - 1] + 0.5 * (centres[n - 1] - centres[n - 2]));
            e
        }
    }
}

/// The `(lo, hi)` interval of cell `i`, if both edges are finite and distinct.
fn cell_span(edges: &[f64], i: usize) -> Option<(f64, f64)> {
    let (a, b) = (*edges.get(i)?, *edges.get(i + 1)?);
    (a.is_finite() && b.is_finite() && a != b).then(|| (a.min(b), a.max(b)))
}

/// Draws 45° hatch lines, aligned on a global pixel grid, inside the pixel rectangle.
fn hatch<DB: DrawingBackend>(
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

/// A legend entry drawn by hand (outside the plotting area).
enum Swatch {
    Hatched,
    Ring,
    Box,
    Dot(RGBColor),
}

fn draw_swatch<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    swatch: &Swatch,
    (x, y): Px,
) -> DrawResult<DB> {
    match swatch {
        Swatch::Hatched => {
            root.draw(&Rectangle::new(
                [(x, y - 9), (x + 26, y + 9)],
                NONE_FILL.filled(),
            ))?;
            hatch(root, (x, y - 9), (x + 26, y + 9))?;
            root.draw(&Rectangle::new([(x, y - 9), (x + 26, y + 9)], NONE_HATCH))
        }
        Swatch::Ring => draw_ring(root, (x + 13, y)),
        Swatch::Box => {
            root.draw(&Rectangle::new(
                [(x, y - 9), (x + 26, y + 9)],
                RGBColor(0x9A, 0x9A, 0x9A).mix(0.55).filled(),
            ))?;
            root.draw(&Rectangle::new([(x, y - 9), (x + 26, y + 9)], REF_GREY))
        }
        Swatch::Dot(color) => root.draw(&Circle::new((x + 13, y), 6, color.filled())),
    }
}

fn draw_ring<DB: DrawingBackend>(root: &DrawingArea<DB, Shift>, at: Px) -> DrawResult<DB> {
    root.draw(&Circle::new(at, 7, WHITE.filled()))?;
    root.draw(&Circle::new(at, 7, BLACK.stroke_width(2)))
}

/// Draws legend entries in one row, centred in `area` (a part of `root`).
fn legend_row<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    area: &DrawingArea<DB, Shift>,
    entries: &[(Swatch, String)],
) -> DrawResult<DB> {
    const SWATCH_W: i32 = 26;
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

/// One heat-map cell: x interval, y interval, value.
type Cell = ((f64, f64), (f64, f64), Option<f64>);

fn render_heatmap<DB: DrawingBackend>(
    m: &Heatmap,
    root: &DrawingArea<DB, Shift>,
) -> DrawResult<DB> {
    root.fill(&WHITE)?;
    let area = titled(root, &m.title)?;

    let xe = cell_edges(&m.x);
    let ye = cell_edges(&m.y);
    let value = |ix: usize, iy: usize| -> Option<f64> {
        m.z.get(iy)
            .and_then(|row| row.get(ix))
            .copied()
            .flatten()
            .filter(|v| v.is_finite())
    };
    let cells: Vec<Cell> = (0..m.y.len())
        .flat_map(|iy| (0..m.x.len()).map(move |ix| (ix, iy)))
        .filter_map(|(ix, iy)| Some((cell_span(&xe, ix)?, cell_span(&ye, iy)?, value(ix, iy))))
        .collect();
    let overlay: Vec<&(f64, f64, String)> = m
        .overlay
        .iter()
        .filter(|o| o.0.is_finite() && o.1.is_finite())
        .collect();
    let any_value = cells.iter().any(|c| c.2.is_some());
    let any_none = cells.iter().any(|c| c.2.is_none());

    let x_range = finite_extent(
        cells
            .iter()
            .flat_map(|c| [c.0 .0, c.0 .1])
            .chain(overlay.iter().map(|o| o.0)),
    )
    .map(|(a, b)| widen(a, b))
    .unwrap_or((0.0, 1.0));
    let y_range = finite_extent(
        cells
            .iter()
            .flat_map(|c| [c.1 .0, c.1 .1])
            .chain(overlay.iter().map(|o| o.1)),
    )
    .map(|(a, b)| widen(a, b))
    .unwrap_or((0.0, 1.0));
    // Overlay points on the border get some room.
    let pad = |(lo, hi): (f64, f64), vals: &mut dyn Iterator<Item = f64>| {
        let margin = 0.03 * (hi - lo);
        let (mut a, mut b) = (lo, hi);
        for v in vals {
            if v - margin < a {
                a = v - margin;
            }
            if v + margin > b {
                b = v + margin;
            }
        }
        (a, b)
    };
    let x_range = pad(x_range, &mut overlay.iter().map(|o| o.0));
    let y_range = pad(y_range, &mut overlay.iter().map(|o| o.1));

    let z_range = if m.z_range.0.is_finite() && m.z_range.1.is_finite() {
        widen(m.z_range.0, m.z_range.1)
    } else {
        finite_extent(cells.iter().filter_map(|c| c.2))
            .map(|(a, b)| widen(a, b))
            .unwrap_or((0.0, 1.0))
    };

    let mut entries: Vec<(Swatch, String)> = Vec::new();
    if any_none {
        let label = if m.none_label.is_empty() {
            "no value".to_string()
        } else {
            m.none_label.clone()
        };
        entries.push((Swatch::Hatched, label));
    }
    if !overlay.is_empty() {
        entries.push((Swatch::Ring, OVERLAY_LEGEND.to_string()));
    }
    let (area, legend_area) = if entries.is_empty() {
        (area, None)
    } else {
        let h = area.dim_in_pixel().1 as i32;
        let (a, b) = area.split_vertically(h - 40);
        (a, Some(b))
    };

    let xa = Axis::new(x_range, 9);
    let ya = Axis::new(y_range, 7);
    let za = Axis::new(z_range, 7);

    let bar_labels = tick_label_width(&area, &za) + 20 + DESC_PX as i32 + 14;
    let bar_w = 28;
    let strip = bar_w + bar_labels + 2 * MARGIN;
    let aw = area.dim_in_pixel().0 as i32;
    let (main, bar) = area.split_horizontally(aw - strip);

    let mut chart = ChartBuilder::on(&main)
        .margin(MARGIN)
        .x_label_area_size(X_LABEL_AREA)
        .y_label_area_size(y_label_area(&main, &ya))
        .build_cartesian_2d(xa.clone(), ya.clone())?;
    draw_mesh(&mut chart, &xa, &ya, &m.x_label, &m.y_label)?;

    let cmap = ViridisRGB;
    let colored = cells.iter().filter_map(|&((x0, x1), (y0, y1), v)| {
        let v = v?;
        let c: RGBColor =
            cmap.get_color_normalized(v.clamp(z_range.0, z_range.1), z_range.0, z_range.1);
        Some(Rectangle::new([(x0, y0), (x1, y1)], c.filled()))
    });
    chart.draw_series(colored)?;
    for &((x0, x1), (y0, y1), v) in &cells {
        if v.is_none() {
            chart.draw_series(std::iter::once(Rectangle::new(
                [(x0, y0), (x1, y1)],
                NONE_FILL.filled(),
            )))?;
            let a = chart.backend_coord(&(x0, y1));
            let b = chart.backend_coord(&(x1, y0));
            hatch(root, a, b)?;
        }
    }
    // Frame again on top of the cells.
    chart.draw_series(std::iter::once(Rectangle::new(
        [(xa.lo, ya.lo), (xa.hi, ya.hi)],
        BLACK.stroke_width(1),
    )))?;

    for (x, y, label) in &overlay {
        let at = chart.backend_coord(&(*x, *y));
        draw_ring(root, at)?;
        if !label.is_empty() {
            let style = anchored(text_style(NOTE_PX, BLACK), HPos::Left, VPos::Center);
            let (w, h) = root.estimate_text_size(label, &style)?;
            let (w, h) = (w as i32, h as i32);
            let x0 = at.0 + 11;
            root.draw(&Rectangle::new(
                [(x0, at.1 - h / 2 - 3), (x0 + w + 8, at.1 + h / 2 + 3)],
                WHITE.mix(0.8).filled(),
            ))?;
            root.draw(&Text::new(label.clone(), (x0 + 4, at.1), style))?;
        }
    }

    if !any_value {
        let style = anchored(
            text_style(28.0, RGBColor(0x50, 0x50, 0x50)),
            HPos::Center,
            VPos::Center,
        );
        let c = chart.backend_coord(&(xa.mid(), ya.mid()));
        let (w, h) = root.estimate_text_size(NO_DATA, &style)?;
        let (w, h) = (w as i32, h as i32);
        root.draw(&Rectangle::new(
            [
                (c.0 - w / 2 - 10, c.1 - h / 2 - 8),
                (c.0 + w / 2 + 10, c.1 + h / 2 + 8),
            ],
            WHITE.filled(),
        ))?;
        root.draw(&Text::new(NO_DATA, c, style))?;
    }

    // Colour bar, aligned with the plotting area of the map.
    let mut bar_chart = ChartBuilder::on(&bar)
        .margin(MARGIN)
        .x_label_area_size(X_LABEL_AREA)
        .right_y_label_area_size(bar_labels)
        .build_cartesian_2d(0.0..1.0, za.clone())?;
    let steps = 128;
    let dz = (za.hi - za.lo) / f64::from(steps);
    bar_chart.draw_series((0..steps).map(|i| {
        let z0 = za.lo + f64::from(i) * dz;
        let c: RGBColor = cmap.get_color_normalized(z0 + 0.5 * dz, za.lo, za.hi);
        Rectangle::new([(0.0, z0), (1.0, z0 + dz)], c.filled())
    }))?;
    bar_chart.draw_series(std::iter::once(Rectangle::new(
        [(0.0, za.lo), (1.0, za.hi)],
        BLACK.stroke_width(1),
    )))?;
    // The axis and its ticks after the bar, so that the bar does not cover them.
    let fz = |v: &f64| za.label(*v);
    bar_chart
        .configure_mesh()
        .disable_mesh()
        .disable_x_axis()
        .x_labels(0)
        .y_desc(m.z_label.as_str())
        .y_label_formatter(&fz)
        .label_style(text_style(TICK_PX, BLACK))
        .axis_desc_style(text_style(DESC_PX, BLACK))
        .axis_style(BLACK.stroke_width(1))
        .set_all_tick_mark_size(6)
        .draw()?;

    if let Some(legend) = legend_area {
        legend_row(root, &legend, &entries)?;
    }
    Ok(())
}

// ---------------------------------------------------------------------------------------------
// Particle views
// ---------------------------------------------------------------------------------------------

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

fn render_particles<DB: DrawingBackend>(
    v: &ParticleView,
    root: &DrawingArea<DB, Shift>,
) -> DrawResult<DB> {
    root.fill(&WHITE)?;
    let area = titled(root, &v.title)?;

    let points: Vec<(f64, f64, usize)> = v
        .points
        .iter()
        .copied()
        .filter(|p| p.0.is_finite() && p.1.is_finite())
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
    let xs = points
        .iter()
        .map(|p| p.0)
        .chain(rects.iter().flat_map(|r| [r.0 .0, r.1 .0]));
    let ys = points
        .iter()
        .map(|p| p.1)
        .chain(rects.iter().flat_map(|r| [r.0 .1, r.1 .1]));
    let x_range = auto_range(xs).unwrap_or((0.0, 1.0));
    let y_range = auto_range(ys).unwrap_or((0.0, 1.0));

    // The label area is sized from the unexpanded range; equal scales only add room.
    let provisional = Axis::new(y_range, 7);
    let mut builder = ChartBuilder::on(&area);
    builder
        .margin(MARGIN)
        .margin_right(2 * MARGIN)
        .x_label_area_size(X_LABEL_AREA)
        .y_label_area_size(y_label_area(&area, &provisional) + 8);
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

    let mut entries: Vec<(Swatch, String)> = Vec::new();
    for r in &rects {
        let ((x0, y0), (x1, y1), _) = **r;
        chart.draw_series(std::iter::once(Rectangle::new(
            [(x0, y0), (x1, y1)],
            RGBColor(0x9A, 0x9A, 0x9A).mix(0.55).filled(),
        )))?;
        chart.draw_series(std::iter::once(Rectangle::new(
            [(x0, y0), (x1, y1)],
            REF_GREY.stroke_width(1),
        )))?;
    }
    let mut rect_labels: Vec<&str> = Vec::new();
    for r in &rects {
        if !r.2.is_empty() && !rect_labels.contains(&r.2.as_str()) {
            rect_labels.push(r.2.as_str());
        }
    }

    let radius = (v.marker_px.max(1) as f64 / 2.0).round().max(1.0) as i32;
    // Every named category (for a stable legend) and every category that occurs.
    let cats: std::collections::BTreeSet<usize> = (0..v.categories.len())
        .chain(points.iter().map(|p| p.2))
        .collect();
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
    for label in rect_labels {
        entries.push((Swatch::Box, label.to_string()));
    }

    if entries.len() > 1 {
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
                            + Rectangle::new(
                                [(0, -8), (26, 8)],
                                RGBColor(0x9A, 0x9A, 0x9A).mix(0.55).filled(),
                            )
                            + Rectangle::new([(0, -8), (26, 8)], REF_GREY)
                    });
                }
            }
        }
        let occupancy: Vec<(f64, f64)> = points
            .iter()
            .map(|p| normalised((p.0, p.1), &xa, &ya))
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
                    .map(|q| normalised(q, &xa, &ya)),
            )
            .collect();
        chart
            .configure_series_labels()
            .position(emptiest_corner(&occupancy))
            .margin(10)
            .legend_area_size(36)
            .label_font(text_style(LEGEND_PX, BLACK))
            .background_style(WHITE.mix(0.88))
            .border_style(BLACK)
            .draw()?;
    }

    if points.is_empty() {
        draw_no_data(&chart, &xa, &ya)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A fresh directory for one test's files.
    fn scratch(name: &str) -> PathBuf {
        let dir =
            std::env::temp_dir().join(format!("verify-plot-test-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    /// Checks both files of `stem`: the PNG decodes to 1024×720 and is not one flat colour,
    /// the SVG contains every string of `texts`.
    fn check_outputs(stem: &Path, texts: &[&str]) {
        let png = with_suffix(stem, "png");
        let img = image::open(&png)
            .unwrap_or_else(|e| panic!("{} does not decode: {e}", png.display()))
            .to_rgb8();
        assert_eq!(img.dimensions(), (WIDTH, HEIGHT));
        let first = *img.get_pixel(0, 0);
        let differing = img.pixels().filter(|p| **p != first).count();
        assert!(
            differing > 2000,
            "{}: only {differing} pixels differ from the background",
            png.display()
        );
        let distinct: std::collections::HashSet<[u8; 3]> = img.pixels().map(|p| p.0).collect();
        assert!(distinct.len() > 8, "{}: too few colours", png.display());

        let svg_path = with_suffix(stem, "svg");
        let svg = std::fs::read_to_string(&svg_path).unwrap();
        assert!(
            svg.starts_with("<svg"),
            "{} is not an SVG",
            svg_path.display()
        );
        for t in texts {
            assert!(svg.contains(t), "{} lacks {t:?}", svg_path.display());
        }
    }

    fn series(label: &str, points: Vec<(f64, f64)>, kind: SeriesKind, color: usize) -> Series {
        Series {
            label: label.into(),
            points,
            kind,
            color,
        }
    }

    fn labelled_plot(title: &str, series: Vec<Series>) -> Plot {
        Plot {
            title: title.into(),
            x_label: "c² [m²/s²]".into(),
            y_label: "T [s]".into(),
            series,
            ..Plot::default()
        }
    }

    #[test]
    fn line_plot_with_theory_literature_and_reference_lines() {
        let dir = scratch("lines");
        let theory: Vec<(f64, f64)> = (0..=40)
            .map(|i| {
                let c2 = 50.0 + 12.5 * f64::from(i);
                (c2, 1.2e-3 * (1.0 + 30.0 / c2))
            })
            .collect();
        let sim = vec![(100.0, 1.58e-3), (200.0, 1.40e-3), (400.0, 1.29e-3)];
        let lit = vec![(150.0, 1.47e-3), (300.0, 1.33e-3)];
        let mut plot = labelled_plot(
            "Period vs sound speed",
            vec![
                series("theory", theory, SeriesKind::Dashed, 6),
                series("simulation", sim, SeriesKind::LineMarkers, 0),
                series("literature", lit, SeriesKind::Markers, 1),
                series(
                    "",
                    vec![(100.0, 1.5e-3), (500.0, 1.5e-3)],
                    SeriesKind::Line,
                    2,
                ),
            ],
        );
        plot.hlines = vec![(1.2e-3, "Rayleigh".into())];
        let stem = dir.join("period");
        draw(&plot, &stem).unwrap();
        check_outputs(
            &stem,
            &[
                "Period vs sound speed",
                "c² [m²/s²]",
                "T [s]",
                "theory",
                "simulation",
                "literature",
                "Rayleigh",
                "1.2e-3",
            ],
        );
        let _ = std::fs::remove_dir_all(dir);
    }

    #[test]
    fn empty_plots_show_no_data() {
        let dir = scratch("empty");
        let cases = [
            labelled_plot("No series", vec![]),
            labelled_plot(
                "Empty series",
                vec![
                    series("a", vec![], SeriesKind::Line, 0),
                    series("b", vec![], SeriesKind::Markers, 1),
                ],
            ),
        ];
        for (i, plot) in cases.iter().enumerate() {
            let stem = dir.join(format!("empty{i}"));
            draw(plot, &stem).unwrap();
            check_outputs(&stem, &[&plot.title, "c² [m²/s²]", "T [s]", NO_DATA]);
        }
        let _ = std::fs::remove_dir_all(dir);
    }

    #[test]
    fn nan_and_infinite_points_are_ignored() {
        let dir = scratch("nan");
        let all_nan = labelled_plot(
            "All NaN",
            vec![series(
                "nan",
                vec![(f64::NAN, 1.0), (2.0, f64::NAN), (f64::INFINITY, 3.0)],
                SeriesKind::LineMarkers,
                0,
            )],
        );
        let stem = dir.join("all_nan");
        draw(&all_nan, &stem).unwrap();
        check_outputs(&stem, &["All NaN", "c² [m²/s²]", "T [s]", NO_DATA]);

        let mixed = labelled_plot(
            "Some gaps",
            vec![series(
                "g1g2",
                vec![
                    (0.0, 0.0),
                    (1.0, 1.0),
                    (2.0, f64::NAN),
                    (3.0, 0.5),
                    (4.0, -0.5),
                ],
                SeriesKind::Line,
                0,
            )],
        );
        let stem = dir.join("mixed");
        draw(&mixed, &stem).unwrap();
        check_outputs(&stem, &["Some gaps", "c² [m²/s²]", "T [s]"]);
        let svg = std::fs::read_to_string(with_suffix(&stem, "svg")).unwrap();
        assert!(!svg.contains(NO_DATA));
        assert!(!svg.contains("NaN"));
        let _ = std::fs::remove_dir_all(dir);
    }

    #[test]
    fn single_point_and_degenerate_ranges_are_widened() {
        let dir = scratch("single");
        let cases = [
            ("Single point", vec![(2.0e-3, 5.0)]),
            ("Equal x", vec![(1.0, 1.0), (1.0, 2.0), (1.0, 3.0)]),
            ("All zero", vec![(0.0, 0.0), (0.0, 0.0)]),
        ];
        for (i, (title, points)) in cases.into_iter().enumerate() {
            let plot = labelled_plot(title, vec![series("p", points, SeriesKind::Markers, 3)]);
            let stem = dir.join(format!("single{i}"));
            draw(&plot, &stem).unwrap();
            check_outputs(&stem, &[title, "c² [m²/s²]", "T [s]"]);
        }
        // A caller range of zero width, reversed ranges, and a NaN range.
        let mut plot = labelled_plot(
            "Given ranges",
            vec![series(
                "p",
                vec![(0.0, 0.0), (10.0, 10.0)],
                SeriesKind::Line,
                0,
            )],
        );
        plot.x_range = Some((5.0, 5.0));
        plot.y_range = Some((8.0, 2.0));
        let stem = dir.join("given");
        draw(&plot, &stem).unwrap();
        check_outputs(&stem, &["Given ranges"]);
        plot.x_range = Some((f64::NAN, 1.0));
        draw(&plot, &stem).unwrap();
        check_outputs(&stem, &["Given ranges"]);
        let _ = std::fs::remove_dir_all(dir);
    }

    #[test]
    fn file_names_keep_dots_and_parents_are_created() {
        let dir = scratch("names");
        let stem = dir.join("sub").join("c_10.5");
        let plot = labelled_plot(
            "Dots",
            vec![series(
                "p",
                vec![(0.0, 1.0), (1.0, 2.0)],
                SeriesKind::Line,
                0,
            )],
        );
        draw(&plot, &stem).unwrap();
        assert!(dir.join("sub").join("c_10.5.svg").is_file());
        assert!(dir.join("sub").join("c_10.5.png").is_file());
        let _ = std::fs::remove_dir_all(dir);
    }

    fn contact_angle_map() -> Heatmap {
        let x = vec![60.0, 90.0, 120.0, 150.0];
        let y = vec![0.5, 1.0, 1.5];
        let z = vec![
            vec![Some(62.0), Some(88.0), Some(118.0), None],
            vec![Some(61.0), Some(91.0), None, None],
            // Short row: the missing cells count as "no value".
            vec![Some(f64::NAN), Some(93.0)],
        ];
        Heatmap {
            title: "Contact angle map".into(),
            x_label: "θ_in [deg]".into(),
            y_label: "H [mm]".into(),
            x,
            y,
            z,
            none_label: "detached".into(),
            z_label: "θ [deg]".into(),
            z_range: (0.0, 180.0),
            overlay: vec![(90.0, 1.0, "run A".into()), (f64::NAN, 1.0, "bad".into())],
        }
    }

    #[test]
    fn heatmap_with_missing_cells_and_overlay() {
        let dir = scratch("heat");
        let stem = dir.join("angles");
        let map = contact_angle_map();
        draw_heatmap(&map, &stem).unwrap();
        check_outputs(
            &stem,
            &[
                "Contact angle map",
                "θ_in [deg]",
                "H [mm]",
                "θ [deg]",
                "detached",
                "run A",
                OVERLAY_LEGEND,
            ],
        );
        let svg = std::fs::read_to_string(with_suffix(&stem, "svg")).unwrap();
        assert!(!svg.contains(NO_DATA));
        // The hatch colour appears in the PNG.
        let img = image::open(with_suffix(&stem, "png")).unwrap().to_rgb8();
        assert!(img
            .pixels()
            .any(|p| p.0 == [NONE_FILL.0, NONE_FILL.1, NONE_FILL.2]));
        let _ = std::fs::remove_dir_all(dir);
    }

    #[test]
    fn heatmap_without_values_or_cells() {
        let dir = scratch("heat_empty");
        let mut map = contact_angle_map();
        map.z = vec![vec![None; 4]; 3];
        map.z_range = (f64::NAN, f64::NAN);
        let stem = dir.join("all_none");
        draw_heatmap(&map, &stem).unwrap();
        check_outputs(&stem, &["Contact angle map", "detached", NO_DATA]);

        let empty = Heatmap {
            title: "Empty map".into(),
            x_label: "x [m]".into(),
            y_label: "y [m]".into(),
            z_label: "z [-]".into(),
            z_range: (1.0, 1.0),
            ..Heatmap::default()
        };
        let stem = dir.join("empty");
        draw_heatmap(&empty, &stem).unwrap();
        check_outputs(&stem, &["Empty map", "x [m]", "y [m]", "z [-]", NO_DATA]);

        let single = Heatmap {
            title: "One cell".into(),
            x: vec![3.0],
            y: vec![0.0],
            z: vec![vec![Some(0.5)]],
            z_range: (0.0, 1.0),
            ..Heatmap::default()
        };
        let stem = dir.join("single");
        draw_heatmap(&single, &stem).unwrap();
        check_outputs(&stem, &["One cell"]);
        let _ = std::fs::remove_dir_all(dir);
    }

    #[test]
    fn particle_view_with_wall() {
        let dir = scratch("particles");
        let dx = 1.0e-4;
        let mut points = Vec::new();
        for i in -20..=20 {
            for j in 0..=12 {
                let (x, y) = (f64::from(i) * dx, f64::from(j) * dx + 0.5 * dx);
                if x * x + y * y < (1.2e-3f64).powi(2) {
                    points.push((x, y, 0));
                }
            }
            points.push((f64::from(i) * dx, -0.5 * dx, 1));
        }
        points.push((f64::NAN, 0.0, 0));
        let view = ParticleView {
            title: "Side view t = 1 ms".into(),
            x_label: "x [m]".into(),
            y_label: "z [m]".into(),
            points,
            categories: vec!["fluid".into(), "wall".into()],
            rects: vec![((-2.0e-3, -1.0e-4), (2.0e-3, 0.0), "wall section".into())],
            marker_px: 6,
        };
        let stem = dir.join("side");
        draw_particles(&view, &stem).unwrap();
        check_outputs(
            &stem,
            &[
                "Side view t = 1 ms",
                "x [m]",
                "z [m]",
                "fluid",
                "wall section",
            ],
        );
        let _ = std::fs::remove_dir_all(dir);
    }

    #[test]
    fn particle_view_empty_and_single() {
        let dir = scratch("particles_empty");
        let empty = ParticleView {
            title: "No particles".into(),
            x_label: "x [m]".into(),
            y_label: "z [m]".into(),
            ..ParticleView::default()
        };
        let stem = dir.join("empty");
        draw_particles(&empty, &stem).unwrap();
        check_outputs(&stem, &["No particles", "x [m]", "z [m]", NO_DATA]);

        let single = ParticleView {
            title: "One particle".into(),
            points: vec![(1.0, 1.0, 7), (1.0, 1.0, usize::MAX)],
            marker_px: 0,
            ..ParticleView::default()
        };
        let stem = dir.join("single");
        draw_particles(&single, &stem).unwrap();
        check_outputs(&stem, &["One particle"]);
        let _ = std::fs::remove_dir_all(dir);
    }

    #[test]
    fn equal_aspect_gives_equal_scales() {
        let (xr, yr) = equal_aspect((0.0, 4.0), (0.0, 1.0), (800, 400));
        assert!(((xr.1 - xr.0) / 800.0 - (yr.1 - yr.0) / 400.0).abs() < 1e-12);
        assert_eq!(xr, (0.0, 4.0));
        assert!((yr.0 + 0.5).abs() < 1e-12 && (yr.1 - 1.5).abs() < 1e-12);
    }

    #[test]
    fn tick_labels_are_compact() {
        let a = Axis::new((0.0, 1.0e-3), 5);
        let labels: Vec<String> = a.ticks.iter().map(|&t| a.label(t)).collect();
        assert_eq!(labels, ["0", "2e-4", "4e-4", "6e-4", "8e-4", "1e-3"]);
        let a = Axis::new((1.0e-3, 2.0e-3), 4);
        assert_eq!(a.label(1.5e-3), "1.5e-3");
        let a = Axis::new((0.0, 1.0), 5);
        assert_eq!(a.label(0.4), "0.4");
        assert_eq!(a.label(1.0), "1.0");
        let a = Axis::new((0.0, 500.0), 5);
        assert_eq!(a.label(300.0), "300");
        let a = Axis::new((0.0, 3.0e6), 3);
        assert_eq!(a.label(2.0e6), "2e6");
        assert_eq!(format_tick(-0.0, 0.1, 1.0), "0");
        assert_eq!(format_tick(f64::NAN, 0.1, 1.0), "");
    }

    #[test]
    fn ranges_and_ticks_survive_degenerate_input() {
        assert_eq!(widen(2.0, 2.0), (1.9, 2.1));
        assert_eq!(widen(0.0, 0.0), (-1.0, 1.0));
        assert_eq!(widen(3.0, 1.0), (1.0, 3.0));
        assert_eq!(auto_range([f64::NAN, f64::INFINITY]), None);
        let (lo, hi) = auto_range([0.0, 10.0, f64::NAN]).unwrap();
        assert!((lo + 0.5).abs() < 1e-12 && (hi - 10.5).abs() < 1e-12);
        assert_eq!(given_range(Some((f64::NAN, 1.0))), None);
        for (lo, hi) in [
            (0.0, 1e-300),
            (1.0, 1.0 + 1e-15),
            (-1e300, 1e300),
            (5.0, 5.0),
        ] {
            let a = Axis::new((lo, hi), 7);
            assert!(!a.ticks.is_empty() && a.ticks.len() < 1000);
            assert!(a.lo < a.hi);
        }
    }

    #[test]
    fn lines_are_clipped_to_the_range() {
        let b = Bounds {
            x0: 0.0,
            x1: 1.0,
            y0: 0.0,
            y1: 1.0,
        };
        let lines = b.polylines(&[
            (-1.0, 0.5),
            (0.5, 0.5),
            (0.5, 2.0),
            (f64::NAN, 0.0),
            (0.2, 0.2),
            (0.3, 0.3),
        ]);
        assert_eq!(lines.len(), 2);
        assert_eq!(lines[0], vec![(0.0, 0.5), (0.5, 0.5), (0.5, 1.0)]);
        assert_eq!(lines[1], vec![(0.2, 0.2), (0.3, 0.3)]);
        assert!(b.polylines(&[(2.0, 2.0), (3.0, 3.0)]).is_empty());
    }

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
