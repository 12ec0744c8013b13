//! The teacher's controls hold: a locked control keeps its value through every preset,
//! "defaults", every lesson step, the screen reader's mirror and a new link in the open tab;
//! a lesson's Share link leaves the answers out unless asked; the keys a presenter's
//! clicker sends walk the steps; steps and labs are history entries.

use super::*;
use attlab::model::ParamValues;
use attlab::page::Lab;
use attlab_web::state::{AppState, Command, LessonCommand, ShareCommand, UrlCommand, ViewCommand};
use egui::{Key, Modifiers};

/// Every way the page changes parameters without the locked slider itself: each preset,
/// "defaults", and each step of the lesson.
fn every_way_round(state: &mut AppState, lab: &dyn Lab) -> Vec<(String, ParamValues)> {
    let mut seen = Vec::new();
    for preset in lab.presets() {
        state.apply(RunCommand::ApplyPreset(preset.id).into());
        seen.push((
            format!("preset “{}”", preset.name),
            state.sim().params().clone(),
        ));
    }
    state.apply(RunCommand::RestoreDefaults.into());
    seen.push(("defaults".into(), state.sim().params().clone()));
    let steps = lab.lesson().map_or(0, |l| l.steps.len());
    state.apply(LessonCommand::Start.into());
    for n in 1..=steps {
        state.apply(LessonCommand::Go(n).into());
        seen.push((format!("lesson step {n}"), state.sim().params().clone()));
    }
    seen
}

#[test]
fn lock_all_holds_every_parameter_of_every_lab_through_presets_defaults_and_steps() {
    for lab in labs::all() {
        let link = format!("lab={}&lock=all", lab.id());
        let mut state = AppState::from_fragment(&link);
        let locked = state.sim().params().clone();
        for (way, params) in every_way_round(&mut state, *lab) {
            assert_eq!(params, locked, "{link}: {way} moved a locked control");
        }
        // The page said why the presets and steps that asked for other values did not
        // take them.
        let said = state.messages().iter().any(|m| m.text.contains("locked"));
        assert!(said, "{link}: {:?}", state.messages());
    }
}

#[test]
fn one_locked_control_holds_while_the_others_follow_the_presets_and_steps() {
    let lab = labs::find("p4").unwrap();
    let mut state = AppState::from_fragment("lab=p4&lock=gamma&gamma=0.05");
    let mut others_moved = false;
    for (way, params) in every_way_round(&mut state, lab) {
        assert_eq!(params.get("gamma"), 0.05, "{way} moved the locked γ");
        others_moved |= params != state_defaults_with_gamma(lab, 0.05);
    }
    assert!(others_moved, "no preset or step moved an unlocked control");
    // The preset "γ = 0.2: noisy" from the issue: γ stays, and the link still says so.
    state.apply(LessonCommand::Close.into());
    state.apply(RunCommand::ApplyPreset("gamma-large").into());
    assert_eq!(state.sim().params().get("gamma"), 0.05);
    assert!(
        state.fragment().contains("lock=gamma"),
        "{}",
        state.fragment()
    );
}

fn state_defaults_with_gamma(lab: &dyn Lab, gamma: f64) -> ParamValues {
    let mut p = ParamValues::defaults(lab.params());
    p.set(lab.params(), "gamma", gamma).unwrap();
    p
}

#[test]
fn a_new_link_in_the_open_tab_keeps_the_lock_and_its_value() {
    let mut state = AppState::from_fragment("lab=p4&lock=gamma&gamma=0.05");
    // A student edits the address bar: another γ, and the lock taken out.
    state.apply(UrlCommand::Load("lab=p4&gamma=0.5&seed=3".into()).into());
    assert_eq!(state.sim().params().get("gamma"), 0.05);
    assert_eq!(state.run().seed, 3, "the rest of the link is applied");
    assert!(state.view().locks("gamma"));
    // Another lab's link is a new page: its own controls, unlocked.
    state.apply(UrlCommand::Load("lab=p1".into()).into());
    assert_eq!(state.sim().lab().id(), "p1");
    assert!(state.view().lock.is_empty());
}

#[test]
fn a_locked_slider_is_disabled_with_a_padlock_and_refuses_the_screen_readers_value() {
    let mut h = harness_from_link("lab=p4&lock=gamma");
    h.run();
    let label = "γ = det Q / det R";
    let slider = h.get_by_role_and_label(Role::Slider, label);
    assert!(
        slider.accesskit_node().is_disabled(),
        "the locked slider is enabled"
    );
    support::set_slider_by_accesskit(&mut h, label, 0.2);
    h.run();
    assert_eq!(h.state().state.sim().params().get("gamma"), 2e-3);
    // One padlock, which says why (to a screen reader, and on hover).
    let padlocks = h
        .query_all_by_label_contains("Locked by the teacher's link")
        .count();
    assert_eq!(padlocks, 1);
    let unlocked = harness_from_link("lab=p4");
    let slider = unlocked.get_by_role_and_label(Role::Slider, label);
    assert!(!slider.accesskit_node().is_disabled());
    let padlocks = (unlocked.query_all_by_label_contains("Locked by the teacher's link")).count();
    assert_eq!(padlocks, 0);
}

#[test]
fn a_lessons_share_link_leaves_the_answers_out_unless_ticked() {
    let mut state = AppState::from_fragment("lesson=p3&step=3");
    state.apply(LessonCommand::Answer(2).into());
    assert!(
        state.fragment().contains("answers=3b"),
        "the page's own link keeps them"
    );
    state.apply(ShareCommand::Open.into());
    let options = state.share().unwrap().clone();
    let link = state.share_fragment(&options);
    assert!(
        !link.contains("answers="),
        "a class link with answers: {link}"
    );
    state.apply(ShareCommand::Answers(true).into());
    let options = state.share().unwrap().clone();
    assert!(state.share_fragment(&options).contains("answers=3b"));
}

#[test]
fn the_share_dialog_shows_the_whole_link() {
    let mut h = harness_from_link("lesson=p2&step=4&presenter=1&lock=all&hide=gyro_bias_deg_s");
    h.state_mut().apply(ShareCommand::Open.into());
    h.run();
    let link = {
        let state = &h.state().state;
        state.share_link(state.share().unwrap())
    };
    // Wrapped anywhere, the link's lines join to the whole link: none is cut.
    let shown: String = painted(&h)
        .into_iter()
        .filter(|t| link.contains(t.trim()) && t.len() > 8)
        .collect::<Vec<_>>()
        .join("");
    assert!(shown.contains(&link), "shown {shown:?}, the link {link:?}");
}

#[test]
fn a_clickers_keys_walk_the_lesson_and_shift_arrows_the_tabs() {
    let mut h = harness_from_link("lesson=p3&step=1");
    h.run();
    let step = |h: &Harness<'_, AttLabApp>| h.state().state.lesson().map(|l| l.step);
    for (key, to) in [
        (Key::ArrowRight, 2),
        (Key::PageDown, 3),
        (Key::PageUp, 2),
        (Key::ArrowLeft, 1),
        (Key::ArrowLeft, 1),
    ] {
        h.key_press(key);
        h.run();
        assert_eq!(step(&h), Some(to), "after {key:?}");
    }
    let last = labs::find("p3").unwrap().lesson().unwrap().steps.len();
    for _ in 0..last + 2 {
        h.key_press(Key::PageDown);
        h.run();
    }
    assert_eq!(step(&h), Some(last), "PageDown past the last step");
    let tab = h.state().state.view().plots.tab;
    h.key_press_modifiers(Modifiers::SHIFT, Key::ArrowRight);
    h.run();
    assert_ne!(
        h.state().state.view().plots.tab,
        tab,
        "Shift+→ moves the tab"
    );
    assert_eq!(step(&h), Some(last), "Shift+→ leaves the step");
}

#[test]
fn steps_and_labs_are_history_entries_and_a_slider_is_not() {
    let mut h = harness_from_link("lesson=p1&step=1");
    h.run();
    let added = |h: &Harness<'_, AttLabApp>| h.state().state.history_entries_added();
    assert_eq!(added(&h), 0, "opening the link adds no entry");
    h.get_by_label("Next ▶").click();
    h.run();
    assert_eq!(added(&h), 1);
    h.state_mut().apply(RunCommand::SetSeed(9).into());
    h.state_mut()
        .apply(Command::from(ViewCommand::SetShowBands(false)));
    h.state_mut()
        .apply(RunCommand::SetParam("gyro_noise_deg_s", 0.05).into());
    h.run();
    assert_eq!(
        added(&h),
        1,
        "a slider moved in the step replaces its entry"
    );
    h.state_mut()
        .apply(RunCommand::SelectLab(labs::find("p4").unwrap()).into());
    h.run();
    assert_eq!(added(&h), 2, "another lab is an entry");
}
