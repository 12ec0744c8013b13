//! The lessons walked as a student walks them, the teacher's link and its QR code, and the
//! filter's cycle panel against the filter's own state.

use super::*;
use attlab::page::default_tab;
use attlab::page::{Lab, LessonStep};
use attlab::state::{ALL_CONTROLS, UrlState};
use attlab_web::state::{AppState, Command, LessonCommand, ShareCommand, ViewCommand, qr};

/// What the state must show at step `n` of `lab`'s lesson.
fn assert_step(state: &AppState, lab: &'static dyn Lab, n: usize, step: &LessonStep) {
    let at = format!("{} step {n}", lab.id());
    assert_eq!(state.lesson().map(|l| l.step), Some(n), "{at}");
    let params = attlab::lessons::step_params(lab, step).unwrap();
    assert_eq!(state.sim().params(), &params, "{at}: parameters");
    let tab = step.tab.unwrap_or_else(|| default_tab(lab));
    assert_eq!(state.view().plots.tab, tab, "{at}: tab");
    let shown: Vec<&str> = state
        .sim()
        .estimators()
        .iter()
        .enumerate()
        .filter(|(i, _)| !state.view().hidden.contains(&(i + 1)))
        .map(|(_, e)| e.id())
        .collect();
    if !step.show.is_empty() {
        let (mut shown, mut asked) = (shown, step.show.to_vec());
        shown.sort_unstable();
        asked.sort_unstable();
        assert_eq!(shown, asked, "{at}: filters shown");
    }
    for tile in step.tiles {
        let name = tile.name();
        assert!(
            state.sim().value(&name).is_ok(),
            "{at}: tile {name} is not recorded"
        );
    }
    let errors: Vec<_> = state.messages().iter().filter(|m| m.is_error).collect();
    assert!(errors.is_empty(), "{at}: {errors:?}");
    assert!(
        state.link_problems().is_empty(),
        "{at}: {:?}",
        state.link_problems()
    );
}

#[test]
fn every_lesson_walks_from_its_first_step_to_its_last_by_its_buttons() {
    for lab in labs::all() {
        let lesson = lab.lesson().expect("every lab has a lesson");
        let mut h = harness(lab.id());
        h.run_steps(6);
        h.get_by_label("▶ Start the lesson").click();
        h.run_steps(6);
        for (i, step) in lesson.steps.iter().enumerate() {
            let n = i + 1;
            assert_step(&h.state().state, *lab, n, step);
            for key in step.highlight {
                let spec = lab.params().iter().find(|p| p.key == *key).unwrap();
                let shown = if spec.kind == attlab::model::ParamKind::Real {
                    h.query_by_role_and_label(Role::Slider, spec.label)
                        .is_some()
                } else {
                    h.query_all_by_label_contains(spec.label).next().is_some()
                };
                assert!(shown, "{} step {n}: the control of {key}", lab.id());
            }
            if let Some(q) = step.question {
                assert!(
                    !h.state().state.run().playing,
                    "{} step {n}: a question waits",
                    lab.id()
                );
                let label = format!("b) {}", q.answers[1]);
                h.get_by_label(&label).click();
                h.run_steps(6);
                let s = &h.state().state;
                assert_eq!(
                    s.lesson().unwrap().answer(n),
                    Some(2),
                    "{} step {n}",
                    lab.id()
                );
                assert!(
                    s.run().playing || s.lesson_revealed(),
                    "{} step {n}: runs after the answer",
                    lab.id()
                );
            }
            if n < lesson.steps.len() {
                h.get_by_label("Next ▶").click();
                h.run_steps(6);
            }
        }
        // The answers were kept through the walk, and the link carries them.
        let questions = lesson.steps.iter().filter(|s| s.question.is_some()).count();
        assert_eq!(h.state().state.lesson().unwrap().answers.len(), questions);
        assert!(h.state().state.fragment().contains("answers="));
        h.get_by_label("End the lesson").click();
        h.run_steps(6);
        assert!(h.state().state.lesson().is_none(), "{}", lab.id());
    }
}

#[test]
fn a_lesson_link_opens_its_step_with_the_steps_state() {
    for lab in labs::all() {
        let lesson = lab.lesson().unwrap();
        for (i, step) in lesson.steps.iter().enumerate() {
            let state = AppState::from_fragment(&format!("lesson={}&step={}", lab.id(), i + 1));
            assert_step(&state, *lab, i + 1, step);
            assert_eq!(
                state.run().playing,
                step.question.is_none(),
                "{} step {}",
                lab.id(),
                i + 1
            );
        }
    }
}

#[test]
fn the_share_link_round_trips_and_hides_and_locks_what_it_says() {
    let lab = labs::find("p2").unwrap();
    let mut state = AppState::from_fragment("lesson=p2&step=4");
    let first_question = lab
        .lesson()
        .unwrap()
        .steps
        .iter()
        .position(|s| s.question.is_some())
        .unwrap()
        + 1;
    state.apply(LessonCommand::Go(first_question).into());
    state.apply(LessonCommand::Answer(1).into());
    state.apply(ShareCommand::Open.into());
    let (hidden, locked) = (lab.params()[0].key, lab.params()[1].key);
    for c in [
        ShareCommand::Hide(hidden, true),
        ShareCommand::Lock(locked, true),
        ShareCommand::Presenter(true),
        ShareCommand::FromStep(true),
        // A student sending theirs to the teacher ticks the answers (off by default).
        ShareCommand::Answers(true),
    ] {
        state.apply(Command::Share(c));
    }
    let options = state.share().unwrap().clone();
    let fragment = state.share_fragment(&options);
    let (url, errors) = UrlState::parse(&fragment);
    assert!(errors.is_empty(), "{errors:?}");
    assert_eq!(
        (url.hide, url.lock, url.presenter),
        (vec![hidden.to_string()], vec![locked.to_string()], true)
    );
    let link = url.lesson.unwrap();
    assert_eq!(
        (link.step, link.answers),
        (first_question, vec![(first_question, 1)])
    );
    // The page the link opens says the same link again.
    let opened = AppState::from_fragment(&fragment);
    assert_eq!(opened.fragment(), fragment);
    assert_eq!(opened.sim().params(), state.sim().params());
    let mut h = harness_for(opened);
    h.run_steps(6);
    let label = |key: &str| lab.params().iter().find(|p| p.key == key).unwrap().label;
    assert!(
        h.query_by_role_and_label(Role::Slider, label(hidden))
            .is_none(),
        "hidden slider shown"
    );
    // In presenter mode the sliders wait behind "All parameters" (scrolled to, as a reader
    // would: the panel is longer than the window).
    if h.query_by_label("All parameters").is_some() {
        h.get_by_label("All parameters").scroll_to_me();
        h.run();
        h.get_by_label("All parameters").click();
        h.run_steps(6);
    }
    let locked_node = h.get_by_role_and_label(Role::Slider, label(locked));
    assert!(
        locked_node.accesskit_node().is_disabled(),
        "locked slider can be moved"
    );
    // Every control hidden: no slider at all.
    let (all, _) = UrlState::parse(&format!("lab=p2&hide={ALL_CONTROLS}"));
    assert_eq!(all.hide, vec![ALL_CONTROLS.to_string()]);
    let mut h = harness_for(AppState::from_fragment(&format!(
        "lab=p2&hide={ALL_CONTROLS}"
    )));
    h.run_steps(6);
    for spec in lab.params() {
        assert!(
            h.query_by_role_and_label(Role::Slider, spec.label)
                .is_none(),
            "{} shown",
            spec.key
        );
    }
}

#[test]
fn the_qr_code_decodes_to_the_link() {
    let state = AppState::from_fragment("lesson=p4&step=2&presenter=1&lock=all");
    let mut state = state;
    state.apply(ShareCommand::Open.into());
    let link = format!(
        "https://example.org/attlab/#{}",
        state.share_fragment(state.share().unwrap())
    );
    let code = qr(&link).unwrap();
    let (scale, quiet) = (4, 4);
    let side = (code.width + 2 * quiet) * scale;
    let mut img = rqrr::PreparedImage::prepare_from_greyscale(side, side, |x, y| {
        let (mx, my) = (
            (x / scale).wrapping_sub(quiet),
            (y / scale).wrapping_sub(quiet),
        );
        let dark = mx < code.width && my < code.width && code.dark[my * code.width + mx];
        if dark { 0 } else { 255 }
    });
    let grids = img.detect_grids();
    assert_eq!(grids.len(), 1);
    let (_, content) = grids[0].decode().unwrap();
    assert_eq!(content, link);
}

#[test]
fn the_cycle_panel_prints_the_filters_own_state_at_this_sample() {
    let mut h = harness("p4");
    h.state_mut().apply(ViewCommand::SetCycle(true).into());
    for _ in 0..7 {
        h.state_mut().apply(RunCommand::StepOnce.into());
    }
    h.run_steps(6);
    let s = &h.state().state;
    let (i, _) = attlab_web::panels::shown_filter(s).expect("a filter with a cycle");
    let filter = &s.sim().estimators()[i];
    let est = filter.estimate();
    let x = [est.angle_rad.unwrap(), est.rate_body_rad_s.unwrap().z];
    let lang = s.view().lang();
    let x_text = attlab_web::panels::cycle_vector(lang, &x, 2);
    let cov = filter.covariance().unwrap();
    let n = cov.states.len();
    let p: Vec<[f64; 3]> = (0..n)
        .map(|r| std::array::from_fn(|c| if c < n { cov.matrix[c * n + r] } else { 0.0 }))
        .collect();
    let p_text = attlab_web::panels::cycle_matrix(lang, &p, n, n);
    let x_shown = if n == 2 {
        x_text
    } else {
        attlab_web::panels::cycle_vector(
            lang,
            &[x[0], x[1], filter.teaching().unwrap().cycle().x_after[2]],
            3,
        )
    };
    assert!(
        h.query_by_label(&x_shown).is_some(),
        "x̂⁺ {x_shown} not shown"
    );
    assert!(h.query_by_label(&p_text).is_some(), "P⁺ {p_text} not shown");
    // One more sample: the panel follows.
    h.get_by_label("Step one sample (s)").click();
    h.run_steps(6);
    assert_eq!(h.state().state.sim().steps(), 8);
}

/// Paper 2's lesson step 4 blinds the star tracker and several filters lose the attitude.
/// The status line says how many on one line (six had taken six lines, squeezing the
/// projector's plot to a strip); its menu lists each filter with its reason.
#[test]
fn many_diverged_filters_take_one_status_line_whose_menu_lists_them() {
    let mut state = AppState::from_fragment("lesson=p2&step=4&presenter=1");
    while state.sim().t_s() < 1380.0 {
        state.apply(RunCommand::StepOnce.into());
    }
    let diverged = state
        .sim()
        .statuses()
        .iter()
        .filter(|s| matches!(s, attlab::model::EstimatorStatus::Diverged(_)))
        .count();
    assert!(
        diverged >= 2,
        "the blinded star tracker should leave several filters diverged, {diverged} were"
    );
    let mut h = harness_for(state);
    h.run();
    let title = format!("· {diverged} filters diverged: which and why… (press Reset)");
    let reset_lines =
        |h: &Harness<'static, AttLabApp>| h.query_all_by_label_contains("(press Reset)").count();
    assert_eq!(reset_lines(&h), 1, "one line before the menu opens");
    h.get_by_label(&title).click();
    h.run();
    assert_eq!(
        reset_lines(&h),
        1 + diverged,
        "the menu lists every diverged filter"
    );
}

/// The same lesson step in Russian: each filter's reason is in Russian too (it had been the
/// core's English sentence, "…: the filter has lost the attitude", in a Russian page).
#[test]
fn a_diverged_filter_says_why_in_the_readers_language() {
    use attlab::i18n::{Lang, trouble};
    let mut state = AppState::from_fragment("lesson=p2&step=4&presenter=1&lang=ru");
    while state.sim().t_s() < 1380.0 {
        state.apply(RunCommand::StepOnce.into());
    }
    let reasons: Vec<String> = state
        .sim()
        .statuses()
        .iter()
        .filter_map(|s| match s {
            attlab::model::EstimatorStatus::Diverged(why) => Some(trouble(Lang::Ru, why)),
            _ => None,
        })
        .collect();
    assert!(
        reasons.len() >= 2,
        "several filters should have diverged: {reasons:?}"
    );
    let mut h = harness_for(state);
    h.run();
    h.query_all_by_label_contains("какие и почему")
        .next()
        .expect("the status line's Russian menu")
        .click();
    h.run();
    for why in &reasons {
        assert!(
            h.query_all_by_label_contains(why).next().is_some(),
            "the menu does not say {why:?}"
        );
    }
    let english = h.query_all_by_label_contains("the filter has lost").count();
    assert_eq!(english, 0, "an English reason in the Russian page");
}
