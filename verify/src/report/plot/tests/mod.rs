//! Tests that draw whole figures and check both files: the PNG decodes, is not blank and has
//! enough colours; the SVG holds the expected texts.

use std::path::{Path, PathBuf};

use super::output::{with_suffix, HEIGHT, WIDTH};

mod heatmap;
mod line;
mod particles;

/// A fresh directory for one test's files.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("verify-plot-test-{}-{name}", std::process::id()));
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
