//! Fonts: the app ships its own subsets instead of egui's bundled fonts (eframe's
//! `default_fonts` feature is off; the whole Ubuntu-Light and Hack files were 0.67 MB of the
//! wasm). `assets/fonts/subset.py` cuts them:
//! - `AttLabSans` (Ubuntu-Light: Latin, Greek, Cyrillic, punctuation, super/subscripts),
//! - `AttLabMono` (Hack, the same ranges),
//! - `DejaVuSans-symbols`: what the labs' labels use beyond those — combining accents as in φ̇,
//!   ϑ, ᵀ, primes, arrows, maths, ▶ ✕ ⟲ — as the fallback of both families.
//!
//! The page fetches the three files beside its wasm (`index.html` hands them to `start`);
//! the desktop app and the tests carry them in the binary.
//!
//! In the browser, a character none of them has (a CJK column name in an imported log) is still
//! drawn by eframe's canvas glyph fallback; on the desktop it shows as a box.

use std::sync::{Arc, OnceLock};

/// The fonts' files, as the site serves them (`assets/fonts/`): (name, file).
pub const FILES: [(&str, &str); 3] = [
    ("sans", "AttLabSans.ttf"),
    ("mono", "AttLabMono.ttf"),
    ("symbols", "DejaVuSans-symbols.ttf"),
];

/// The proportional font (a subset of Ubuntu-Light), the monospace font (a subset of Hack)
/// and the symbols fallback (a subset of DejaVu Sans). The desktop app and the tests carry
/// them in the binary; the page fetches the same files beside the wasm (see `index.html`):
/// they are 0.19 MB that a new release of the code need not send again, since the browser
/// and the service worker keep them apart from the wasm.
#[cfg(not(target_arch = "wasm32"))]
fn bundled() -> [&'static [u8]; 3] {
    [
        include_bytes!("../../../assets/fonts/AttLabSans.ttf"),
        include_bytes!("../../../assets/fonts/AttLabMono.ttf"),
        include_bytes!("../../../assets/fonts/DejaVuSans-symbols.ttf"),
    ]
}

/// The fonts the page fetched, handed over by `start` before the app's first frame.
static FETCHED: OnceLock<[Vec<u8>; 3]> = OnceLock::new();

/// Keeps the fonts the page fetched (sans, mono, symbols) for [`install`]; `false` if they
/// were given already.
pub fn provide(sans: Vec<u8>, mono: Vec<u8>, symbols: Vec<u8>) -> bool {
    FETCHED.set([sans, mono, symbols]).is_ok()
}

/// The three fonts' bytes: bundled (desktop, tests) or fetched (the page).
fn bytes() -> Vec<Arc<[u8]>> {
    #[cfg(not(target_arch = "wasm32"))]
    if FETCHED.get().is_none() {
        return bundled().iter().map(|b| Arc::from(*b)).collect();
    }
    FETCHED
        .get()
        .map(|f| f.iter().map(|b| Arc::from(b.as_slice())).collect())
        .unwrap_or_default()
}

/// The app's font set: each family's fonts in fallback order (empty in the page until the
/// fonts are provided).
pub fn definitions() -> egui::FontDefinitions {
    let mut fonts = egui::FontDefinitions::empty();
    for ((name, _), data) in FILES.iter().zip(bytes()) {
        fonts.font_data.insert(
            (*name).to_owned(),
            Arc::new(egui::FontData::from_owned(data.to_vec())),
        );
    }
    let chain = |names: &[&str]| names.iter().map(|n| (*n).to_owned()).collect::<Vec<_>>();
    fonts
        .families
        .insert(egui::FontFamily::Proportional, chain(&["sans", "symbols"]));
    fonts.families.insert(
        egui::FontFamily::Monospace,
        chain(&["mono", "sans", "symbols"]),
    );
    fonts
}

/// Installs the app's fonts on `ctx`.
pub fn install(ctx: &egui::Context) {
    ctx.set_fonts(definitions());
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::BTreeMap;
    use std::path::Path;

    /// Every non-ASCII character inside a string or char literal of `src`, with the first
    /// place it appears. Comments (`//…`) are skipped; the scan is line-based, which is
    /// enough for this code base (no multi-line string literals hold symbols).
    fn literal_chars(src: &str, file: &str, out: &mut BTreeMap<char, String>) {
        for (n, line) in src.lines().enumerate() {
            if line.trim_start().starts_with("//") {
                continue;
            }
            let mut in_str = false;
            let mut escaped = false;
            let mut prev = ' ';
            for c in line.chars() {
                if !in_str && c == '/' && prev == '/' {
                    break;
                }
                if in_str {
                    if escaped {
                        escaped = false;
                    } else if c == '\\' {
                        escaped = true;
                    } else if c == '"' {
                        in_str = false;
                    } else if !c.is_ascii() {
                        out.entry(c).or_insert_with(|| format!("{file}:{}", n + 1));
                    }
                } else if c == '"' {
                    in_str = true;
                } else if !c.is_ascii() {
                    // Char literals ('▶') count too.
                    out.entry(c).or_insert_with(|| format!("{file}:{}", n + 1));
                }
                prev = c;
            }
        }
    }

    fn scan(dir: &Path, out: &mut BTreeMap<char, String>) {
        for entry in std::fs::read_dir(dir).expect("source folder") {
            let path = entry.expect("entry").path();
            if path.is_dir() {
                scan(&path, out);
            } else if path.extension().is_some_and(|e| e == "rs") {
                let text = std::fs::read_to_string(&path).expect("source file");
                literal_chars(&text, &path.display().to_string(), out);
            } else if path.extension().is_some_and(|e| e == "ftl") {
                // A message catalogue: every character of its messages (comments aside).
                let text = std::fs::read_to_string(&path).expect("catalogue");
                for (n, line) in text.lines().enumerate() {
                    if line.trim_start().starts_with('#') {
                        continue;
                    }
                    for c in line.chars().filter(|c| !c.is_ascii()) {
                        let at = format!("{}:{}", path.display(), n + 1);
                        out.entry(c).or_insert(at);
                    }
                }
            }
        }
    }

    /// A label that uses a character none of the subsets has would show as a box on the
    /// desktop (and lean on the browser's fonts in the page): regenerate the subsets with
    /// `assets/fonts/subset.py` after adding its range there.
    #[test]
    fn every_label_has_a_glyph() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
        let mut chars = BTreeMap::new();
        for dir in ["web/src", "crate/src", "crate/locales"] {
            scan(&root.join(dir), &mut chars);
        }
        assert!(
            chars.contains_key(&'ϑ') && chars.contains_key(&'▶') && chars.contains_key(&'ж'),
            "the scan found neither ϑ (p3's labels), ▶ (the run button) nor ж (Russian): {} characters",
            chars.len()
        );
        let ctx = egui::Context::default();
        install(&ctx);
        ctx.run_ui(egui::RawInput::default(), |_| {})
            .textures_delta
            .clear();
        let missing: Vec<String> = ctx.fonts_mut(|fonts| {
            chars
                .iter()
                .filter(|(c, _)| !c.is_control())
                .filter(|(c, _)| {
                    [
                        egui::FontId::proportional(14.0),
                        egui::FontId::monospace(14.0),
                    ]
                    .iter()
                    .any(|id| !fonts.has_glyph(id, **c))
                })
                .map(|(c, at)| format!("{c:?} U+{:04X} at {at}", *c as u32))
                .collect()
        });
        assert!(missing.is_empty(), "no glyph for: {missing:#?}");
    }

    /// The subsets keep what a number, a unit or a Greek symbol needs.
    #[test]
    fn text_ranges_are_covered() {
        let ctx = egui::Context::default();
        install(&ctx);
        ctx.run_ui(egui::RawInput::default(), |_| {})
            .textures_delta
            .clear();
        let sample = "0123456789 ABCxyz °±×÷µ·² αβγδθσφψωΔΣΦΩ –—‘’“”…′″ ⁻¹ ₀₁ →←↑↓ ≈≤≥∞√∑∫ φ̇ ϑ ᵀ ▶✕⟲ \
             АБВГДЕЁЖЗИЙКЛМНОПРСТУФХЦЧШЩЪЫЬЭЮЯ абвгдеёжзийклмнопрстуфхцчшщъыьэюя «»№";
        for family in [
            egui::FontId::proportional(14.0),
            egui::FontId::monospace(14.0),
        ] {
            let lacking: Vec<char> = ctx.fonts_mut(|f| {
                sample
                    .chars()
                    .filter(|c| !c.is_whitespace() && !f.has_glyph(&family, *c))
                    .collect()
            });
            assert!(lacking.is_empty(), "{family:?} lacks {lacking:?}");
        }
    }
}
