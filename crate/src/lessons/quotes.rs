//! The numbers a lesson step's words quote, checked against the run the step opens: each
//! [`Quote`] is a parameter of the step, a number of the paper, a number a question poses, or
//! a reading of a run, which is taken here and must round to what the words write (or come
//! within the share the words' "about" allows). The Russian words must quote the same number
//! (with its decimal comma), and every measured-looking number of the English words must be
//! one of the step's quotes (see [`unquoted`]).

mod error;

pub use error::QuoteError;

use crate::analysis::scenario::run_trace_with;
use crate::i18n::{self, Lang};
use crate::model::{ParamValues, ReadingError, SeriesKey, q};
use crate::page::{Holds, Lab, LessonStep, Quote, QuoteSource, Reading};

/// The seed a lesson step opens with (the page's, unless its link names another).
pub const SEED: u64 = 1;

/// The number `shown` writes and half a unit of its last digit: "0.19°" → (0.19, 0.005),
/// "6·10⁻¹³ °" → (6e-13, 5e-14), "1.18e-4 N·m" → (1.18e-4, 5e-7), "−0.82" → (−0.82, 0.005).
pub fn shown_number(shown: &str) -> Option<(f64, f64)> {
    let s = shown
        .trim()
        .trim_matches(['(', ')', ',', ';', '±'])
        .replace('−', "-");
    let end = s
        .char_indices()
        .find(|(i, c)| !(c.is_ascii_digit() || *c == '.' || (*i == 0 && *c == '-')))
        .map_or(s.len(), |(i, _)| i);
    let (mantissa, rest) = s.split_at(end);
    // A bare power of ten: "10⁻¹²".
    if mantissa == "10" && rest.starts_with(|c: char| c == '⁻' || SUPERSCRIPTS.contains(c)) {
        let exponent = exponent_of(&format!("·10{rest}"))?;
        let scale = 10f64.powi(exponent);
        return Some((scale, 0.5 * scale));
    }
    let value: f64 = mantissa.parse().ok()?;
    let decimals = mantissa.split('.').nth(1).map_or(0, str::len);
    let half = 0.5 * 10f64.powi(-(decimals as i32));
    let exponent = exponent_of(rest).unwrap_or(0);
    let scale = 10f64.powi(exponent);
    Some((value * scale, half * scale))
}

/// The power of ten after a mantissa: "·10⁻¹³" or "e-4" (none for anything else).
fn exponent_of(rest: &str) -> Option<i32> {
    if let Some(e) = rest.strip_prefix('e') {
        let digits: String = e
            .chars()
            .take_while(|c| c.is_ascii_digit() || *c == '-')
            .collect();
        return digits.parse().ok();
    }
    let sup = rest.strip_prefix("·10")?;
    let mut text = String::new();
    for c in sup.chars() {
        match c {
            '⁻' => text.push('-'),
            c if SUPERSCRIPTS.contains(c) => text.push(superscript_digit(c)?),
            _ => break,
        }
    }
    text.parse().ok()
}

/// The superscript digits, 0 to 9 (not one run of Unicode: ¹²³ are Latin-1's).
const SUPERSCRIPTS: &str = "⁰¹²³⁴⁵⁶⁷⁸⁹";

fn superscript_digit(c: char) -> Option<char> {
    SUPERSCRIPTS
        .chars()
        .position(|d| d == c)
        .and_then(|k| char::from_digit(k as u32, 10))
}

/// The step's English words: text, question, answers and why.
fn english_words(step: &LessonStep) -> String {
    let mut words = vec![step.text];
    if let Some(q) = &step.question {
        words.push(q.ask);
        words.extend(q.answers);
        words.push(q.why);
    }
    words.join(" ")
}

/// The step's Russian words, as the catalogue has them.
fn russian_words(lab: &dyn Lab, step: &LessonStep) -> String {
    let id = |part: &str| i18n::lesson_id(lab.id(), Some(step.id), part);
    let mut words = vec![i18n::lab_text(Lang::Ru, &id("text"), step.text)];
    if let Some(q) = &step.question {
        words.push(i18n::lab_text(Lang::Ru, &id("ask"), q.ask));
        for (k, answer) in q.answers.iter().enumerate() {
            words.push(i18n::lab_text(
                Lang::Ru,
                &id(&format!("answer-{}", k + 1)),
                answer,
            ));
        }
        words.push(i18n::lab_text(Lang::Ru, &id("why"), q.why));
    }
    words.join(" ")
}

/// What is wrong with the quotes of `step` of `lab`, whose parameters are `params`: one
/// line each (none for a step whose words hold).
pub fn step_quote_problems(
    lab: &'static dyn Lab,
    step: &LessonStep,
    params: &ParamValues,
) -> Vec<String> {
    let english = english_words(step);
    let russian = russian_words(lab, step);
    let mut out = Vec::new();
    for quote in step.quotes {
        if !english.contains(quote.shown) {
            out.push(format!("quotes “{}”, which its words do not", quote.shown));
        }
        for number in numbers_in(quote.shown) {
            let ru = i18n::number(Lang::Ru, &number);
            if !russian.contains(&ru) && !russian.contains(&ru.replace('−', "-")) {
                out.push(format!("its Russian words lack “{ru}” (“{}”)", quote.shown));
            }
        }
        if let Err(e) = check(lab, (params, step.pause_at_s), quote) {
            out.push(format!("“{}”: {e}", quote.shown));
        }
    }
    for number in unquoted(&english, step.quotes) {
        out.push(format!(
            "its words quote “{number}”, which no quote accounts for"
        ));
    }
    out
}

/// Whether `quote` holds for the run of `params` (the step's, which pauses at `pause_s`).
fn check(
    lab: &'static dyn Lab,
    (params, pause_s): (&ParamValues, Option<f64>),
    quote: &Quote,
) -> Result<(), QuoteError> {
    if matches!(quote.source, QuoteSource::Paper | QuoteSource::Posed) {
        return Ok(());
    }
    let (value, half) =
        shown_number(quote.shown).ok_or(QuoteError::NotANumber { shown: quote.shown })?;
    let exact = half.max(1e-9 * value.abs());
    let (got, tolerance) = match quote.source {
        QuoteSource::Paper | QuoteSource::Posed => return Ok(()),
        QuoteSource::Param(key) => (params.try_get(key)?, exact),
        QuoteSource::Pause => (pause_s.ok_or(QuoteError::NoPause)?, exact),
        QuoteSource::Run {
            with,
            reading,
            holds,
            scale,
        } => {
            let mut p = params.clone();
            for (key, v) in with {
                p.set(lab.params(), key, *v)?;
            }
            let got = scale * read(lab, p, &reading)?;
            match holds {
                Holds::Digits => (got, half),
                Holds::About(share) => (got, share * value.abs()),
                Holds::AtMost if got.is_finite() && got <= value + half => return Ok(()),
                Holds::AtMost => return Err(QuoteError::Over { got, value }),
            }
        }
    };
    if got.is_finite() && (got - value).abs() <= tolerance {
        Ok(())
    } else {
        Err(QuoteError::Off {
            got,
            value,
            tolerance,
        })
    }
}

/// The series a reading needs and the time the run must reach.
fn needs(reading: &Reading) -> (Vec<SeriesKey>, f64) {
    match *reading {
        Reading::At(k, t) | Reading::SqrtAt(k, t) | Reading::LastFinite(k, t) => (vec![k], t),
        Reading::Rms(k, _, to)
        | Reading::Std(k, _, to)
        | Reading::Mean(k, _, to)
        | Reading::Min(k, _, to)
        | Reading::Max(k, _, to)
        | Reading::Drift(k, _, to)
        | Reading::MaxAbs(k, _, to) => (vec![k], to),
        Reading::MaxAbsDiff(a, b, _, to) | Reading::RmsDiff(a, b, _, to) => (vec![a, b], to),
        Reading::FirstWithin(k, _, _, to) | Reading::FirstAbove(k, _, _, to) => (vec![k], to),
        Reading::FirstClose(a, b, _, _, to) => (vec![a, b], to),
        Reading::WorstAxisRms(src, _, to) => (axes(src).to_vec(), to),
        Reading::Lab(_) => (Vec::new(), 0.0),
    }
}

/// Takes `reading` off the run of `params` at [`SEED`].
pub fn read(
    lab: &'static dyn Lab,
    params: ParamValues,
    reading: &Reading,
) -> Result<f64, ReadingError> {
    if let Reading::Lab(name) = *reading {
        return lab
            .study()
            .and_then(|s| s.lesson_reading(name, &params, SEED))
            .unwrap_or_else(|| {
                Err(ReadingError::NoSuchReading {
                    lab: lab.id(),
                    name,
                })
            });
    }
    let (keys, until) = needs(reading);
    let dt_s = lab.dt_s(&params);
    let trace = run_trace_with(lab, params, SEED, until + dt_s, &keys)?;
    at_a_time(&Traced { trace, dt_s }, reading)
}

/// A run's full-rate trace and its step.
struct Traced {
    trace: crate::analysis::scenario::Trace,
    dt_s: f64,
}

impl Traced {
    /// Every value of series `k`.
    fn series(&self, k: SeriesKey) -> Result<&[f64], ReadingError> {
        self.trace.series(k).map_err(ReadingError::from)
    }

    /// The values of series `k` over [from, to]: at least one, each finite, or an error.
    fn span(&self, k: SeriesKey, from: f64, to: f64) -> Result<Vec<f64>, ReadingError> {
        let half = 0.5 * self.dt_s;
        let v: Vec<f64> = (self.trace.t_s().iter().zip(self.series(k)?))
            .filter(|(t, _)| **t >= from - half && **t <= to + half)
            .map(|(_, y)| *y)
            .collect();
        if v.is_empty() || v.iter().any(|x| !x.is_finite()) {
            return Err(ReadingError::NoFiniteValues {
                series: k.name(),
                from_s: from,
                to_s: to,
            });
        }
        Ok(v)
    }
}

fn rms(v: &[f64]) -> f64 {
    (v.iter().map(|x| x * x).sum::<f64>() / v.len() as f64).sqrt()
}

/// A reading at one time, or the first time something holds; any other, over a span.
fn at_a_time(run: &Traced, reading: &Reading) -> Result<f64, ReadingError> {
    let t = run.trace.t_s();
    Ok(match *reading {
        Reading::At(k, at) => run.span(k, at, at)?[0],
        Reading::SqrtAt(k, at) => run.span(k, at, at)?[0].max(0.0).sqrt(),
        Reading::LastFinite(k, at) => (t.iter().zip(run.series(k)?).rev())
            .find(|(t, y)| **t <= at + 0.5 * run.dt_s && y.is_finite())
            .map(|(_, y)| *y)
            .ok_or(ReadingError::NoFiniteValue)?,
        Reading::FirstWithin(k, bound, from, _) => {
            first(t, from, run.series(k)?.iter().map(|y| y.abs() <= bound))?
        }
        Reading::FirstAbove(k, level, from, _) => {
            first(t, from, run.series(k)?.iter().map(|y| *y > level))?
        }
        Reading::FirstClose(a, b, bound, from, _) => {
            let close =
                (run.series(a)?.iter().zip(run.series(b)?)).map(|(a, b)| (a - b).abs() <= bound);
            first(t, from, close)?
        }
        _ => return over_a_span(run, reading),
    })
}

/// A statistic over a span of time.
fn over_a_span(run: &Traced, reading: &Reading) -> Result<f64, ReadingError> {
    let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
    let fold = |v: Vec<f64>, start: f64, f: fn(f64, f64) -> f64| v.into_iter().fold(start, f);
    let pair = |x, y, a, b| -> Result<Vec<f64>, ReadingError> {
        let (u, v) = (run.span(x, a, b)?, run.span(y, a, b)?);
        Ok(u.iter().zip(&v).map(|(p, q)| p - q).collect())
    };
    Ok(match *reading {
        Reading::Rms(k, a, b) => rms(&run.span(k, a, b)?),
        Reading::Std(k, a, b) => {
            let v = run.span(k, a, b)?;
            let m = mean(&v);
            rms(&v.iter().map(|x| x - m).collect::<Vec<_>>())
        }
        Reading::Mean(k, a, b) => mean(&run.span(k, a, b)?),
        Reading::Min(k, a, b) => fold(run.span(k, a, b)?, f64::INFINITY, f64::min),
        Reading::Max(k, a, b) => fold(run.span(k, a, b)?, f64::NEG_INFINITY, f64::max),
        Reading::MaxAbs(k, a, b) => fold(run.span(k, a, b)?, 0.0, |m, x| m.max(x.abs())),
        Reading::Drift(k, a, b) => {
            let v = run.span(k, a, b)?;
            let x0 = v[0];
            fold(v.iter().map(|x| x - x0).collect(), 0.0, |m, x| {
                m.max(x.abs())
            }) / x0.abs()
        }
        Reading::RmsDiff(x, y, a, b) => rms(&pair(x, y, a, b)?),
        Reading::MaxAbsDiff(x, y, a, b) => fold(pair(x, y, a, b)?, 0.0, |m, x| m.max(x.abs())),
        Reading::WorstAxisRms(src, a, b) => {
            let each: Vec<f64> = (axes(src).into_iter())
                .map(|k| run.span(k, a, b).map(|v| rms(&v)))
                .collect::<Result<_, _>>()?;
            fold(each, 0.0, f64::max)
        }
        _ => return Err(ReadingError::NotOverASpan),
    })
}

/// An estimator's attitude errors about x, y and z.
fn axes(source: &'static str) -> [SeriesKey; 3] {
    [&q::ERR_X_DEG, &q::ERR_Y_DEG, &q::ERR_Z_DEG].map(|quantity| SeriesKey::new(source, quantity))
}

/// The first time at or after `from` at which `hits` holds.
fn first(t: &[f64], from: f64, mut hits: impl Iterator<Item = bool>) -> Result<f64, ReadingError> {
    t.iter()
        .find(|t| hits.next().unwrap_or(false) && **t >= from)
        .copied()
        .ok_or(ReadingError::Never)
}

/// The numbers of `english` that look measured or set (with a decimal point, a power of
/// ten, or a unit after them) and that no quote's words contain: a number added to a
/// step's words without saying where it comes from. References (Fig. 5, eq. 21, Table 3,
/// step 4, set 10, method (9)) and notation (2Δt, 3σ, x₀) are not numbers of that kind.
pub fn unquoted(english: &str, quotes: &[Quote]) -> Vec<String> {
    let words: Vec<&str> = english.split_whitespace().collect();
    let mut out = Vec::new();
    for (i, w) in words.iter().enumerate() {
        let token = w.trim_start_matches(['(', '[', '“', '"']);
        let Some(first) = token.chars().next() else {
            continue;
        };
        if !(first.is_ascii_digit()
            || (first == '−' && token.chars().nth(1).is_some_and(|c| c.is_ascii_digit())))
        {
            continue;
        }
        // An equation's number in parentheses: "(4.2)".
        if w.starts_with('(') && w.trim_end_matches([',', '.', ';', ':']).ends_with(')') {
            continue;
        }
        let previous = i.checked_sub(1).map_or("", |j| words[j]);
        if REFERENCES.contains(&previous.trim_start_matches('(')) {
            continue;
        }
        let number: String = token
            .chars()
            .take_while(|c| {
                c.is_ascii_digit()
                    || matches!(c, '.' | '−' | '·' | '⁻' | 'e' | '-')
                    || SUPERSCRIPTS.contains(*c)
            })
            .collect();
        let number = number.trim_end_matches(['.', 'e']).to_string();
        let after = &token[number.len()..];
        // Notation: a digit run into a letter (2Δt, 3σ, 2π, 4θ).
        if after.chars().next().is_some_and(|c| c.is_alphabetic()) && !after.starts_with("e-") {
            continue;
        }
        let next = words.get(i + 1).copied().unwrap_or("");
        let unit = after.starts_with(['°', '%'])
            || UNITS
                .iter()
                .any(|u| next.trim_end_matches([',', '.', ';', ')', ':']) == *u);
        let decimal = number.contains('.') || number.contains('·') || number.contains('e');
        if !(unit || decimal) {
            continue;
        }
        if !quotes.iter().any(|q| numbers_in(q.shown).contains(&number)) {
            out.push(number);
        }
    }
    out
}

/// The numbers written in `text` (each a run of digits with its point, sign and power of
/// ten: "(1, −1, 2)" has 1, −1 and 2).
fn numbers_in(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut current = String::new();
    let mut chars = text.chars().peekable();
    while let Some(c) = chars.next() {
        let digit_next = chars.peek().is_some_and(char::is_ascii_digit);
        let part = c.is_ascii_digit()
            || (!current.is_empty() && (matches!(c, '.' | '·' | '⁻') || SUPERSCRIPTS.contains(c)))
            || (current.is_empty() && c == '−' && digit_next)
            || (!current.is_empty()
                && c == 'e'
                && chars
                    .peek()
                    .is_some_and(|d| *d == '-' || d.is_ascii_digit()))
            || (current.ends_with('e') && c == '-');
        if part {
            current.push(c);
        } else if !current.is_empty() {
            out.push(current.trim_end_matches(['.', '·']).to_string());
            current.clear();
        }
    }
    if !current.is_empty() {
        out.push(current.trim_end_matches(['.', '·']).to_string());
    }
    out
}

/// Words before a number that make it a reference, not a quantity.
const REFERENCES: &[&str] = &[
    "Fig.", "Figs.", "eq.", "eqs.", "Eq.", "Table", "Tables", "§", "step", "steps", "Set", "set",
    "sets", "method", "methods", "update", "updates", "Paper", "paper",
];

/// Units after a space that make a number a quantity.
const UNITS: &[&str] = &[
    "°/s", "°", "s", "%", "g", "Hz", "nT", "N·m", "rad/s²", "rad/s", "rad", "kg·m²", "mm", "m",
    "deg²", "s⁻²", "kg", "ms",
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_shown_number_is_read_with_half_its_last_digit() {
        assert_eq!(shown_number("0.19°"), Some((0.19, 0.005)));
        assert_eq!(shown_number("−0.82"), Some((-0.82, 0.005)));
        assert_eq!(shown_number("10.4°"), Some((10.4, 0.05)));
        assert_eq!(shown_number("1390 s"), Some((1390.0, 0.5)));
        let (v, h) = shown_number("6·10⁻¹³ °").unwrap();
        assert!(
            (v - 6e-13).abs() < 1e-25 && (h - 5e-14).abs() < 1e-26,
            "{v} {h}"
        );
        let (v, h) = shown_number("1.18e-4 N·m").unwrap();
        assert!(
            (v - 1.18e-4).abs() < 1e-16 && (h - 5e-7).abs() < 1e-18,
            "{v} {h}"
        );
        assert_eq!(shown_number("2·10⁻³").map(|p| p.0), Some(2e-3));
        assert_eq!(shown_number("10⁻¹²").map(|p| p.0), Some(1e-12));
        assert_eq!(shown_number("deg"), None);
    }

    #[test]
    fn a_number_without_a_quote_is_found_and_references_and_notation_are_not() {
        let text = "In Fig. 5 and eq. 21 the error is 0.19° after 60 s; 2Δt and 3σ are notation, \
                    step 4 and set 10 references, 6·10⁻¹³ ° small and 11 values a count.";
        let quotes = [Quote::posed("0.19°"), Quote::posed("60 s")];
        assert_eq!(unquoted(text, &quotes), vec!["6·10⁻¹³".to_string()]);
        assert!(unquoted(text, &[Quote::posed("6·10⁻¹³ °"), quotes[0], quotes[1]]).is_empty());
        // A quote accounts for its own numbers, not for one that contains them.
        assert_eq!(unquoted("it is 10.19°", &quotes), vec!["10.19".to_string()]);
        assert_eq!(
            numbers_in("(1, −1, 2)/√6 and 1.18e-4 N·m"),
            ["1", "−1", "2", "6", "1.18e-4"]
        );
    }
}
