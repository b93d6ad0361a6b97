//! The embedded font: DejaVu Sans, registered once as the `sans-serif` family of plotters'
//! `ab_glyph` text backend, so that no system font is needed.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Once;

use anyhow::bail;
use plotters::style::FontStyle;

/// The embedded font (DejaVu Sans, see `assets/DejaVuSans-LICENSE.txt`).
static FONT_BYTES: &[u8] = include_bytes!("../../../assets/DejaVuSans.ttf");

/// The family name every text style of the module uses (and the SVG files name).
pub(super) const FAMILY: &str = "sans-serif";

/// Registers the embedded font once; fails if the font could not be parsed.
pub(super) fn ensure_font() -> anyhow::Result<()> {
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
