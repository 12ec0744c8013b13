//! What a lab offers beyond its run: sweeps over its parameters (with the lab's own scores),
//! the paper's output file, and the work whose cost it wants measured.

use super::key::SeriesKey;
use super::params::ParamValues;

/// A sweep a lab offers, e.g. paper 1's adaptation window N over a log grid.
#[derive(Clone, Copy, Debug)]
pub struct SweepSpec {
    /// Title for the panel.
    pub title: &'static str,
    /// Stable id within the lab (`gamma`): its messages and a lesson step name it.
    pub id: &'static str,
    /// Parameter swept.
    pub key: &'static str,
    /// Values, in order.
    pub values: &'static [f64],
    /// A second parameter swept for each value of the first: the sweep becomes a grid, drawn
    /// as a heat map.
    pub grid: Option<SweepAxis>,
    /// Parameters set for every run of the sweep (e.g. a mode the sweep needs).
    pub fixed: &'static [(&'static str, f64)],
    /// Runs per value, seeds `seed`, `seed + 1`, …: a Monte Carlo over the noise.
    pub seeds: u64,
    /// Length of each run (s).
    pub duration_s: f64,
    /// Statistics are taken over t > `after_s`.
    pub after_s: f64,
    /// Series whose RMS (and maximum of |·|) is reported.
    pub series: &'static [SeriesKey],
    /// Scores the lab computes from each simulated run (medians over the seeds).
    pub scoring: Option<&'static SweepScoring>,
    /// Scores the lab computes from each run on a recorded log (no truth there), if the
    /// sweep can run on one.
    pub log_scoring: Option<&'static SweepScoring>,
}

impl SweepSpec {
    /// A one-parameter sweep of `key` over `values`, one seed, RMS of `series` only.
    pub const fn new(
        id: &'static str,
        title: &'static str,
        key: &'static str,
        values: &'static [f64],
        duration_s: f64,
        series: &'static [SeriesKey],
    ) -> Self {
        Self {
            id,
            title,
            key,
            values,
            grid: None,
            fixed: &[],
            seeds: 1,
            duration_s,
            after_s: 0.0,
            series,
            scoring: None,
            log_scoring: None,
        }
    }

    /// The statistics start after `after_s`.
    pub const fn after(mut self, after_s: f64) -> Self {
        self.after_s = after_s;
        self
    }

    /// Each value runs over `seeds` seeds.
    pub const fn seeds(mut self, seeds: u64) -> Self {
        self.seeds = seeds;
        self
    }

    /// A grid: `key` is also swept over `values` for each value of the first.
    pub const fn grid(mut self, key: &'static str, values: &'static [f64]) -> Self {
        self.grid = Some(SweepAxis { key, values });
        self
    }

    /// Parameters set for every run.
    pub const fn fixed(mut self, fixed: &'static [(&'static str, f64)]) -> Self {
        self.fixed = fixed;
        self
    }

    /// The lab's scores of each simulated run.
    pub const fn scoring(mut self, scoring: &'static SweepScoring) -> Self {
        self.scoring = Some(scoring);
        self
    }

    /// The lab's scores of each run on a recorded log.
    pub const fn log_scoring(mut self, scoring: &'static SweepScoring) -> Self {
        self.log_scoring = Some(scoring);
        self
    }
}

/// The second parameter of a grid sweep.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SweepAxis {
    /// Parameter swept.
    pub key: &'static str,
    /// Values, in order.
    pub values: &'static [f64],
}

/// The scores of one run: from its times and the columns of [`SweepScoring::series`], with
/// the run's parameters; an error says why the run cannot be scored.
pub type ScoreFn = fn(&ParamValues, &[f64], &[Vec<f64>]) -> Result<Vec<f64>, super::ScoreError>;

/// Lines drawn over a grid's heat map, in (key, grid key) coordinates, for the sweep's
/// parameters (e.g. paper 4's det Q = γ det R), each with its English name: line `k`'s name
/// is translated as the sweep's word `overlay-<k>` (the names must not depend on the
/// parameters, only the lines).
pub type OverlayFn = fn(&ParamValues) -> Vec<(&'static str, Vec<[f64; 2]>)>;

/// What a lab scores in each run of a sweep beyond the RMS of series, e.g. paper 4's MSE
/// and transient time, and the weighted sums it minimises, e.g. J = α·MSE + β·t_tr.
#[derive(Clone, Copy, Debug)]
pub struct SweepScoring {
    /// Names of the scores, with units.
    pub names: &'static [&'static str],
    /// How each score is defined (the panel's help).
    pub help: &'static str,
    /// Series the scoring reads, in order.
    pub series: &'static [SeriesKey],
    /// The scoring.
    pub score: ScoreFn,
    /// Weighted sums of the scores, each with its name; the sweep marks each one's argmin.
    pub objectives: &'static [(&'static str, &'static [f64])],
    /// Lines over the heat map of a grid sweep.
    pub overlay: Option<OverlayFn>,
}

/// A lab's own output file, as its paper's program wrote it: these columns, one row per step,
/// and (if `stop` is given) ending at the first row where that series is 1.
#[derive(Clone, Debug, PartialEq)]
pub struct OutputFile {
    /// Series written, in order (the first is usually `t_s`).
    pub columns: Vec<String>,
    /// Header cells for them (the paper's names).
    pub headers: Vec<String>,
    /// A 0/1 series: the file ends at the first row where it is 1.
    pub stop: Option<String>,
}

/// A piece of work whose cost a lab wants measured (`attlab bench`, `attlab reproduce`).
pub struct TimingItem {
    /// What is timed.
    pub name: &'static str,
    /// Floating-point operations of one repetition, where counted (printed beside the time).
    pub flops: Option<u64>,
    /// One repetition.
    pub run: Box<dyn FnMut()>,
}
