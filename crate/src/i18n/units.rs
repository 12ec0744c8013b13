//! Units in the reader's language. The code writes a unit once, in SI's Latin symbols
//! (`deg/s`, `N·m`, `kg·m²`, `°/s/√Hz`), which the CLI and the CSV headers keep; the page
//! shows each of its words as the catalogue's `unit-<word>` (`s` is «с» in Russian, `nT`
//! «нТл», `deg` is ° in both) and every sign between them as it is.

use super::{Lang, has, t};

/// `unit` as the reader of `lang` writes it: each word (a run of letters) is the message
/// `unit-<word>` in `lang`, else in English, else the word itself; `µ` is `u` in the id.
///
/// ```
/// # use attlab::i18n::{Lang, unit};
/// assert_eq!(unit(Lang::Ru, "N·m"), "Н·м");
/// assert_eq!(unit(Lang::Ru, "deg/s/√Hz"), "°/с/√Гц");
/// assert_eq!(unit(Lang::En, "(deg/s)²"), "(°/s)²");
/// assert_eq!(unit(Lang::En, "kg·m²"), "kg·m²");
/// ```
pub fn unit(lang: Lang, unit: &str) -> String {
    let mut out = String::with_capacity(unit.len() + 4);
    let mut word = String::new();
    for c in unit.chars() {
        if c.is_alphabetic() {
            word.push(c);
        } else {
            out.push_str(&unit_word(lang, &word));
            word.clear();
            out.push(c);
        }
    }
    out.push_str(&unit_word(lang, &word));
    out
}

/// `text` with every unit written as the code writes it that follows a number ("Δt = 1.17
/// s") in `lang`'s words ("Δt = 1.17 с"); the rest, spacing and punctuation included, as it
/// is. The tests read the Russian catalogue with it: a Russian message must not write an
/// English unit after a number ("100 Hz").
#[cfg(test)]
fn units_after_numbers(lang: Lang, text: &str) -> String {
    let mut out = String::with_capacity(text.len() + 8);
    let mut rest = text;
    let mut after_number = false;
    while !rest.is_empty() {
        let space = rest.len() - rest.trim_start().len();
        out.push_str(&rest[..space]);
        rest = &rest[space..];
        let end = rest.find(char::is_whitespace).unwrap_or(rest.len());
        let (word, tail) = rest.split_at(end);
        rest = tail;
        let core = word.trim_end_matches([',', '.', ';', ':', ')']);
        if after_number && english_unit(core) {
            out.push_str(&unit(lang, core));
            out.push_str(&word[core.len()..]);
        } else {
            out.push_str(word);
        }
        after_number = word.ends_with(char::is_numeric);
    }
    out
}

#[cfg(test)]
/// `word` is a unit as the code writes it and Russian writes it otherwise: every word of it
/// is a unit's word (`unit-<word>` in English), and the Russian differs ("g" is not).
fn english_unit(word: &str) -> bool {
    let words: Vec<&str> = word.split(|c: char| !c.is_alphabetic()).collect();
    words.iter().any(|w| !w.is_empty())
        && words
            .iter()
            .all(|w| w.is_empty() || word_id(w).is_some_and(|id| has(Lang::En, &id)))
        && unit(Lang::Ru, word) != unit(Lang::En, word)
}

/// The catalogue's id of a unit's `word`, if the word can be one (ASCII letters, and `µ`).
fn word_id(word: &str) -> Option<String> {
    let id: String = word
        .chars()
        .map(|c| if c == 'µ' { 'u' } else { c })
        .collect();
    id.chars()
        .all(|c| c.is_ascii_alphabetic())
        .then(|| format!("unit-{id}"))
}

fn unit_word(lang: Lang, word: &str) -> String {
    if let Some(id) = word_id(word) {
        for l in [lang, Lang::En] {
            if has(l, &id) {
                return t(l, &id);
            }
        }
    }
    word.to_string()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::ParamValues;

    /// Every unit of every lab: its parameters' (and its log format's) and its series'.
    fn every_unit() -> std::collections::BTreeSet<&'static str> {
        let mut out = std::collections::BTreeSet::new();
        for lab in crate::labs::all() {
            out.extend(lab.params().iter().map(|p| p.unit));
            if let Some(f) = lab.page().log_format {
                out.extend(f.units.iter().map(|p| p.unit));
            }
            let sim = crate::sim::Simulation::new(*lab, ParamValues::defaults(lab.params()), 1);
            out.extend(sim.available_specs().iter().map(|s| s.unit));
        }
        out
    }

    /// The words a Russian text writes as in English: g, of acceleration.
    const SAME_IN_RUSSIAN: [&str; 1] = ["g"];

    #[test]
    fn every_word_of_every_unit_is_in_russian() {
        let mut missing = Vec::new();
        for u in every_unit() {
            let ru = unit(Lang::Ru, u);
            let latin: String = ru.chars().filter(char::is_ascii_alphabetic).collect();
            let words: Vec<&str> = ru
                .split(|c: char| !c.is_ascii_alphabetic())
                .filter(|w| !w.is_empty() && !SAME_IN_RUSSIAN.contains(w))
                .collect();
            if !words.is_empty() {
                missing.push(format!("`{u}` reads `{ru}` (Latin: {latin})"));
            }
        }
        assert!(
            missing.is_empty(),
            "units not in Russian:\n{}",
            missing.join("\n")
        );
    }

    /// No Russian message writes a number with an English unit ("100 Hz", "0.35 mm",
    /// "8·10⁻⁷ N·m": a superscript digit is numeric too).
    #[test]
    fn the_russian_catalogue_writes_its_units_in_russian() {
        let found: Vec<&str> = Lang::Ru
            .sources()
            .iter()
            .copied()
            .chain(Lang::Ru.lab_sources())
            .flat_map(|source| source.lines())
            .filter(|l| !l.starts_with('#') && units_after_numbers(Lang::Ru, l) != *l)
            .collect();
        assert!(found.is_empty(), "English units:\n{}", found.join("\n"));
        // The check itself sees one.
        assert!(english_unit("Hz") && english_unit("°/s") && !english_unit("g"));
        assert!(!english_unit("Гц") && !english_unit("отсчётов"));
    }

    #[test]
    fn a_unit_after_a_number_is_said_in_the_readers_language() {
        let detail = "Δt = 1.17 s, ε = 0.1";
        assert_eq!(
            units_after_numbers(Lang::Ru, detail),
            "Δt = 1.17 с, ε = 0.1"
        );
        assert_eq!(units_after_numbers(Lang::En, detail), detail);
        assert_eq!(
            units_after_numbers(Lang::Ru, "8·10⁻⁷ N·m  (s is a word; 3 g)"),
            "8·10⁻⁷ Н·м  (s is a word; 3 g)"
        );
        assert_eq!(units_after_numbers(Lang::Ru, ""), "");
    }

    #[test]
    fn degrees_are_a_sign_in_both_languages_and_signs_stay() {
        for lang in Lang::ALL {
            assert_eq!(
                unit(lang, "deg²/s²"),
                "°²/s²".replace('s', &unit(lang, "s"))
            );
            assert_eq!(unit(lang, ""), "");
            assert_eq!(unit(lang, "%"), "%");
        }
        assert_eq!(unit(Lang::Ru, "µg/√Hz"), "мкg/√Гц");
        assert_eq!(unit(Lang::Ru, "kg·m²"), "кг·м²");
        assert_eq!(unit(Lang::En, "N·m·s"), "N·m·s");
        // A word the catalogue does not know stays as written.
        assert_eq!(unit(Lang::Ru, "furlong/s"), "furlong/с");
    }
}
