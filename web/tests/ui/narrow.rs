//! A phone's width: the bar, the sheet, one view at a time.

use super::*;

fn phone(lab_id: &str) -> Harness<'static, AttLabApp> {
    held(lab_id, egui::vec2(390.0, 844.0))
}

/// Lab `lab_id`'s page on a screen of `size`, paused.
fn held(lab_id: &str, size: egui::Vec2) -> Harness<'static, AttLabApp> {
    let lab = labs::find(lab_id).expect("registered");
    let mut app = AttLabApp::with_state(lab, ParamValues::defaults(lab.params()), 1, 1.0);
    app.apply(RunCommand::SetPlaying(false).into());
    Harness::builder()
        .with_size(size)
        .with_context_setup(attlab_web::app::setup_context)
        .build_ui_state(|ui, app: &mut AttLabApp| app.frame(ui), app)
}

/// The sliders of the lab's controls (the timeline under the plot is a slider of its own,
/// always on screen).
fn controls<'a>(
    h: &'a Harness<'_, AttLabApp>,
) -> impl Iterator<Item = egui_kittest::Node<'a>> + 'a {
    h.query_all_by_role(Role::Slider).filter(|n| {
        !n.accesskit_node()
            .label()
            .is_some_and(|l| l.starts_with("Timeline"))
    })
}

#[test]
fn a_phone_shows_the_plot_and_keeps_the_sliders_in_a_sheet() {
    let mut h = phone("p4");
    h.run();
    // No slider on the first screen: the controls wait in the sheet.
    assert!(controls(&h).next().is_none());
    h.get_by_label("Controls").click();
    h.run();
    assert!(h.state().state.view().sheet_open);
    assert!(controls(&h).next().is_some());
    h.get_by_label("Close").click();
    h.run();
    assert!(!h.state().state.view().sheet_open);
}

#[test]
fn a_phone_switches_between_the_views_one_at_a_time() {
    let mut h = phone("p4");
    h.run();
    assert_eq!(h.state().state.view().narrow_view, 0);
    h.get_by_label("Phase portrait").click();
    h.run();
    assert_eq!(h.state().state.view().narrow_view, 2);
}

#[test]
fn on_a_phone_every_button_is_a_finger_high() {
    let mut h = phone("p4");
    h.run();
    for node in h.query_all_by_role(Role::Button) {
        let Some(rect) = node.accesskit_node().raw_bounds() else {
            continue;
        };
        let label = node.accesskit_node().label().unwrap_or_default();
        assert!(rect.height() >= 31.9, "{label}: {} pt high", rect.height());
    }
}

#[test]
fn a_phone_opened_on_a_question_step_shows_the_question_then_gives_the_page_to_the_run() {
    let state = attlab_web::state::AppState::from_fragment("lesson=p4&step=3");
    let mut h = Harness::builder()
        .with_size(egui::vec2(390.0, 844.0))
        .with_context_setup(attlab_web::app::setup_context)
        .build_ui_state(
            |ui, app: &mut AttLabApp| app.frame(ui),
            AttLabApp::headless(state),
        );
    h.run_steps(6);
    let s = &h.state().state;
    assert!(
        s.view().sheet_open && !s.run().playing,
        "the question waits in the open sheet"
    );
    let q = labs::find("p4")
        .unwrap()
        .lesson()
        .unwrap()
        .step(3)
        .unwrap()
        .question
        .unwrap();
    h.get_by_label(&format!("b) {}", q.answers[1])).click();
    h.run_steps(6);
    let s = &h.state().state;
    assert!(
        !s.view().sheet_open && s.run().playing,
        "the run shows the answer"
    );
    // The bar names the lesson and opens its card again.
    h.get_by_label("Lesson · step 3 of 6").click();
    h.run_steps(6);
    assert!(h.state().state.view().sheet_open);
}

#[test]
fn a_phone_held_sideways_puts_one_view_beside_a_plot_of_at_least_two_fifths_its_height() {
    // As on a laptop and a projector: the plot itself takes 40 % of the window's height.
    const SHARE: f32 = 0.4;
    for lab in labs::all() {
        let mut h = held(lab.id(), egui::vec2(844.0, 390.0));
        h.run();
        let id = lab.id();
        assert!(controls(&h).next().is_none(), "{id}: sliders out");
        let regions = h.state().regions();
        let plot = regions.plot_area.expect("a plot");
        assert!(
            plot.height() >= SHARE * 390.0,
            "{id}: the plot is {} pt tall",
            plot.height()
        );
        assert_eq!(regions.views.len(), 1, "{id}: one view");
        assert!(
            regions.views[0].1.max.x <= plot.min.x,
            "{id}: the view beside the plot"
        );
        // The controls open from the side, the plot still beside them (the view gives way).
        h.get_by_label("Controls").click();
        h.run();
        assert!(
            h.query_all_by_role(Role::Slider).next().is_some(),
            "{id}: the sheet"
        );
        let plot = h.state().regions().plot_area.expect("a plot");
        assert!(
            plot.height() >= SHARE * 390.0,
            "{id}: with the sheet {} pt",
            plot.height()
        );
        assert!(
            h.state().regions().views.is_empty(),
            "{id}: the view gives way"
        );
    }
}

#[test]
fn a_phone_starts_the_lesson_from_its_bar_and_opens_the_why_when_the_run_shows_it() {
    let mut h = phone("p4");
    h.run();
    h.get_by_label("▶ Start the lesson").click();
    h.run();
    assert_eq!(h.state().state.lesson().map(|l| l.step), Some(1));
    assert!(h.state().state.view().sheet_open, "the card is open");
    // Step 3's question, answered: the sheet gives the page to the run, which opens it
    // again at the pause, where the why is.
    let mut state = attlab_web::state::AppState::from_fragment("lesson=p4&step=3");
    state.apply(attlab_web::state::LessonCommand::Answer(2).into());
    assert!(!state.view().sheet_open && state.run().playing);
    let t0 = web_time::Instant::now();
    for k in 0..400 {
        state.apply(RunCommand::Advance(t0 + web_time::Duration::from_millis(250 * k)).into());
    }
    assert!(
        state.lesson_revealed() && !state.run().playing,
        "at the pause"
    );
    assert!(state.view().sheet_open, "the why is in view");
}

#[test]
fn a_slow_finger_on_a_button_still_presses_it() {
    let mut h = phone("p4");
    h.run();
    let at = h.get_by_label("Controls").rect().center();
    h.event(egui::Event::PointerMoved(at));
    h.event(egui::Event::PointerButton {
        pos: at,
        button: egui::PointerButton::Primary,
        pressed: true,
        modifiers: egui::Modifiers::NONE,
    });
    // A second and a half held (egui's frames are 1/60 s apart in the harness).
    for _ in 0..90 {
        h.step();
    }
    h.event(egui::Event::PointerButton {
        pos: at,
        button: egui::PointerButton::Primary,
        pressed: false,
        modifiers: egui::Modifiers::NONE,
    });
    h.run();
    assert!(
        h.state().state.view().sheet_open,
        "held 1.5 s, the press did nothing"
    );
}
