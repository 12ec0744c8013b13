//! A log line that could not be used, and why a whole log was refused, in the reader's
//! language: the same facts the CLI prints in English (`LineFault`'s and `LogRefusal`'s
//! `Display`), from the catalogue.

use attlab::i18n::{self, FluentValue, Lang};
use attlab::model::{LineFault, LogCounts, LogLineError, LogRefusal};

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
            vec![
                ("t", text(i18n::number(lang, &t_s.to_string()))),
                ("last", text(i18n::number(lang, &last_s.to_string()))),
            ],
        ),
        LineFault::Duplicate { line } => ("log-fault-duplicate", vec![("line", text(line))]),
        LineFault::Averaged { line } => ("log-fault-averaged", vec![("line", text(line))]),
        LineFault::OutOfOrder { line } => ("log-fault-out-of-order", vec![("line", text(line))]),
    };
    i18n::t_with(lang, id, &args)
}

/// Why a whole log cannot be replayed, in `lang`; a format is named in the reader's words
/// of the lab that reads it.
pub fn refusal(lang: Lang, r: &LogRefusal) -> String {
    let format_name =
        |lab: &str, english: &str| i18n::lab_text(lang, &i18n::log_format_id(lab, "name"), english);
    let (id, args): (&str, Vec<(&str, FluentValue<'_>)>) = match r {
        LogRefusal::NotReplayed { lab, replaying } => (
            "log-refused-not-replayed",
            vec![("lab", text(lab)), ("labs", text(replaying.join(", ")))],
        ),
        LogRefusal::OtherWidth {
            lines,
            width,
            own,
            columns,
            lab,
            format,
            other,
        } => {
            let mut args = vec![
                ("lines", text(lines)),
                ("width", text(width)),
                ("own", text(own)),
                ("columns", text(columns)),
                ("lab", text(lab)),
                ("format", text(format_name(lab, format))),
            ];
            let Some(other) = other else {
                return i18n::t_with(lang, "log-refused-width", &args);
            };
            let first = other.labs.first().copied().unwrap_or_default();
            args.extend([
                ("other", text(format_name(first, other.name))),
                ("labs", text(other.labs.join(", "))),
                ("count", FluentValue::from(other.labs.len())),
            ]);
            ("log-refused-width-like", args)
        }
        LogRefusal::TooFewSamples { counts, first } => {
            let mut args = counted(counts);
            let Some(first) = first else {
                return i18n::t_with(lang, "log-refused-few", &args);
            };
            args.push(("first", line_problem(lang, first).into()));
            ("log-refused-few-first", args)
        }
        LogRefusal::AccelUnit {
            median_g,
            unit,
            gives_g,
        } => (
            "log-refused-accel",
            vec![
                ("g", text(i18n::number(lang, &format!("{median_g:.3e}")))),
                ("unit", text(unit)),
                ("gives", text(i18n::fixed(lang, *gives_g, 2))),
            ],
        ),
    };
    i18n::t_with(lang, id, &args)
}

/// What became of a log's lines, as arguments.
fn counted(c: &LogCounts) -> Vec<(&'static str, FluentValue<'static>)> {
    vec![
        ("kept", text(c.kept)),
        ("lines", text(c.data_lines)),
        ("reordered", text(c.reordered)),
        ("merged", text(c.merged)),
        ("rejected", text(c.rejected)),
    ]
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

    /// A refusal of every kind, as read_log and the IMU format's check give them.
    fn every_refusal() -> Vec<LogRefusal> {
        let counts = LogCounts {
            data_lines: 3,
            kept: 1,
            reordered: 0,
            merged: 1,
            rejected: 1,
        };
        let first = LogLineError {
            line: 2,
            text: "x,y".into(),
            reason: LineFault::NotANumber("x".into()),
        };
        let width = |other| LogRefusal::OtherWidth {
            lines: 1000,
            width: 7,
            own: 3,
            columns: 2,
            lab: "p1",
            format: "a one-axis gyro log (time, rate)",
            other,
        };
        let other = |labs: Vec<&'static str>| attlab::model::OtherFormat {
            name: "an MPU-6050 IMU log (time, accelerometer, gyro)",
            labs,
        };
        vec![
            LogRefusal::NotReplayed {
                lab: "p2",
                replaying: vec!["p1", "p3", "p4"],
            },
            width(None),
            width(Some(other(vec!["p4"]))),
            width(Some(other(vec!["p3", "p4"]))),
            LogRefusal::TooFewSamples {
                counts,
                first: None,
            },
            LogRefusal::TooFewSamples {
                counts,
                first: Some(first),
            },
            LogRefusal::AccelUnit {
                median_g: 16384.0,
                unit: "counts2",
                gives_g: 1.0,
            },
        ]
    }

    /// A whole log's refusal: the page's English is the CLI's; the Russian has Cyrillic
    /// words, every number of the English, and no argument unfilled.
    #[test]
    fn a_refusal_is_the_clis_in_english_and_russian_with_its_numbers() {
        for r in every_refusal() {
            assert_eq!(refusal(Lang::En, &r), r.to_string());
            let (en, ru) = (refusal(Lang::En, &r), refusal(Lang::Ru, &r));
            assert!(ru.chars().any(|c| ('а'..='я').contains(&c)), "{ru}");
            assert!(!ru.contains('$') && ru != en, "{ru}");
            same_numbers(&en, &ru);
        }
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
            same_numbers(&en, &ru);
        }
    }

    /// `ru` says the numbers `en` says, each with the Russian decimal comma.
    fn same_numbers(en: &str, ru: &str) {
        let digit = |k: Option<char>| k.is_some_and(|k| k.is_ascii_digit());
        let decimal_points: String = (ru.char_indices())
            .map(|(i, c)| {
                let around = (
                    ru[..i].chars().next_back(),
                    ru[i + c.len_utf8()..].chars().next(),
                );
                if c == ',' && digit(around.0) && digit(around.1) {
                    '.'
                } else {
                    c
                }
            })
            .collect();
        assert_eq!(numbers(&decimal_points), numbers(en), "{en} / {ru}");
        for n in numbers(en).iter().filter(|n| n.contains('.')) {
            assert!(ru.contains(&i18n::number(Lang::Ru, n)), "{n} in {ru}");
        }
    }

    /// The numbers in `s`, sorted (a language may give them in another order).
    fn numbers(s: &str) -> Vec<String> {
        let mut out: Vec<String> = s
            .split(|c: char| !c.is_ascii_alphanumeric() && c != '.' && c != '+' && c != '-')
            .filter(|w| w.starts_with(|c: char| c.is_ascii_digit()))
            .map(|w| {
                let end = w
                    .find(|c: char| !(c.is_ascii_digit() || ".e+-".contains(c)))
                    .unwrap_or(w.len());
                w[..end]
                    .trim_end_matches(|c: char| !c.is_ascii_digit())
                    .to_string()
            })
            .collect();
        out.sort();
        out
    }
}
