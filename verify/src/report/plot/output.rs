//! Output: every figure is rendered twice from the same drawing code, into `STEM.svg` and
//! `STEM.png`, both [`WIDTH`] × [`HEIGHT`] pixels.

use std::path::{Path, PathBuf};

use anyhow::{anyhow, Context};
use plotters::coord::Shift;
use plotters::prelude::*;

use super::font::ensure_font;

/// Width in pixels of every PNG written by this module (the SVG has the same size in user units).
pub const WIDTH: u32 = 1024;
/// Height in pixels of every PNG written by this module.
pub const HEIGHT: u32 = 720;

/// A pixel position of the backend.
pub(super) type Px = (i32, i32);

/// The result of a drawing call on backend `DB`.
pub(super) type DrawResult<DB> =
    Result<(), DrawingAreaErrorKind<<DB as DrawingBackend>::ErrorType>>;

/// `stem` with `.ext` appended (not replacing any dot already in the file name).
pub(super) fn with_suffix(stem: &Path, ext: &str) -> PathBuf {
    let mut name = stem.as_os_str().to_owned();
    name.push(".");
    name.push(ext);
    PathBuf::from(name)
}

/// Renders one figure with both backends into `STEM.svg` and `STEM.png`, creating missing
/// parent directories (the renderer is passed twice because a closure cannot be generic over
/// the backend).
pub(super) fn write_both<S, B>(stem: &Path, render_svg: S, render_png: B) -> anyhow::Result<()>
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
    render_into(SVGBackend::new(&svg, (WIDTH, HEIGHT)), &svg, render_svg)?;
    let png = with_suffix(stem, "png");
    render_into(BitMapBackend::new(&png, (WIDTH, HEIGHT)), &png, render_png)
}

/// Renders on `backend` and writes the result to its file `path` (named in errors).
fn render_into<DB: DrawingBackend>(
    backend: DB,
    path: &Path,
    render: impl Fn(&DrawingArea<DB, Shift>) -> DrawResult<DB>,
) -> anyhow::Result<()> {
    let root = backend.into_drawing_area();
    render(&root).map_err(|e| anyhow!("drawing {}: {e}", path.display()))?;
    root.present()
        .map_err(|e| anyhow!("writing {}: {e}", path.display()))
}
