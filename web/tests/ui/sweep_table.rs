//! Paper 4's γ sweep table fits the side panel: every header and every cell of its last
//! column is painted whole inside the panel (its eight columns with their ranges had run
//! past the panel's edge, and the wheel over the panel had panned the sweep's plots).

use super::*;

#[test]
fn the_gamma_sweeps_table_fits_the_side_panel() {
    let mut h = harness("p4");
    h.state_mut().apply(RunCommand::RunSweep(0).into());
    while !(h.state().state.run().sweep.as_ref()).is_some_and(|(_, s)| s.is_done()) {
        h.state_mut()
            .apply(RunCommand::AdvanceSweep(std::time::Duration::from_millis(50)).into());
    }
    h.run_steps(4);
    let sweep = &h.state().state.run().sweep.as_ref().expect("a sweep").1;
    let last_point = sweep.points.last().expect("points");
    let last_row: Vec<String> = std::iter::once(last_point.value)
        .chain(last_point.objectives.iter().copied())
        .map(attlab::model::fmt_sig)
        .collect();
    let scoring = sweep.scoring().expect("the γ sweep is scored");
    let headers: Vec<String> = (scoring
        .names
        .iter()
        .chain(scoring.objectives.iter().map(|o| &o.0)))
    .map(|s| s.to_string())
    .collect();
    // The objectives' table is the lowest of the names (the plot's legend has them too):
    // its last header brought into view.
    let last = headers.last().expect("headers").clone();
    // The objectives' table is the lowest of the names (the plot's legend has them too):
    // the wheel over the panel scrolls its last header into view.
    let header_y = |h: &Harness<'_, AttLabApp>| {
        (h.query_all_by_label(&last))
            .filter_map(|n| n.accesskit_node().bounding_box())
            .map(|r| r.y0)
            .fold(f64::MIN, f64::max)
    };
    h.hover_at(egui::pos2(150.0, 450.0));
    h.run();
    for _ in 0..60 {
        if header_y(&h) < 500.0 {
            break;
        }
        support::wheel(&mut h, -60.0);
        h.run_steps(2);
    }
    h.run_steps(3);
    let shown: Vec<String> = support::whole_texts(&h)
        .into_iter()
        .map(|(_, t)| t)
        .collect();
    let cut: Vec<&String> = headers.iter().filter(|t| !shown.contains(t)).collect();
    assert!(cut.is_empty(), "headers cut or missing: {cut:?}");
    // The objectives' last row, its value and each objective, whole.
    let cut: Vec<&String> = last_row.iter().filter(|t| !shown.contains(t)).collect();
    assert!(
        cut.is_empty(),
        "cells of the last row cut or missing: {cut:?} of {last_row:?}"
    );
}
