//! A log line that could not be used, in the reader's language: the same facts the CLI
//! prints in English (`LineFault`'s `Display`), from the catalogue.

use attlab::i18n::{self, FluentValue, Lang};
use attlab::model::{LineFault, LogLineError};

/// "line 7: not a number: `abc`" in `lang`.
pub fn line_problem(lang: Lang, e: &LogLineError) -> String {
    let args = [
        ("line", text(e.line)),
        ("reason", fault(lang, &e.reason).into()),
        ("text", e.text.clone().into()),
    ];
    i18n::t_with(lang, "log-line", &args)
}

/// What was wrong with a line, in `lang`.
pub fn fault(lang: Lang, f: &LineFault) -> String {
    let (id, args): (&str, Vec<(&str, FluentValue<'_>)>) = match f {
        LineFault::Columns {
            expected,
            names,
            found,
            merged,
        } => (
            if *merged {
                "log-fault-columns-merged"
            } else {
                "log-fault-columns"
            },
            vec![
                ("expected", text(expected)),
                ("names", text(names)),
                ("found", text(found)),
            ],
        ),
        LineFault::BeforeData => ("log-fault-before-data", vec![]),
        LineFault::NotANumber(bad) => ("log-fault-not-a-number", vec![("text", text(bad))]),
        LineFault::NotUtf8 { byte, column } => (
            "log-fault-not-utf8",
            vec![
                ("byte", text(format!("0x{byte:02X}"))),
                ("column", text(column)),
            ],
        ),
        LineFault::NotAWord { raw, bits, max } => (
            "log-fault-not-a-word",
            vec![("raw", text(raw)), ("bits", text(bits)), ("max", text(max))],
        ),
        LineFault::TimeGlitch { t_s, last_s } => (
            "log-fault-time-glitch",
            vec![("t", text(t_s)), ("last", text(last_s))],
        ),
        LineFault::Duplicate { line } => ("log-fault-duplicate", vec![("line", text(line))]),
        LineFault::Averaged { line } => ("log-fault-averaged", vec![("line", text(line))]),
        LineFault::OutOfOrder { line } => ("log-fault-out-of-order", vec![("line", text(line))]),
    };
    i18n::t_with(lang, id, &args)
}

/// A number as Rust writes it (as the CLI's English does), not as Fluent would.
fn text(value: impl std::fmt::Display) -> FluentValue<'static> {
    FluentValue::from(value.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One fault of every kind (a new kind without words fails to compile in `fault`, and
    /// one missing here is not checked: keep the list whole).
    fn every_fault() -> Vec<LineFault> {
        vec![
            LineFault::Columns {
                expected: 2,
                names: "time, rate",
                found: 4,
                merged: true,
            },
            LineFault::Columns {
                expected: 7,
                names: "time, ax, ay, az, gx, gy, gz",
                found: 3,
                merged: false,
            },
            LineFault::BeforeData,
            LineFault::NotANumber("abc".into()),
            LineFault::NotUtf8 {
                byte: 0xFF,
                column: 5,
            },
            LineFault::NotAWord {
                raw: 16_777_216.0,
                bits: 24,
                max: 16_777_215.0,
            },
            LineFault::TimeGlitch {
                t_s: 1e6,
                last_s: 12.5,
            },
            LineFault::Duplicate { line: 3 },
            LineFault::Averaged { line: 4 },
            LineFault::OutOfOrder { line: 9 },
        ]
    }

    /// The page's English is the CLI's, word for word, so the two cannot drift apart.
    #[test]
    fn the_pages_english_is_the_clis() {
        for f in every_fault() {
            assert_eq!(fault(Lang::En, &f), f.to_string());
            let e = LogLineError {
                line: 7,
                text: "1.0,abc".into(),
                reason: f,
            };
            assert_eq!(line_problem(Lang::En, &e), e.to_string());
        }
    }

    /// In Russian every fault has its own words (no Latin word left but the columns' names,
    /// the line's text and "UTF-8"), no argument unfilled, and the numbers the English gives.
    #[test]
    fn every_fault_is_said_in_russian_with_its_numbers() {
        let cyrillic = |s: &str| {
            s.chars()
                .any(|c| ('а'..='я').contains(&c.to_lowercase().next().unwrap_or(c)))
        };
        for f in every_fault() {
            let (en, ru) = (fault(Lang::En, &f), fault(Lang::Ru, &f));
            // The columns' names stay as the CSV writes them, and the line's own text as it
            // was; the rest is Russian.
            let words = match &f {
                LineFault::Columns { names, .. } => ru.replace(names, ""),
                LineFault::NotANumber(bad) => ru.replace(bad.as_str(), ""),
                _ => ru.clone(),
            };
            assert!(
                cyrillic(&ru)
                    && !words.contains(|c: char| c.is_ascii_lowercase() && c != 'x')
                    && !ru.contains('$'),
                "{ru}"
            );
            let digits = |s: &str| -> Vec<String> {
                s.split(|c: char| !c.is_ascii_alphanumeric() && c != '.')
                    .filter(|w| w.starts_with(|c: char| c.is_ascii_digit()))
                    .map(str::to_string)
                    .collect()
            };
            assert_eq!(digits(&ru), digits(&en), "{en} / {ru}");
        }
    }
}
