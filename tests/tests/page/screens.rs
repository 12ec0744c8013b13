//! The page on the screens it is used on: every lab in presenter mode (light theme) on a
//! projector's 1280×720, on a laptop's 1366×768 (in English and in Russian), on a 390×844
//! phone (touch, stacked) and on the same phone held sideways, 844×390 (one view beside the
//! plot);
//! its plot a fair share of the window's height on each, a screenshot of each in
//! `target/page-test/screens/` (docs/page.md shows them).

use super::*;

/// A screen the page is tried on.
pub(crate) struct Screen {
    /// Name in file names and messages.
    pub name: &'static str,
    /// CSS pixels.
    pub size: (u32, u32),
    /// What the link adds (`&presenter=1`).
    pub link: &'static str,
    /// A phone: touch events and the mobile viewport.
    pub mobile: bool,
    /// The share of the window's height the plot must get at least.
    pub min_plot_share: f64,
    /// Check the accessibility tree too: every slider named as in English, with its value
    /// (the English screen that shows every slider outside presenter mode).
    pub tree: bool,
}

/// The screens, as the issue that asked for them names them, and the laptop in Russian.
pub(crate) const SCREENS: [Screen; 5] = [
    Screen {
        name: "projector",
        size: (1280, 720),
        link: "&presenter=1",
        mobile: false,
        min_plot_share: 0.40,
        tree: false,
    },
    Screen {
        name: "laptop",
        size: (1366, 768),
        // English whatever the browser's language: the tree is checked by English labels.
        link: "&lang=en",
        mobile: false,
        min_plot_share: 0.40,
        tree: true,
    },
    // A phone stacks the view above the plot and the plot's legend below it: the plot
    // shares the height with both.
    Screen {
        name: "russian",
        size: (1366, 768),
        link: "&lang=ru",
        mobile: false,
        min_plot_share: 0.40,
        tree: false,
    },
    Screen {
        name: "phone",
        size: (390, 844),
        link: "",
        mobile: true,
        min_plot_share: 0.25,
        tree: false,
    },
    // Sideways the phone's bar spans the top and one view stands beside the plot, which
    // gets what a laptop's does.
    Screen {
        name: "sideways",
        size: (844, 390),
        link: "",
        mobile: true,
        min_plot_share: 0.40,
        tree: false,
    },
];

/// Problems of the layout `status` reports: the window's size as emulated, and the plot's
/// share of its height.
pub(crate) fn layout_problems(status: &Value, (w, h): (u32, u32), min_share: f64) -> Vec<String> {
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
    if share < min_share {
        problems.push(format!(
            "the plot is {:.0} px high, {:.0} % of the window (want ≥ {:.0} %)",
            plot[3],
            100.0 * share,
            100.0 * min_share
        ));
    }
    problems
}

/// Every lab on every screen: frames, the lab its link opened, console, the plot's share and
/// a screenshot (`screens/<screen>-<lab>.png`); on the laptop's, the accessibility tree.
pub(crate) fn screen_problems(session: &Session<'_>, base: &str) -> Vec<String> {
    let mut problems = Vec::new();
    for screen in &SCREENS {
        if let Err(e) = session.set_viewport(Some(screen.size), screen.mobile) {
            problems.push(format!("cannot emulate {}: {e}", screen.name));
            continue;
        }
        for lab in attlab::labs::all() {
            let id = lab.id();
            let (w, h) = screen.size;
            let tag = format!("{} {id} at {w}×{h}", screen.name);
            if let Err(e) = session.open(&format!("{base}#lab={id}{}", screen.link)) {
                problems.push(format!("{tag}: navigate failed: {e}"));
                continue;
            }
            let status = wait_for_frames(session);
            let opened = (status["lab"].as_str() != Some(id))
                .then(|| format!("the link opened lab {:?}", status["lab"]));
            let tree = if screen.tree {
                println!("page test: #lab={id}: attlabStatus = {status}");
                super::a11y::tree_problems(session, *lab)
            } else {
                Vec::new()
            };
            let found = status_problems(&status)
                .into_iter()
                .chain(opened)
                .chain(tree)
                .chain(layout_problems(&status, screen.size, screen.min_plot_share))
                .chain(boot_problems(session, screen))
                .chain(console_and_screenshot(
                    session,
                    &tag,
                    &format!("screens/{}-{id}.png", screen.name),
                ));
            problems.extend(found.map(|p| format!("{tag}: {p}")));
        }
    }
    if let Err(e) = session.set_viewport(None, false) {
        problems.push(format!("cannot end the emulation: {e}"));
    }
    problems
}

/// The words index.html shows before the app starts (its loading line) must be in the
/// language the app then chose (`<html lang>`, which the app sets too): Russian on the
/// screen whose link asks for it.
fn boot_problems(session: &Session<'_>, screen: &Screen) -> Vec<String> {
    let script = "return [document.querySelector('[data-word=boot-loading]')?.textContent ?? null, \
                  document.documentElement.lang];";
    let seen = match session.execute(script) {
        Ok(v) => v,
        Err(e) => return vec![format!("cannot read the loading line: {e}")],
    };
    let (Some(text), Some(code)) = (seen[0].as_str(), seen[1].as_str()) else {
        return vec![format!("no loading line or <html lang>: {seen}")];
    };
    let Some(lang) = attlab::i18n::Lang::from_tag(code) else {
        return vec![format!(
            "<html lang={code:?}> is not a language the page speaks"
        )];
    };
    let mut problems = Vec::new();
    if screen.link.contains("lang=ru") && lang != attlab::i18n::Lang::Ru {
        problems.push(format!("the link asks for Russian, the page is in {code}"));
    }
    let expected = attlab::i18n::t(lang, "boot-loading");
    if text != expected {
        problems.push(format!(
            "the loading line says {text:?}, not {expected:?} ({code})"
        ));
    }
    problems
}
