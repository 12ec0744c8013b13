//! The page as a screen reader and a keyboard user meet it, in headless Chromium:
//! - the accessibility tree (DevTools' `Accessibility.getFullAXTree`) holds every slider of
//!   the lab, named by its label, with its value;
//! - a keyboard-only walk: real key events (DevTools' `Input.dispatchKeyEvent`) Tab into the
//!   canvas, Space pauses the run, Tab goes on to paper 5's ε slider, End moves it to its
//!   greatest value, and the diagram of the update's eigenvalues, drawn for the current ε,
//!   changes on screen.
//!
//! Paused, the app draws only on input, so each key's frames end and the walk waits for the
//! page to settle; while it ran, every call waited for SwiftShader's frames (the walk took
//! about 90 s, 41 Tabs).

use super::*;
use attlab::model::ParamKind;
use attlab::page::Lab;

/// The slider the walk moves, and what it expects of it.
const WALK_LAB: &str = "p5";
const WALK_SLIDER: &str = "Regularisation ε";
const WALK_KEY: &str = "eps";
/// Tab presses the walk allows before it gives up.
const WALK_TABS: usize = 150;
/// Pixels of the diagram that must differ after the key (of about 300×300).
const MIN_CHANGED_PIXELS: usize = 200;

/// The page's accessibility tree: (role, name, value) of every node not ignored.
fn ax_tree(session: &Session<'_>) -> Result<Vec<(String, String, String)>, String> {
    let tree = session.cdp_value("Accessibility.getFullAXTree", json!({}))?;
    let nodes = tree["nodes"].as_array().ok_or("no nodes in the tree")?;
    let text = |v: &Value| match v {
        Value::String(s) => s.clone(),
        Value::Null => String::new(),
        other => other.to_string(),
    };
    Ok(nodes
        .iter()
        .filter(|n| n["ignored"] != true)
        .map(|n| {
            (
                text(&n["role"]["value"]),
                text(&n["name"]["value"]),
                text(&n["value"]["value"]),
            )
        })
        .collect())
}

/// The number a slider's value text starts with ("0.02 °/s" → 0.02).
fn leading_number(text: &str) -> Option<f64> {
    text.split_whitespace().next()?.parse().ok()
}

/// Problems with the open lab's sliders in the accessibility tree (defaults expected), and
/// with the live description (the caller names the lab and the screen).
pub(crate) fn tree_problems(session: &Session<'_>, lab: &dyn Lab) -> Vec<String> {
    let id = lab.id();
    let nodes = match ax_tree(session) {
        Ok(nodes) => nodes,
        Err(e) => return vec![format!("no accessibility tree: {e}")],
    };
    let sliders: Vec<&(String, String, String)> =
        nodes.iter().filter(|n| n.0 == "slider").collect();
    let mut problems = Vec::new();
    let real = |k: &ParamKind| matches!(k, ParamKind::Real | ParamKind::Integer);
    for spec in lab.params().iter().filter(|s| real(&s.kind)) {
        let Some((_, _, value)) = sliders.iter().find(|n| n.1 == spec.label) else {
            problems.push(format!("no slider named `{}` in the tree", spec.label));
            continue;
        };
        let read = leading_number(value);
        let close =
            read.is_some_and(|v| (v - spec.default).abs() <= 1e-6 * spec.default.abs().max(1e-9));
        if !close {
            problems.push(format!(
                "slider `{}` reads `{value}`, its value is {}",
                spec.label, spec.default
            ));
        }
    }
    let live = session
        .execute("return document.getElementById('attlab_live').textContent;")
        .unwrap_or(Value::Null);
    let live = live.as_str().unwrap_or_default();
    if !live.contains(" t = ") {
        problems.push(format!("the live description is `{live}`"));
    }
    println!(
        "page test: #lab={id}: {} sliders in the accessibility tree of {} nodes; live: {live}",
        sliders.len(),
        nodes.len()
    );
    problems
}

/// One real key press (down and up) through DevTools: trusted, as a keyboard sends it.
fn key(session: &Session<'_>, key: &str, code: u32) -> Result<(), String> {
    key_with(session, key, code, 0)
}

/// [`key`] with the DevTools protocol's `modifiers` (8: Shift) held.
pub(crate) fn key_with(
    session: &Session<'_>,
    key: &str,
    code: u32,
    modifiers: u32,
) -> Result<(), String> {
    // The physical key's name: the same as the key's but for Space.
    let code_name = if key == " " { "Space" } else { key };
    for kind in ["rawKeyDown", "keyUp"] {
        let event = json!({ "type": kind, "key": key, "code": code_name,
                            "windowsVirtualKeyCode": code, "nativeVirtualKeyCode": code,
                            "modifiers": modifiers });
        session.cdp_value("Input.dispatchKeyEvent", event)?;
    }
    Ok(())
}

/// Resolves, with the frame count, once the paused app has drawn no frame for `QUIET` ms
/// (a key's frames follow it within one animation frame), or after `MAX` ms.
const SETTLE_JS: &str = "const attlabSettled = () => new Promise(done => { \
    const frames = () => window.attlabStatus ? window.attlabStatus.frames : 0; \
    const t0 = performance.now(); let last = frames(), since = t0; \
    const tick = () => { const now = performance.now(), f = frames(); \
      if (f !== last) { last = f; since = now; } \
      (now - since >= QUIET || now - t0 > MAX) ? done(f) : setTimeout(tick, 20); }; \
    tick(); });\n";
/// Quiet time that counts as settled, and the longest wait (ms).
const SETTLE_QUIET_MS: u32 = 300;
const SETTLE_MAX_MS: u32 = 10_000;

/// A script that resolves `result` (an expression) once the paused page has settled.
fn after_settling(result: &str) -> String {
    let settle = SETTLE_JS
        .replace("QUIET", &SETTLE_QUIET_MS.to_string())
        .replace("MAX", &SETTLE_MAX_MS.to_string());
    format!("{settle} return attlabSettled().then(() => {result});")
}

/// Waits until the paused page has drawn a key's frames.
pub(crate) fn settle(session: &Session<'_>) {
    let _ = session.execute(&after_settling("null"));
}

/// The element the canvas names as the control with the keyboard once the page has settled:
/// (role, label).
pub(crate) fn active_control_after_settling(session: &Session<'_>) -> (String, String) {
    let control = "(() => { const c = document.getElementById('attlab_canvas'); \
        const id = c && c.getAttribute('aria-activedescendant'); \
        const e = id && document.getElementById(id); \
        return [e ? e.getAttribute('role') : '', e ? e.getAttribute('aria-label') : '']; })()";
    let v = session
        .execute(&after_settling(control))
        .unwrap_or(Value::Null);
    let s = |i: usize| v[i].as_str().unwrap_or_default().to_string();
    (s(0), s(1))
}

/// The keyboard-only walk on paper 5 (see the module's doc).
pub(crate) fn keyboard_walk_problems(session: &Session<'_>, base: &str) -> Vec<String> {
    let url = format!("{base}#lab={WALK_LAB}&lang=en");
    if let Err(e) = session.open(&url) {
        return vec![format!("keyboard walk: navigate failed: {e}")];
    }
    let status = wait_for_frames(session);
    let mut problems = status_problems(&status);
    let presses = match tab_to_walk_slider(session) {
        Ok(presses) => presses,
        Err(e) => {
            problems.push(format!("keyboard walk: {e}"));
            return problems;
        }
    };
    println!("page test: keyboard walk: {presses} Tabs to `{WALK_SLIDER}`");
    let diagram = |session: &Session<'_>| -> Result<Vec<[u8; 3]>, String> {
        settle(session);
        let status = wait_for_frames(session);
        let views = status["views"].as_array().cloned().unwrap_or_default();
        let index = diagram_index() as f64;
        let rect = views.iter().find(|v| v[0].as_f64() == Some(index));
        let rect = rect.ok_or_else(|| format!("no view {index} in {views:?}"))?;
        let zoom = status["zoom"].as_f64().unwrap_or(1.0);
        let r: Vec<f64> = (1..5)
            .map(|i| rect[i].as_f64().unwrap_or(0.0) * zoom)
            .collect();
        crop(&session.screenshot()?, [r[0], r[1], r[2], r[3]])
    };
    let before = diagram(session);
    if let Err(e) = key(session, "End", 35) {
        problems.push(format!("keyboard walk: End failed: {e}"));
    }
    let after = diagram(session);
    let fragment = session
        .execute("return location.hash;")
        .unwrap_or(Value::Null);
    let eps = attlab::labs::find(WALK_LAB).and_then(|lab| {
        lab.params()
            .iter()
            .find(|s| s.key == WALK_KEY)
            .map(|s| s.max)
    });
    let wanted = format!("{WALK_KEY}={}", eps.unwrap_or(f64::NAN));
    if !fragment.as_str().is_some_and(|f| f.contains(&wanted)) {
        problems.push(format!(
            "keyboard walk: after End the link is {fragment}, want {wanted}"
        ));
    }
    match (before, after) {
        (Ok(a), Ok(b)) if a.len() == b.len() => {
            let changed = a.iter().zip(&b).filter(|(p, q)| p != q).count();
            println!("page test: keyboard walk: End changed {changed} pixels of the diagram");
            if changed < MIN_CHANGED_PIXELS {
                problems.push(format!(
                    "keyboard walk: the diagram changed in {changed} pixels after End (want {MIN_CHANGED_PIXELS})"
                ));
            }
        }
        (a, b) => problems.push(format!(
            "keyboard walk: no diagram to compare: {:?} {:?}",
            a.err(),
            b.err()
        )),
    }
    problems
}

/// From no focus: Tab into the canvas, Space to pause, then Tab until the walk's slider has
/// the keyboard. The number of Tabs, the first one counted.
fn tab_to_walk_slider(session: &Session<'_>) -> Result<usize, String> {
    let _ = session.execute("document.activeElement && document.activeElement.blur();");
    pause_by_keyboard(session)?;
    for presses in 2..=WALK_TABS {
        key(session, "Tab", 9).map_err(|e| format!("Tab failed: {e}"))?;
        let (role, label) = active_control_after_settling(session);
        if role == "slider" && label == WALK_SLIDER {
            return Ok(presses);
        }
    }
    Err(format!("{WALK_TABS} Tabs never reached `{WALK_SLIDER}`"))
}

/// Tab into the canvas (no control has the keyboard yet), then Space: the run must pause.
fn pause_by_keyboard(session: &Session<'_>) -> Result<(), String> {
    key(session, "Tab", 9).map_err(|e| format!("Tab failed: {e}"))?;
    settle_running(session);
    key(session, " ", 32).map_err(|e| format!("Space failed: {e}"))?;
    let status = session
        .execute(&after_settling(
            "window.attlabStatus ? window.attlabStatus.playing : null",
        ))
        .unwrap_or(Value::Null);
    if status == Value::Bool(false) {
        Ok(())
    } else {
        Err(format!(
            "Space on the canvas, no control focused, did not pause the run (playing: {status})"
        ))
    }
}

/// Waits for two frames of the running page (the Tab's focus drawn).
fn settle_running(session: &Session<'_>) {
    let _ = session.execute(&format!("{LATER_JS} return attlabLater(2, 20000);"));
}

/// Where paper 5 draws its diagram: in the place of the w plane among its views.
fn diagram_index() -> usize {
    attlab::labs::find(WALK_LAB)
        .and_then(|lab| {
            let views = &lab.page().views;
            views
                .iter()
                .position(|v| *v == attlab::page::ViewKind::WPlane)
        })
        .unwrap_or(usize::MAX)
}

/// The pixels of `png` inside `[x, y, w, h]` (CSS pixels of a 1:1 screenshot).
fn crop(png: &[u8], [x, y, w, h]: [f64; 4]) -> Result<Vec<[u8; 3]>, String> {
    let width = png::Decoder::new(std::io::Cursor::new(png))
        .read_info()
        .map_err(|e| e.to_string())?
        .info()
        .width as usize;
    let pixels = rgb_pixels(png)?;
    let (x0, y0) = (x.max(0.0) as usize, y.max(0.0) as usize);
    let (x1, y1) = ((x + w) as usize, (y + h) as usize);
    if w < 20.0 || h < 20.0 || x1 > width {
        return Err(format!(
            "the diagram's place {x} {y} {w} {h} is not on the page"
        ));
    }
    Ok((y0..y1)
        .flat_map(|row| (x0..x1).map(move |col| (row, col)))
        .filter_map(|(row, col)| pixels.get(row * width + col).copied())
        .collect())
}
