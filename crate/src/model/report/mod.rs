//! Reproduction reports: each row is either a measurement (no verdict) or a check whose
//! expectation is an interval computed from the paper, a closed form or an independent
//! computation — never a literal verdict. A check the paper's number does not meet is
//! declared with its reason and prints as "differs"; if it starts to match, or an undeclared
//! check stops matching, the row fails. A check that holds only because this project chose a
//! setting the paper does not give prints as "matches after calibration", naming the setting,
//! with the same quantity at the setting ±50 % beside it ([`Calibration`]).

use serde::Serialize;
use thiserror::Error;

mod calibration;
pub use calibration::{Calibration, SENSITIVITY_FACTORS};

/// What a check expects of its measured value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Expectation {
    /// `lo ≤ x ≤ hi`; either bound may be infinite.
    Interval {
        /// Lower bound.
        lo: f64,
        /// Upper bound.
        hi: f64,
    },
    /// Within a factor of the paper's range: `lo / factor ≤ x ≤ hi · factor`.
    WithinFactor {
        /// The paper's lower value.
        lo: f64,
        /// The paper's upper value.
        hi: f64,
        /// Allowed factor (> 1).
        factor: f64,
    },
    /// `|x − value| ≤ tol`.
    Near {
        /// Expected value.
        value: f64,
        /// Absolute tolerance.
        tol: f64,
    },
}

impl Expectation {
    /// `x < bound` (strictly below another measurement or a limit).
    pub fn below(bound: f64) -> Self {
        Self::Interval {
            lo: f64::NEG_INFINITY,
            hi: bound,
        }
    }

    /// `x > bound`.
    pub fn above(bound: f64) -> Self {
        Self::Interval {
            lo: bound,
            hi: f64::INFINITY,
        }
    }

    /// Within `factor` of a single value.
    pub fn within_factor_of(value: f64, factor: f64) -> Self {
        Self::WithinFactor {
            lo: value,
            hi: value,
            factor,
        }
    }

    /// The accepted interval `[lo, hi]`.
    pub fn bounds(&self) -> (f64, f64) {
        match *self {
            Self::Interval { lo, hi } => (lo, hi),
            Self::WithinFactor { lo, hi, factor } => (lo / factor, hi * factor),
            Self::Near { value, tol } => (value - tol, value + tol),
        }
    }

    /// Whether `x` meets the expectation (never for NaN, or when a bound is NaN).
    pub fn holds(&self, x: f64) -> bool {
        let (lo, hi) = self.bounds();
        !x.is_nan() && !lo.is_nan() && !hi.is_nan() && lo <= x && x <= hi
    }

    /// The expectation as text, e.g. `0.005 … 0.03 (2× of 0.01–0.015)`.
    pub fn describe(&self) -> String {
        match *self {
            Self::Interval { lo, hi } if lo == f64::NEG_INFINITY => format!("< {}", fmt_sig(hi)),
            Self::Interval { lo, hi } if hi == f64::INFINITY => format!("> {}", fmt_sig(lo)),
            Self::Interval { lo, hi } => format!("{} … {}", fmt_sig(lo), fmt_sig(hi)),
            Self::WithinFactor { lo, hi, factor } => {
                let paper = if lo == hi {
                    fmt_sig(lo)
                } else {
                    format!("{}–{}", fmt_sig(lo), fmt_sig(hi))
                };
                format!(
                    "{} … {} ({}× of {paper})",
                    fmt_sig(lo / factor),
                    fmt_sig(hi * factor),
                    fmt_sig(factor)
                )
            }
            Self::Near { value, tol } => format!("{} ± {}", fmt_sig(value), fmt_sig(tol)),
        }
    }
}

/// Whether a row carries a verdict.
#[derive(Clone, Debug, PartialEq)]
pub enum RowKind {
    /// A number this simulator measured; no verdict.
    Measurement,
    /// A number checked against an expectation.
    Check {
        /// What is expected.
        expect: Expectation,
        /// Declared when the paper's number is known not to be met here: why (one line).
        differs_because: Option<String>,
        /// The setting the paper does not give that was chosen here so that this check holds.
        calibrated_by: Option<String>,
    },
}

/// The verdict of a row.
#[derive(Clone, Debug, PartialEq)]
pub enum Outcome {
    /// No verdict.
    Measurement,
    /// The check holds.
    Matches,
    /// The check holds at a setting chosen here so that it would (the setting).
    MatchesAfterCalibration(String),
    /// The check does not hold, as declared, for this reason.
    Differs(String),
    /// Something is wrong: an undeclared mismatch, a declared mismatch that now matches, or
    /// a value that is not a number.
    Fails(String),
}

impl Outcome {
    /// Whether the row is as declared (everything but [`Outcome::Fails`]).
    pub fn is_as_declared(&self) -> bool {
        !matches!(self, Self::Fails(_))
    }

    /// The verdict in words: `measurement`, `matches`, `matches after calibration`,
    /// `differs`, `FAILS`.
    pub fn word(&self) -> &'static str {
        match self {
            Self::Measurement => "measurement",
            Self::Matches => "matches",
            Self::MatchesAfterCalibration(_) => "matches after calibration",
            Self::Differs(_) => "differs",
            Self::Fails(_) => "FAILS",
        }
    }

    /// The reason, for `differs` and `FAILS`; the setting, for a calibrated match.
    pub fn reason(&self) -> Option<&str> {
        match self {
            Self::Differs(r) | Self::Fails(r) | Self::MatchesAfterCalibration(r) => Some(r),
            _ => None,
        }
    }
}

/// One line of a reproduction report.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    /// What is measured.
    pub quantity: String,
    /// What the paper says about it (text; "—" when the paper is silent).
    pub paper: String,
    /// What this simulator measured.
    pub measured: f64,
    /// Unit of `measured`.
    pub unit: &'static str,
    /// Measurement or check.
    pub kind: RowKind,
}

impl Row {
    /// A measurement: printed, never judged (but a NaN still fails).
    pub fn measurement(
        quantity: impl Into<String>,
        paper: impl Into<String>,
        measured: f64,
        unit: &'static str,
    ) -> Self {
        Self {
            quantity: quantity.into(),
            paper: paper.into(),
            measured,
            unit,
            kind: RowKind::Measurement,
        }
    }

    /// A check of `measured` against `expect`.
    pub fn check(
        quantity: impl Into<String>,
        paper: impl Into<String>,
        measured: f64,
        unit: &'static str,
        expect: Expectation,
    ) -> Self {
        Self {
            kind: RowKind::Check {
                expect,
                differs_because: None,
                calibrated_by: None,
            },
            ..Self::measurement(quantity, paper, measured, unit)
        }
    }

    /// Declares that this check is known not to hold, and why (one line).
    pub fn known_to_differ(mut self, reason: impl Into<String>) -> Self {
        if let RowKind::Check {
            differs_because, ..
        } = &mut self.kind
        {
            *differs_because = Some(reason.into());
        }
        self
    }

    /// Declares that this check holds only at `setting`, which the paper does not give and
    /// which was chosen here so that it would (e.g. "gyro rate = 10 Hz"). Use
    /// [`Calibration::rows`] to put the same quantity at the setting ±50 % beside it.
    pub fn calibrated_by(mut self, setting: impl Into<String>) -> Self {
        if let RowKind::Check { calibrated_by, .. } = &mut self.kind {
            *calibrated_by = Some(setting.into());
        }
        self
    }

    /// The verdict.
    pub fn outcome(&self) -> Outcome {
        if self.measured.is_nan() {
            return Outcome::Fails("the measured value is not a number".into());
        }
        match &self.kind {
            RowKind::Measurement => Outcome::Measurement,
            RowKind::Check {
                expect,
                differs_because,
                calibrated_by,
            } => match (expect.holds(self.measured), differs_because) {
                (true, None) => match calibrated_by {
                    Some(setting) => Outcome::MatchesAfterCalibration(setting.clone()),
                    None => Outcome::Matches,
                },
                (false, Some(reason)) => Outcome::Differs(reason.clone()),
                (false, None) => Outcome::Fails(format!("expected {}", expect.describe())),
                (true, Some(reason)) => Outcome::Fails(format!(
                    "declared to differ ({reason}) but now matches: update the row"
                )),
            },
        }
    }

    /// The expectation as text ("—" for a measurement).
    pub fn expected_text(&self) -> String {
        match &self.kind {
            RowKind::Measurement => "—".into(),
            RowKind::Check { expect, .. } => expect.describe(),
        }
    }
}

/// The JSON shape of a row.
#[derive(Serialize)]
struct RowJson<'a> {
    quantity: &'a str,
    paper: &'a str,
    expected: String,
    measured: f64,
    unit: &'a str,
    outcome: &'static str,
    reason: Option<&'a str>,
}

impl Serialize for Row {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let outcome = self.outcome();
        RowJson {
            quantity: &self.quantity,
            paper: &self.paper,
            expected: self.expected_text(),
            measured: self.measured,
            unit: self.unit,
            outcome: outcome.word(),
            reason: outcome.reason(),
        }
        .serialize(s)
    }
}

/// Why a reproduction could not be computed (a programming error: a series or parameter
/// that does not exist, a statistic over no data).
#[derive(Clone, Debug, Error, PartialEq)]
#[error("{0}")]
pub struct ReproError(pub String);

/// A lab's reproduction report.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct Reproduction {
    /// Lab id.
    pub lab: String,
    /// The rows.
    pub rows: Vec<Row>,
    /// Notes on deviations and unstated parameters.
    pub notes: Vec<String>,
}

impl Reproduction {
    /// Every row is as declared (no row fails).
    pub fn all_as_declared(&self) -> bool {
        self.rows.iter().all(|r| r.outcome().is_as_declared())
    }

    /// Rows that fail, as text.
    pub fn failures(&self) -> Vec<String> {
        self.rows
            .iter()
            .filter_map(|r| match r.outcome() {
                Outcome::Fails(why) => {
                    Some(format!("{}: {} {} — {why}", r.quantity, r.measured, r.unit))
                }
                _ => None,
            })
            .collect()
    }

    /// Plain-text table for the terminal.
    pub fn to_table(&self) -> String {
        let w = self
            .rows
            .iter()
            .map(|r| r.quantity.chars().count())
            .max()
            .unwrap_or(8)
            .max(8);
        let mut s = format!(
            "== {} ==\n{:<w$}  {:>28}  {:>11}  {:<7} verdict\n",
            self.lab, "quantity", "expected", "measured", "unit"
        );
        for r in &self.rows {
            let outcome = r.outcome();
            let verdict = match outcome.reason() {
                Some(why) => format!("{} — {why}", outcome.word()),
                None => outcome.word().to_string(),
            };
            s += &format!(
                "{:<w$}  {:>28}  {:>11}  {:<7} {verdict}\n",
                r.quantity,
                r.expected_text(),
                fmt_sig(r.measured),
                r.unit,
            );
            if r.paper != "—" && !r.paper.is_empty() {
                s += &format!("{:<w$}    paper: {}\n", "", r.paper);
            }
        }
        for n in &self.notes {
            s += &format!("note: {n}\n");
        }
        s
    }

    /// A Markdown table (what the lab's chapter shows, generated from this report).
    pub fn to_markdown(&self) -> String {
        let mut s = String::from(
            "| quantity | paper | expected | measured | verdict |\n|---|---|---|---|---|\n",
        );
        for r in &self.rows {
            let outcome = r.outcome();
            let verdict = match outcome.reason() {
                Some(why) => format!("{}: {why}", outcome.word()),
                None => outcome.word().to_string(),
            };
            let unit = if r.unit.is_empty() {
                String::new()
            } else {
                format!(" {}", r.unit)
            };
            s += &format!(
                "| {} | {} | {} | {}{unit} | {} |\n",
                md(&r.quantity),
                md(&r.paper),
                md(&r.expected_text()),
                fmt_sig(r.measured),
                md(&verdict)
            );
        }
        s
    }
}

fn md(text: &str) -> String {
    text.replace('|', "\\|")
}

/// A number with three significant digits, fixed-point between 1e-3 and 1e5, else
/// scientific: `0.0217`, `1.35`, `9.77e-6`.
///
/// ```
/// # use attlab::model::fmt_sig;
/// assert_eq!(fmt_sig(0.021734), "0.0217");
/// assert_eq!(fmt_sig(9.7712e-6), "9.77e-6");
/// assert_eq!(fmt_sig(1350.2), "1350");
/// assert_eq!(fmt_sig(f64::NAN), "NaN");
/// ```
pub fn fmt_sig(x: f64) -> String {
    if x.is_nan() {
        return "NaN".into();
    }
    if x.is_infinite() {
        return if x > 0.0 {
            "∞".into()
        } else {
            "−∞".into()
        };
    }
    if x == 0.0 {
        return "0".into();
    }
    let a = x.abs();
    if (1e-3..1e5).contains(&a) {
        let digits = (2 - a.log10().floor() as i32).max(0) as usize;
        let s = format!("{x:.digits$}");
        // "0.0500" → "0.05": trailing zeros after the point carry no information here.
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        }
    } else {
        let s = format!("{x:.2e}");
        let (mantissa, exp) = s.split_once('e').unwrap_or((&s, "0"));
        let mantissa = if mantissa.contains('.') {
            mantissa.trim_end_matches('0').trim_end_matches('.')
        } else {
            mantissa
        };
        format!("{mantissa}e{exp}")
    }
}

#[cfg(test)]
mod tests;
