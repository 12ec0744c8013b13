//! The plots' axes: round marks with labels on the time axis as on the value axis.

use super::legend::{PRESENTER_ZOOM, window};
use attlab::labs;
use attlab::model::ParamValues;
use egui::epaint::Shape;
use std::collections::BTreeMap;

/// Paper 1 after 600 s (its lesson's run) on a projector (presenter mode): the time axis
/// is labelled at 0, 200, 400 and 600 s. egui_plot's own marks are powers of ten, and it
/// had labelled only "0" there.
#[test]
fn the_time_axis_of_a_long_run_is_labelled_at_round_marks() {
    let lab = labs::find("p1").expect("registered");
    let dt_s = lab.dt_s(&ParamValues::defaults(lab.params()));
    let steps = (600.0 / dt_s).round() as usize;
    let h = window(
        "lab=p1&presenter=1",
        steps,
        (egui::vec2(1280.0, 720.0), PRESENTER_ZOOM),
    );
    // The numbers painted, row by row (a row: one height on the page, to a point).
    let mut rows: BTreeMap<i32, Vec<f64>> = BTreeMap::new();
    for c in &h.output().shapes {
        if let Shape::Text(t) = &c.shape
            && let Ok(v) = t.galley.text().parse::<f64>()
        {
            let y = t.visual_bounding_rect().center().y.round() as i32;
            rows.entry(y).or_default().push(v);
        }
    }
    let marks = [0.0, 200.0, 400.0, 600.0];
    assert!(
        rows.values()
            .any(|row| marks.iter().all(|m| row.contains(m))),
        "no row of numbers holds {marks:?}: {rows:?}"
    );
}

/// Paper 1's lesson step 2 on a projector, where the plot is short under the tiles and the
/// tabs: the y axis' title ("log10 mixed units (see the legend)" did) must not run over the
/// tabs above the plot or any other text; in both languages.
#[test]
fn the_y_axis_title_stays_beside_its_plot() {
    for lang in ["en", "ru"] {
        let fragment = format!("lesson=p1&step=2&presenter=1&lang={lang}");
        let h = window(&fragment, 20, (egui::vec2(1280.0, 720.0), PRESENTER_ZOOM));
        let texts: Vec<_> = (h.output().shapes.iter())
            .filter_map(|c| match &c.shape {
                Shape::Text(t) => Some(t),
                _ => None,
            })
            .collect();
        let title = (texts.iter())
            .find(|t| t.angle != 0.0 && t.galley.text().starts_with("log10"))
            .unwrap_or_else(|| panic!("{fragment}: no y axis title"));
        let over: Vec<&str> = (texts.iter())
            .filter(|t| t.angle == 0.0)
            .filter(|t| {
                t.visual_bounding_rect()
                    .intersects(title.visual_bounding_rect())
            })
            .map(|t| t.galley.text())
            .collect();
        assert!(
            over.is_empty(),
            "{fragment}: “{}” runs over {over:?}",
            title.galley.text()
        );
    }
}
