//! Why an item of a link that is not a lab parameter was refused (the lab, the lesson and
//! its step, the page's own settings, a lesson's answers and controls), typed: the CLI and
//! [`super::UrlStateError`]'s text say it in English ([`std::fmt::Display`]), the page in
//! the reader's language ([`LinkFault::words`], the catalogue's `link-fault-*` messages).

use crate::i18n::{self, FluentValue, Lang};
use thiserror::Error;

/// A refused link item's reason.
#[derive(Clone, Debug, Error, PartialEq)]
pub enum LinkFault {
    /// `lab=` names no lab; the lab ids, comma-separated.
    #[error("no such lab (labs: {0})")]
    NoSuchLab(String),
    /// `lesson=` names no lab with a lesson; their ids.
    #[error("no such lesson (lessons: {0})")]
    NoSuchLesson(String),
    /// `step=` without `lesson=`.
    #[error("step needs a lesson (lesson=<lab>)")]
    StepWithoutLesson,
    /// `step=` outside 1..=steps.
    #[error("step must be a whole number 1–{0}")]
    NoSuchStep(usize),
    /// An item without `=`.
    #[error("expected key=value")]
    NotKeyValue,
    /// `seed=` not a whole number.
    #[error("seed must be a whole number ≥ 0")]
    Seed,
    /// `speed=` outside the page's range.
    #[error("speed must be between {lo} and {hi}")]
    Speed {
        /// The slowest.
        lo: f64,
        /// The fastest.
        hi: f64,
    },
    /// `presenter=` not 1 or 0.
    #[error("presenter must be 1 or 0")]
    Presenter,
    /// `theme=` not light or dark.
    #[error("theme must be light or dark")]
    Theme,
    /// `lang=` not a language of the page.
    #[error("lang must be en or ru")]
    Lang,
    /// `embed=` not 1 or 0.
    #[error("embed must be 1 or 0")]
    Embed,
    /// `origin=` not a web origin.
    #[error("`{0}` is not a web origin (like https://example.org or http://127.0.0.1:8000, or *)")]
    Origin(String),
    /// `at=` not a time in seconds.
    #[error("at must be a time in seconds ≥ 0")]
    At,
    /// `whatif=` not a time and changes.
    #[error(
        "`{0}` is not a what-if: a time in seconds, then the changes (like 1390:q_scale=0.1,x=2)"
    )]
    WhatIf(String),
    /// More `whatif=` items than the page runs.
    #[error("at most {0} what-ifs")]
    TooManyWhatIfs(usize),
    /// `answers=` without `lesson=`.
    #[error("answers need a lesson (lesson=<lab>)")]
    AnswersWithoutLesson,
    /// `answers=` for a lab without a lesson.
    #[error("this lab has no lesson")]
    NoLesson,
    /// A part of `answers=` that is not a step and a letter.
    #[error("`{0}` is not a step number and an answer letter (like 2b)")]
    NotAnAnswer(String),
    /// An answer letter the step does not offer.
    #[error("step {step} has no answer {letter}")]
    NoSuchAnswer {
        /// The step (1-based).
        step: usize,
        /// The letter asked for.
        letter: char,
    },
    /// A key of `hide=` or `lock=` that is no parameter of the lab.
    #[error("`{key}` is not a parameter of {lab} (or `all`)")]
    NotAParameter {
        /// The key as written.
        key: String,
        /// The lab's id.
        lab: &'static str,
    },
}

impl LinkFault {
    /// The catalogue's message for it.
    pub fn message_id(&self) -> &'static str {
        match self {
            Self::NoSuchLab(_) => "link-fault-no-such-lab",
            Self::NoSuchLesson(_) => "link-fault-no-such-lesson",
            Self::StepWithoutLesson => "link-fault-step-without-lesson",
            Self::NoSuchStep(_) => "link-fault-no-such-step",
            Self::NotKeyValue => "link-fault-not-key-value",
            Self::Seed => "link-fault-seed",
            Self::Speed { .. } => "link-fault-speed",
            Self::Presenter => "link-fault-presenter",
            Self::Theme => "link-fault-theme",
            Self::Lang => "link-fault-lang",
            Self::Embed => "link-fault-embed",
            Self::Origin(_) => "link-fault-origin",
            Self::At => "link-fault-at",
            Self::WhatIf(_) => "link-fault-what-if",
            Self::TooManyWhatIfs(_) => "link-fault-too-many-what-ifs",
            Self::AnswersWithoutLesson => "link-fault-answers-without-lesson",
            Self::NoLesson => "link-fault-no-lesson",
            Self::NotAnAnswer(_) => "link-fault-not-an-answer",
            Self::NoSuchAnswer { .. } => "link-fault-no-such-answer",
            Self::NotAParameter { .. } => "link-fault-not-a-parameter",
        }
    }

    /// Its arguments as the message names them, numbers in `lang`'s decimals.
    pub fn arguments(&self, lang: Lang) -> Vec<(&'static str, String)> {
        match self {
            Self::NoSuchLab(ids) | Self::NoSuchLesson(ids) => vec![("ids", ids.clone())],
            Self::NoSuchStep(steps) => vec![("steps", steps.to_string())],
            Self::Speed { lo, hi } => vec![
                ("lo", i18n::number(lang, &lo.to_string())),
                ("hi", i18n::number(lang, &hi.to_string())),
            ],
            Self::NotAnAnswer(part) => vec![("part", part.clone())],
            Self::Origin(text) | Self::WhatIf(text) => vec![("text", text.clone())],
            Self::TooManyWhatIfs(most) => vec![("most", most.to_string())],
            Self::NoSuchAnswer { step, letter } => {
                vec![("step", step.to_string()), ("letter", letter.to_string())]
            }
            Self::NotAParameter { key, lab } => {
                vec![("key", key.clone()), ("lab", (*lab).to_string())]
            }
            _ => Vec::new(),
        }
    }

    /// What it says in `lang`.
    pub fn words(&self, lang: Lang) -> String {
        let args: Vec<(&str, FluentValue<'_>)> = (self.arguments(lang).into_iter())
            .map(|(name, value)| (name, FluentValue::from(value)))
            .collect();
        i18n::t_with(lang, self.message_id(), &args)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One of each (the match fails to compile when a fault is added and not listed).
    fn every_fault() -> Vec<LinkFault> {
        let all = vec![
            LinkFault::NoSuchLab("p1, p2".into()),
            LinkFault::NoSuchLesson("p3".into()),
            LinkFault::StepWithoutLesson,
            LinkFault::NoSuchStep(7),
            LinkFault::NotKeyValue,
            LinkFault::Seed,
            LinkFault::Speed {
                lo: 0.1,
                hi: 10_000.0,
            },
            LinkFault::Presenter,
            LinkFault::Theme,
            LinkFault::Lang,
            LinkFault::Embed,
            LinkFault::Origin("ftp://x".into()),
            LinkFault::At,
            LinkFault::WhatIf("zz".into()),
            LinkFault::TooManyWhatIfs(3),
            LinkFault::AnswersWithoutLesson,
            LinkFault::NoLesson,
            LinkFault::NotAnAnswer("9q".into()),
            LinkFault::NoSuchAnswer {
                step: 2,
                letter: 'z',
            },
            LinkFault::NotAParameter {
                key: "zz".into(),
                lab: "p1",
            },
        ];
        for fault in &all {
            match fault {
                LinkFault::NoSuchLab(_)
                | LinkFault::NoSuchLesson(_)
                | LinkFault::StepWithoutLesson
                | LinkFault::NoSuchStep(_)
                | LinkFault::NotKeyValue
                | LinkFault::Seed
                | LinkFault::Speed { .. }
                | LinkFault::Presenter
                | LinkFault::Theme
                | LinkFault::Lang
                | LinkFault::Embed
                | LinkFault::Origin(_)
                | LinkFault::At
                | LinkFault::WhatIf(_)
                | LinkFault::TooManyWhatIfs(_)
                | LinkFault::AnswersWithoutLesson
                | LinkFault::NoLesson
                | LinkFault::NotAnAnswer(_)
                | LinkFault::NoSuchAnswer { .. }
                | LinkFault::NotAParameter { .. } => {}
            }
        }
        all
    }

    /// Every fault in both languages: its own words (the Russian not the English), its
    /// arguments in them, and the English as the CLI says it.
    #[test]
    fn every_link_fault_is_said_in_both_languages_with_its_arguments() {
        let faults = every_fault();
        assert_eq!(faults.len(), 20);
        for fault in faults {
            let id = fault.message_id();
            let (en, ru) = (fault.words(Lang::En), fault.words(Lang::Ru));
            assert_eq!(en, fault.to_string(), "{id}");
            assert!(i18n::has(Lang::Ru, id), "{id} is missing in Russian");
            assert!(ru != en && !ru.contains('$'), "{id}: {ru}");
            for lang in Lang::ALL {
                let text = fault.words(lang);
                for (name, value) in fault.arguments(lang) {
                    assert!(
                        text.contains(&value),
                        "{id}: ${name} = {value} not in {text}"
                    );
                }
            }
        }
        assert!(
            LinkFault::Speed { lo: 0.1, hi: 1.0 }
                .words(Lang::Ru)
                .contains("0,1")
        );
    }
}
