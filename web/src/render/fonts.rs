//! Fonts: egui's default proportional font lacks several symbols the labs use (combining
//! accents as in φ̇, ϑ, ᵀ, primes, arrows, ▶ ✕ ⟲); a 60-KB subset of DejaVu Sans
//! (`assets/fonts/`, made by its `subset.sh`) is added as the fallback after it.

use std::sync::Arc;

/// The subset font.
const SYMBOLS: &[u8] = include_bytes!("../../../assets/fonts/DejaVuSans-symbols.ttf");

/// Installs the fallback font on `ctx` (both families).
pub fn install(ctx: &egui::Context) {
    let mut fonts = egui::FontDefinitions::default();
    fonts.font_data.insert(
        "dejavu-symbols".to_owned(),
        Arc::new(egui::FontData::from_static(SYMBOLS)),
    );
    for family in [egui::FontFamily::Proportional, egui::FontFamily::Monospace] {
        fonts
            .families
            .entry(family)
            .or_default()
            .push("dejavu-symbols".to_owned());
    }
    ctx.set_fonts(fonts);
}
