//! Failures in the reader's language: each error type keeps its facts and its English
//! (`Display`, what the CLI prints); [`Worded::words`] says it with the catalogue's words
//! (the `error-*` and `param-*` messages), numbers with the reader's decimal sign and a
//! parameter by its slider's label. Every kind of every error a page reader can meet has
//! words in both languages (the catalogue's test walks each type's `examples()`).

use super::{FluentValue, Lang};
use crate::analysis::sweep::{Skipped, SweepError};
use crate::model::{ParamError, ParamKind, ParamSpec, ScoreError, StatsError, Unscored};
use crate::page::Lab;
use crate::sim::{SimError, TravelError, UnknownSeries};

/// An error said in the reader's language.
pub trait Worded {
    /// The error in `lang`, in `lab`'s words (its sliders' labels and units).
    fn words(&self, lang: Lang, lab: &dyn Lab) -> String;
}

/// Message `id` in `lang` with text arguments.
fn said(lang: Lang, id: &str, args: &[(&str, String)]) -> String {
    let args: Vec<(&str, FluentValue<'_>)> = args
        .iter()
        .map(|(name, value)| (*name, FluentValue::from(value.clone())))
        .collect();
    super::t_with(lang, id, &args)
}

/// A number in `lang`'s way of writing it.
fn num(lang: Lang, value: impl ToString) -> String {
    super::number(lang, &value.to_string())
}

/// Why a value for one of `specs` (the lab's sliders, or its log format's unit choices) was
/// refused, in `lang`: named by the control's label with its range, not by its key (only a
/// key no control has is said as given). The run and the choice stay as they were.
pub fn param_problem(lang: Lang, lab: &dyn Lab, specs: &[ParamSpec], e: &ParamError) -> String {
    let key = match e {
        ParamError::Malformed { text } => {
            return super::t_with(lang, "param-malformed", &[("text", text.clone().into())]);
        }
        ParamError::Unknown { key, .. }
        | ParamError::NotANumber { key, .. }
        | ParamError::NotFinite { key }
        | ParamError::OutOfRange { key, .. }
        | ParamError::NotInteger { key, .. }
        | ParamError::NoSuchOption { key, .. } => key,
    };
    let Some(spec) = specs.iter().find(|s| s.key == key.as_str()) else {
        return super::t_with(lang, "param-unknown", &[("key", key.clone().into())]);
    };
    let choice = matches!(spec.kind, ParamKind::Choice(_));
    let (id, given) = match e {
        // A choice is said by its options, whatever number was asked for.
        ParamError::OutOfRange { value, .. } | ParamError::NotInteger { value, .. } if choice => {
            ("param-no-option", super::number(lang, &value.to_string()))
        }
        ParamError::NotANumber { text, .. } => ("param-not-a-number", text.clone()),
        ParamError::NoSuchOption { text, .. } => ("param-no-option", text.clone()),
        ParamError::OutOfRange { value, .. } => {
            ("param-out-of-range", param_shown(lang, spec, *value))
        }
        ParamError::NotInteger { value, .. } => {
            ("param-not-whole", super::number(lang, &value.to_string()))
        }
        _ => ("param-not-finite", String::new()),
    };
    let args = [
        ("label", param_label(lang, lab, spec).into()),
        ("range", param_range(lang, lab, spec).into()),
        ("given", given.into()),
    ];
    super::t_with(lang, id, &args)
}

/// What a control takes, in `lang`: its options, or its range with the unit.
pub fn param_range(lang: Lang, lab: &dyn Lab, spec: &ParamSpec) -> String {
    match spec.kind {
        ParamKind::Choice(options) => (0..options.len())
            .map(|i| {
                let id = super::param_option_id(lab.id(), spec.key, i);
                super::lab_text(lang, &id, options[i])
            })
            .collect::<Vec<_>>()
            .join(", "),
        _ => format!(
            "{} … {} {}",
            super::number(lang, &spec.min.to_string()),
            super::number(lang, &spec.max.to_string()),
            super::unit(lang, spec.unit)
        )
        .trim_end()
        .to_string(),
    }
}

/// A parameter's label in `lang`.
pub fn param_label(lang: Lang, lab: &dyn Lab, spec: &ParamSpec) -> String {
    super::lab_text(lang, &super::param_label_id(lab.id(), spec.key), spec.label)
}

/// A value as the slider shows it, with its unit in `lang`.
pub fn param_shown(lang: Lang, spec: &ParamSpec, v: f64) -> String {
    let v = super::number(lang, &v.to_string());
    format!("{v} {}", super::unit(lang, spec.unit))
        .trim_end()
        .to_string()
}

/// `key = value` in `lab`'s words: the slider's label and the value with its unit (the key
/// itself where no slider has it).
pub fn param_at(lang: Lang, lab: &dyn Lab, key: &str, value: f64) -> String {
    match lab.params().iter().find(|s| s.key == key) {
        Some(spec) => format!(
            "{} = {}",
            param_label(lang, lab, spec),
            param_shown(lang, spec, value)
        ),
        None => format!("{key} = {}", num(lang, value)),
    }
}

impl Worded for ParamError {
    fn words(&self, lang: Lang, lab: &dyn Lab) -> String {
        param_problem(lang, lab, lab.params(), self)
    }
}

impl Worded for StatsError {
    fn words(&self, lang: Lang, _: &dyn Lab) -> String {
        match self {
            StatsError::Empty => said(lang, "error-stats-empty", &[]),
            StatsError::NotANumber { index } => {
                said(lang, "error-stats-nan", &[("index", index.to_string())])
            }
        }
    }
}

impl Worded for ScoreError {
    fn words(&self, lang: Lang, lab: &dyn Lab) -> String {
        match self {
            ScoreError::Columns { expected, got } => said(
                lang,
                "error-score-columns",
                &[("expected", expected.to_string()), ("got", got.to_string())],
            ),
            ScoreError::EmptyRun => said(lang, "error-score-empty-run", &[]),
            ScoreError::Diverged => said(lang, "error-score-diverged", &[]),
            ScoreError::NoStep => said(lang, "error-score-no-step", &[]),
            ScoreError::EndsTooSoon { end_s, step_s } => said(
                lang,
                "error-score-ends-too-soon",
                &[
                    ("end", super::fixed(lang, *end_s, 1)),
                    ("step", super::fixed(lang, *step_s, 1)),
                ],
            ),
            ScoreError::FewSamples { n } => {
                said(lang, "error-score-few-samples", &[("n", n.to_string())])
            }
            ScoreError::Stat { of, source } => said(
                lang,
                "error-score-stat",
                &[
                    ("of", of.key().to_string()),
                    ("why", source.words(lang, lab)),
                ],
            ),
            ScoreError::Count { got, expected } => said(
                lang,
                "error-score-count",
                &[("got", got.to_string()), ("expected", expected.to_string())],
            ),
        }
    }
}

impl Worded for Unscored {
    fn words(&self, lang: Lang, lab: &dyn Lab) -> String {
        said(
            lang,
            "error-score-seed",
            &[
                ("seed", self.seed.to_string()),
                ("why", self.why.words(lang, lab)),
            ],
        )
    }
}

impl Worded for UnknownSeries {
    fn words(&self, lang: Lang, _: &dyn Lab) -> String {
        said(lang, "error-sim-series", &[("name", self.name.clone())])
    }
}

impl Worded for SimError {
    fn words(&self, lang: Lang, lab: &dyn Lab) -> String {
        match self {
            SimError::Series(e) => e.words(lang, lab),
            SimError::FewSamples => said(lang, "error-sim-few-samples", &[]),
            SimError::Refused(r) => said(
                lang,
                "error-sim-refused",
                &[
                    ("change", param_at(lang, lab, &r.key, r.value)),
                    ("step", r.step.to_string()),
                    ("why", r.reason.words(lang, lab)),
                ],
            ),
            SimError::Csv { detail } => said(lang, "error-sim-csv", &[("detail", detail.clone())]),
        }
    }
}

impl Worded for TravelError {
    fn words(&self, lang: Lang, lab: &dyn Lab) -> String {
        match self {
            TravelError::NoHistory => said(lang, "error-travel-no-history", &[]),
            TravelError::Before { t_s, first_s } => said(
                lang,
                "error-travel-before",
                &[
                    ("t", super::fixed(lang, *t_s, 2)),
                    ("first", super::fixed(lang, *first_s, 2)),
                ],
            ),
            TravelError::NeedsReset { key } => {
                let name = lab
                    .params()
                    .iter()
                    .find(|s| s.key == *key)
                    .map_or_else(|| key.to_string(), |s| param_label(lang, lab, s));
                said(lang, "error-travel-needs-reset", &[("name", name)])
            }
            TravelError::Param(e) => e.words(lang, lab),
            TravelError::Series(e) => e.words(lang, lab),
        }
    }
}

impl Worded for SweepError {
    fn words(&self, lang: Lang, lab: &dyn Lab) -> String {
        match self {
            SweepError::Param(e) => e.words(lang, lab),
            SweepError::Sim(e) => e.words(lang, lab),
            SweepError::WrongLab { job, lab: other } => said(
                lang,
                "error-sweep-wrong-lab",
                &[("job", job.clone()), ("lab", other.clone())],
            ),
            SweepError::NoSweep { lab: other, sweep } => said(
                lang,
                "error-sweep-no-sweep",
                &[("lab", other.clone()), ("sweep", sweep.to_string())],
            ),
            SweepError::NoPoint { sweep, point } => said(
                lang,
                "error-sweep-no-point",
                &[("sweep", sweep.to_string()), ("point", point.to_string())],
            ),
        }
    }
}

impl Worded for Skipped {
    fn words(&self, lang: Lang, lab: &dyn Lab) -> String {
        let mut at = param_at(lang, lab, &self.at.0, self.at.1);
        if let Some((key, value)) = &self.grid {
            at = format!("{at}, {}", param_at(lang, lab, key, *value));
        }
        format!("{at}: {}", self.why.words(lang, lab))
    }
}
