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

/// Every text of the last frame painted whole inside its clip rectangle, with that
/// rectangle.
pub(super) fn whole_texts(h: &Harness<'_, AttLabApp>) -> Vec<(egui::Rect, String)> {
    (h.output().shapes.iter())
        .filter_map(|c| match &c.shape {
            egui::Shape::Text(t)
                if c.clip_rect
                    .expand(0.5)
                    .contains_rect(t.visual_bounding_rect()) =>
            {
                Some((c.clip_rect, t.galley.text().to_owned()))
            }
            _ => None,
        })
        .collect()
}

/// One turn of the mouse wheel by `dy` points (negative: down the page) where the pointer
/// is.
pub(super) fn wheel(h: &mut Harness<'_, AttLabApp>, dy: f32) {
    h.event(egui::Event::MouseWheel {
        unit: egui::MouseWheelUnit::Point,
        delta: egui::vec2(0.0, dy),
        phase: egui::TouchPhase::Move,
        source: egui::MouseWheelSource::Unknown,
        modifiers: egui::Modifiers::NONE,
    });
}

/// A screen reader's "set value" of `v` on the slider named `label`, as accesskit sends it.
pub(super) fn set_slider_by_accesskit(h: &mut Harness<'_, AttLabApp>, label: &str, v: f64) {
    use egui::accesskit::{Action, ActionData, ActionRequest, Role};
    use egui_kittest::kittest::{NodeT, Queryable};
    let (target_node, target_tree) = (h.get_by_role_and_label(Role::Slider, label))
        .accesskit_node()
        .locate();
    h.event(egui::Event::AccessKitActionRequest(ActionRequest {
        action: Action::SetValue,
        target_node,
        target_tree,
        data: Some(ActionData::NumericValue(v)),
    }));
}
