//! Parameter sweeps run a little at a time (so a page can draw a progress bar and stay
//! responsive): one run per value, the RMS of chosen series after a settling time.

use crate::labs::Lab;
use crate::params::ParamValues;
use crate::sim::Simulation;

/// A sweep a lab offers, e.g. paper 1's adaptation window N over a log grid.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SweepSpec {
    /// Title for the panel.
    pub title: &'static str,
    /// Parameter swept.
    pub key: &'static str,
    /// Values, in order.
    pub values: &'static [f64],
    /// Length of each run (s).
    pub duration_s: f64,
    /// RMS is taken over t > `after_s`.
    pub after_s: f64,
    /// Series whose RMS is reported.
    pub series: &'static [&'static str],
}

/// RMS of each series for one value.
#[derive(Clone, Debug, PartialEq)]
pub struct SweepPoint {
    /// Parameter value.
    pub value: f64,
    /// RMS per series, in the order of [`SweepSpec::series`].
    pub rms: Vec<f64>,
}

/// A sweep in progress.
pub struct Sweep {
    lab: &'static dyn Lab,
    spec: SweepSpec,
    base: ParamValues,
    seed: u64,
    current: Option<(Simulation, Vec<usize>, Vec<f64>, usize)>,
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
            let Some((sim, cols, acc, n)) = self.current.as_mut() else {
                return true;
            };
            while budget > 0 && sim.t_s() < self.spec.duration_s {
                sim.step();
                budget -= 1;
                if sim.t_s() > self.spec.after_s {
                    *n += 1;
                    for (a, c) in acc.iter_mut().zip(cols.iter()) {
                        let v = sim.last_row().get(*c).copied().unwrap_or(f64::NAN);
                        *a += v * v;
                    }
                }
            }
            if sim.t_s() >= self.spec.duration_s {
                let value = sim.params().get(self.spec.key);
                let rms = acc
                    .iter()
                    .map(|a| (a / (*n).max(1) as f64).sqrt())
                    .collect();
                self.points.push(SweepPoint { value, rms });
                self.current = None;
            }
        }
        self.is_done()
    }

    fn start_next(&mut self) -> bool {
        while let Some(&value) = self.spec.values.get(self.points.len() + self.skipped.len()) {
            let mut p = self.base.clone();
            match p.set(self.lab.params(), self.spec.key, value) {
                Ok(()) => {
                    let sim = Simulation::with_history(self.lab, p, self.seed, 2);
                    let cols = self
                        .spec
                        .series
                        .iter()
                        .map(|s| sim.recorder().index_of(s).unwrap_or(usize::MAX))
                        .collect();
                    self.current = Some((sim, cols, vec![0.0; self.spec.series.len()], 0));
                    return true;
                }
                Err(e) => self.skipped.push(format!("{value}: {e}")),
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
            .map_or(0.0, |(sim, ..)| (sim.t_s() / self.spec.duration_s).min(1.0));
        ((self.points.len() + self.skipped.len()) as f64 + per_run)
            / self.spec.values.len().max(1) as f64
    }

    /// The value with the smallest RMS of series `index`, with that RMS.
    pub fn best(&self, index: usize) -> Option<(f64, f64)> {
        self.points
            .iter()
            .filter_map(|p| p.rms.get(index).map(|r| (p.value, *r)))
            .filter(|(_, r)| r.is_finite())
            .min_by(|a, b| a.1.total_cmp(&b.1))
    }
}
