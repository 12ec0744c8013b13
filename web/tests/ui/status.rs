//! The status line at the bottom: a job under way (a plot's re-run, a CSV export) says what
//! it does in the page's language, with its share done.

use super::legend::window;
use super::painted;
use attlab_web::state::IoCommand;
use egui::epaint::Shape;

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

/// The engineer's status line (time, step, rates, frame, recorder) on a laptop, 1366×768:
/// one line in both languages for every lab (the Russian had wrapped, its last words on a
/// second line the plot gave up), and the Russian with the plural its count asks for
/// ("194 ряда", "41 ряд", "8 рядов").
#[test]
fn the_status_line_is_one_line_on_a_laptop_and_its_count_agrees() {
    for lab in attlab::labs::all() {
        // At the top speed the pace's numbers are at their widest ("×9876,54 … задано ×10000").
        for (lang, speed) in [("en", 1.0), ("ru", 1.0), ("en", 10_000.0), ("ru", 10_000.0)] {
            let fragment = format!("lab={}&lang={lang}&speed={speed}", lab.id());
            let h = window(&fragment, 10, (egui::vec2(1366.0, 768.0), 1.0));
            let status = (h.output().shapes.iter()).find_map(|c| match &c.shape {
                Shape::Text(t) if t.galley.text().starts_with("t =") => Some(t.galley.clone()),
                _ => None,
            });
            let status = status.unwrap_or_else(|| panic!("{fragment}: no status line"));
            assert_eq!(status.rows.len(), 1, "{fragment}: {}", status.text());
            eprintln!(
                "WIDTH {fragment} {} {}",
                status.rect.width(),
                status.text().chars().count()
            );
            let series = h.state().state.sim().recorder().specs().len();
            if lang == "ru" {
                let word = match (series % 10, series % 100) {
                    (1, n) if n != 11 => "ряд,",
                    (2..=4, n) if !(12..=14).contains(&n) => "ряда,",
                    _ => "рядов,",
                };
                let said = format!("({series} {word}");
                assert!(
                    status.text().contains(&said),
                    "{fragment}: {}",
                    status.text()
                );
            }
        }
    }
}
