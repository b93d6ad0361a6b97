//! Line/marker charts: every series kind, reference lines, empty and degenerate data.

use super::{check_outputs, scratch};
use crate::report::plot::output::with_suffix;
use crate::report::plot::text::NO_DATA;
use crate::report::plot::{draw, Plot, Series, SeriesKind};

/// A series with the given label, points, kind and colour index.
fn series(label: &str, points: Vec<(f64, f64)>, kind: SeriesKind, color: usize) -> Series {
    Series {
        label: label.into(),
        points,
        kind,
        color,
    }
}

/// A plot with the test's axis labels.
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
