//! The host API against the app's state: what a request changes, what it refuses, and the
//! events the reporter sends.

use super::protocol::{Action, StepRef, parse};
use super::*;
use crate::state::AppState;

/// Carries out `text` as a host would send it; the refusal's code if it is refused.
fn send(state: &mut AppState, text: &str) -> Result<(), &'static str> {
    let request = parse(text).map_err(|e| e.code())?;
    for c in commands(state, &request.action).map_err(|e| e.code())? {
        let _ = state.apply(c);
    }
    Ok(())
}

#[test]
fn a_host_sets_parameters_steps_through_the_lesson_and_pauses() {
    let mut state = AppState::from_fragment("lab=p4&embed=1");
    assert!(state.view().embed);
    send(
        &mut state,
        r#"{"api":1,"type":"set","params":{"gamma":0.02}}"#,
    )
    .unwrap();
    assert_eq!(state.sim().params().get("gamma"), 0.02);
    send(&mut state, r#"{"api":1,"type":"lesson","step":2}"#).unwrap();
    assert_eq!(state.lesson().map(|l| l.step), Some(2));
    send(&mut state, r#"{"api":1,"type":"play"}"#).unwrap();
    assert!(state.run().playing);
    send(&mut state, r#"{"api":1,"type":"pause"}"#).unwrap();
    assert!(!state.run().playing);
    let before = state.sim().steps();
    send(&mut state, r#"{"api":1,"type":"step"}"#).unwrap();
    assert_eq!(state.sim().steps(), before + 1);
}

#[test]
fn a_bad_request_changes_nothing() {
    let mut state = AppState::from_fragment("lab=p4&lock=gamma");
    let fragment = state.fragment();
    // The second value is out of range: the first is not set either.
    let refused = [
        (
            r#"{"api":1,"type":"set","params":{"imu_offset_m":0.05,"gamma":1e9}}"#,
            "bad-parameter",
        ),
        (r#"{"api":1,"type":"set","params":{"gamma":0.5}}"#, "locked"),
        (
            r#"{"api":1,"type":"set","params":{"warp":1}}"#,
            "bad-parameter",
        ),
        (r#"{"api":1,"type":"preset","id":"nope"}"#, "no-preset"),
        (r#"{"api":1,"type":"lab","id":"p9"}"#, "no-lab"),
        (r#"{"api":1,"type":"lesson","step":99}"#, "no-step"),
        (
            r#"{"api":1,"type":"lesson","step":"no-such-id"}"#,
            "no-step",
        ),
        (r#"{"api":1,"type":"answer","choice":1}"#, "no-question"),
        (r#"{"api":1,"type":"speed","value":1e9}"#, "bad-parameter"),
    ];
    for (text, code) in refused {
        assert_eq!(send(&mut state, text), Err(code), "{text}");
        assert_eq!(state.fragment(), fragment, "{text} changed the state");
    }
}

#[test]
fn a_step_is_named_by_its_number_or_its_id_and_its_question_answered() {
    let mut state = AppState::from_fragment("lab=p3");
    let lesson = state.sim().lab().lesson().unwrap();
    let (n, step) = (lesson.steps.iter().enumerate())
        .find(|(_, s)| s.question.is_some())
        .map(|(i, s)| (i + 1, s))
        .unwrap();
    let by_id = Action::Lesson(StepRef::Id(step.id.into()));
    for c in commands(&state, &by_id).unwrap() {
        let _ = state.apply(c);
    }
    assert_eq!(state.lesson().map(|l| l.step), Some(n));
    let answers = step.question.unwrap().answers.len();
    assert_eq!(
        commands(&state, &Action::Answer(answers + 1)).map(|_| ()),
        Err(HostError::NoAnswer(answers + 1))
    );
    let mut reporter = Reporter::default();
    let now = Instant::now();
    let first = reporter.due(&state, now);
    assert_eq!(first[0]["type"], "ready");
    assert_eq!(first[0]["lab"], "p3");
    assert_eq!(first[0]["lesson"]["step"], n);
    assert_eq!(first[1]["type"], "tick");
    send(&mut state, r#"{"api":1,"type":"answer","choice":1}"#).unwrap();
    // Within the second: the answer is reported, no tick yet.
    let next = reporter.due(&state, now + Duration::from_millis(10));
    assert_eq!(next.len(), 1, "{next:?}");
    assert_eq!(next[0]["type"], "answered");
    assert_eq!(next[0]["step"], n);
    assert_eq!(next[0]["answer"], 1);
    assert_eq!(next[0]["supported"], step.question.unwrap().answer + 1);
    let later = reporter.due(&state, now + TICK_EVERY);
    assert_eq!(later.len(), 1);
    assert_eq!(later[0]["type"], "tick");
}

#[test]
fn a_tick_gives_each_filters_error_by_its_id() {
    let mut state = AppState::from_fragment("lab=free-rotation");
    for _ in 0..20 {
        let _ = state.apply(RunCommand::StepOnce.into());
    }
    let tick = tick(&state);
    let errors = tick["errors_deg"].as_object().unwrap();
    assert_eq!(errors.len(), state.sim().estimators().len());
    for (id, error) in errors {
        let e = error.as_f64().unwrap_or_else(|| panic!("{id}: {error}"));
        assert!(e.is_finite() && e >= 0.0, "{id}: {e}");
    }
    assert!(tick["t"].as_f64().unwrap() > 0.0);
}
