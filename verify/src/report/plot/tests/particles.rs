//! Particle views: categories with a wall section, no particles, one particle.

use super::{check_outputs, scratch};
use crate::report::plot::text::NO_DATA;
use crate::report::plot::{draw_particles, ParticleView};

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
