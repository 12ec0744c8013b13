//! Parameter sweeps run a little at a time (so a page can draw a progress bar and stay
//! responsive): one run per value (or per cell of a two-parameter grid) and seed, the RMS and
//! the largest |value| of chosen series after a settling time, and the lab's own scores of
//! each run (medians over the seeds) with the weighted sums it minimises. A sweep can also
//! run on a recorded log instead of the simulation (one run per value, no truth).

use super::stats;
use crate::model::{
    ParamValues, ScoreError, SeriesKey, SeriesSpec, SweepScoring, SweepSpec, Unscored,
};
use crate::page::Lab;
use crate::sensors::RateLog;
use crate::sim::{SimOptions, Simulation};

#[cfg(not(target_arch = "wasm32"))]
mod parallel;
mod points;
mod skip;

pub use points::{PointDone, PointJob, run_point_job};
pub use skip::{Skipped, SweepError};

/// Statistics of each series for one value (one cell of a grid).
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct SweepPoint {
    /// Parameter value.
    pub value: f64,
    /// Value of the grid's second parameter, for a grid sweep.
    pub grid_value: Option<f64>,
    /// RMS per series over every seed's samples, in the order of [`SweepSpec::series`];
    /// NaN when a sample was missing.
    #[serde(with = "points::f64_bits")]
    pub rms: Vec<f64>,
    /// Largest |value| per series; NaN when a sample was missing.
    #[serde(with = "points::f64_bits")]
    pub max_abs: Vec<f64>,
    /// Samples that were NaN, per series (a diverged filter, a missing value).
    pub missing: Vec<usize>,
    /// The lab's scores, medians over the seeds that could be scored (NaN when none could).
    #[serde(with = "points::f64_bits")]
    pub scores: Vec<f64>,
    /// Smallest and largest of each score over those seeds.
    #[serde(with = "points::pair_bits")]
    pub score_range: Vec<[f64; 2]>,
    /// The scoring's weighted sums of the median scores.
    #[serde(with = "points::f64_bits")]
    pub objectives: Vec<f64>,
    /// Seeds run for this point.
    pub runs: u64,
    /// Why runs could not be scored.
    pub unscored: Vec<Unscored>,
}

struct Running {
    sim: Simulation,
    cols: Vec<usize>,
    score_cols: Vec<Option<usize>>,
    t_s: Vec<f64>,
    recorded: Vec<Vec<f64>>,
}

/// What the runs of the current point have gathered so far.
#[derive(Default)]
struct Gathered {
    sum_sq: Vec<f64>,
    max_abs: Vec<f64>,
    missing: Vec<usize>,
    n: usize,
    per_seed: Vec<Vec<f64>>,
    unscored: Vec<Unscored>,
    runs: u64,
}

/// A sweep in progress.
pub struct Sweep {
    lab: &'static dyn Lab,
    spec: SweepSpec,
    base: ParamValues,
    seed: u64,
    values: Vec<f64>,
    log: Option<RateLog>,
    next_run: usize,
    /// The run after the last one this sweep makes (all of them unless it is one point of a
    /// parallel sweep).
    runs_end: Option<usize>,
    current: Option<Running>,
    gathered: Gathered,
    /// What a legend calls each of the spec's series (from the first run's catalogue).
    legends: Vec<String>,
    /// Finished points, in the order of the values (grid: row by row).
    pub points: Vec<SweepPoint>,
    /// Values that could not be run, with the reason.
    pub skipped: Vec<Skipped>,
}

impl Sweep {
    /// A sweep of `spec` over `lab` from the parameters `base`, the first run with `seed`.
    pub fn new(lab: &'static dyn Lab, spec: SweepSpec, base: ParamValues, seed: u64) -> Self {
        Self {
            lab,
            spec,
            base,
            seed,
            values: spec.values.to_vec(),
            log: None,
            next_run: 0,
            runs_end: None,
            current: None,
            gathered: Gathered::default(),
            legends: Vec::new(),
            points: Vec::new(),
            skipped: Vec::new(),
        }
    }

    /// The same sweep over other values of its parameter.
    pub fn with_values(mut self, values: Vec<f64>) -> Self {
        self.values = values;
        self
    }

    /// The sweep runs the lab's estimators on `log` (one run per value, to its end) and
    /// scores with the spec's log scoring; `None` when the spec has none.
    pub fn on_log(mut self, log: RateLog) -> Option<Self> {
        self.spec.log_scoring?;
        self.log = Some(log);
        Some(self)
    }

    /// True when the sweep runs on a recorded log.
    pub fn is_on_log(&self) -> bool {
        self.log.is_some()
    }

    /// The sweep's specification.
    pub fn spec(&self) -> &SweepSpec {
        &self.spec
    }

    /// The scoring that applies: the log's on a log, else the simulation's.
    pub fn scoring(&self) -> Option<&'static SweepScoring> {
        if self.log.is_some() {
            self.spec.log_scoring
        } else {
            self.spec.scoring
        }
    }

    /// What a legend calls series `k` of the spec: its label and unit once a run has
    /// started, its name before.
    pub fn legend(&self, k: usize) -> String {
        match (self.legends.get(k), self.spec.series.get(k)) {
            (Some(legend), _) => legend.clone(),
            (None, Some(key)) => key.name(),
            (None, None) => String::new(),
        }
    }

    /// The values of the first parameter.
    pub fn values(&self) -> &[f64] {
        &self.values
    }

    fn seeds(&self) -> usize {
        if self.log.is_some() {
            1
        } else {
            self.spec.seeds.max(1) as usize
        }
    }

    fn grid_len(&self) -> usize {
        self.spec.grid.map_or(1, |g| g.values.len().max(1))
    }

    fn total_runs(&self) -> usize {
        self.values.len() * self.grid_len() * self.seeds()
    }

    fn runs_end(&self) -> usize {
        self.runs_end.unwrap_or_else(|| self.total_runs())
    }

    fn duration_s(&self) -> f64 {
        match &self.log {
            Some(log) => log.span_s(),
            None => self.spec.duration_s,
        }
    }

    /// The (value, grid value) of point `k`.
    fn point_values(&self, k: usize) -> Option<(f64, Option<f64>)> {
        let g = self.grid_len();
        let value = *self.values.get(k / g)?;
        let grid = self.spec.grid.and_then(|a| a.values.get(k % g).copied());
        Some((value, grid))
    }

    /// Runs at most `max_steps` simulation steps; returns true when the sweep is complete.
    pub fn advance(&mut self, max_steps: usize) -> bool {
        let mut budget = max_steps;
        let end = self.duration_s();
        let after = if self.log.is_some() {
            0.0
        } else {
            self.spec.after_s
        };
        while budget > 0 {
            if self.current.is_none() && !self.start_next() {
                return true;
            }
            let Some(r) = self.current.as_mut() else {
                return true;
            };
            let stop = end - 1e-9 * r.sim.dt_s();
            let g = &mut self.gathered;
            while budget > 0 && r.sim.t_s() < stop {
                r.sim.step();
                budget -= 1;
                let row = r.sim.last_row();
                if !r.score_cols.is_empty() {
                    r.t_s.push(r.sim.t_s());
                    for (c, col) in r.score_cols.iter().zip(&mut r.recorded) {
                        col.push(c.map_or(f64::NAN, |c| row[c]));
                    }
                }
                if r.sim.t_s() > after {
                    g.n += 1;
                    for (k, c) in r.cols.iter().enumerate() {
                        let v = row[*c];
                        if v.is_nan() {
                            g.missing[k] += 1;
                        } else {
                            g.sum_sq[k] += v * v;
                            g.max_abs[k] = g.max_abs[k].max(v.abs());
                        }
                    }
                }
            }
            if r.sim.t_s() >= stop {
                self.finish_run();
            }
        }
        self.is_done()
    }

    /// Scores the run that just ended and, after its point's last seed, closes the point.
    fn finish_run(&mut self) {
        let Some(r) = self.current.take() else {
            return;
        };
        let scoring = self.scoring();
        let g = &mut self.gathered;
        g.runs += 1;
        if let Some(sc) = scoring {
            let seed = r.sim.seed();
            match (sc.score)(r.sim.params(), &r.t_s, &r.recorded) {
                Ok(s) if s.len() == sc.names.len() => g.per_seed.push(s),
                Ok(s) => g.unscored.push(Unscored {
                    seed,
                    why: ScoreError::Count {
                        got: s.len(),
                        expected: sc.names.len(),
                    },
                }),
                Err(why) => g.unscored.push(Unscored { seed, why }),
            }
        }
        self.next_run += 1;
        if self.next_run.is_multiple_of(self.seeds()) {
            self.close_point(self.next_run / self.seeds() - 1);
        }
    }

    fn close_point(&mut self, k: usize) {
        let Some((value, grid_value)) = self.point_values(k) else {
            return;
        };
        let g = std::mem::take(&mut self.gathered);
        let n = g.n.max(1) as f64;
        let names = self.scoring().map_or(0, |s| s.names.len());
        let column = |i: usize| -> Vec<f64> {
            let mut v: Vec<f64> = g.per_seed.iter().map(|s| s[i]).collect();
            v.sort_by(f64::total_cmp);
            v
        };
        // A NaN score (or none) makes the point's score NaN: nothing is dropped.
        let scores: Vec<f64> = (0..names)
            .map(|i| stats::median(&column(i)).unwrap_or(f64::NAN))
            .collect();
        let score_range = (0..names)
            .map(|i| {
                let c = column(i);
                match (c.first(), c.last()) {
                    (Some(a), Some(b)) => [*a, *b],
                    _ => [f64::NAN, f64::NAN],
                }
            })
            .collect();
        let objectives = self.scoring().map_or_else(Vec::new, |sc| {
            sc.objectives
                .iter()
                .map(|(_, w)| w.iter().zip(&scores).map(|(w, s)| w * s).sum())
                .collect()
        });
        self.points.push(SweepPoint {
            value,
            grid_value,
            rms: g
                .sum_sq
                .iter()
                .zip(&g.missing)
                .map(|(s, m)| if *m > 0 { f64::NAN } else { (s / n).sqrt() })
                .collect(),
            max_abs: g
                .max_abs
                .iter()
                .zip(&g.missing)
                .map(|(x, m)| if *m > 0 { f64::NAN } else { *x })
                .collect(),
            missing: g.missing.clone(),
            scores,
            score_range,
            objectives,
            runs: g.runs,
            unscored: g.unscored,
        });
    }

    fn start_next(&mut self) -> bool {
        let seeds = self.seeds();
        while self.next_run < self.runs_end() {
            let point = self.next_run / seeds;
            let Some((value, grid_value)) = self.point_values(point) else {
                return false;
            };
            let seed = self.seed + (self.next_run % seeds) as u64;
            match self.start_run(value, grid_value, seed) {
                Ok(running) => {
                    if self.legends.is_empty() {
                        self.legends = legends_of(self.spec.series, running.sim.specs());
                    }
                    if self.next_run.is_multiple_of(seeds) {
                        let k = self.spec.series.len();
                        self.gathered = Gathered {
                            sum_sq: vec![0.0; k],
                            max_abs: vec![0.0; k],
                            missing: vec![0; k],
                            ..Gathered::default()
                        };
                    }
                    self.current = Some(running);
                    return true;
                }
                Err(why) => {
                    let grid = match (self.spec.grid, grid_value) {
                        (Some(a), Some(v)) => Some((a.key.to_string(), v)),
                        _ => None,
                    };
                    self.skipped.push(Skipped {
                        at: (self.spec.key.to_string(), value),
                        grid,
                        why,
                    });
                    // The whole point is skipped: on to the next point's first seed.
                    self.next_run = (point + 1) * seeds;
                    self.gathered = Gathered::default();
                }
            }
        }
        false
    }

    fn start_run(
        &self,
        value: f64,
        grid_value: Option<f64>,
        seed: u64,
    ) -> Result<Running, SweepError> {
        let specs = self.lab.params();
        let mut p = self.base.clone();
        for (key, v) in self.spec.fixed {
            p.set(specs, key, *v)?;
        }
        p.set(specs, self.spec.key, value)?;
        if let (Some(axis), Some(v)) = (self.spec.grid, grid_value) {
            p.set(specs, axis.key, v)?;
        }
        let score_series: &[SeriesKey] = self.scoring().map_or(&[], |s| s.series);
        let mut keys: Vec<SeriesKey> = self.spec.series.to_vec();
        keys.extend(
            score_series
                .iter()
                .filter(|s| !self.spec.series.contains(s)),
        );
        let names = crate::model::names(&keys);
        let names: Vec<&str> = names.iter().map(String::as_str).collect();
        let sim = match &self.log {
            Some(log) => Simulation::replay(self.lab, p, log.clone(), SimOptions::named(&names))?,
            None => Simulation::with_options(self.lab, p, seed, SimOptions::named(&names))?,
        };
        let cols = self
            .spec
            .series
            .iter()
            .filter_map(|s| sim.series_index(&s.name()).ok())
            .collect();
        let score_cols: Vec<Option<usize>> = score_series
            .iter()
            .map(|s| sim.series_index(&s.name()).ok())
            .collect();
        let row = sim.last_row();
        let recorded = score_cols
            .iter()
            .map(|c| vec![c.map_or(f64::NAN, |c| row[c])])
            .collect();
        Ok(Running {
            t_s: if score_cols.is_empty() {
                Vec::new()
            } else {
                vec![sim.t_s()]
            },
            sim,
            cols,
            score_cols,
            recorded,
        })
    }

    /// All values done.
    pub fn is_done(&self) -> bool {
        self.current.is_none() && self.next_run >= self.runs_end()
    }

    /// Fraction done, 0…1.
    pub fn progress(&self) -> f64 {
        let end = self.duration_s();
        let per_run = self
            .current
            .as_ref()
            .map_or(0.0, |r| (r.sim.t_s() / end.max(1e-9)).min(1.0));
        (self.next_run as f64 + per_run) / self.total_runs().max(1) as f64
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

    /// The point with the smallest objective `index` (a finite one), if any.
    pub fn argmin(&self, index: usize) -> Option<&SweepPoint> {
        self.points
            .iter()
            .filter(|p| p.objectives.get(index).is_some_and(|j| j.is_finite()))
            .min_by(|a, b| a.objectives[index].total_cmp(&b.objectives[index]))
    }

    /// Runs the sweep to its end: natively its points on every core (rayon; each point runs
    /// its seeds in order in a sweep of its own, so every number is the same in any number
    /// of threads and in the page's slices), in the page in one go.
    pub fn run_to_end(self) -> Self {
        #[cfg(not(target_arch = "wasm32"))]
        if self.next_run == 0 && self.current.is_none() {
            return self.run_points_in_parallel();
        }
        self.run_in_order()
    }

    /// Runs the rest of the sweep on this thread, point after point.
    pub fn run_in_order(mut self) -> Self {
        while !self.advance(100_000) {}
        self
    }
}

/// Each key's legend among `specs` (its name where it is not recorded).
fn legends_of(keys: &[SeriesKey], specs: &[SeriesSpec]) -> Vec<String> {
    keys.iter()
        .map(|k| {
            specs
                .iter()
                .find(|s| k.is(&s.name))
                .map_or_else(|| k.name(), SeriesSpec::legend)
        })
        .collect()
}
