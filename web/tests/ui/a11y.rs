//! The accessibility mirror planned from egui's AccessKit tree (the page writes the same
//! plan into the DOM): every slider of a lab named with its value and range, buttons
//! clickable, the focused control marked; a screen reader's request comes back to egui.
//! And the live description a screen reader hears.

use super::*;
use attlab_web::a11y::{Element, LastPlan, Mirror, MirrorNode, Requests};
use attlab_web::state::ViewCommand;

fn mirrored(lab_id: &str) -> (Harness<'static, AttLabApp>, Requests, LastPlan) {
    let lab = labs::find(lab_id).expect("registered");
    let mut app = AttLabApp::with_state(lab, ParamValues::defaults(lab.params()), 1, 1.0);
    app.apply(RunCommand::SetPlaying(false).into());
    let handles = std::rc::Rc::new(std::cell::RefCell::new(None));
    let slot = handles.clone();
    let h = Harness::builder()
        .with_size(egui::vec2(1400.0, 900.0))
        .with_context_setup(move |ctx| {
            attlab_web::app::setup_context(ctx);
            *slot.borrow_mut() = Some(Mirror::install(ctx));
        })
        .build_ui_state(|ui, app: &mut AttLabApp| app.frame(ui), app);
    let (requests, last) = handles
        .borrow_mut()
        .take()
        .expect("the mirror was installed");
    (h, requests, last)
}

fn plan(last: &LastPlan) -> Vec<MirrorNode> {
    last.lock().expect("not poisoned").clone()
}

#[test]
fn every_slider_of_every_lab_is_mirrored_with_its_name_value_and_range() {
    for lab in labs::all() {
        let (mut h, _, last) = mirrored(lab.id());
        h.run();
        let nodes = plan(&last);
        let sliders: Vec<&MirrorNode> = nodes.iter().filter(|n| n.role == "slider").collect();
        let app = &h.state().state;
        for spec in lab.params().iter().filter(|s| {
            matches!(
                s.kind,
                attlab::model::ParamKind::Real | attlab::model::ParamKind::Integer
            )
        }) {
            let found = sliders.iter().find(|n| n.name == spec.label);
            let node = found.unwrap_or_else(|| {
                panic!("{}: no mirrored slider named `{}`", lab.id(), spec.label)
            });
            assert_eq!(node.element, Element::Range);
            let n = node.numeric.expect("a slider has a value");
            assert_eq!(n.value, app.sim().params().get(spec.key), "{}", spec.key);
            assert_eq!(
                (n.min, n.max),
                (Some(spec.min), Some(spec.max)),
                "{}",
                spec.key
            );
            // Its value in words, with the unit the slider shows (in the page's language).
            let text = node.text.as_deref().unwrap_or_default();
            let unit = attlab::i18n::unit(app.view().lang(), spec.unit);
            assert!(text.ends_with(&unit), "{}: `{text}`", spec.key);
            let [_, _, w, h] = node.rect_css.expect("a slider has a place");
            assert!(w > 10.0 && h > 5.0, "{}: {w}×{h}", spec.key);
        }
        assert!(
            nodes
                .iter()
                .any(|n| n.role == "button" && n.clickable && n.name.contains("Reset")),
            "{}: Reset is a clickable button",
            lab.id()
        );
    }
}

#[test]
fn a_screen_readers_value_and_click_reach_the_app_and_focus_is_marked() {
    let (mut h, requests, last) = mirrored("free-rotation");
    h.run();
    let slider = plan(&last)
        .into_iter()
        .find(|n| n.name == "Gyro noise σ")
        .expect("mirrored");
    requests.push(ActionRequest {
        action: Action::SetValue,
        target_node: egui::accesskit::NodeId(slider.id),
        target_tree: egui::accesskit::TreeId::ROOT,
        data: Some(ActionData::NumericValue(0.25)),
    });
    h.run();
    assert_eq!(h.state().state.sim().params().get("gyro_noise_deg_s"), 0.25);
    let play = plan(&last)
        .into_iter()
        .find(|n| n.role == "button" && n.name.contains("Play"))
        .expect("a Play button");
    requests.push(ActionRequest {
        action: Action::Click,
        target_node: egui::accesskit::NodeId(play.id),
        target_tree: egui::accesskit::TreeId::ROOT,
        data: None,
    });
    h.run();
    assert!(
        h.state().state.run().playing,
        "the mirrored click pressed Play"
    );
    h.key_press(egui::Key::Tab);
    h.run();
    let focused: Vec<MirrorNode> = plan(&last).into_iter().filter(|n| n.focused).collect();
    assert_eq!(
        focused.len(),
        1,
        "one control has the keyboard: {focused:?}"
    );
}

#[test]
fn the_live_description_names_the_lab_the_time_and_the_ghosts_error_against_its_band() {
    let lab = labs::find("p2").expect("registered");
    let mut app = AttLabApp::with_state(lab, ParamValues::defaults(lab.params()), 1, 1.0);
    app.apply(RunCommand::SetPlaying(false).into());
    for _ in 0..300 {
        app.apply(RunCommand::StepOnce.into());
    }
    let text = attlab_web::panels::describe_run(&app.state);
    assert!(text.contains("TabletSat"), "{text}");
    assert!(text.contains("paused"), "{text}");
    assert!(
        text.contains("3σ band"),
        "a filter with a covariance: {text}"
    );
    app.apply(ViewCommand::SetLang(attlab::i18n::Lang::Ru).into());
    let ru = attlab_web::panels::describe_run(&app.state);
    assert!(ru.contains("пауза") && ru.contains("3σ"), "{ru}");
}

/// In Russian a slider's value is read with its unit in Russian: the page shows the code's
/// SI symbols (km, kg·m², N·m) in the reader's words.
#[test]
fn a_russian_slider_reads_its_unit_in_russian() {
    use attlab::i18n::{self, Lang};
    for (lab_id, key, unit) in [
        ("p2", "altitude_km", " км"),
        ("p1", "inertia_kg_m2", " кг·м²"),
        ("p1", "string_length_m", " м"),
        ("free-rotation", "spin_deg_s", " °/с"),
    ] {
        let (mut h, _, last) = mirrored(lab_id);
        h.state_mut().apply(ViewCommand::SetLang(Lang::Ru).into());
        h.run();
        let lab = labs::find(lab_id).expect("registered");
        let spec = lab
            .params()
            .iter()
            .find(|s| s.key == key)
            .expect("a slider");
        let name = i18n::lab_text(Lang::Ru, &i18n::param_label_id(lab_id, key), spec.label);
        let nodes = plan(&last);
        let node = nodes
            .iter()
            .find(|n| n.role == "slider" && n.name == name)
            .unwrap_or_else(|| panic!("{lab_id}: no slider named `{name}`"));
        let text = node.text.as_deref().unwrap_or_default();
        assert!(
            text.ends_with(unit),
            "{lab_id} {key}: `{text}`, want it to end with `{unit}`"
        );
    }
}
