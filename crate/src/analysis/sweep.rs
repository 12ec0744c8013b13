//! Parameter sweeps run a little at a time (so a page can draw a progress bar and stay
//! responsive): one run per value, the RMS and the largest |value| of chosen series after a
//! settling time.

use crate::model::{Lab, ParamValues, SweepSpec};
use crate::sim::{SimOptions, Simulation};

/// Statistics of each series for one value.
#[derive(Clone, Debug, PartialEq)]
pub struct SweepPoint {
    /// Parameter value.
    pub value: f64,
    /// RMS per series, in the order of [`SweepSpec::series`]; NaN when a sample was missing.
    pub rms: Vec<f64>,
    /// Largest |value| per series; NaN when a sample was missing.
    pub max_abs: Vec<f64>,
    /// Samples that were NaN, per series (a diverged filter, a missing value).
    pub missing: Vec<usize>,
}

struct Running {
    sim: Simulation,
    cols: Vec<usize>,
    sum_sq: Vec<f64>,
    max_abs: Vec<f64>,
    missing: Vec<usize>,
    n: usize,
}

/// A sweep in progress.
pub struct Sweep {
    lab: &'static dyn Lab,
    spec: SweepSpec,
    base: ParamValues,
    seed: u64,
    current: Option<Running>,
    /// Finished points.
    pub points: Vec<SweepPoint>,
    /// Values that could not be run, with the reason.
    pub skipped: Vec<String>,
}

impl Sweep {
    /// A sweep of `spec` over `lab` from the parameters `base`.
    pub fn new(lab: &'static dyn Lab, spec: SweepSpec, base: ParamValues, seed: u64) -> Self {
        Self {
            lab,
            spec,
            base,
            seed,
            current: None,
            points: Vec::new(),
            skipped: Vec::new(),
        }
    }

    /// The sweep's specification.
    pub fn spec(&self) -> &SweepSpec {
        &self.spec
    }

    /// Runs at most `max_steps` simulation steps; returns true when the sweep is complete.
    pub fn advance(&mut self, max_steps: usize) -> bool {
        let mut budget = max_steps;
        while budget > 0 {
            if self.current.is_none() && !self.start_next() {
                return true;
            }
            let Some(r) = self.current.as_mut() else {
                return true;
            };
            while budget > 0 && r.sim.t_s() < self.spec.duration_s {
                r.sim.step();
                budget -= 1;
                if r.sim.t_s() > self.spec.after_s {
                    r.n += 1;
                    let row = r.sim.last_row();
                    for (k, c) in r.cols.iter().enumerate() {
                        let v = row[*c];
                        if v.is_nan() {
                            r.missing[k] += 1;
                        } else {
                            r.sum_sq[k] += v * v;
                            r.max_abs[k] = r.max_abs[k].max(v.abs());
                        }
                    }
                }
            }
            if r.sim.t_s() >= self.spec.duration_s {
                let n = r.n.max(1) as f64;
                let value = r.sim.params().get(self.spec.key);
                let point = SweepPoint {
                    value,
                    rms: r
                        .sum_sq
                        .iter()
                        .zip(&r.missing)
                        .map(|(s, m)| if *m > 0 { f64::NAN } else { (s / n).sqrt() })
                        .collect(),
                    max_abs: r
                        .max_abs
                        .iter()
                        .zip(&r.missing)
                        .map(|(x, m)| if *m > 0 { f64::NAN } else { *x })
                        .collect(),
                    missing: r.missing.clone(),
                };
                self.points.push(point);
                self.current = None;
            }
        }
        self.is_done()
    }

    fn start_next(&mut self) -> bool {
        while let Some(&value) = self.spec.values.get(self.points.len() + self.skipped.len()) {
            let mut p = self.base.clone();
            let started = p
                .set(self.lab.params(), self.spec.key, value)
                .map_err(|e| e.to_string())
                .and_then(|()| {
                    Simulation::with_options(
                        self.lab,
                        p,
                        self.seed,
                        SimOptions::named(self.spec.series),
                    )
                    .map_err(|e| e.to_string())
                });
            match started {
                Ok(sim) => {
                    let cols = self
                        .spec
                        .series
                        .iter()
                        .filter_map(|s| sim.series_index(s).ok())
                        .collect();
                    let k = self.spec.series.len();
                    self.current = Some(Running {
                        sim,
                        cols,
                        sum_sq: vec![0.0; k],
                        max_abs: vec![0.0; k],
                        missing: vec![0; k],
                        n: 0,
                    });
                    return true;
                }
                Err(e) => self
                    .skipped
                    .push(format!("{} = {value}: {e}", self.spec.key)),
            }
        }
        false
    }

    /// All values done.
    pub fn is_done(&self) -> bool {
        self.current.is_none() && self.points.len() + self.skipped.len() >= self.spec.values.len()
    }

    /// Fraction done, 0…1.
    pub fn progress(&self) -> f64 {
        let per_run = self
            .current
            .as_ref()
            .map_or(0.0, |r| (r.sim.t_s() / self.spec.duration_s).min(1.0));
        ((self.points.len() + self.skipped.len()) as f64 + per_run)
            / self.spec.values.len().max(1) as f64
    }

    /// The value with the smallest RMS of series `index`, with that RMS; values whose run
    /// had missing samples (a diverged filter) are not candidates.
    pub fn best(&self, index: usize) -> Option<(f64, f64)> {
        self.points
            .iter()
            .filter_map(|p| p.rms.get(index).map(|r| (p.value, *r)))
            .filter(|(_, r)| r.is_finite())
            .min_by(|a, b| a.1.total_cmp(&b.1))
    }
}
