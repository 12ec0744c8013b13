//! The Russian page writes its numbers with a decimal comma ("0,35 мм"), as the papers and
//! the Russian catalogue's own prose do; the English page with a point. References to a
//! section, an equation, a figure or a table keep their point in both ("§3.3", "рис. 5.3").

use super::{harness, harness_from_link, painted};
use attlab::i18n::Lang;
use attlab::labs;
use attlab_web::AttLabApp;
use attlab_web::state::{RunCommand, ViewCommand};
use egui::accesskit::Role;
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT, Queryable};

/// What comes right before a number that is a reference, not a value: "§3.3", "рис. 5.3",
/// "ур. 4.1", "табл. 2.3", and their English. (An equation's "(4.2)" is told by its
/// brackets on both sides.)
const REFERENCE_BEFORE: [&str; 8] = [
    "§",
    "рис. ",
    "ур. ",
    "табл. ",
    "Fig. ",
    "Eq. ",
    "Table ",
    "eq. ",
];

/// The numbers in `text` written with a decimal `separator` between two digits (and not a
/// reference), each with a few characters around it.
fn numbers_with(text: &str, separator: char) -> Vec<String> {
    let chars: Vec<char> = text.chars().collect();
    let digit = |k: usize| chars.get(k).is_some_and(char::is_ascii_digit);
    let mut found = Vec::new();
    for i in 1..chars.len() {
        if chars[i] != separator || !digit(i - 1) || !digit(i + 1) {
            continue;
        }
        let start = (0..i).rev().take_while(|&k| digit(k)).last().unwrap_or(i);
        let end = (i + 1..chars.len())
            .find(|&k| !digit(k))
            .unwrap_or(chars.len());
        let before: String = chars[..start].iter().collect();
        let equation = before.ends_with('(') && chars.get(end) == Some(&')');
        // "1,2,3" is a list in English, not a number; "2,5" is.
        let listed = separator == ','
            && (chars.get(end) == Some(&',') || (start > 0 && chars[start - 1] == ','));
        if REFERENCE_BEFORE.iter().any(|r| before.ends_with(r)) || equation || listed {
            continue;
        }
        let from = start.saturating_sub(12);
        found.push(chars[from..(end + 4).min(chars.len())].iter().collect());
    }
    found
}

/// The painted numbers with a decimal point, which a Russian page must not have.
fn points_in(texts: &[String]) -> Vec<String> {
    texts.iter().flat_map(|t| numbers_with(t, '.')).collect()
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
    let references = "как на рис. 5.3 и по ур. 4.1 (§3.3, табл. 2.3), (4.2)";
    assert!(numbers_with(references, '.').is_empty());
    assert_eq!(numbers_with("(0.35 мм)", '.').len(), 1);
    assert_eq!(numbers_with("(0.35)", '.').len(), 0);
    assert!(numbers_with("0,35 мм", '.').is_empty());
    assert_eq!(numbers_with("0,35 мм", ',').len(), 1);
    assert_eq!(numbers_with("x = 12.5", '.').len(), 1);
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
        let points = points_in(&ru);
        assert!(points.is_empty(), "{} in Russian: {points:#?}", lab.id());
        let commas = ru.iter().flat_map(|t| numbers_with(t, ',')).count();
        assert!(commas >= 5, "{}: {commas} numbers with a comma", lab.id());
        let en = painted(&page_in(lab.id(), Lang::En, steps));
        let commas: Vec<String> = en.iter().flat_map(|t| numbers_with(t, ',')).collect();
        assert!(commas.is_empty(), "{} in English: {commas:#?}", lab.id());
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
    let points = points_in(&texts);
    assert!(points.is_empty(), "a decimal point: {points:#?}");
    // The cycle's vectors, "[a; b]" (a matrix has an em space in its rows), each decimal
    // entry with a comma.
    let vectors: Vec<&String> = (texts.iter())
        .filter(|t| t.starts_with('[') && t.contains("; ") && !t.contains('\u{2003}'))
        .collect();
    assert!(vectors.len() >= 3, "the cycle's vectors: {texts:#?}");
    for v in vectors {
        let entries = v.trim_matches(['[', ']']).split("; ");
        let decimals = entries.filter(|e| e.contains(['.', ','])).count();
        assert!(
            decimals > 0 && numbers_with(v, ',').len() == decimals,
            "{v}"
        );
    }
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

/// A lesson's step in Russian: the time it runs to ("t = 62,8 с") and the rest of the page.
#[test]
fn a_russian_lesson_writes_its_numbers_with_a_decimal_comma() {
    let mut h = harness_from_link("lesson=p3&step=2&lang=ru");
    h.run_steps(3);
    let texts = painted(&h);
    let points = points_in(&texts);
    assert!(points.is_empty(), "a decimal point: {points:#?}");
    assert!(
        texts.iter().any(|t| t.contains("62,8")),
        "the step runs to t = 62,8 s: {texts:#?}"
    );
}

/// A link's refused values in Russian: the sliders' ranges ("0,1 … 10 кг·м²") and the values
/// kept ("0,02 °/с") with commas.
#[test]
fn a_russian_links_problem_writes_its_range_with_a_decimal_comma() {
    let mut h =
        harness_from_link("lab=free-rotation&lang=ru&gyro_noise_deg_s=9&inertia_x_kg_m2=50");
    h.run_steps(3);
    let problems = h.state().state.link_problems().join("\n");
    assert!(numbers_with(&problems, '.').is_empty(), "{problems}");
    assert!(numbers_with(&problems, ',').len() >= 2, "{problems}");
}

/// A value typed into a Russian slider's box with a decimal comma is read (and with a point
/// too); in English a comma is not a decimal separator, and the value stays.
#[test]
fn a_typed_value_is_read_with_the_readers_decimal_separator() {
    for (lang, label, typed, want) in [
        (Lang::Ru, "Шум гироскопа σ", "0,05", 0.05),
        (Lang::Ru, "Шум гироскопа σ", "0.07", 0.07),
        (Lang::En, "Gyro noise σ", "0,05", 0.02),
        (Lang::En, "Gyro noise σ", "0.05", 0.05),
    ] {
        let mut h = page_in("free-rotation", lang, 1);
        h.get_by_role_and_label(Role::SpinButton, label).click();
        h.run();
        h.get_by_role_and_label(Role::SpinButton, label)
            .type_text(typed);
        h.run();
        h.key_press(egui::Key::Enter);
        h.run_steps(2);
        let got = h.state().state.sim().params().get("gyro_noise_deg_s");
        assert!((got - want).abs() < 1e-12, "{lang:?} `{typed}`: {got}");
    }
}
