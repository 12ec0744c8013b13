//! Helpers the labs' reproductions share: run a scenario, read its series, build rows.

use super::{AnchorRow, Lab};
use crate::params::ParamValues;
use crate::sim::Simulation;

/// Runs `lab` from its defaults plus `assignments` (`key=value`, the lab's own keys, so a
/// typo is a programming error caught in debug builds) for `duration_s`, keeping every row.
pub fn run_scenario(
    lab: &'static dyn Lab,
    assignments: &[&str],
    seed: u64,
    duration_s: f64,
) -> Simulation {
    let mut p = ParamValues::defaults(lab.params());
    let errors = p.apply_assignments(lab.params(), assignments.iter().copied());
    debug_assert!(errors.is_empty(), "{errors:?}");
    let rows = (duration_s / lab.dt_s(&p)).ceil() as usize + 2;
    let mut sim = Simulation::with_history(lab, p, seed, rows);
    sim.run_for(duration_s);
    sim
}

/// Values of series `name` for t > `after_s` (all held rows for a negative `after_s`).
pub fn series_after(sim: &Simulation, name: &str, after_s: f64) -> Vec<f64> {
    let r = sim.recorder();
    let (Some(t), Some(y)) = (
        r.index_of("t_s").and_then(|i| r.column(i)),
        r.index_of(name).and_then(|i| r.column(i)),
    ) else {
        return Vec::new();
    };
    t.iter()
        .zip(y)
        .filter(|(t, _)| **t > after_s)
        .map(|(_, y)| *y)
        .collect()
}

/// The latest value of series `name` (NaN if there is none).
pub fn last_value(sim: &Simulation, name: &str) -> f64 {
    sim.recorder()
        .index_of(name)
        .and_then(|i| sim.recorder().last(i))
        .unwrap_or(f64::NAN)
}

/// Root mean square.
pub fn rms(v: &[f64]) -> f64 {
    (v.iter().map(|x| x * x).sum::<f64>() / v.len().max(1) as f64).sqrt()
}

/// Largest absolute value.
pub fn max_abs(v: &[f64]) -> f64 {
    v.iter().fold(0.0_f64, |m, x| m.max(x.abs()))
}

impl AnchorRow {
    /// A row of a reproduction table.
    pub fn new(
        quantity: impl Into<String>,
        expected: impl Into<String>,
        measured: f64,
        unit: &'static str,
        pass: bool,
    ) -> Self {
        Self {
            quantity: quantity.into(),
            expected: expected.into(),
            measured,
            unit,
            pass,
        }
    }
}
