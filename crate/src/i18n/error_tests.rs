//! Every kind of every error a page reader can meet has words in both languages: none left
//! as an id, no argument left unfilled, the Russian not the English.

use super::Lang;
use super::errors::Worded;
use crate::analysis::sweep::{Skipped, SweepError};
use crate::model::{ScoreError, StatsError, Unscored};
use crate::sim::{SimError, TravelError};

/// Each example, by its English `Display`, with its words in both languages.
pub(crate) fn said(examples: Vec<(String, &dyn Worded)>) -> Vec<(String, String, String)> {
    let lab = crate::labs::find("p4").expect("registered");
    examples
        .into_iter()
        .map(|(english, e)| (english, e.words(Lang::En, lab), e.words(Lang::Ru, lab)))
        .collect()
}

/// What is wrong with one error's words, if anything.
pub(crate) fn problem(english: &str, en: &str, ru: &str) -> Option<String> {
    let unfilled = |s: &str| s.contains("{$") || s.contains('$') || s.contains("error-");
    let cyrillic = ru
        .chars()
        .any(|c| ('а'..='я').contains(&c.to_lowercase().next().unwrap_or(c)));
    if en.trim().is_empty() || unfilled(en) || unfilled(ru) {
        return Some(format!(
            "{english}: unfilled or missing words: en `{en}`, ru `{ru}`"
        ));
    }
    (ru == en || !cyrillic).then(|| format!("{english}: no Russian: `{ru}`"))
}

#[test]
fn every_error_a_page_reader_meets_is_said_in_both_languages() {
    let sims = SimError::examples();
    let travels = [
        TravelError::NoHistory,
        TravelError::Before {
            t_s: 1.5,
            first_s: 2.25,
        },
        TravelError::NeedsReset { key: "gamma" },
    ];
    let scores = ScoreError::examples();
    let unscored: Vec<Unscored> = scores
        .iter()
        .map(|why| Unscored { seed: 3, why: *why })
        .collect();
    let stats = [StatsError::Empty, StatsError::NotANumber { index: 4 }];
    let sweeps = SweepError::examples();
    let skipped: Vec<Skipped> = sweeps
        .iter()
        .map(|why| Skipped {
            at: ("gamma".into(), 1e-4),
            grid: Some(("q_scale".into(), 2.5)),
            why: why.clone(),
        })
        .collect();
    let mut all: Vec<(String, &dyn Worded)> = Vec::new();
    all.extend(sims.iter().map(|e| (e.to_string(), e as &dyn Worded)));
    all.extend(travels.iter().map(|e| (e.to_string(), e as &dyn Worded)));
    all.extend(scores.iter().map(|e| (e.to_string(), e as &dyn Worded)));
    all.extend(unscored.iter().map(|e| (e.to_string(), e as &dyn Worded)));
    all.extend(stats.iter().map(|e| (e.to_string(), e as &dyn Worded)));
    all.extend(sweeps.iter().map(|e| (e.to_string(), e as &dyn Worded)));
    all.extend(skipped.iter().map(|e| (e.to_string(), e as &dyn Worded)));
    assert!(all.len() >= 27, "only {} examples", all.len());
    let problems: Vec<String> = said(all)
        .iter()
        .filter_map(|(english, en, ru)| problem(english, en, ru))
        .collect();
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn numbers_in_error_words_take_the_readers_decimal_sign() {
    let lab = crate::labs::find("p4").expect("registered");
    let e = ScoreError::EndsTooSoon {
        end_s: 4.5,
        step_s: 4.0,
    };
    assert!(e.words(Lang::En, lab).contains("4.5"));
    assert!(
        e.words(Lang::Ru, lab).contains("4,5"),
        "{}",
        e.words(Lang::Ru, lab)
    );
}

#[test]
fn a_missing_message_is_caught() {
    assert!(problem("x", "error-nope", "error-nope").is_some());
    assert!(problem("x", "a { $b }", "а").is_some());
    assert!(problem("x", "same", "same").is_some());
    assert_eq!(problem("x", "fine", "хорошо"), None);
}
