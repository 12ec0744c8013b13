//! The Russian page writes its numbers with a decimal comma ("0,35 мм"), as the papers and
//! the Russian catalogue's own prose do; the English page with a point. References to a
//! section, an equation, a figure or a table keep their point in both ("§3.3", "рис. 5.3").

use super::harness;
use attlab::i18n::Lang;
use attlab::labs;
use attlab_web::AttLabApp;
use attlab_web::state::{RunCommand, ViewCommand};
use egui::Shape;
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT, Queryable};

/// What comes right before a number that is a reference, not a value: "§3.3", "рис. 5.3",
/// "ур. 4.1", "табл. 2.3", "(4.2)", and their English.
const REFERENCE_BEFORE: [&str; 9] = [
    "§",
    "рис. ",
    "ур. ",
    "табл. ",
    "(",
    "Fig. ",
    "Eq. ",
    "Table ",
    "eq. ",
];

/// The numbers in `text` written with a decimal `separator` between two digits (and not a
/// reference), each with a few characters around it.
fn numbers_with(text: &str, separator: char) -> Vec<String> {
    let chars: Vec<char> = text.chars().collect();
    let mut found = Vec::new();
    for i in 1..chars.len().saturating_sub(1) {
        if chars[i] != separator || !chars[i - 1].is_ascii_digit() || !chars[i + 1].is_ascii_digit()
        {
            continue;
        }
        let start = (0..i)
            .rev()
            .take_while(|&k| chars[k].is_ascii_digit())
            .last()
            .unwrap_or(i);
        let before: String = chars[..start].iter().collect();
        // "1,2,3" is a list in English, not a number; "2,5" is.
        let listed = separator == ','
            && (chars.get(i + 2) == Some(&',') || (start > 0 && chars[start - 1] == ','));
        if REFERENCE_BEFORE.iter().any(|r| before.ends_with(r)) || listed {
            continue;
        }
        let from = start.saturating_sub(12);
        let to = (i + 8).min(chars.len());
        found.push(chars[from..to].iter().collect());
    }
    found
}

/// Every text the page painted in its last frame.
fn painted(h: &Harness<'_, AttLabApp>) -> Vec<String> {
    (h.output().shapes.iter())
        .filter_map(|c| match &c.shape {
            Shape::Text(t) => Some(t.galley.text().to_owned()),
            _ => None,
        })
        .collect()
}

/// Lab `lab_id` in `lang`, `steps` steps into its run.
fn page_in(lab_id: &str, lang: Lang, steps: usize) -> Harness<'static, AttLabApp> {
    let mut h = harness(lab_id);
    h.state_mut().apply(ViewCommand::SetLang(lang).into());
    for _ in 0..steps {
        h.state_mut().apply(RunCommand::StepOnce.into());
    }
    h.run_steps(3);
    h
}

#[test]
fn the_number_finder_tells_values_from_references() {
    assert_eq!(numbers_with("t = 1.40 с", '.'), ["t = 1.40 с"]);
    assert!(numbers_with("как на рис. 5.3 и по ур. 4.1 (§3.3, табл. 2.3), (4.2)", '.').is_empty());
    assert!(numbers_with("0,35 мм", '.').is_empty());
    assert_eq!(numbers_with("0,35 мм", ',').len(), 1);
    assert!(numbers_with("[1,2,3] and 2, 3", ',').is_empty());
    assert!(numbers_with("Keldysh preprint 2014-64. 7 s", '.').is_empty());
}

/// Every lab in Russian, a second into its run: its sliders, plot ticks, status line, dial
/// and notes write every number with a comma, and the page shows such numbers at all. The
/// same page in English writes none with a comma.
#[test]
fn the_russian_page_writes_its_numbers_with_a_decimal_comma() {
    for lab in labs::all() {
        let steps =
            (1.0 / lab.dt_s(&attlab::model::ParamValues::defaults(lab.params()))).ceil() as usize;
        let ru = painted(&page_in(lab.id(), Lang::Ru, steps));
        let points: Vec<String> = ru.iter().flat_map(|t| numbers_with(t, '.')).collect();
        assert!(
            points.is_empty(),
            "{} in Russian writes a decimal point: {points:#?}",
            lab.id()
        );
        let commas = ru.iter().flat_map(|t| numbers_with(t, ',')).count();
        assert!(
            commas >= 5,
            "{}: only {commas} numbers with a comma",
            lab.id()
        );
        let en = painted(&page_in(lab.id(), Lang::En, steps));
        let commas: Vec<String> = en.iter().flat_map(|t| numbers_with(t, ',')).collect();
        assert!(
            commas.is_empty(),
            "{} in English writes a decimal comma: {commas:#?}",
            lab.id()
        );
    }
}

/// What paper 4's page adds on request, in Russian: the filter's cycle with its vectors and
/// matrices (entries apart by a semicolon or a wide space, as the comma is taken), and a
/// finished γ sweep with its argmins and its table.
#[test]
fn the_cycle_and_a_finished_sweep_write_decimal_commas_in_russian() {
    let mut h = page_in("p4", Lang::Ru, 7);
    h.state_mut().apply(ViewCommand::SetCycle(true).into());
    h.state_mut().apply(RunCommand::RunSweep(0).into());
    while !(h.state().state.run().sweep.as_ref()).is_some_and(|(_, s)| s.is_done()) {
        h.state_mut()
            .apply(RunCommand::AdvanceSweep(std::time::Duration::from_millis(50)).into());
    }
    h.run_steps(4);
    let argmin = attlab::i18n::t(Lang::Ru, "sweep-argmin");
    // "минимум J(": the argmin lines (the lab's summary says "минимум" too).
    let head = format!("{} J(", argmin.split('{').next().unwrap_or_default().trim());
    (h.query_all_by_label_contains(&head).next())
        .expect("the sweep's argmins on the panel")
        .scroll_to_me();
    h.run_steps(2);
    let texts = painted(&h);
    let points: Vec<String> = texts.iter().flat_map(|t| numbers_with(t, '.')).collect();
    assert!(points.is_empty(), "a decimal point: {points:#?}");
    // The cycle's state vector, "[a; b]" with both entries written with a comma.
    let state = texts
        .iter()
        .find(|t| t.starts_with('[') && t.contains("; ") && !t.contains(", "));
    assert!(state.is_some(), "no vector of the cycle: {texts:#?}");
    // The sweep's argmin lines (read by their accessible names: the side panel holds them
    // below its fold) name each objective's weights and the best γ with a comma.
    let argmins: Vec<String> = (h.query_all_by_label_contains(&head))
        .filter_map(|n| n.accesskit_node().label())
        .collect();
    assert_eq!(argmins.len(), 3, "{argmins:#?}");
    for line in &argmins {
        assert!(numbers_with(line, '.').is_empty(), "{line}");
        assert!(numbers_with(line, ',').len() >= 2, "{line}");
    }
}

/// What a screen reader hears of the run in Russian: the time and the errors with a comma.
#[test]
fn the_russian_narration_writes_its_numbers_with_a_decimal_comma() {
    let h = page_in("p2", Lang::Ru, 15);
    let text = attlab_web::panels::describe_run(&h.state().state);
    assert!(numbers_with(&text, '.').is_empty(), "{text}");
    assert!(numbers_with(&text, ',').len() >= 2, "{text}");
}
