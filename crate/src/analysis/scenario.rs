//! Scenarios for reproductions and tests: run a lab with some parameters and keep the
//! full-rate values of the series asked for. Every name is checked: an unknown parameter or
//! series is an error, never an empty list or a NaN.

use super::AnalysisError;
use crate::model::{ParamValues, SeriesRef};
use crate::page::Lab;
use crate::sim::{SimOptions, Simulation};

/// The lab's defaults with `assignments` (`key=value`) applied; any bad assignment is an
/// error.
pub fn params_with(lab: &dyn Lab, assignments: &[&str]) -> Result<ParamValues, AnalysisError> {
    let mut p = ParamValues::defaults(lab.params());
    match p
        .apply_assignments(lab.params(), assignments.iter().copied())
        .into_iter()
        .next()
    {
        Some(e) => Err(AnalysisError::Param(e)),
        None => Ok(p),
    }
}

/// Full-rate values of some series over one run (series 0 is `t_s`).
#[derive(Clone, Debug, PartialEq)]
pub struct Trace {
    lab: &'static str,
    names: Vec<String>,
    columns: Vec<Vec<f64>>,
}

impl Trace {
    /// Every value of series `name`, from t = 0.
    pub fn series(&self, name: impl SeriesRef) -> Result<&[f64], AnalysisError> {
        let name = name.series_name();
        self.names
            .iter()
            .position(|n| *n == *name)
            .map(|i| self.columns[i].as_slice())
            .ok_or_else(|| {
                AnalysisError::UnknownSeries(format!(
                    "`{name}` was not recorded in this {} trace (recorded: {})",
                    self.lab,
                    self.names.join(", ")
                ))
            })
    }

    /// The times (s).
    pub fn t_s(&self) -> &[f64] {
        &self.columns[0]
    }

    /// Values of `name` for t > `after_s`.
    pub fn after(&self, name: impl SeriesRef, after_s: f64) -> Result<Vec<f64>, AnalysisError> {
        let y = self.series(name)?;
        Ok(self
            .t_s()
            .iter()
            .zip(y)
            .filter(|(t, _)| **t > after_s)
            .map(|(_, y)| *y)
            .collect())
    }

    /// The last value of `name`.
    pub fn last(&self, name: impl SeriesRef) -> Result<f64, AnalysisError> {
        let name = name.series_name();
        self.series(name.as_ref())?
            .last()
            .copied()
            .ok_or_else(|| AnalysisError::UnknownSeries(format!("`{name}` has no values")))
    }

    /// Number of rows.
    pub fn len(&self) -> usize {
        self.columns[0].len()
    }

    /// No rows.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// Runs `lab` with `params` and `seed` for `duration_s`, keeping every row of `series`.
pub fn run_trace_with(
    lab: &'static dyn Lab,
    params: ParamValues,
    seed: u64,
    duration_s: f64,
    series: &[impl SeriesRef],
) -> Result<Trace, AnalysisError> {
    let wanted: Vec<_> = series.iter().map(SeriesRef::series_name).collect();
    let wanted: Vec<&str> = wanted.iter().map(AsRef::as_ref).collect();
    let mut sim = Simulation::with_options(lab, params, seed, SimOptions::named(&wanted))
        .map_err(|e| AnalysisError::UnknownSeries(e.to_string()))?;
    let names: Vec<String> = sim.specs().iter().map(|s| s.name.clone()).collect();
    let rows = (duration_s / sim.dt_s()).ceil() as usize + 2;
    let mut columns: Vec<Vec<f64>> = names.iter().map(|_| Vec::with_capacity(rows)).collect();
    let mut push = |row: &[f64]| {
        for (c, v) in columns.iter_mut().zip(row) {
            c.push(*v);
        }
    };
    push(sim.last_row());
    let end = duration_s - 1e-9 * sim.dt_s();
    while sim.t_s() < end {
        sim.step();
        push(sim.last_row());
    }
    Ok(Trace {
        lab: lab.id(),
        names,
        columns,
    })
}

/// Runs `lab` from its defaults plus `assignments` for `duration_s`, keeping every row of
/// `series`.
pub fn run_trace(
    lab: &'static dyn Lab,
    assignments: &[&str],
    seed: u64,
    duration_s: f64,
    series: &[impl SeriesRef],
) -> Result<Trace, AnalysisError> {
    run_trace_with(
        lab,
        params_with(lab, assignments)?,
        seed,
        duration_s,
        series,
    )
}
