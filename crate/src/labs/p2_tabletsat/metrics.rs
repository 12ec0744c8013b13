//! The paper's own metric beside the measured one (issue 19, in part): Table 3 reports
//! σ = √max diag P∞, so its hierarchy findings are checked in that metric too, and its "only
//! slightly worse" for the bias-estimating filters becomes a check in both metrics. A
//! difference is declared with what was measured about its cause: the same rows with the
//! gyro read at 10 Hz instead of 1 Hz (the paper gives no rate), and for the bias ratios
//! over the last minute of 1800 s, once the Mag+Sun+Gyro filters have converged.
// Only the CLI and the tests reproduce a paper (the `study` feature).
#![cfg_attr(not(feature = "study"), allow(dead_code, unused_imports))]

use super::accuracy::{FilterAccuracy, Runs, acc_of, run_all};
use super::paper_tables::{CONVERGED, converged};
use crate::analysis::stats;
use crate::analysis::{AnalysisError, StatsContext};
use crate::model::{Calibration, Expectation, Row};

/// How a metric is read from a filter's accuracy (deg).
type Metric = fn(&FilterAccuracy) -> f64;

/// The two metrics: name and how to read it.
const METRICS: [(&str, Metric); 2] = [
    ("measured σ", |a| a.att_rms_deg),
    ("√max P∞", |a| a.att_p_deg),
];

/// A filter with a bias state, the same filter without it, and their names.
const BIAS_PAIRS: [(&str, &str, &str); 3] = [
    ("st-gyro-gbias", "st-gyro", "ST+Gyro+Δω over ST+Gyro"),
    (
        "mag-sun-gyro-gbias",
        "mag-sun-gyro",
        "Mag+Sun+Gyro+Δω over Mag+Sun+Gyro",
    ),
    (
        "mag-sun-gyro-mbias",
        "mag-sun-gyro",
        "Mag+Sun+Gyro+Δb over Mag+Sun+Gyro",
    ),
];

/// "Only slightly worse" read as at most this ratio (ours: the paper gives no number).
const SLIGHTLY: f64 = 1.5;

/// The star-tracker sets of Table 3.
const ST_SETS: [&str; 7] = [
    "st-gyro-mag-sun",
    "st-gyro-mag",
    "st-mag-sun",
    "st-mag-mbias",
    "st-gyro",
    "st-gyro-gbias",
    "st",
];

/// The hierarchy in √max P∞, and the bias ratios in both metrics: at 200 s with the gyro at
/// 1 Hz, and converged (1800 s, the gyro at 10 Hz).
pub(super) fn rows(all: &Runs) -> Result<Vec<Row>, AnalysisError> {
    let converged = [converged(1.0)?, converged(0.5)?, converged(1.5)?];
    let mut rows = hierarchy_rows(all)?;
    for (name, metric) in METRICS {
        for (k, (bias, plain, label)) in BIAS_PAIRS.iter().enumerate() {
            let ratio = |runs: &Runs| -> Result<f64, AnalysisError> {
                Ok(metric(acc_of(runs, bias)?) / metric(acc_of(runs, plain)?))
            };
            let check = |quantity: String, value: f64| {
                Row::check(
                    quantity,
                    format!("\"only slightly worse\" (§3.1); read as ≤ {SLIGHTLY}× (ours)"),
                    value,
                    "×",
                    Expectation::Interval {
                        lo: 0.0,
                        hi: SLIGHTLY,
                    },
                )
            };
            let at_200 = check(
                format!("{label}, {name} (bias states only slightly worse)"),
                ratio(all)?,
            );
            let quantity = format!("{label}, {name}, gyro at 10 Hz, last 60 s of an 1800-s run");
            if k == 0 {
                rows.push(at_200);
                rows.push(Row::measurement(quantity, "—", ratio(&converged[0])?, "×"));
                continue;
            }
            rows.push(at_200.known_to_differ(
                "by 200 s, with the gyro read at 1 Hz, Mag+Sun+Gyro and its bias variant have not converged: only the slow turn of the field and the sun in the body frame separates a bias from the attitude; the next rows run 1800 s with the gyro at 10 Hz",
            ));
            let converged_check = check(quantity, ratio(&converged[0])?);
            rows.extend(CONVERGED.rows(converged_check, |f| {
                ratio(&converged[if f < 1.0 { 1 } else { 2 }])
            })?);
        }
    }
    Ok(rows)
}

/// Table 3's hierarchy in its own metric, √max P∞.
fn hierarchy_rows(all: &Runs) -> Result<Vec<Row>, AnalysisError> {
    let p = |runs: &Runs, id: &str| acc_of(runs, id).map(|a| a.att_p_deg);
    let st: Vec<f64> = ST_SETS
        .iter()
        .map(|id| p(all, id))
        .collect::<Result<_, _>>()?;
    let worst_st = stats::max(&st).of("star-tracker sets")?;
    let (msg, ms, mg) = (
        p(all, "mag-sun-gyro")?,
        p(all, "mag-sun")?,
        p(all, "mag-gyro")?,
    );
    let mut rows = vec![Row::check(
        "finding in √max P∞: worst star-tracker set below Mag+Sun+Gyro",
        "ST sets ≈ 5e-4–8e-4° ≪ Mag+Sun+Gyro ≈ 0.02° (Table 3)",
        worst_st,
        "deg",
        Expectation::below(msg),
    )];
    rows.push(
        Row::check(
            "finding in √max P∞: Mag+Sun+Gyro below Mag+Sun",
            "0.02° < 0.12° (Table 3)",
            msg,
            "deg",
            Expectation::below(ms),
        )
        .known_to_differ(
            "the gyro here is read at 1 Hz; read at 10 Hz (next row) Mag+Sun+Gyro's P∞ falls below Mag+Sun's",
        ),
    );
    let at_rate = |hz: f64| -> Result<f64, AnalysisError> {
        let set = format!("gyro_rate_hz={hz}");
        p(&run_all(&[&set], 1)?, "mag-sun-gyro")
    };
    let fast = Row::check(
        "finding in √max P∞: Mag+Sun+Gyro below Mag+Sun, gyro read at 10 Hz",
        "0.02° < 0.12° (Table 3)",
        at_rate(10.0)?,
        "deg",
        Expectation::below(ms),
    );
    let gyro_rate = Calibration::new("gyro rate", 10.0, "Hz");
    rows.extend(gyro_rate.rows(fast, |f| at_rate(10.0 * f))?);
    rows.push(Row::check(
        "finding in √max P∞: Mag+Sun+Gyro below Mag+Gyro",
        "0.02° < 0.2° (Table 3)",
        msg,
        "deg",
        Expectation::below(mg),
    ));
    Ok(rows)
}
