//! The message catalogue: every word the page shows, in English and Russian, as Project
//! Fluent messages (`fluent-bundle`, Mozilla's implementation: plural rules per language,
//! arguments, one `.ftl` file per part in `crate/locales/<lang>/`). The papers are Russian
//! and so are most of their readers; their own notation (φ̇, Δω, γ = det Q / det R) stays as
//! it is in both.
//!
//! A message missing in a language falls back to English; one missing in English shows its
//! id, so the gap is visible. The tests below fail when either language lacks a message the
//! other has, and the page's own test fails when a message it asks for exists in neither.

pub use fluent_bundle::FluentValue;
use fluent_bundle::concurrent::FluentBundle;
use fluent_bundle::{FluentArgs, FluentResource};
use std::sync::OnceLock;

/// A language of the page.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Lang {
    /// English (the fallback).
    #[default]
    En,
    /// Russian.
    Ru,
}

impl Lang {
    /// Every language, in the order the switch offers them.
    pub const ALL: [Lang; 2] = [Lang::En, Lang::Ru];

    /// The code in a link (`lang=ru`) and in a BCP 47 tag.
    pub fn code(self) -> &'static str {
        match self {
            Self::En => "en",
            Self::Ru => "ru",
        }
    }

    /// The language's own name (the switch shows it).
    pub fn name(self) -> &'static str {
        match self {
            Self::En => "English",
            Self::Ru => "Русский",
        }
    }

    /// The language of a BCP 47 tag (`ru`, `ru-RU`, `en_GB`), if the page speaks it.
    pub fn from_tag(tag: &str) -> Option<Self> {
        let primary = tag.trim().split(['-', '_']).next()?.to_ascii_lowercase();
        Self::ALL.into_iter().find(|l| l.code() == primary)
    }

    /// The first of the reader's languages (the browser's, in order) the page speaks;
    /// English when none.
    pub fn negotiate<'a>(tags: impl IntoIterator<Item = &'a str>) -> Self {
        tags.into_iter()
            .find_map(Self::from_tag)
            .unwrap_or_default()
    }

    /// The page's own messages: each in every language.
    fn sources(self) -> &'static [&'static str] {
        match self {
            Self::En => &[include_str!("../locales/en/page.ftl")],
            Self::Ru => &[include_str!("../locales/ru/page.ftl")],
        }
    }

    /// Translations of what the labs say in English in their code (see [`lab_text`]).
    fn lab_sources(self) -> &'static [&'static str] {
        match self {
            Self::En => &[],
            Self::Ru => &[include_str!("../locales/ru/labs.ftl")],
        }
    }
}

/// A lab's own words in `lang`: the lab writes them in English (its code holds them), and a
/// translation is the message `id` of the language's `labs.ftl` (`lab-p1-title`); without
/// one, the English.
pub fn lab_text(lang: Lang, id: &str, english: &str) -> String {
    if lang == Lang::En || !has(lang, id) {
        return english.to_string();
    }
    t(lang, id)
}

/// The id of a lab's title in the catalogue.
pub fn lab_title_id(lab_id: &str) -> String {
    format!("lab-{lab_id}-title")
}

/// The id of a lab's summary ("What am I looking at?") in the catalogue.
pub fn lab_summary_id(lab_id: &str) -> String {
    format!("lab-{lab_id}-summary")
}

/// The id of the label of a lab's parameter `key` in the catalogue.
pub fn param_label_id(lab_id: &str, key: &str) -> String {
    format!("lab-{lab_id}-param-{key}")
}

/// The id of option `index` of a lab's choice parameter `key` in the catalogue.
pub fn param_option_id(lab_id: &str, key: &str, index: usize) -> String {
    format!("lab-{lab_id}-param-{key}-option-{index}")
}

/// The id of the title of a lab's figure (plot tab) `index` in the catalogue.
pub fn figure_id(lab_id: &str, index: usize) -> String {
    format!("lab-{lab_id}-figure-{index}")
}

/// The id of the name of a lab's preset `index` in the catalogue.
pub fn preset_id(lab_id: &str, index: usize) -> String {
    format!("lab-{lab_id}-preset-{index}")
}

/// Every word a lab gives in English that a translation can take: `(id, English)` — its
/// title, its summary, each parameter's label, each choice's options, each preset's name.
pub fn lab_words(lab: &dyn crate::model::Lab) -> Vec<(String, &'static str)> {
    let id = lab.id();
    let mut out = vec![
        (lab_title_id(id), lab.title()),
        (lab_summary_id(id), lab.summary()),
    ];
    for spec in lab.params() {
        out.push((param_label_id(id, spec.key), spec.label));
        if let crate::model::ParamKind::Choice(options) = spec.kind {
            for (i, option) in options.iter().enumerate() {
                out.push((param_option_id(id, spec.key, i), *option));
            }
        }
    }
    for (i, preset) in lab.presets().iter().enumerate() {
        out.push((preset_id(id, i), preset.name));
    }
    for (i, figure) in lab.page().figures.iter().enumerate() {
        out.push((figure_id(id, i), figure.title));
    }
    out
}

type Bundle = FluentBundle<FluentResource>;

/// The bundle of `lang`, parsed once. A message with a syntax error is left out (the tests
/// fail on it); the rest of its file is kept.
fn bundle(lang: Lang) -> &'static Bundle {
    static BUNDLES: OnceLock<Vec<Bundle>> = OnceLock::new();
    let all = BUNDLES.get_or_init(|| {
        Lang::ALL
            .iter()
            .map(|l| {
                let id = l.code().parse().unwrap_or_default();
                let mut bundle = Bundle::new_concurrent(vec![id]);
                // No bidi isolation marks around arguments: the page's fonts have no glyph
                // for them, and every text here runs left to right.
                bundle.set_use_isolating(false);
                for source in l.sources().iter().chain(l.lab_sources()) {
                    let resource = FluentResource::try_new((*source).to_string())
                        .unwrap_or_else(|(partial, _)| partial);
                    // A duplicate id keeps the first; the tests fail on it.
                    let _ = bundle.add_resource(resource);
                }
                bundle
            })
            .collect()
    });
    &all[Lang::ALL.iter().position(|l| *l == lang).unwrap_or(0)]
}

/// Whether `lang` has the message `id`.
pub fn has(lang: Lang, id: &str) -> bool {
    bundle(lang).has_message(id)
}

/// The message `id` in `lang` (English if `lang` lacks it; the id itself if English does).
pub fn t(lang: Lang, id: &str) -> String {
    format(lang, id, None)
}

/// The message `id` in `lang` with its arguments (`$name` in the message): a number passed
/// as a number picks the plural form.
pub fn t_with(lang: Lang, id: &str, args: &[(&str, FluentValue<'_>)]) -> String {
    let mut fluent = FluentArgs::new();
    for (name, value) in args {
        fluent.set(*name, value.clone());
    }
    format(lang, id, Some(&fluent))
}

fn format(lang: Lang, id: &str, args: Option<&FluentArgs<'_>>) -> String {
    for l in [lang, Lang::En] {
        let b = bundle(l);
        if let Some(pattern) = b.get_message(id).and_then(|m| m.value()) {
            let mut errors = Vec::new();
            return b.format_pattern(pattern, args, &mut errors).into_owned();
        }
    }
    id.to_string()
}

#[cfg(test)]
mod tests {
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
    fn every_message_formats_without_an_error_in_both() {
        for lang in Lang::ALL {
            let b = bundle(lang);
            for id in ids(lang) {
                let pattern = b.get_message(&id).and_then(|m| m.value());
                let pattern = pattern.unwrap_or_else(|| panic!("{id} has no value"));
                let mut args = FluentArgs::new();
                let words = ["help", "names", "n", "name", "title", "label", "ids", "t"];
                let more = ["lab", "state", "speed", "error", "band"];
                for name in words.into_iter().chain(more) {
                    args.set(name, "x");
                }
                for name in ["realtime", "asked", "step", "rate", "frame", "sim", "mib"] {
                    args.set(name, "1");
                }
                for name in ["series", "id", "why"] {
                    args.set(name, "y");
                }
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
                assert_eq!(lab_text(Lang::En, &id, english), english);
                derived.insert(id);
            }
        }
        assert!(missing.is_empty(), "no Russian for {missing:#?}");
        assert_ne!(lab_text(Lang::Ru, &lab_title_id("p1"), "x"), "x");
        for source in Lang::Ru.lab_sources() {
            let resource = FluentResource::try_new((*source).to_string()).expect("parses");
            for entry in resource.entries() {
                if let fluent_syntax::ast::Entry::Message(m) = entry {
                    assert!(
                        derived.contains(m.id.name),
                        "stale translation `{}`",
                        m.id.name
                    );
                }
            }
        }
    }

    #[test]
    fn the_readers_language_is_the_first_the_page_speaks() {
        assert_eq!(Lang::negotiate(["de-DE", "ru-RU", "en"]), Lang::Ru);
        assert_eq!(Lang::negotiate(["fr"]), Lang::En);
        assert_eq!(Lang::from_tag("RU"), Some(Lang::Ru));
        assert_eq!(Lang::from_tag("en_GB"), Some(Lang::En));
        assert_eq!(Lang::from_tag(""), None);
    }
}
