//! Heat maps: cells without value, overlay points, maps without values or cells.

use super::{check_outputs, scratch};
use crate::report::plot::heatmap::OVERLAY_LEGEND;
use crate::report::plot::output::with_suffix;
use crate::report::plot::style::NONE_FILL;
use crate::report::plot::text::NO_DATA;
use crate::report::plot::{draw_heatmap, Heatmap};

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
