//! Time travel in the page (issue 58): paper 2 run to 1 500 s by the link (`at=1500`), the
//! timeline reached by Shift+Tab and moved back to 1 390 s with Shift+←, the star tracker's sun exclusion set to 0 there
//! (through the page's own postMessage API, as a host would) and "What if…" pressed; after
//! 200 s more both runs are drawn and the branch's summary is in the screen reader's
//! mirror, with no console error; screenshots at a projector's 1280×720 and a 390×844 phone.

use super::a11y::{active_control_after_settling, key_with, settle};
use super::*;

/// The moment the issue names: paper 2's star tracker is blinded by the sun near it.
const BRANCH_S: f64 = 1390.0;

/// The run's time now (s), from the status object.
fn t_now(session: &Session<'_>) -> f64 {
    session
        .execute("return window.attlabStatus ? window.attlabStatus.tS : 0;")
        .ok()
        .and_then(|v| v.as_f64())
        .unwrap_or(0.0)
}

/// The moment the focused timeline shows ("Timeline: t = 1390.00 s"), if it has the keys.
fn shown_t(session: &Session<'_>) -> Option<f64> {
    let (_, label) = active_control_after_settling(session);
    (label.strip_prefix("Timeline: t = "))
        .and_then(|rest| rest.split(' ').next())
        .and_then(|n| n.parse::<f64>().ok())
}

/// The two numbers of the what-if's summary line in the mirror ("…: 0.0011° → 0.0004°").
fn summary(session: &Session<'_>) -> Option<(f64, f64)> {
    let text = session
        .execute(
            "const said = e => e.getAttribute('aria-label') || e.textContent || ''; \
             const e = [...document.querySelectorAll('#attlab_a11y *')]\
               .find(e => said(e).includes('attitude error over the next')); \
             return e ? said(e) : null;",
        )
        .ok()?;
    let text = text.as_str()?;
    let (left, right) = text.split_once('→')?;
    let number = |s: &str| s.trim().trim_end_matches('°').parse::<f64>().ok();
    Some((number(left.rsplit(' ').nth(1)?)?, number(right)?))
}

/// A request of the host API (docs/embed.md) from the page's own origin, as a message event
/// without a source window (the page ignores what it posts to itself).
fn request(session: &Session<'_>, message: &str) -> Result<Value, String> {
    session.execute(&format!(
        "window.dispatchEvent(new MessageEvent('message', \
           {{ data: {message}, origin: location.origin }})); return true;"
    ))
}

/// Shift+Tab (the timeline is near the end of the page's order) until the control with
/// the keyboard is the timeline; how many presses it took.
fn tab_to_timeline(session: &Session<'_>) -> Result<usize, String> {
    for presses in 1..=160 {
        key_with(session, "Tab", 9, 8)?;
        let (role, label) = active_control_after_settling(session);
        if role == "slider" && label.starts_with("Timeline") {
            return Ok(presses);
        }
    }
    Err("160 Shift+Tabs never reached the timeline".into())
}

pub(crate) fn travel_problems(session: &Session<'_>, base: &str) -> Vec<String> {
    let _ = session.set_viewport(Some((1280, 720)), false);
    // The link runs to 1 500 s and shows that moment (the cursor), paused.
    if let Err(e) = session.open(&format!(
        "{base}#lab=p2&lang=en&speed=100&star_sun_exclusion_deg=90&at=1500"
    )) {
        return vec![format!("time travel: navigate failed: {e}")];
    }
    let mut problems = status_problems(&wait_for_frames(session));
    if !eventually(|| mirror_says(session, &["Timeline: now, t = 1500"])) {
        problems.push(format!(
            "time travel: the link's at=1500 not shown ({} s)",
            t_now(session)
        ));
        return problems;
    }
    match tab_to_timeline(session) {
        Ok(n) => println!("page test: time travel: {n} Shift+Tabs to the timeline"),
        Err(e) => {
            problems.push(format!("time travel: {e}"));
            return problems;
        }
    }
    let from = 1500.0;
    let back = (from - BRANCH_S).round() as usize;
    // Shift+← `back` times, as fast as keys come (every press of a frame counts).
    let presses = format!(
        "const c = document.querySelector('canvas'); \
         for (let i = 0; i < {back}; i++) {{ for (const type of ['keydown', 'keyup']) {{ \
           c.dispatchEvent(new KeyboardEvent(type, {{ key: 'ArrowLeft', code: 'ArrowLeft', \
             shiftKey: true, bubbles: true }})); }} }} return true;"
    );
    if let Err(e) = session.execute(&presses) {
        problems.push(format!("time travel: Shift+← failed: {e}"));
    }
    let wanted = from - back as f64;
    let there = || shown_t(session).is_some_and(|t| (t - wanted).abs() <= 0.2);
    if !eventually(there) {
        let (_, label) = active_control_after_settling(session);
        problems.push(format!(
            "time travel: after {back} Shift+← from {from} s the timeline says `{label}`"
        ));
    }
    problems.extend(branch_and_run(session));
    problems
}

/// At the cursor: the sun exclusion at 0, "What if…", 200 s more; the second run's chip and
/// summary, and the screenshots.
fn branch_and_run(session: &Session<'_>) -> Vec<String> {
    let mut problems = Vec::new();
    let set = "{ api: 1, type: 'set', id: 7, params: { star_sun_exclusion_deg: 0 } }";
    if let Err(e) = request(session, set) {
        problems.push(format!("time travel: setting the exclusion failed: {e}"));
    }
    settle(session);
    if !click_mirrored(session, "What if…") {
        problems.push("time travel: no What if… button at the cursor".into());
    }
    // What if… went back to now, paused as the link left it: play 200 s more.
    if !eventually(|| mirror_says(session, &["What if 1"])) {
        problems.push("time travel: What if… made no second run".into());
    }
    let _ = request(session, "{ api: 1, type: 'play', id: 9 }");
    let end = 1500.0 + 200.0;
    if !eventually(|| t_now(session) >= end) {
        problems.push(format!(
            "time travel: the run stopped at {} s",
            t_now(session)
        ));
    }
    let _ = request(session, "{ api: 1, type: 'pause', id: 8 }");
    let chip = ["What if 1", "Star-tracker sun exclusion = 0"];
    if !eventually(|| mirror_says(session, &chip)) {
        problems.push(format!("time travel: the mirror never said {chip:?}"));
    }
    // The second run catches up with the first within the frames' budget.
    eventually(|| summary(session).is_some());
    match summary(session) {
        Some((before, after)) if before != after => {
            println!("page test: time travel: the what-if's summary {before}° → {after}°");
        }
        other => problems.push(format!("time travel: the what-if's summary is {other:?}")),
    }
    problems.extend(console_and_screenshot(
        session,
        "time travel",
        "screens/travel-p2.png",
    ));
    let _ = session.set_viewport(Some((390, 844)), true);
    settle(session);
    problems.extend(console_and_screenshot(
        session,
        "time travel (phone)",
        "screens/travel-p2-phone.png",
    ));
    let _ = session.set_viewport(None, false);
    problems
}
