//! A step of every lab's lesson opened from the teacher's link on a projector's 1280×720 in
//! presenter mode, its question answered in the link: the step opens, runs to its pause and
//! stops there, with nothing in the console; a screenshot of each for docs/lessons.md
//! (`target/page-test/screens/lesson-<lab>.png`).

use super::*;

/// How long a step may take to reach its pause (its own speed sets it: 10–15 s here).
const PAUSE_TIMEOUT: Duration = Duration::from_secs(90);

/// The link of step `n` of `lab`'s lesson with the answer the run shows chosen.
fn link(base: &str, lab: &dyn attlab::page::Lab, n: usize) -> String {
    let answer = lab
        .lesson()
        .and_then(|l| l.step(n))
        .and_then(|s| s.question)
        .map(|q| format!("&answers={n}{}", char::from(b'a' + q.answer as u8)))
        .unwrap_or_default();
    format!("{base}#lesson={}&step={n}{answer}&presenter=1", lab.id())
}

/// Polls the status until the run has paused at the step's pause.
fn wait_for_pause(session: &Session<'_>) -> Value {
    let start = Instant::now();
    let mut status = Value::Null;
    while start.elapsed() < PAUSE_TIMEOUT {
        if let Ok(Value::String(text)) = session.execute(STATUS_SCRIPT) {
            status = serde_json::from_str(&text).unwrap_or(Value::Null);
        }
        if status["playing"] == Value::Bool(false) {
            break;
        }
        sleep(Duration::from_millis(250));
    }
    status
}

/// The problems of each lab's lesson step opened from its link.
pub(crate) fn lesson_problems(session: &Session<'_>, base: &str) -> Vec<String> {
    let mut problems = Vec::new();
    if let Err(e) = session.set_viewport(Some((1280, 720)), false) {
        return vec![format!("cannot emulate a projector: {e}")];
    }
    for lab in attlab::labs::all() {
        let id = lab.id();
        let Some(n) = lab.lesson().and_then(|l| l.number_of(l.showcase)) else {
            problems.push(format!("{id}: no lesson, or its showcase is not a step"));
            continue;
        };
        let tag = format!("lesson {id} step {n}");
        if let Err(e) = session.open(&link(base, *lab, n)) {
            problems.push(format!("{tag}: navigate failed: {e}"));
            continue;
        }
        let status = wait_for_frames(session);
        problems.extend(
            status_problems(&status)
                .into_iter()
                .map(|p| format!("{tag}: {p}")),
        );
        let status = wait_for_pause(session);
        println!("page test: {tag}: attlabStatus = {status}");
        if status["lessonStep"].as_f64() != Some(n as f64) {
            problems.push(format!(
                "{tag}: the page shows step {:?}",
                status["lessonStep"]
            ));
        }
        if status["playing"] != Value::Bool(false) {
            problems.push(format!(
                "{tag}: not paused at its pause after {PAUSE_TIMEOUT:?}"
            ));
        }
        problems.extend(console_and_screenshot(
            session,
            &tag,
            &format!("screens/lesson-{id}.png"),
        ));
    }
    problems.extend(steady_problems_at_laptop(session, base));
    if let Err(e) = session.set_viewport(None, false) {
        problems.push(format!("cannot end the emulation: {e}"));
    }
    problems
}

/// Paper 2's first plot on a laptop once its filters have settled: scaled to the steady
/// error and its band, not to the first second (`screens/laptop-p2-steady.png`).
fn steady_problems_at_laptop(session: &Session<'_>, base: &str) -> Vec<String> {
    const SETTLED_S: f64 = 60.0;
    let tag = "p2's steady error on a laptop";
    if let Err(e) = session.set_viewport(Some((1366, 768)), false) {
        return vec![format!("{tag}: cannot emulate a laptop: {e}")];
    }
    if let Err(e) = session.open(&format!("{base}#lab=p2&speed=100&lang=en")) {
        return vec![format!("{tag}: navigate failed: {e}")];
    }
    let mut problems = status_problems(&wait_for_frames(session));
    let start = Instant::now();
    let mut t = 0.0;
    while start.elapsed() < PAUSE_TIMEOUT && t < SETTLED_S {
        if let Ok(Value::String(text)) = session.execute(STATUS_SCRIPT) {
            let status: Value = serde_json::from_str(&text).unwrap_or(Value::Null);
            t = status["tS"].as_f64().unwrap_or(0.0);
        }
        sleep(Duration::from_millis(250));
    }
    if t < SETTLED_S {
        problems.push(format!("{tag}: the run reached only {t:.1} s"));
    }
    problems.extend(console_and_screenshot(
        session,
        tag,
        "screens/laptop-p2-steady.png",
    ));
    problems
}
