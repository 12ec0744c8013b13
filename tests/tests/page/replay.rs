//! A recorded log through the page's own picker, as a student loads one: paper 4 on a
//! projector's 1280×720, the log panel opened and its load button pressed through the
//! accessibility mirror (a script's press: the browser refuses to open its chooser, which
//! the page must say, with the canvas still on top and drawing), a log whose Arduino sketch
//! restarted handed to the page's file input. The page must say what became of every line,
//! replay both segments and shade the join; a screenshot for a look
//! (`target/page-test/screens/replay-p4.png`).

use super::*;

/// The log panel's heading and load button (paper 4's format).
const PANEL: &str = "Real data: an Arduino MPU-6050 log";
const LOAD: &str = "Load MPU-6050 log…";
/// What the page must say once it replays the log below.
const SAID: [&str; 2] = ["replaying 600 samples of 601 lines", "clock gaps: 1"];

/// 300 samples, the sketch restarting (`millis()` from 0), 300 more, and a banner line.
fn restarted_log() -> String {
    let mut text = String::from("MPU6050 connection successful\n");
    for (k, t) in (0..300).chain(0..300).enumerate() {
        let roll = 20.0 * ((k as f64) / 100.0).sin();
        let (ay, az) = (roll.to_radians().sin(), roll.to_radians().cos());
        text += &format!(
            "{},0,{:.0},{:.0},{:.0},0,0\n",
            10 * t,
            ay * 16384.0,
            az * 16384.0,
            131.0 * 20.0 * ((k as f64) / 100.0).cos()
        );
    }
    text
}

/// Clicks the mirrored control labelled `label`; whether it was there.
pub(crate) fn click_mirrored(session: &Session<'_>, label: &str) -> bool {
    let script = format!(
        "const e = [...document.querySelectorAll('#attlab_a11y [aria-label]')]\
           .find(e => e.getAttribute('aria-label') === {label:?}); \
         if (e) {{ e.click(); }} return !!e;"
    );
    session
        .execute(&script)
        .is_ok_and(|v| v == Value::Bool(true))
}

/// Whether some mirrored text contains every part of `parts`.
pub(crate) fn mirror_says(session: &Session<'_>, parts: &[&str]) -> bool {
    let script = format!(
        "const parts = {}; return [...document.querySelectorAll('#attlab_a11y *')]\
           .some(e => {{ const t = (e.getAttribute('aria-label') || '') + ' ' + e.textContent; \
                        return parts.every(p => t.includes(p)); }});",
        json!(parts)
    );
    session
        .execute(&script)
        .is_ok_and(|v| v == Value::Bool(true))
}

/// Polls `ready` every 100 ms for up to 20 s.
pub(crate) fn eventually(mut ready: impl FnMut() -> bool) -> bool {
    let start = Instant::now();
    while start.elapsed() < Duration::from_secs(20) {
        if ready() {
            return true;
        }
        sleep(Duration::from_millis(100));
    }
    false
}

/// The page's file input (`attlab_web::pick::INPUT_ID`).
const INPUT: &str = "attlab-file-input";
/// What the page says when a script, not the student, pressed the load button: the browser
/// opens no chooser then.
const REFUSED: &str = "the browser opened no file window";

/// Hands `path` to the page's file input, as the browser's chooser would.
fn pick(session: &Session<'_>, path: &std::path::Path) -> Result<(), String> {
    let found = session.call(
        "POST",
        "/element",
        Some(&json!({ "using": "css selector", "value": format!("#{INPUT}") })),
    )?;
    let element = found
        .as_object()
        .and_then(|o| o.values().next())
        .and_then(Value::as_str)
        .ok_or("no file input")?
        .to_string();
    let text = path.display().to_string();
    session.call(
        "POST",
        &format!("/element/{element}/value"),
        Some(&json!({ "text": text })),
    )?;
    Ok(())
}

/// What covers the canvas once the load button was pressed: the page must keep the canvas
/// on top (no modal card over it) and keep drawing.
fn canvas_problems(session: &Session<'_>) -> Vec<String> {
    let top = "const e = document.elementFromPoint(innerWidth / 2, innerHeight / 2); \
               return e ? e.tagName + '#' + e.id : 'nothing';";
    let mut problems = Vec::new();
    match session.execute(top) {
        Ok(Value::String(t)) if t.starts_with("CANVAS") => {}
        other => problems.push(format!(
            "replay: after the load button the page's centre is {other:?}, not the canvas"
        )),
    }
    let frames = |s: &Session<'_>| {
        s.execute("return window.attlabStatus ? window.attlabStatus.frames : null;")
            .ok()
            .and_then(|v| v.as_u64())
    };
    let before = frames(session);
    if !eventually(|| frames(session) > before.map(|f| f + 3)) {
        problems.push(format!(
            "replay: no frames drawn after the load button (frames stayed {before:?})"
        ));
    }
    problems
}

/// The replay of a restarted log through the picker (see the module's doc).
#[test]
#[ignore = "needs the built site; `cargo xtask test` runs it with ATTLAB_PAGE_URL"]
fn a_log_picked_in_the_page_replays_with_its_join_shaded() {
    page_test("replay", replay_problems);
}

fn replay_problems(session: &Session<'_>, base: &str) -> Vec<String> {
    let size = (1280, 720);
    if let Err(e) = session.set_viewport(Some(size), false) {
        return vec![format!("replay: cannot emulate 1280×720: {e}")];
    }
    let path = out_dir().join("restarted-log.csv");
    if let Err(e) = std::fs::write(&path, restarted_log()) {
        return vec![format!("replay: cannot write {}: {e}", path.display())];
    }
    if let Err(e) = session.open(&format!("{base}#lab=p4&lang=en")) {
        return vec![format!("replay: navigate failed: {e}")];
    }
    let mut problems = status_problems(&wait_for_frames(session));
    if !eventually(|| click_mirrored(session, PANEL)) {
        problems.push(format!("replay: no control `{PANEL}` in the mirror"));
    }
    if !eventually(|| click_mirrored(session, LOAD)) {
        problems.push(format!("replay: no control `{LOAD}` in the mirror"));
    }
    let ready = eventually(|| {
        session
            .execute(&format!("return !!document.getElementById('{INPUT}');"))
            .is_ok_and(|v| v == Value::Bool(true))
    });
    if !eventually(|| mirror_says(session, &[REFUSED])) {
        problems.push(format!("replay: a script's press did not say `{REFUSED}`"));
    }
    problems.extend(canvas_problems(session));
    match (ready, ready.then(|| pick(session, &path))) {
        (true, Some(Ok(()))) => {}
        (_, Some(Err(e))) => problems.push(format!("replay: the picker: {e}")),
        _ => problems.push("replay: the load button opened no picker".into()),
    }
    if !eventually(|| mirror_says(session, &SAID)) {
        problems.push(format!("replay: the page never said {SAID:?}"));
    }
    // Past the join (3 s of samples, 1 s of join) into the second segment.
    sleep(Duration::from_secs(6));
    problems.extend(console_and_screenshot(
        session,
        "replay p4 at 1280×720",
        "screens/replay-p4.png",
    ));
    if let Err(e) = session.set_viewport(None, false) {
        problems.push(format!("replay: cannot end the emulation: {e}"));
    }
    problems
}
