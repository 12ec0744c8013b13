//! What several UI tests share: a harness around a state or a link, and the texts a frame
//! painted.

use attlab_web::AttLabApp;
use attlab_web::state::RunCommand;
use egui_kittest::Harness;

/// Every text the page painted in its last frame.
pub(super) fn painted(h: &Harness<'_, AttLabApp>) -> Vec<String> {
    (h.output().shapes.iter())
        .filter_map(|c| match &c.shape {
            egui::Shape::Text(t) => Some(t.galley.text().to_owned()),
            _ => None,
        })
        .collect()
}

/// A harness around `state`, paused.
pub(super) fn harness_for(state: attlab_web::state::AppState) -> Harness<'static, AttLabApp> {
    let mut app = AttLabApp::headless(state);
    app.apply(RunCommand::SetPlaying(false).into());
    Harness::builder()
        .with_size(egui::vec2(1400.0, 900.0))
        .with_context_setup(attlab_web::app::setup_context)
        .build_ui_state(|ui, app: &mut AttLabApp| app.frame(ui), app)
}

/// The page a link opens (`fragment` as after `#`), paused.
pub(super) fn harness_from_link(fragment: &str) -> Harness<'static, AttLabApp> {
    harness_for(attlab_web::state::AppState::from_fragment(fragment))
}
