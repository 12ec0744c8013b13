//! The message catalogue: every word the page shows, in English and Russian, as Project
//! Fluent messages (`fluent-bundle`, Mozilla's implementation: plural rules per language,
//! arguments, one `.ftl` file per part in `crate/locales/<lang>/`). The papers are Russian
//! and so are most of their readers; their own notation (φ̇, Δω, γ = det Q / det R) stays as
//! it is in both.
//!
//! A message missing in a language falls back to English; one missing in English shows its
//! id, so the gap is visible. The tests below fail when either language lacks a message the
//! other has, and the page's own test fails when a message it asks for exists in neither.

pub mod errors;
mod numbers;
mod series;
mod units;

pub use fluent_bundle::FluentValue;
use fluent_bundle::concurrent::FluentBundle;
use fluent_bundle::{FluentArgs, FluentResource};
pub use numbers::{diagram_detail, fixed, list_separator, number, parse_number};
pub use series::{
    LegendParts, compose, estimator_id, estimator_name, lab_series_words, quantity_id,
    series_label, series_legend, series_legend_parts, series_legend_without_unit,
};
use std::sync::OnceLock;
pub use units::unit;

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
            Self::En => &[
                include_str!("../../locales/en/page.ftl"),
                include_str!("../../locales/en/series.ftl"),
                include_str!("../../locales/en/travel.ftl"),
            ],
            #[cfg(not(target_arch = "wasm32"))]
            Self::Ru => &[
                include_str!("../../locales/ru/page.ftl"),
                include_str!("../../locales/ru/series.ftl"),
                include_str!("../../locales/ru/travel.ftl"),
            ],
            // The page fetches the Russian catalogue beside its wasm (see [`provide_russian`]).
            #[cfg(target_arch = "wasm32")]
            Self::Ru => RUSSIAN.get().map_or(&[], std::slice::from_ref),
        }
    }

    /// Translations of what the labs say in English in their code (see [`lab_text`]): the
    /// quantities the labs share, then each registered lab's own file from its folder
    /// ([`crate::model::LabWords`]; the registry is the only list of labs).
    fn lab_sources(self) -> Vec<&'static str> {
        let shared: &[&'static str] = match self {
            Self::En => &[],
            #[cfg(not(target_arch = "wasm32"))]
            Self::Ru => &[include_str!("../../locales/ru/quantities.ftl")],
            // In the page the shared Russian comes in the fetched file with the rest.
            #[cfg(target_arch = "wasm32")]
            Self::Ru => &[],
        };
        let own = crate::labs::all().iter().map(|lab| {
            let words = lab.spec().words;
            match self {
                Self::En => words.en,
                Self::Ru => words.ru,
            }
        });
        shared
            .iter()
            .copied()
            .chain(own)
            .filter(|s| !s.is_empty())
            .collect()
    }
}

/// The Russian catalogue the page fetched: every file of `crate/locales/ru/` and every lab
/// folder's `ru.ftl` in one (`assets/locales/ru.ftl`, which `cargo xtask dist` writes).
/// Natively the files are in the binary; in the page they stay beside the wasm, so a
/// reader in English does not download them as code and a new release of the code need not
/// send them again.
#[cfg(target_arch = "wasm32")]
static RUSSIAN: OnceLock<&'static str> = OnceLock::new();

/// Hands the page's fetched Russian catalogue over, before the first message is looked up
/// (the page's `start` does). Without it Russian falls back to English, message by message.
#[cfg(target_arch = "wasm32")]
pub fn provide_russian(text: String) {
    let _ = RUSSIAN.set(Box::leak(text.into_boxed_str()));
}

/// A lab's own words in `lang`: the lab writes them in English (its code holds them), and a
/// translation is the message `id` of the language's lab files (`lab-p1-title`). Where the
/// code's English is a code rather than words (a log's unit choice `deg_s`, which the CLI
/// takes as written), the English lab files give the words the page shows (`°/s`). Without
/// either, the code's English.
pub fn lab_text(lang: Lang, id: &str, english: &str) -> String {
    for l in [lang, Lang::En] {
        if has(l, id) {
            return t(l, id);
        }
    }
    english.to_string()
}

/// The id of a lab's title in the catalogue.
pub fn lab_title_id(lab_id: &str) -> String {
    format!("lab-{lab_id}-title")
}

/// The id of a lab's summary ("What am I looking at?") in the catalogue.
pub fn lab_summary_id(lab_id: &str) -> String {
    format!("lab-{lab_id}-summary")
}

/// The id of the line under a lab's title: the paper it reproduces, as a reader of the
/// language cites it.
pub fn lab_paper_id(lab_id: &str) -> String {
    format!("lab-{lab_id}-paper")
}

/// The id of the label of a lab's parameter `key` in the catalogue.
pub fn param_label_id(lab_id: &str, key: &str) -> String {
    format!("lab-{lab_id}-param-{key}")
}

/// The id of option `index` of a lab's choice parameter `key` in the catalogue.
pub fn param_option_id(lab_id: &str, key: &str, index: usize) -> String {
    format!("lab-{lab_id}-param-{key}-option-{index}")
}

/// The id of the title of a lab's figure (plot tab) `figure` (its id) in the catalogue.
pub fn figure_id(lab_id: &str, figure: &str) -> String {
    format!("lab-{lab_id}-figure-{figure}")
}

/// The id of the name of a lab's preset `preset` (its id) in the catalogue.
pub fn preset_id(lab_id: &str, preset: &str) -> String {
    format!("lab-{lab_id}-preset-{preset}")
}

/// The id of the hover help of a lab's parameter `key`.
pub fn param_help_id(lab_id: &str, key: &str) -> String {
    format!("lab-{lab_id}-param-{key}-help")
}

/// The id of the hover help of a lab's preset `preset` (its id).
pub fn preset_help_id(lab_id: &str, preset: &str) -> String {
    format!("lab-{lab_id}-preset-{preset}-help")
}

/// The id of the label of a lab's outage `outage` (its id; the plots' shading).
pub fn outage_id(lab_id: &str, outage: &str) -> String {
    format!("lab-{lab_id}-outage-{outage}")
}

/// The id of a word of a lab's sweep `sweep` (its id): `part` is `title`, `help`,
/// `score-<j>`, `objective-<j>`, `log-help`, `log-score-<j>` or `log-objective-<j>` (j the
/// place of a score in what the sweep's scoring function returns, which fixes it).
pub fn sweep_id(lab_id: &str, sweep: &str, part: &str) -> String {
    format!("lab-{lab_id}-sweep-{sweep}-{part}")
}

/// The id of the title of a lab's diagram `diagram` (its id).
pub fn diagram_id(lab_id: &str, diagram: &str) -> String {
    format!("lab-{lab_id}-diagram-{diagram}")
}

/// The id of the title of a lab's live accuracy table.
pub fn accuracy_title_id(lab_id: &str) -> String {
    format!("lab-{lab_id}-accuracy-title")
}

/// The id of the label of a reference direction a lab draws in the 3D view ("sun").
pub fn scene_id(lab_id: &str, label: &str) -> String {
    let slug: String = label
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() {
                c.to_ascii_lowercase()
            } else {
                '-'
            }
        })
        .collect();
    format!("lab-{lab_id}-scene-{slug}")
}

/// The id of a word of a lab's log format: `part` is `name`, `title`, `help` or `load`.
pub fn log_format_id(lab_id: &str, part: &str) -> String {
    format!("lab-{lab_id}-log-{part}")
}

/// Every word a lab gives in English that a translation can take: `(id, English)` — its
/// title, summary, parameters (label, options, help), presets (name, help), plot tabs,
/// outages, sweeps (title, help, scores, objectives), log format, and (see
/// [`lab_series_words`]) its estimators' names and its series' quantities.
pub fn lab_words(lab: &'static dyn crate::page::Lab) -> Vec<(String, &'static str)> {
    let id = lab.id();
    let mut out = vec![
        (lab_title_id(id), lab.title()),
        (lab_paper_id(id), lab.paper()),
        (lab_summary_id(id), lab.summary()),
    ];
    for spec in lab.params() {
        out.extend(param_words(id, spec));
    }
    for preset in lab.presets() {
        out.push((preset_id(id, preset.id), preset.name));
        out.push((preset_help_id(id, preset.id), preset.help));
    }
    let page = lab.page();
    for figure in page.figures {
        out.push((figure_id(id, figure.id), figure.title));
    }
    for outage in page.outages {
        out.push((outage_id(id, outage.id), outage.label));
    }
    for sweep in lab.sweeps() {
        out.extend(sweep_words(id, sweep, &defaults(lab)));
    }
    for d in page.diagrams(&defaults(lab)) {
        out.push((diagram_id(id, d.id), d.title));
    }
    if let Some(table) = lab.accuracy_table() {
        out.push((accuracy_title_id(id), table.title));
    }
    if let Some(f) = page.log_format {
        for spec in f.units {
            out.extend(param_words(id, spec));
        }
        for (part, english) in [
            ("name", f.name),
            ("title", f.title),
            ("help", f.help),
            ("load", f.load_label),
        ] {
            out.push((log_format_id(id, part), english));
        }
    }
    out.extend(series::lab_series_words(lab));
    if let Some(lesson) = lab.lesson() {
        out.extend(lesson_words(id, lesson));
    }
    // An empty English text (a parameter without help) has nothing to translate.
    out.retain(|(_, english)| !english.is_empty());
    out
}

/// The id of a lesson's word: its title (`step` `None`, `part` `title`) or a part of the
/// step with id `step`: `title`, `text`, `ask`, `why` or `answer-<k>` (k 1-based: the
/// answers' order is the question's, which its `answer` index names).
pub fn lesson_id(lab_id: &str, step: Option<&str>, part: &str) -> String {
    match step {
        Some(n) => format!("lesson-{lab_id}-{n}-{part}"),
        None => format!("lesson-{lab_id}-{part}"),
    }
}

/// A lesson's words: its title, each step's title and text, and each question's words.
fn lesson_words(lab_id: &str, lesson: &crate::page::Lesson) -> Vec<(String, &'static str)> {
    let mut out = vec![(lesson_id(lab_id, None, "title"), lesson.title)];
    for step in lesson.steps {
        let n = Some(step.id);
        out.push((lesson_id(lab_id, n, "title"), step.title));
        out.push((lesson_id(lab_id, n, "text"), step.text));
        if let Some(q) = &step.question {
            out.push((lesson_id(lab_id, n, "ask"), q.ask));
            out.push((lesson_id(lab_id, n, "why"), q.why));
            for (k, answer) in q.answers.iter().enumerate() {
                out.push((lesson_id(lab_id, n, &format!("answer-{}", k + 1)), *answer));
            }
        }
    }
    out
}

/// A parameter's words: its label, its help, its choices.
fn param_words(lab_id: &str, spec: &crate::model::ParamSpec) -> Vec<(String, &'static str)> {
    let mut out = vec![
        (param_label_id(lab_id, spec.key), spec.label),
        (param_help_id(lab_id, spec.key), spec.help),
    ];
    if let crate::model::ParamKind::Choice(options) = spec.kind {
        for (i, option) in options.iter().enumerate() {
            out.push((param_option_id(lab_id, spec.key, i), *option));
        }
    }
    out
}

/// A lab's default parameters.
fn defaults(lab: &dyn crate::page::Lab) -> crate::model::ParamValues {
    crate::model::ParamValues::defaults(lab.params())
}

/// The words of a lab's sweep.
fn sweep_words(
    lab_id: &str,
    sweep: &crate::model::SweepSpec,
    defaults: &crate::model::ParamValues,
) -> Vec<(String, &'static str)> {
    let mut out = vec![(sweep_id(lab_id, sweep.id, "title"), sweep.title)];
    if let Some(overlay) = sweep.scoring.and_then(|s| s.overlay) {
        for (k, (name, _)) in overlay(defaults).iter().enumerate() {
            out.push((sweep_id(lab_id, sweep.id, &format!("overlay-{k}")), *name));
        }
    }
    for (prefix, scoring) in [("", sweep.scoring), ("log-", sweep.log_scoring)] {
        let Some(scoring) = scoring else { continue };
        out.push((
            sweep_id(lab_id, sweep.id, &format!("{prefix}help")),
            scoring.help,
        ));
        for (j, name) in scoring.names.iter().enumerate() {
            out.push((
                sweep_id(lab_id, sweep.id, &format!("{prefix}score-{j}")),
                *name,
            ));
        }
        for (j, (name, _)) in scoring.objectives.iter().enumerate() {
            out.push((
                sweep_id(lab_id, sweep.id, &format!("{prefix}objective-{j}")),
                *name,
            ));
        }
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
                if *l == Lang::Ru {
                    bundle.set_formatter(Some(numbers::russian_fluent_number));
                }
                for source in l.sources().iter().chain(&l.lab_sources()) {
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

/// Why an estimator is in trouble, in `lang`, with its numbers (each argument is one).
pub fn trouble(lang: Lang, why: &crate::model::Trouble) -> String {
    let args: Vec<(&str, FluentValue<'_>)> = why
        .arguments()
        .into_iter()
        .map(|(name, value)| (name, FluentValue::from(number(lang, &value))))
        .collect();
    t_with(lang, why.message_id(), &args)
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
mod error_tests;
#[cfg(test)]
mod id_tests;
#[cfg(test)]
mod tests;
