//! Paper 2's live accuracy table: one tab per table of the paper, each showing its filters.

use super::harness;
use egui_kittest::kittest::Queryable;

/// Clicks the tab `name`, scrolled into view first (a widget outside the panel's view takes
/// no click).
fn open_tab(h: &mut egui_kittest::Harness<'static, attlab_web::AttLabApp>, name: &str) {
    h.get_by_label(name).scroll_to_me();
    h.run();
    h.get_by_label(name).click();
    h.run();
}

/// How many widgets carry `label` (the filter chips carry the names too, so a table row
/// adds one).
fn count(h: &egui_kittest::Harness<'static, attlab_web::AttLabApp>, label: &str) -> usize {
    h.query_all_by_label(label).count()
}

#[test]
fn the_accuracy_table_has_a_tab_for_each_of_the_papers_tables() {
    let mut h = harness("p2");
    h.run();
    let table3 = "1 ST+Gyro+Mag+Sun [λ,ω]";
    let table5 = "Mag+Sun [λ,ω,d] constant gain (Table 5)";
    // Table 3 first: its filter has a row, Table 5's has none.
    let (t3_open, t5_hidden) = (count(&h, table3), count(&h, table5));
    assert_eq!(
        t3_open, 1,
        "Table 3's filter has one row (its chip reads '● …')"
    );
    open_tab(&mut h, "Table 5");
    assert_eq!(count(&h, table3), t3_open - 1, "Table 3's row left");
    assert_eq!(count(&h, table5), t5_hidden + 1, "Table 5's row came");
    open_tab(&mut h, "Table 4");
    let table4 = "ST+Gyro [λ,ω,Δω] + disturbance filter (Table 4)";
    let t4_open = count(&h, table4);
    assert_eq!(t4_open, 1, "Table 4's filter has its row");
    assert_eq!(count(&h, table5), t5_hidden, "Table 5's row left");
    open_tab(&mut h, "all filters");
    assert_eq!(
        count(&h, table4),
        t4_open,
        "Table 4's row stays in 'all filters'"
    );
    assert_eq!(count(&h, table3), t3_open);
    assert_eq!(count(&h, table5), t5_hidden + 1);
}
