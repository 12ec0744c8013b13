//! The catalogue's tests: both languages complete, every message formats, every lab word
//! translated.
use super::*;
use std::collections::BTreeSet;

/// The ids of `lang`'s messages, after checking its files parse without an error and
/// hold no id twice.
fn ids(lang: Lang) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    for source in lang.sources() {
        let resource = match FluentResource::try_new((*source).to_string()) {
            Ok(r) => r,
            Err((_, errors)) => panic!("{}: syntax errors {errors:?}", lang.code()),
        };
        for entry in resource.entries() {
            if let fluent_syntax::ast::Entry::Message(m) = entry {
                let id = m.id.name.to_string();
                assert!(out.insert(id.clone()), "{}: `{id}` twice", lang.code());
            }
        }
    }
    out
}

#[test]
fn every_message_is_in_both_languages() {
    let (en, ru) = (ids(Lang::En), ids(Lang::Ru));
    let only_en: Vec<_> = en.difference(&ru).collect();
    let only_ru: Vec<_> = ru.difference(&en).collect();
    assert!(only_en.is_empty(), "missing in Russian: {only_en:?}");
    assert!(only_ru.is_empty(), "missing in English: {only_ru:?}");
    assert!(en.len() > 50, "{} messages", en.len());
}

#[test]
fn every_series_groups_tab_title_and_axis_noun_are_in_the_catalogue() {
    let en = ids(Lang::En);
    let mut nouns = 0;
    for group in crate::model::SeriesGroup::ALL {
        assert!(
            en.contains(group.message()),
            "{group:?}: no `{}`",
            group.message()
        );
        if let Some(id) = group.axis_message() {
            assert!(en.contains(id), "{group:?}: no `{id}`");
            nouns += 1;
        }
    }
    assert_eq!(nouns, 5, "the groups whose series measure one thing");
}

/// The arguments the catalogue's messages take as text, each given "x" by the format test.
const TEXT_ARGUMENTS: &[&str] = &[
    // Time travel's timeline and branches.
    "changes",
    "estimator",
    "over",
    "before",
    "after",
    "most",
    // The About line and the host API's errors.
    "version",
    "commit",
    "date",
    "line",
    "column",
    "api",
    "type",
    "must",
    "origin",
    "text",
    "steps",
    "part",
    "letter",
    "key",
    "help",
    "what",
    "percent",
    "names",
    "n",
    "name",
    "title",
    "label",
    "ids",
    "t",
    "lab",
    "state",
    "speed",
    "error",
    "band",
    "a",
    "b",
    "axis",
    "covered",
    "window",
    "at",
    "param",
    "value",
    "rms",
    "lo",
    "hi",
    "best",
    "s",
    "ms",
    "item",
    "range",
    "kept",
    "k",
    "count",
    "answer",
    "lines",
    "reordered",
    "merged",
    "rejected",
    "gaps",
    "mass",
    "factor",
    "required",
    "dmin",
    "period",
    "limit",
    "needed",
    "att",
    "bias",
    "paper_att",
    "paper_rate",
    "paper_bias",
    "sigma",
    "deg",
    "path",
    "detail",
    "saved",
    "w",
    "h",
    "source",
    "api",
    "line",
    "reason",
    "text",
    "expected",
    "found",
    "byte",
    "column",
    "raw",
    "bits",
    "max",
    "last",
    "labs",
    "width",
    "own",
    "columns",
    "format",
    "other",
    "first",
    "g",
    "unit",
    "given",
    "key",
    "gives",
    // The errors' words (i18n::errors).
    "preset",
    "index",
    "got",
    "end",
    "of",
    "seed",
    "change",
    "job",
    "sweep",
    "point",
    "bytes",
    "name",
    "n",
];

#[test]
fn every_message_formats_without_an_error_in_both() {
    for lang in Lang::ALL {
        let b = bundle(lang);
        for id in ids(lang) {
            let pattern = b.get_message(&id).and_then(|m| m.value());
            let pattern = pattern.unwrap_or_else(|| panic!("{id} has no value"));
            let mut args = FluentArgs::new();
            for name in TEXT_ARGUMENTS {
                args.set(*name, "x");
            }
            for name in [
                "realtime", "asked", "step", "rate", "frame", "sim", "mib", "baud",
            ] {
                args.set(name, "1");
            }
            for name in ["series", "id", "why"] {
                args.set(name, "y");
            }
            // Plural selectors take numbers.
            args.set("cells", 3);
            args.set("seeds", 2);
            let mut errors = Vec::new();
            let text = b.format_pattern(pattern, Some(&args), &mut errors);
            assert!(errors.is_empty(), "{}: {id}: {errors:?}", lang.code());
            assert!(!text.trim().is_empty(), "{}: {id} is empty", lang.code());
        }
    }
}

#[test]
fn a_message_is_looked_up_then_falls_back_to_english_then_to_its_id() {
    assert_eq!(t(Lang::En, "pause"), "Pause");
    assert_eq!(t(Lang::Ru, "pause"), "Пауза");
    assert_eq!(t(Lang::Ru, "no-such-message"), "no-such-message");
    let with = t_with(Lang::Ru, "more-estimators", &[("n", 3.into())]);
    assert_eq!(with, "ещё 3…");
}

#[test]
fn every_word_of_every_lab_is_translated_and_nothing_else_is_there() {
    let mut derived = BTreeSet::new();
    let mut missing = Vec::new();
    for lab in crate::labs::all() {
        for (id, english) in lab_words(*lab) {
            if !has(Lang::Ru, &id) {
                missing.push(format!("{id} ({english})"));
            }
            // The code's English, or the English lab files' words for a code.
            if !has(Lang::En, &id) {
                assert_eq!(lab_text(Lang::En, &id, english), english);
            }
            derived.insert(id);
        }
    }
    assert!(missing.is_empty(), "no Russian for {missing:#?}");
    assert_ne!(lab_text(Lang::Ru, &lab_title_id("p1"), "x"), "x");
    // A lab's folder holds its own words only; the shared file, words some lab says.
    let mut stale = Vec::new();
    for lab in crate::labs::all() {
        let own: BTreeSet<String> = lab_words(*lab).into_iter().map(|(id, _)| id).collect();
        for source in [lab.spec().words.en, lab.spec().words.ru] {
            for id in message_ids(source) {
                if !own.contains(&id) {
                    stale.push(format!("{}'s folder: `{id}`", lab.id()));
                }
            }
        }
    }
    for id in message_ids(include_str!("../../locales/ru/quantities.ftl")) {
        if !derived.contains(&id) {
            stale.push(format!("locales/ru/quantities.ftl: `{id}`"));
        }
    }
    assert!(
        stale.is_empty(),
        "translations no lab says there: {stale:#?}"
    );
}

/// The ids of the messages of one catalogue file.
fn message_ids(source: &str) -> Vec<String> {
    let resource = FluentResource::try_new(source.to_string()).expect("parses");
    (resource.entries())
        .filter_map(|entry| match entry {
            fluent_syntax::ast::Entry::Message(m) => Some(m.id.name.to_string()),
            _ => None,
        })
        .collect()
}

#[test]
fn the_readers_language_is_the_first_the_page_speaks() {
    assert_eq!(Lang::negotiate(["de-DE", "ru-RU", "en"]), Lang::Ru);
    assert_eq!(Lang::negotiate(["fr"]), Lang::En);
    assert_eq!(Lang::from_tag("RU"), Some(Lang::Ru));
    assert_eq!(Lang::from_tag("en_GB"), Some(Lang::En));
    assert_eq!(Lang::from_tag(""), None);
}

/// Every series of every lab (defaults and presets) composes from its key in English to
/// exactly the label the core gave it, and composes in Russian.
#[test]
fn every_series_label_composes_from_its_key_in_both_languages() {
    let mut wrong = Vec::new();
    for lab in crate::labs::all() {
        let sim =
            crate::sim::Simulation::new(*lab, crate::model::ParamValues::defaults(lab.params()), 1);
        for spec in sim.available_specs() {
            match compose(Lang::En, lab.id(), spec) {
                Some(en) if en == spec.label => {}
                other => wrong.push(format!(
                    "{}: {} `{}` composes as {other:?}",
                    lab.id(),
                    spec.name,
                    spec.label
                )),
            }
            if compose(Lang::Ru, lab.id(), spec).is_none() {
                wrong.push(format!(
                    "{}: {} `{}` has no Russian",
                    lab.id(),
                    spec.name,
                    spec.label
                ));
            }
        }
    }
    assert!(
        wrong.is_empty(),
        "{} series:\n{}",
        wrong.len(),
        wrong.join("\n")
    );
}

/// A quantity key names one thing: the same key never carries two labels (its translation
/// is keyed by it).
#[test]
fn one_quantity_key_has_one_label() {
    let mut labels: std::collections::BTreeMap<String, BTreeSet<&str>> = Default::default();
    for lab in crate::labs::all() {
        for (id, english) in series::lab_series_words(*lab) {
            if id.starts_with("q-") {
                labels.entry(id).or_default().insert(english);
            }
        }
    }
    let twice: Vec<_> = labels.iter().filter(|(_, l)| l.len() > 1).collect();
    assert!(twice.is_empty(), "keys with two labels: {twice:#?}");
    assert!(labels.len() > 40, "{} quantities", labels.len());
}

#[test]
fn the_binary_reads_every_russian_file_the_page_fetches() {
    // `cargo xtask dist` joins every .ftl of locales/ru and every lab folder's ru.ftl into
    // the page's ru.ftl; natively the same files are included one by one. A file added to
    // one must be in the other.
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let files_in = |dir: std::path::PathBuf| -> Vec<std::path::PathBuf> {
        (std::fs::read_dir(dir).unwrap())
            .filter_map(|e| e.ok().map(|e| e.path()))
            .collect()
    };
    let central = files_in(root.join("locales/ru"));
    let labs = files_in(root.join("src/labs"))
        .into_iter()
        .map(|d| d.join("ru.ftl"));
    let mut on_disk: Vec<String> = (central.into_iter().chain(labs))
        .filter(|p| p.is_file() && p.extension().is_some_and(|x| x == "ftl"))
        .map(|p| std::fs::read_to_string(p).unwrap())
        .collect();
    let mut included: Vec<String> = Lang::Ru
        .sources()
        .iter()
        .copied()
        .chain(Lang::Ru.lab_sources())
        .map(|s| s.to_string())
        .collect();
    on_disk.sort();
    included.sort();
    assert_eq!(on_disk.len(), included.len());
    assert!(
        on_disk == included,
        "locales/ru and the included files differ"
    );
}

#[test]
fn every_trouble_is_said_in_both_languages_with_its_numbers() {
    for why in crate::model::Trouble::EXAMPLES {
        let id = why.message_id();
        let en = trouble(Lang::En, &why);
        let ru = trouble(Lang::Ru, &why);
        for lang in Lang::ALL {
            assert!(has(lang, id), "{}: {id} is missing", lang.code());
        }
        assert_ne!(en, ru, "{id}: the Russian is the English");
        for (name, value) in why.arguments() {
            // Each in the language's own decimals ("12,5" in Russian).
            for (lang, text) in [(Lang::En, &en), (Lang::Ru, &ru)] {
                let value = number(lang, &value);
                assert!(
                    text.contains(&value),
                    "{id}: ${name} = {value} not in {text:?}"
                );
            }
        }
        // Fluent writes an argument it was not given as `{$name}`.
        assert!(
            !en.contains('$') && !ru.contains('$'),
            "{id}: an unfilled argument"
        );
    }
}

/// index.html speaks before the app and its catalogue have started (loading, the error box,
/// no JavaScript): its copy of the `boot-*` messages must say what the catalogue says.
#[test]
fn the_page_says_what_the_catalogue_says_before_the_app_starts() {
    let html = include_str!("../../../index.html");
    let open = r#"<script type="application/json" id="attlab_boot_words">"#;
    let json = html
        .split_once(open)
        .and_then(|(_, rest)| rest.split_once("</script>"))
        .map(|(json, _)| json)
        .expect("index.html has no attlab_boot_words");
    let words: serde_json::Value = serde_json::from_str(json).expect("attlab_boot_words is JSON");
    for lang in Lang::ALL {
        let copy = words[lang.code()]
            .as_object()
            .unwrap_or_else(|| panic!("attlab_boot_words has no {}", lang.code()));
        let boot: Vec<String> = ids(lang)
            .into_iter()
            .filter(|id| id.starts_with("boot-"))
            .collect();
        let copied: Vec<&String> = copy.keys().collect();
        assert_eq!(
            copied.len(),
            boot.len(),
            "{}: {copied:?} against {boot:?}",
            lang.code()
        );
        for id in &boot {
            assert_eq!(
                copy[id].as_str(),
                Some(t(lang, id).as_str()),
                "{}: {id}",
                lang.code()
            );
        }
    }
    // Without JavaScript nothing can choose: the page says it in both.
    for lang in Lang::ALL {
        assert!(
            html.contains(&t(lang, "boot-no-script")),
            "noscript lacks {}",
            lang.code()
        );
    }
    // The text each element holds until the script sets it is the English.
    for element in html.split("data-word=\"").skip(1) {
        let (id, rest) = element.split_once('"').expect("data-word is quoted");
        let text = rest.split_once('>').and_then(|(_, r)| r.split_once('<'));
        assert_eq!(
            text.map(|(t, _)| t.to_string()),
            Some(t(Lang::En, id)),
            "{id}"
        );
    }
}

/// The Russian status line's count of series takes the plural its number asks for.
#[test]
fn the_russian_series_count_agrees_with_its_number() {
    for (n, word) in [
        (1, "ряд,"),
        (2, "ряда,"),
        (5, "рядов,"),
        (11, "рядов,"),
        (12, "рядов,"),
        (14, "рядов,"),
        (21, "ряд,"),
        (22, "ряда,"),
        (111, "рядов,"),
        (194, "ряда,"),
    ] {
        let mut args: Vec<(&str, FluentValue<'_>)> = ["t", "step", "rate", "realtime", "asked"]
            .into_iter()
            .chain(["frame", "sim", "mib"])
            .map(|name| (name, FluentValue::from("1")))
            .collect();
        args.push(("series", n.into()));
        let text = t_with(Lang::Ru, "status-long", &args);
        assert!(text.contains(&format!("({n} {word}")), "{n}: {text}");
    }
}
