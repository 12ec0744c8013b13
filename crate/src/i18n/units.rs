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

    /// `word` is a unit as the code writes it and Russian writes it otherwise: every word
    /// of it is a unit's word (`unit-<word>` in English), and the Russian differs.
    fn english_unit(word: &str) -> bool {
        let words: Vec<&str> = word.split(|c: char| !c.is_alphabetic()).collect();
        words.iter().any(|w| !w.is_empty())
            && words
                .iter()
                .all(|w| w.is_empty() || word_id(w).is_some_and(|id| has(Lang::En, &id)))
            && unit(Lang::Ru, word) != unit(Lang::En, word)
    }

    /// No Russian message writes a number with an English unit ("100 Hz", "0.35 mm",
    /// "8·10⁻⁷ N·m": a superscript digit is numeric too).
    #[test]
    fn the_russian_catalogue_writes_its_units_in_russian() {
        let mut found = Vec::new();
        for source in Lang::Ru.sources().iter().chain(Lang::Ru.lab_sources()) {
            for line in source.lines().filter(|l| !l.starts_with('#')) {
                let words: Vec<&str> = line.split_whitespace().collect();
                for pair in words.windows(2) {
                    let after = pair[1].trim_end_matches([',', '.', ';', ':', ')']);
                    if pair[0].ends_with(char::is_numeric) && english_unit(after) {
                        found.push(format!("`{} {}` in: {line}", pair[0], pair[1]));
                    }
                }
            }
        }
        assert!(found.is_empty(), "English units:\n{}", found.join("\n"));
        // The check itself sees one.
        assert!(english_unit("Hz") && english_unit("°/s") && !english_unit("g"));
        assert!("8·10⁻⁷".ends_with(char::is_numeric) && !"T".ends_with(char::is_numeric));
        assert!(!english_unit("Гц") && !english_unit("отсчётов"));
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
