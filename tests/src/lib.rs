//! Shared helpers for the Attitude Lab test suites: angle comparisons, scenario traces, and
//! the golden traces that native and browser runs must agree on.

use attlab::analysis::scenario::{Trace, run_trace};
use attlab::labs;
use attlab::model::ParamValues;
use attlab::page::Lab;
use attlab::sim::{Selection, SimOptions, Simulation};
use std::f64::consts::{PI, TAU};

/// Difference of two angles wrapped to (−π, π].
pub fn angle_diff(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(TAU);
    if d > PI { d - TAU } else { d }
}

/// A lab by id (panics with the registry's ids if there is none: a test's own typo).
pub fn lab(id: &str) -> &'static dyn Lab {
    labs::find(id).unwrap_or_else(|| panic!("no lab `{id}` (labs: {})", labs::ids()))
}

/// Runs lab `id` with `assignments` and keeps every row of `series`; any unknown name fails
/// the test with the reason.
pub fn trace(id: &str, assignments: &[&str], seed: u64, duration_s: f64, series: &[&str]) -> Trace {
    run_trace(lab(id), assignments, seed, duration_s, series)
        .unwrap_or_else(|e| panic!("{id} {assignments:?}: {e}"))
}

/// Steps of each lab's golden trace.
pub const GOLDEN_STEPS: usize = 200;
/// A golden checkpoint every so many steps.
pub const GOLDEN_EVERY: usize = 25;

/// Every series of lab `lab` at every [`GOLDEN_EVERY`]-th step of [`GOLDEN_STEPS`], seed 7:
/// (series names, checkpoint rows).
pub fn golden_trace(lab: &'static dyn Lab) -> (Vec<String>, Vec<Vec<f64>>) {
    let mut p = ParamValues::defaults(lab.params());
    let errors = p.apply_assignments(lab.params(), lab.golden_assignments().iter().copied());
    assert!(errors.is_empty(), "{}: {errors:?}", lab.id());
    let options = SimOptions {
        selection: Selection::All,
        budget_bytes: 1 << 16,
    };
    let mut sim = Simulation::with_options(lab, p, 7, options).expect("every series exists");
    let names = sim.specs().iter().map(|s| s.name.clone()).collect();
    let mut rows = vec![sim.last_row().to_vec()];
    for k in 1..=GOLDEN_STEPS {
        sim.step();
        if k % GOLDEN_EVERY == 0 {
            rows.push(sim.last_row().to_vec());
        }
    }
    (names, rows)
}

// Every lab's `golden.json`, found in its folder by `build.rs`.
include!(concat!(env!("OUT_DIR"), "/golden_files.rs"));

/// One lab's golden trace as committed.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Golden {
    /// Series names.
    pub series: Vec<String>,
    /// Checkpoint rows (None where the value is missing).
    pub rows: Vec<Vec<Option<f64>>>,
}

/// A lab's golden trace file, `golden.json` in its folder (JSON, NaN as null).
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct GoldenFile {
    /// The lab's id.
    pub lab: String,
    /// Its trace.
    #[serde(flatten)]
    pub trace: Golden,
}

/// The committed golden traces by lab id.
pub fn committed_golden() -> std::collections::BTreeMap<String, Golden> {
    GOLDEN_FILES
        .iter()
        .map(|(path, text)| {
            let file: GoldenFile =
                serde_json::from_str(text).unwrap_or_else(|e| panic!("{path} parses: {e}"));
            (file.lab, file.trace)
        })
        .collect()
}

/// A trace in the committed form.
pub fn to_golden(names: Vec<String>, rows: Vec<Vec<f64>>) -> Golden {
    Golden {
        series: names,
        rows: rows
            .into_iter()
            .map(|r| r.into_iter().map(|v| (!v.is_nan()).then_some(v)).collect())
            .collect(),
    }
}

/// Compares a fresh trace with the committed one: same series, missing exactly where missing,
/// and every value within `rel` of the committed one relative to the largest |value| of its
/// series over the trace — for a covariance `src.cov_a_b`, relative to √(var_a·var_b), the
/// scale a correlation is judged on (a cross term that should be zero is rounding noise).
/// Returns the largest relative difference, or the first one over `rel`.
pub fn compare_golden(fresh: &Golden, committed: &Golden, rel: f64) -> Result<f64, String> {
    if fresh.series != committed.series {
        return Err(format!(
            "series differ: now {} series, committed {}",
            fresh.series.len(),
            committed.series.len()
        ));
    }
    if fresh.rows.len() != committed.rows.len() {
        return Err("checkpoint count differs".into());
    }
    let mut worst = 0.0_f64;
    let largest = |s: usize| {
        committed
            .rows
            .iter()
            .filter_map(|r| r[s])
            .fold(0.0_f64, |m, v| m.max(v.abs()))
    };
    let index = |n: &str| committed.series.iter().position(|x| x == n);
    for (s, name) in fresh.series.iter().enumerate() {
        let mut scale = largest(s);
        if let Some((src, pair)) = name.split_once(".cov_")
            && let Some((a, b)) = pair.split_once('_')
            && let (Some(ia), Some(ib)) = (
                index(&format!("{src}.var_{a}")),
                index(&format!("{src}.var_{b}")),
            )
        {
            scale = scale.max((largest(ia) * largest(ib)).sqrt());
        }
        let scale = scale.max(1e-300);
        for (k, (a, b)) in fresh.rows.iter().zip(&committed.rows).enumerate() {
            match (a[s], b[s]) {
                (None, None) => {}
                (Some(x), Some(y)) => {
                    let d = (x - y).abs() / scale;
                    if d.is_nan() || d > rel {
                        return Err(format!(
                            "{name} at checkpoint {k}: {x} vs committed {y} (relative {d:e})"
                        ));
                    }
                    worst = worst.max(d);
                }
                (x, y) => {
                    return Err(format!(
                        "{name} at checkpoint {k}: {x:?} vs committed {y:?}"
                    ));
                }
            }
        }
    }
    Ok(worst)
}

/// `a.max(b)` that keeps a NaN instead of dropping it (as `f64::max` does), so a worst case
/// taken over values that include a NaN fails the comparison it feeds.
///
/// ```
/// # use attlab_tests::max_keep_nan;
/// assert!(max_keep_nan(1.0, f64::NAN).is_nan());
/// assert_eq!(max_keep_nan(1.0, 2.0), 2.0);
/// ```
pub fn max_keep_nan(a: f64, b: f64) -> f64 {
    if a.is_nan() || b.is_nan() {
        f64::NAN
    } else {
        a.max(b)
    }
}

/// `a.min(b)` that keeps a NaN.
pub fn min_keep_nan(a: f64, b: f64) -> f64 {
    if a.is_nan() || b.is_nan() {
        f64::NAN
    } else {
        a.min(b)
    }
}
