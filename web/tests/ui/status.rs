//! The status line at the bottom: a job under way (a plot's re-run, a CSV export) says what
//! it does in the page's language, with its share done.

use super::legend::window;
use attlab_web::state::IoCommand;
use egui::epaint::Shape;

/// Every text the last frame painted.
fn painted(h: &egui_kittest::Harness<'_, attlab_web::AttLabApp>) -> Vec<String> {
    (h.output().shapes.iter())
        .filter_map(|c| match &c.shape {
            Shape::Text(t) => Some(t.galley.text().to_owned()),
            _ => None,
        })
        .collect()
}

/// A CSV export of 20 000 steps of paper 2 (a re-run of ≥ 0.2 s, many frames' budgets):
/// the progress bar reads "Выгрузка всех отсчётов в CSV · N %" in Russian and "Exporting
/// every sample as CSV · N %" in English (its words were English in every language).
#[test]
fn a_job_under_way_says_what_it_does_in_the_readers_language() {
    for (lang, words) in [
        ("ru", "Выгрузка всех отсчётов в CSV · "),
        ("en", "Exporting every sample as CSV · "),
    ] {
        let fragment = format!("lab=p2&lang={lang}");
        let mut h = window(&fragment, 20_000, (egui::vec2(1280.0, 800.0), 1.0));
        h.state_mut().apply(IoCommand::ExportCsv.into());
        h.run_steps(1);
        assert!(
            h.state().state.run().job().is_some(),
            "{lang}: the export ended within one frame"
        );
        let texts = painted(&h);
        let bar = texts.iter().find(|t| t.starts_with(words));
        let bar = bar.unwrap_or_else(|| panic!("{lang}: no “{words}…” in {texts:?}"));
        assert!(bar.ends_with(" %"), "{lang}: {bar}");
    }
}
