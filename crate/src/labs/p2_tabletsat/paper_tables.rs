//! Tables 3, 4 and 5 row by row (issue 19): every accuracy the OCR kept — attitude, rate
//! and bias — is a check in both of the paper's metrics, the measured σ and √max P∞, within
//! 3× of the paper's value. The sensor rates behind every one of them are this project's
//! (1 Hz; the paper gives none), so each match is "after calibration", with the same
//! quantity at all sensor rates × 0.5 and × 1.5 beside it. Where a value is not met, the row
//! declares why, and the rows after it test that cause.
// Only the CLI and the tests reproduce a paper (the `study` feature).
#![cfg_attr(not(feature = "study"), allow(dead_code, unused_imports))]

use super::PARAMS;
use super::accuracy::{FilterAccuracy, Runs, acc_of, bias_unit, run_all, run_all_for};
use super::sets::FilterRow;
use crate::analysis::AnalysisError;
use crate::estimators::StateSet;
use crate::model::{Calibration, Expectation, ParamValues, Row, fmt_sig};

/// What a value of the tables is the accuracy of.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Of {
    Att,
    Rate,
    Bias,
}

/// The paper's two metrics.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Metric {
    /// The RMS of the error over the last 60 s (measured against the truth).
    Sigma,
    /// √max diag P at the end of the run (the filter's own claim; the paper's tables).
    PInf,
}

/// Why a value of the tables is not met here. Each cause comes with rows that test it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Cause {
    /// The Mag+Sun+Gyro filters have not converged by 200 s with the gyro read at 1 Hz.
    Converging,
    /// The disturbance filter runs beside this EKF (the id: the same EKF without it) and
    /// leaves its P unchanged.
    ParallelFilter(&'static str),
    /// The onboard field here is exact, so Δb absorbs no field-model error.
    FieldModel,
    /// The rate estimate follows the gyro: its error is the gyro's σ.
    GyroBound,
}

/// The values of the tables known not to be met here, and why.
const DIFFERS: &[(&str, Of, Metric, Cause)] = &[
    ("st-mag-mbias", Of::Bias, Metric::Sigma, Cause::FieldModel),
    ("st-mag-mbias", Of::Bias, Metric::PInf, Cause::FieldModel),
    ("mag-sun-gyro", Of::Att, Metric::Sigma, Cause::Converging),
    ("mag-sun-gyro", Of::Att, Metric::PInf, Cause::Converging),
    (
        "mag-sun-gyro-gbias",
        Of::Att,
        Metric::Sigma,
        Cause::Converging,
    ),
    (
        "mag-sun-gyro-gbias",
        Of::Att,
        Metric::PInf,
        Cause::Converging,
    ),
    (
        "mag-sun-dist",
        Of::Att,
        Metric::PInf,
        Cause::ParallelFilter("mag-sun"),
    ),
    (
        "st-dist",
        Of::Rate,
        Metric::PInf,
        Cause::ParallelFilter("st"),
    ),
    (
        "mag-sun-gyro-const",
        Of::Att,
        Metric::Sigma,
        Cause::Converging,
    ),
    (
        "mag-sun-gyro-const",
        Of::Att,
        Metric::PInf,
        Cause::Converging,
    ),
    (
        "mag-sun-gyro-const",
        Of::Rate,
        Metric::Sigma,
        Cause::GyroBound,
    ),
    (
        "mag-sun-gyro-const",
        Of::Rate,
        Metric::PInf,
        Cause::GyroBound,
    ),
    (
        "mag-sun-gyro-mbias-const",
        Of::Att,
        Metric::Sigma,
        Cause::Converging,
    ),
    (
        "mag-sun-gyro-mbias-const",
        Of::Att,
        Metric::PInf,
        Cause::Converging,
    ),
    (
        "mag-sun-gyro-gbias-dist",
        Of::Att,
        Metric::Sigma,
        Cause::Converging,
    ),
    (
        "mag-sun-gyro-gbias-dist",
        Of::Att,
        Metric::PInf,
        Cause::Converging,
    ),
    (
        "mag-sun-gyro-gbias-dist",
        Of::Bias,
        Metric::PInf,
        Cause::Converging,
    ),
    (
        "st-dist-const",
        Of::Rate,
        Metric::PInf,
        Cause::ParallelFilter("st-const"),
    ),
    (
        "mag-sun-dist-const",
        Of::Att,
        Metric::PInf,
        Cause::ParallelFilter("mag-sun-const"),
    ),
    (
        "mag-sun-gyro-gbias-dist-const",
        Of::Att,
        Metric::Sigma,
        Cause::Converging,
    ),
    (
        "mag-sun-gyro-gbias-dist-const",
        Of::Att,
        Metric::PInf,
        Cause::Converging,
    ),
    (
        "mag-sun-gyro-gbias-dist-const",
        Of::Bias,
        Metric::PInf,
        Cause::Converging,
    ),
];

/// "Within 3×" of the paper's value, as everywhere in this project's reproductions.
const FACTOR: f64 = 3.0;
/// The converged scenario: its run length (s), how long before its end constant gains
/// freeze (s), and its gyro rate (Hz).
const CONVERGED_RUN_S: f64 = 1800.0;
const CONVERGED_FROZEN_S: f64 = 200.0;
const CONVERGED_GYRO_HZ: f64 = 10.0;
/// The onboard field's error in the field-model row (nT): the paper's "up to 400 nT".
const MODEL_ERROR_NT: f64 = 400.0;

impl Of {
    fn name(self) -> &'static str {
        match self {
            Self::Att => "attitude",
            Self::Rate => "rate",
            Self::Bias => "bias",
        }
    }

    /// The table's value for filter `f`, where the OCR kept it.
    fn paper(self, f: &FilterRow) -> Option<f64> {
        match self {
            Self::Att => f.paper_att_deg,
            Self::Rate => f.paper_rate_deg_s,
            Self::Bias => f.paper_bias,
        }
    }

    /// The unit, or `None` when filter `f` does not estimate this.
    fn unit(self, f: &FilterRow) -> Option<&'static str> {
        match self {
            Self::Att => Some("deg"),
            Self::Rate => (f.config.states != StateSet::AttGyroBias).then_some("deg/s"),
            Self::Bias => Some(bias_unit(f.config.states)).filter(|u| !u.is_empty()),
        }
    }

    fn value(self, a: &FilterAccuracy, metric: Metric) -> f64 {
        match (self, metric) {
            (Self::Att, Metric::Sigma) => a.att_rms_deg,
            (Self::Att, Metric::PInf) => a.att_p_deg,
            (Self::Rate, Metric::Sigma) => a.rate_rms_deg_s,
            (Self::Rate, Metric::PInf) => a.rate_p_deg_s,
            (Self::Bias, Metric::Sigma) => a.bias_rms,
            (Self::Bias, Metric::PInf) => a.bias_p,
        }
    }
}

impl Metric {
    fn name(self) -> &'static str {
        match self {
            Self::Sigma => "σ measured (last 60 s)",
            Self::PInf => "√max P∞ (the paper's metric)",
        }
    }
}

/// Which table a filter's values are from.
fn table_of(f: &FilterRow) -> String {
    f.table()
        .map_or_else(|| "—".into(), |n| format!("Table {n}"))
}

/// The converged scenario with its run length at `factor` of 1800 s: the gyro at 10 Hz,
/// σ over the last 60 s, constant gains frozen 200 s before the end.
pub(super) fn converged(
    factor: f64,
) -> Result<Vec<(&'static FilterRow, FilterAccuracy)>, AnalysisError> {
    let run_s = CONVERGED_RUN_S * factor;
    let gyro = format!("gyro_rate_hz={CONVERGED_GYRO_HZ}");
    let freeze = format!("freeze_after_s={}", run_s - CONVERGED_FROZEN_S);
    run_all_for(&[&gyro, &freeze], 1, run_s)
}

/// The run length of the converged scenario, as the setting its rows are calibrated by.
pub(super) const CONVERGED: Calibration<'static> = Calibration {
    name: "run length",
    value: CONVERGED_RUN_S,
    unit: "s",
    how: "with the gyro at 10 Hz and constant gains frozen 200 s before the end",
};

/// Every scenario the rows are measured in: the default; every sensor's rate × 0.5 and
/// × 1.5; the converged scenario at the gyro rate × 1, × 0.5 and × 1.5; and the onboard
/// field off by 400 nT.
struct Scenarios<'a> {
    default: &'a Runs,
    rates: [Vec<(&'static FilterRow, FilterAccuracy)>; 2],
    converged: [Vec<(&'static FilterRow, FilterAccuracy)>; 3],
    field_error: Vec<(&'static FilterRow, FilterAccuracy)>,
}

impl<'a> Scenarios<'a> {
    fn run(default: &'a Runs) -> Result<Self, AnalysisError> {
        let d = ParamValues::defaults(PARAMS);
        let rates = |f: f64| -> Result<_, AnalysisError> {
            let set: Vec<String> = ["vector_rate_hz", "star_rate_hz", "gyro_rate_hz"]
                .iter()
                .map(|k| format!("{k}={}", d.get(k) * f))
                .collect();
            run_all(&set.iter().map(String::as_str).collect::<Vec<_>>(), 1)
        };
        let field = format!("model_error_nt={MODEL_ERROR_NT}");
        Ok(Self {
            default,
            rates: [rates(0.5)?, rates(1.5)?],
            converged: [converged(1.0)?, converged(0.5)?, converged(1.5)?],
            field_error: run_all(&["onboard_field=2", &field], 1)?,
        })
    }
}

/// One value of the tables: its filter, what it is the accuracy of, and in which metric.
#[derive(Clone, Copy)]
struct Value {
    f: &'static FilterRow,
    of: Of,
    metric: Metric,
    unit: &'static str,
}

impl Value {
    fn quantity(&self) -> String {
        format!(
            "{}: {} {}",
            self.f.config.label,
            self.of.name(),
            self.metric.name()
        )
    }

    fn in_runs(&self, runs: &Runs) -> Result<f64, AnalysisError> {
        Ok(self.of.value(acc_of(runs, self.f.config.id)?, self.metric))
    }
}

/// Every filter's rows: each accuracy in both metrics (a check where the tables give a
/// value), the attitude NEES.
pub(super) fn rows(all: &Runs) -> Result<Vec<Row>, AnalysisError> {
    let s = Scenarios::run(all)?;
    let mut rows = Vec::new();
    for (f, a) in all {
        for of in [Of::Att, Of::Rate, Of::Bias] {
            let Some(unit) = of.unit(f) else { continue };
            for metric in [Metric::Sigma, Metric::PInf] {
                let v = Value {
                    f,
                    of,
                    metric,
                    unit,
                };
                rows.extend(value_rows(&v, a, &s)?);
            }
        }
        let q = f.q_from.label();
        rows.push(Row::measurement(
            format!(
                "{}: mean attitude NEES (χ²₃: 3 if consistent; {q})",
                f.config.label
            ),
            "— (the paper tuned Q by hand)",
            a.nees_mean,
            "",
        ));
    }
    Ok(rows)
}

/// One value's rows: a measurement where the tables give none; else the check, as a
/// calibrated match with its ±50 % rows or as a declared difference with its cause's rows.
fn value_rows(v: &Value, a: &FilterAccuracy, s: &Scenarios<'_>) -> Result<Vec<Row>, AnalysisError> {
    let measured = v.of.value(a, v.metric);
    let Some(paper) = v.of.paper(v.f) else {
        return Ok(vec![Row::measurement(v.quantity(), "—", measured, v.unit)]);
    };
    let paper_text = format!("{}: {} {}", table_of(v.f), fmt_sig(paper), v.unit);
    let check = Row::check(
        v.quantity(),
        paper_text.clone(),
        measured,
        v.unit,
        Expectation::within_factor_of(paper, FACTOR),
    );
    let declared = DIFFERS
        .iter()
        .find(|(id, of, m, _)| *id == v.f.config.id && *of == v.of && *m == v.metric);
    match declared {
        None => {
            let rates = Calibration {
                how: "the magnetometer's, sun sensor's, star tracker's and gyro's together",
                ..Calibration::new("every sensor's rate", 1.0, "Hz")
            };
            rates.rows(check, |f| v.in_runs(&s.rates[usize::from(f > 1.0)]))
        }
        Some((_, _, _, cause)) => cause_rows(v, *cause, check, &paper_text, paper, s),
    }
}

/// A declared difference and the rows that test its cause.
fn cause_rows(
    v: &Value,
    cause: Cause,
    check: Row,
    paper_text: &str,
    paper: f64,
    s: &Scenarios<'_>,
) -> Result<Vec<Row>, AnalysisError> {
    let within = Expectation::within_factor_of(paper, FACTOR);
    Ok(match cause {
        Cause::Converging => {
            let mut rows = vec![check.known_to_differ(
                "by 200 s, with the gyro read at 1 Hz, Mag+Sun+Gyro has not converged: only the slow turn of the field and the sun in the body frame separates its states (the paper gives neither its gyro rate nor its run length); the next rows run 1800 s with the gyro at 10 Hz",
            )];
            let converged = Row::check(
                format!(
                    "{}, gyro at 10 Hz, last 60 s of an 1800-s run",
                    v.quantity()
                ),
                paper_text,
                v.in_runs(&s.converged[0])?,
                v.unit,
                within,
            );
            rows.extend(CONVERGED.rows(converged, |f| {
                v.in_runs(&s.converged[if f < 1.0 { 1 } else { 2 }])
            })?);
            rows
        }
        Cause::ParallelFilter(base) => {
            let base_value = Value {
                f: super::sets::filter(base)
                    .ok_or_else(|| AnalysisError::UnknownSeries(format!("no filter `{base}`")))?,
                ..*v
            };
            vec![
                check.known_to_differ(format!(
                    "the disturbance filter runs beside the EKF and leaves its P as it was, so √max P∞ is that of {base} alone (next row); what the disturbance filter improves is the measured σ"
                )),
                Row::check(
                    format!("{}, over {base}'s", v.quantity()),
                    "— (the EKF's P does not see the disturbance filter)",
                    v.in_runs(s.default)? / base_value.in_runs(s.default)?,
                    "×",
                    Expectation::within_factor_of(1.0, 1.01),
                ),
            ]
        }
        Cause::FieldModel => field_model_rows(v, check, paper_text, paper, s)?,
        Cause::GyroBound => {
            let gyro_sigma = ParamValues::defaults(PARAMS).get("gyro_noise_deg_s");
            vec![
                check.known_to_differ(format!(
                    "the rate estimate here follows the gyro, so its error is the gyro's σ (next row); the paper's {} °/s is {}× Table 1's gyro σ of {gyro_sigma} °/s, which a gain that passes the gyro reading cannot give; where the paper's comes from is not established",
                    fmt_sig(paper),
                    fmt_sig(paper / gyro_sigma)
                )),
                Row::check(
                    format!("{}, over the gyro's σ", v.quantity()),
                    "—",
                    v.in_runs(s.default)? / gyro_sigma,
                    "×",
                    Expectation::within_factor_of(1.0, 1.25),
                ),
            ]
        }
    })
}

/// Table 3's 80 nT for ST+Mag's Δb: here the onboard field is exact.
fn field_model_rows(
    v: &Value,
    check: Row,
    paper_text: &str,
    paper: f64,
    s: &Scenarios<'_>,
) -> Result<Vec<Row>, AnalysisError> {
    let with_error = v.in_runs(&s.field_error)?;
    Ok(match v.metric {
        Metric::Sigma => vec![
            check.known_to_differ(
                "the onboard field here is exact, so Δb carries only the magnetometer's noise; with the paper's field-model error of up to 400 nT (next row) the error is above the paper's value, which lies between the two",
            ),
            Row::check(
                format!("{}, onboard field off by {MODEL_ERROR_NT} nT", v.quantity()),
                format!("{paper_text} (between this and the row above)"),
                with_error,
                v.unit,
                Expectation::above(paper),
            ),
        ],
        Metric::PInf => vec![
            check.known_to_differ(
                "the filter's P knows the magnetometer's noise but not a field-model error, so it is the same with the onboard field off by 400 nT (next row); what makes the paper's P larger is not established",
            ),
            Row::check(
                format!(
                    "{}, onboard field off by {MODEL_ERROR_NT} nT, over exact",
                    v.quantity()
                ),
                "— (P does not see the model error)",
                with_error / v.in_runs(s.default)?,
                "×",
                Expectation::within_factor_of(1.0, 1.01),
            ),
        ],
    })
}
