//! The keyboard alone: Tab reaches a slider, its keys move it by the slider pattern's steps
//! (a twentieth, a hundredth with Shift, a tenth by page, the ends), the shortcuts wait while
//! a control has the keyboard, ? opens the dialog that lists every key, and the shortcuts
//! themselves (space, s, arrows, f) pause, step, switch tabs and focus one view.

use super::*;
use egui::{Key, Modifiers};

/// Presses Tab until the slider labelled `label` has the keyboard (at most `limit` times).
fn tab_to(h: &mut Harness<'static, AttLabApp>, label: &str, limit: usize) -> usize {
    for presses in 1..=limit {
        h.key_press(Key::Tab);
        h.run();
        if h.get_by_role_and_label(Role::Slider, label).is_focused() {
            return presses;
        }
    }
    panic!("Tab did not reach the slider `{label}` in {limit} presses");
}

#[test]
fn tab_reaches_a_slider_and_its_keys_move_it_along_the_rail() {
    let mut h = harness("free-rotation");
    h.run();
    let key = "gyro_noise_deg_s";
    let spec = h
        .state()
        .state
        .sim()
        .lab()
        .params()
        .iter()
        .find(|s| s.key == key)
        .copied();
    let spec = spec.expect("the lab has a gyro noise slider");
    let before = h.state().state.sim().params().get(key);
    tab_to(&mut h, "Gyro noise σ", 80);
    let steps_before = h.state().state.sim().steps();

    h.key_press(Key::End);
    h.run();
    assert_eq!(h.state().state.sim().params().get(key), spec.max, "End");
    h.key_press(Key::Home);
    h.run();
    assert_eq!(h.state().state.sim().params().get(key), spec.min, "Home");
    h.key_press(Key::ArrowRight);
    h.run();
    let one_arrow = h.state().state.sim().params().get(key);
    h.key_press(Key::PageUp);
    h.run();
    let then_page = h.state().state.sim().params().get(key);
    h.key_press_modifiers(Modifiers::SHIFT, Key::ArrowLeft);
    h.run();
    let then_shift = h.state().state.sim().params().get(key);

    // Along the rail: a linear slider moves by its range over 20, 10, 100; a logarithmic one
    // by the same fractions of its decades.
    let rail = |v: f64| attlab_web::panels::rail_position(&spec, v);
    assert!(
        (rail(one_arrow) - 0.05).abs() < 1e-9,
        "→ from Home: {one_arrow}"
    );
    assert!((rail(then_page) - 0.15).abs() < 1e-9, "PageUp: {then_page}");
    assert!(
        (rail(then_shift) - 0.14).abs() < 1e-9,
        "Shift+←: {then_shift}"
    );
    assert_ne!(before, then_shift);
    // The keys moved the slider, not the run: no reset, no step, no tab change.
    assert_eq!(h.state().state.sim().steps(), steps_before);
    assert!(!h.state().state.run().playing);
}

#[test]
fn shortcuts_wait_while_a_control_has_the_keyboard_and_work_after_escape() {
    let mut h = harness("p1");
    h.run();
    let tab = h.state().state.view().plots.tab;
    tab_to(&mut h, "Adaptation window N", 120);
    h.key_press(Key::ArrowRight);
    h.run();
    assert_eq!(
        h.state().state.view().plots.tab,
        tab,
        "→ moved the slider, not the tab"
    );
    h.key_press(Key::Escape);
    h.run();
    h.key_press(Key::ArrowRight);
    h.run();
    assert_ne!(
        h.state().state.view().plots.tab,
        tab,
        "→ with nothing focused: next tab"
    );
    h.key_press(Key::Space);
    h.run();
    assert!(
        h.state().state.run().playing,
        "space with nothing focused: play"
    );
}

#[test]
fn question_mark_opens_the_keyboard_dialog_and_escape_closes_it() {
    let mut h = harness("p4");
    h.run();
    h.event(egui::Event::Text("?".into()));
    h.run();
    assert!(h.state().state.view().keys_help);
    // The dialog names the slider keys in words a student reads.
    assert!(h.query_by_label("PageUp, PageDown").is_some());
    assert!(h.query_by_label("Home, End").is_some());
    h.key_press(Key::Escape);
    h.run();
    assert!(!h.state().state.view().keys_help);
    // And its button opens it too.
    h.get_by_label("Keys (?)").click();
    h.run();
    assert!(h.state().state.view().keys_help);
}

/// The wheel over the plot zooms (it used to pan the data out of view), and a visible ⟲
/// then brings back the whole run.
#[test]
fn the_wheel_zooms_the_plot_and_a_visible_button_resets_it() {
    let mut h = harness("p1");
    for _ in 0..300 {
        h.state_mut().apply(RunCommand::StepOnce.into());
    }
    h.run();
    assert!(h.query_by_label("⟲").is_none(), "no reset before a zoom");
    // The plot fills the lower right of the 1400×900 window.
    let over_plot = egui::pos2(900.0, 700.0);
    h.hover_at(over_plot);
    h.run();
    for _ in 0..3 {
        support::wheel(&mut h, 60.0);
        h.run();
    }
    h.get_by_label("⟲").click();
    h.run();
    h.run();
    assert!(
        h.query_by_label("⟲").is_none(),
        "the reset brought back the whole run"
    );
}

/// The keyboard shortcuts listed in the help: space, s, →, f.
#[test]
fn keyboard_shortcuts_pause_step_switch_tabs_and_focus_one_view() {
    use attlab_web::state::Focus;
    let mut h = harness("p4");
    h.run();
    h.key_press(egui::Key::Space);
    h.run();
    assert!(h.state().state.run().playing, "space resumes");
    h.key_press(egui::Key::Space);
    h.run();
    assert!(!h.state().state.run().playing, "space pauses");
    let steps = h.state().state.sim().steps();
    h.key_press(egui::Key::S);
    h.run();
    assert_eq!(h.state().state.sim().steps(), steps + 1, "s steps once");
    let tab = h.state().state.view().plots.tab;
    h.key_press(egui::Key::ArrowRight);
    h.run();
    assert_ne!(
        h.state().state.view().plots.tab,
        tab,
        "→ selects the next tab"
    );
    h.key_press(egui::Key::ArrowLeft);
    h.run();
    assert_eq!(h.state().state.view().plots.tab, tab, "← goes back");
    let views = h.state().state.sim().lab().page().views.len();
    let mut seen = Vec::new();
    for _ in 0..=views + 1 {
        h.key_press(egui::Key::F);
        h.run();
        seen.push(h.state().state.view().focus);
    }
    let mut expected: Vec<Focus> = (0..views).map(Focus::View).collect();
    expected.extend([Focus::Plots, Focus::All]);
    assert_eq!(seen, expected);
    // p4 turns about one axis: its views are the 3D body, the dial and the phase portrait.
    assert_eq!(
        h.state().state.sim().lab().page().views,
        attlab::page::SINGLE_AXIS_VIEWS
    );
}
