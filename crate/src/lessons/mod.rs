//! Lessons as the page and the tests use them: the parameters a step sets (the lab's
//! defaults, then its preset, then its own values) and a check that every step names only
//! what its lab has. The steps themselves are data in each lab's folder (`lesson.rs`,
//! [`crate::page::Lesson`]).

use crate::i18n::errors::Worded;
use crate::model::{ParamError, ParamValues, PlotTab, SeriesGroup};
use crate::page::{Lab, Lesson, LessonStep};
use crate::sim::Simulation;

#[cfg(feature = "study")]
pub mod quotes;

/// Sentences a step's text may have.
pub const SENTENCES: std::ops::RangeInclusive<usize> = 2..=5;
/// Steps a lesson may have.
pub const STEPS: std::ops::RangeInclusive<usize> = 5..=8;

/// Why a lesson step's parameters could not be set (the lab changed under its lesson).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum LessonError {
    /// The step names a preset the lab does not have.
    #[error("no preset `{preset}` in {lab}")]
    NoPreset {
        /// The preset's id.
        preset: &'static str,
        /// The lab's id.
        lab: &'static str,
    },
    /// The step's preset sets a value the lab refuses.
    #[error("preset `{preset}`: {source}")]
    Preset {
        /// The preset's id.
        preset: &'static str,
        /// What the lab said.
        source: ParamError,
    },
    /// The step sets a value the lab refuses.
    #[error(transparent)]
    Param(#[from] ParamError),
}

impl LessonError {
    /// One of each kind (the match fails to compile when a kind is added and not listed):
    /// the catalogue's test words every one in both languages.
    pub fn examples() -> Vec<LessonError> {
        let bad = ParamError::NotFinite {
            key: "gyro_noise_deg_s".into(),
        };
        let all = vec![
            LessonError::NoPreset {
                preset: "gamma-small",
                lab: "p4",
            },
            LessonError::Preset {
                preset: "gamma-small",
                source: bad.clone(),
            },
            LessonError::Param(bad),
        ];
        for e in &all {
            match e {
                LessonError::NoPreset { .. }
                | LessonError::Preset { .. }
                | LessonError::Param(_) => {}
            }
        }
        all
    }
}

impl Worded for LessonError {
    fn words(&self, lang: crate::i18n::Lang, lab: &dyn Lab) -> String {
        use crate::i18n::FluentValue;
        match self {
            LessonError::NoPreset { preset, lab: id } => crate::i18n::t_with(
                lang,
                "error-lesson-no-preset",
                &[
                    ("preset", FluentValue::from(*preset)),
                    ("lab", FluentValue::from(*id)),
                ],
            ),
            LessonError::Preset { preset, source } => crate::i18n::t_with(
                lang,
                "error-lesson-preset",
                &[
                    ("preset", FluentValue::from(*preset)),
                    ("why", FluentValue::from(source.words(lang, lab))),
                ],
            ),
            LessonError::Param(e) => e.words(lang, lab),
        }
    }
}

/// The parameters of `step` of `lab`: its defaults, then the step's preset, then its values.
/// An unknown preset or a bad value is an error that names it.
pub fn step_params(lab: &dyn Lab, step: &LessonStep) -> Result<ParamValues, LessonError> {
    let specs = lab.params();
    let mut params = ParamValues::defaults(specs);
    if let Some(name) = step.preset {
        let preset = lab.preset(name).ok_or(LessonError::NoPreset {
            preset: name,
            lab: lab.id(),
        })?;
        for (key, value) in preset.values {
            params
                .set(specs, key, *value)
                .map_err(|source| LessonError::Preset {
                    preset: name,
                    source,
                })?;
        }
    }
    for (key, value) in step.set {
        params.set(specs, key, *value)?;
    }
    Ok(params)
}

/// What is wrong with `lab`'s lesson, one line per problem (none for a good lesson): the
/// number of steps and questions, texts, parameters, presets, tabs, filters and tiles.
pub fn problems(lab: &'static dyn Lab) -> Vec<String> {
    let Some(lesson) = lab.lesson() else {
        return vec![format!("{} has no lesson", lab.id())];
    };
    let mut out = lesson_problems(lesson);
    for (i, step) in lesson.steps.iter().enumerate() {
        out.extend(
            step_problems(lab, step)
                .into_iter()
                .map(|p| format!("{} step {}: {p}", lab.id(), i + 1)),
        );
    }
    out
}

/// Problems of the lesson as a whole.
fn lesson_problems(lesson: &Lesson) -> Vec<String> {
    let mut out = Vec::new();
    if !STEPS.contains(&lesson.steps.len()) {
        out.push(format!("{} steps, not 5–8", lesson.steps.len()));
    }
    let questions = lesson.steps.iter().filter(|s| s.question.is_some()).count();
    if questions < 2 {
        out.push(format!("{questions} question steps, fewer than 2"));
    }
    match lesson
        .number_of(lesson.showcase)
        .and_then(|n| lesson.step(n))
    {
        None => out.push(format!(
            "the showcase step `{}` is not a step",
            lesson.showcase
        )),
        Some(step) if step.question.is_none() => out.push(format!(
            "the showcase step `{}` asks no question",
            lesson.showcase
        )),
        Some(_) => {}
    }
    out
}

/// The sentences of a text (ends of sentences: `.`, `?`, `!` before a space or the end,
/// not after a figure or equation abbreviation such as "Fig." or "eq.").
pub fn sentences(text: &str) -> usize {
    let words: Vec<&str> = text.split_whitespace().collect();
    let abbreviations = [
        "Fig.", "Figs.", "eq.", "eqs.", "Eq.", "e.g.", "i.e.", "cf.", "Tab.", "No.", "vs.",
    ];
    words
        .iter()
        .enumerate()
        .filter(|(i, w)| {
            let ends = w.ends_with(['.', '?', '!']) || w.ends_with(".)");
            let last = *i + 1 == words.len();
            let bare = w.trim_start_matches(['(', '[']);
            ends && (last || !abbreviations.contains(&bare))
        })
        .count()
}

/// Problems of one step.
fn step_problems(lab: &'static dyn Lab, step: &LessonStep) -> Vec<String> {
    let mut out = Vec::new();
    let n = sentences(step.text);
    if !SENTENCES.contains(&n) {
        out.push(format!("its text has {n} sentences, not 2–5"));
    }
    if let Some(q) = &step.question
        && (!(2..=4).contains(&q.answers.len()) || q.answer >= q.answers.len())
    {
        out.push(format!(
            "its question has {} answers and answer {}",
            q.answers.len(),
            q.answer
        ));
    }
    for key in step.highlight {
        if !lab.params().iter().any(|p| p.key == *key) {
            out.push(format!("it highlights `{key}`, not a parameter"));
        }
    }
    let params = match step_params(lab, step) {
        Ok(p) => p,
        Err(e) => {
            out.push(e.to_string());
            return out;
        }
    };
    for key in step.highlight {
        let spec = lab.params().iter().find(|p| p.key == *key);
        if spec.is_some_and(|s| !s.outside_run && !s.acts_in(&params)) {
            out.push(format!(
                "it points at `{key}`, which does not act in its run"
            ));
        }
    }
    let sim = Simulation::new(lab, params, 1);
    out.extend(tab_problem(lab, &sim, step.tab));
    for id in step.show {
        if !sim.estimators().iter().any(|e| e.id() == *id) {
            out.push(format!("it shows `{id}`, not an estimator of this run"));
        }
    }
    for tile in step.tiles {
        let name = tile.name();
        if !sim.available_specs().iter().any(|s| s.name == name) {
            out.push(format!("its tile `{name}` is not a series of this run"));
        }
    }
    if let Some(speed) = step.speed {
        let (lo, hi) = crate::page::SPEED_RANGE;
        if !(lo..=hi).contains(&speed) {
            out.push(format!("speed {speed} outside {lo}–{hi}"));
        }
    }
    if let Some(id) = step.sweep
        && lab.sweep_index(id).is_none()
    {
        out.push(format!("sweep `{id}`, but the lab has no sweep of that id"));
    }
    if step.pause_at_s.is_some_and(|t| !(t > 0.0 && t.is_finite())) {
        out.push("its pause time is not a positive time".into());
    }
    out
}

/// Whether the step's tab exists in `lab` and has something to draw.
fn tab_problem(lab: &dyn Lab, sim: &Simulation, tab: Option<PlotTab>) -> Option<String> {
    match tab? {
        PlotTab::Figure(id) => lab
            .page()
            .figure(id)
            .is_none()
            .then(|| format!("tab Figure(\"{id}\"), but the lab has no figure of that id")),
        PlotTab::Group(SeriesGroup::Time) => Some("the time axis is not a tab".into()),
        PlotTab::Group(g) => (!sim.available_specs().iter().any(|s| s.group == g))
            .then(|| format!("tab {g:?} has no series in this lab")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_lesson_error_is_said_in_both_languages() {
        use crate::i18n::Lang;
        let lab = crate::labs::find("p4").expect("registered");
        for e in LessonError::examples() {
            let (en, ru) = (e.words(Lang::En, lab), e.words(Lang::Ru, lab));
            assert!(!en.contains("{$") && !en.contains("error-"), "{e}: {en}");
            assert!(
                !ru.contains("{$") && !ru.contains("error-") && ru != en,
                "{e}: {ru}"
            );
            assert!(ru.chars().any(|c| ('а'..='я').contains(&c)), "{e}: {ru}");
        }
    }

    #[test]
    fn every_lab_has_a_lesson_whose_steps_name_only_what_the_lab_has() {
        let problems: Vec<String> = crate::labs::all()
            .iter()
            .flat_map(|l| problems(*l))
            .collect();
        assert!(problems.is_empty(), "{problems:#?}");
    }

    #[test]
    fn the_check_finds_a_bad_step() {
        let lab = crate::labs::all()[0];
        let bad = LessonStep {
            set: &[("no_such_slider", 1.0)],
            ..LessonStep::new("bad", "Bad", "One sentence only")
        };
        let found = step_problems(lab, &bad);
        assert!(found.iter().any(|p| p.contains("sentences")), "{found:?}");
        assert!(
            found.iter().any(|p| p.contains("no_such_slider")),
            "{found:?}"
        );
        let bad_tab = LessonStep {
            tab: Some(PlotTab::Figure("no-such-figure")),
            show: &["nobody"],
            ..LessonStep::new("bad", "Bad", "Two. Sentences.")
        };
        let found = step_problems(lab, &bad_tab);
        assert_eq!(found.len(), 2, "{found:?}");
    }

    /// Every number each step's words quote holds for the run the step opens (a parameter
    /// it sets, the paper's number, or a reading of the run to the digits written), its
    /// Russian words write the same numbers, and no measured-looking number goes unquoted.
    /// The labs run side by side.
    #[cfg(all(feature = "study", not(target_arch = "wasm32")))]
    #[test]
    fn every_number_a_step_quotes_holds_for_the_run_it_opens() {
        use rayon::prelude::*;
        let steps: Vec<(&'static dyn Lab, usize, &LessonStep)> = crate::labs::all()
            .iter()
            .flat_map(|lab| {
                let lesson = lab.lesson().expect("every lab has a lesson");
                lesson
                    .steps
                    .iter()
                    .enumerate()
                    .map(move |(i, s)| (*lab, i + 1, s))
            })
            .collect();
        let problems: Vec<String> = steps
            .par_iter()
            .flat_map_iter(|(lab, n, step)| {
                let params = step_params(*lab, step).expect("a good step");
                quotes::step_quote_problems(*lab, step, &params)
                    .into_iter()
                    .map(move |p| format!("{} step {n}: {p}", lab.id()))
            })
            .collect();
        assert!(problems.is_empty(), "{}", problems.join("\n"));
    }

    #[test]
    fn sentences_are_counted_past_figure_abbreviations() {
        assert_eq!(sentences("See Fig. 5.3. P collapses (eq. 4.5)."), 2);
        assert_eq!(sentences("Why? Because Q = 0!"), 2);
    }

    #[test]
    fn a_step_sets_defaults_then_preset_then_its_values() {
        for lab in crate::labs::all() {
            let Some(preset) = lab.presets().first() else {
                continue;
            };
            let Some((key, _)) = preset.values.first() else {
                continue;
            };
            let step = LessonStep {
                preset: Some(preset.id),
                ..LessonStep::new("x", "x", "x. y.")
            };
            let p = step_params(*lab, &step).unwrap();
            assert_eq!(p.get(key), preset.values[0].1, "{}", lab.id());
        }
    }
}
