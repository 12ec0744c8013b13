//! The page at a projector's size: every lab in presenter mode at 1280×720, its plot at
//! least 40 % of the window's height, a screenshot of each in `target/page-test/`.

use super::*;

/// A projector's screen (CSS pixels).
pub(crate) const PROJECTOR: (u32, u32) = (1280, 720);
/// The share of the window's height the plot must get at least.
const MIN_PLOT_SHARE: f64 = 0.40;

/// Problems of the layout `status` reports: the window's size as emulated, and the plot's
/// share of its height.
pub(crate) fn layout_problems(status: &Value, (w, h): (u32, u32)) -> Vec<String> {
    let rect = |key: &str| -> Option<[f64; 4]> {
        let a = status[key].as_array()?;
        let v: Vec<f64> = a.iter().filter_map(Value::as_f64).collect();
        <[f64; 4]>::try_from(v).ok()
    };
    let (Some(window), Some(plot)) = (rect("window"), rect("plotArea")) else {
        return vec![format!("attlabStatus has no window or plotArea: {status}")];
    };
    let mut problems = Vec::new();
    // Points times the zoom are CSS pixels.
    let zoom = status["zoom"].as_f64().unwrap_or(f64::NAN);
    let (css_w, css_h) = (window[2] * zoom, window[3] * zoom);
    if !((css_w - f64::from(w)).abs() <= 2.0 && (css_h - f64::from(h)).abs() <= 2.0) {
        problems.push(format!(
            "window is {css_w:.0}×{css_h:.0} CSS px (zoom {zoom}), not {w}×{h}"
        ));
    }
    let share = plot[3] / window[3];
    println!(
        "page test: plot {:.0}×{:.0} at y = {:.0}: {:.0} % of the window's height",
        plot[2],
        plot[3],
        plot[1],
        100.0 * share
    );
    if share < MIN_PLOT_SHARE {
        problems.push(format!(
            "the plot is {:.0} px high, {:.0} % of the window (want ≥ {:.0} %)",
            plot[3],
            100.0 * share,
            100.0 * MIN_PLOT_SHARE
        ));
    }
    problems
}

/// Every lab in presenter mode on a projector: frames, console, the plot's share and a
/// screenshot (`screenshot-presenter-<lab>.png`).
pub(crate) fn projector_problems(session: &Session<'_>, base: &str) -> Vec<String> {
    let mut problems = Vec::new();
    if let Err(e) = session.set_viewport(Some(PROJECTOR)) {
        return vec![format!("cannot emulate {PROJECTOR:?}: {e}")];
    }
    for lab in attlab::labs::all() {
        let id = lab.id();
        let tag = format!("presenter {id} at {}×{}", PROJECTOR.0, PROJECTOR.1);
        if let Err(e) = session.open(&format!("{base}#lab={id}&presenter=1")) {
            problems.push(format!("{tag}: navigate failed: {e}"));
            continue;
        }
        let status = wait_for_frames(session);
        let found = status_problems(&status)
            .into_iter()
            .chain(layout_problems(&status, PROJECTOR))
            .chain(console_and_screenshot(
                session,
                &tag,
                &format!("screenshot-presenter-{id}.png"),
            ));
        problems.extend(found.map(|p| format!("{tag}: {p}")));
    }
    if let Err(e) = session.set_viewport(None) {
        problems.push(format!("cannot end the emulation: {e}"));
    }
    problems
}
