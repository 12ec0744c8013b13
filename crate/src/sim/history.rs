//! Time travel: snapshots of a run at a fixed interval of steps, so that any earlier moment
//! can be shown again ([`Simulation::seek`]) or branched from ([`super::branch`]) at the
//! cost of at most one interval of re-simulation.
//!
//! A snapshot is an exact copy of everything a step reads or changes — the truth, the
//! sensors (their noise generators' state), every estimator (estimate, covariance, windows),
//! the random number generator, the parameters and the health — so stepping on from it
//! gives the original run bit for bit. What is not state is not copied: the recorder, the
//! layout (rebuilt from the run's own) and the accuracy window, which a seek warms up from
//! a snapshot one window earlier (it is large: paper 2 keeps 60 s of every filter's errors).
//!
//! The snapshots stay within a byte budget for a run of any length: when the next one would
//! not fit, every other one goes and the interval doubles (the first, at t = 0, stays).

use super::{AccuracyTracker, Simulation, health::Health, tally::Tally};
use crate::model::{Estimate, LabRun, ParamValues};
use crate::record::Recorder;
use rand_chacha::ChaCha8Rng;

/// What the page keeps for time travel beside the recorder's own budget (bytes).
pub const HISTORY_BUDGET_BYTES: usize = 16 << 20;

/// Steps between snapshots at the start of a run (doubled each time the budget is full).
const FIRST_INTERVAL_STEPS: u64 = 256;

/// The state of a run after `steps` steps: all a step reads or changes.
#[derive(Clone)]
pub(super) struct Frozen {
    pub(super) params: ParamValues,
    pub(super) applied: ParamValues,
    pub(super) rng: ChaCha8Rng,
    pub(super) run: LabRun,
    pub(super) t_s: f64,
    pub(super) dt_s: f64,
    pub(super) steps: u64,
    pub(super) estimates: Vec<Estimate>,
    pub(super) health: Health,
    pub(super) tally: Option<Tally>,
}

impl Frozen {
    /// An upper bound of the bytes this snapshot holds (its struct and every heap block a
    /// clone of it allocates); `tests/tests/memory.rs` checks it against the allocator.
    pub(super) fn bytes(&self) -> usize {
        let run = &self.run;
        let boxed = std::mem::size_of_val(run.truth.as_ref())
            + run.truth.heap_bytes()
            + std::mem::size_of_val(run.sensors.as_ref())
            + run.sensors.heap_bytes()
            + run
                .estimators
                .iter()
                .map(|e| std::mem::size_of_val(e.as_ref()) + e.heap_bytes())
                .sum::<usize>()
            + run.estimators.capacity() * std::mem::size_of::<Box<dyn crate::model::Estimator>>();
        std::mem::size_of::<Self>()
            + boxed
            + self.params.heap_bytes()
            + self.applied.heap_bytes()
            + self.estimates.capacity() * std::mem::size_of::<Estimate>()
            + self.health.heap_bytes()
            + self.tally.as_ref().map_or(0, Tally::heap_bytes)
    }
}

/// Snapshots of one run, oldest first, within a byte budget.
#[derive(Clone, Debug, Default)]
pub(super) struct History {
    /// 0: no snapshots are taken.
    budget_bytes: usize,
    interval_steps: u64,
    snapshots: Vec<FrozenEntry>,
    bytes: usize,
}

/// A snapshot and its size.
#[derive(Clone)]
struct FrozenEntry {
    frozen: Frozen,
    bytes: usize,
}

impl std::fmt::Debug for FrozenEntry {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "snapshot at step {} ({} B)",
            self.frozen.steps, self.bytes
        )
    }
}

impl History {
    /// Snapshots within `budget_bytes` (0: none).
    pub(super) fn new(budget_bytes: usize) -> Self {
        Self {
            budget_bytes,
            interval_steps: FIRST_INTERVAL_STEPS,
            snapshots: Vec::new(),
            bytes: 0,
        }
    }

    pub(super) fn budget_bytes(&self) -> usize {
        self.budget_bytes
    }

    /// Whether a snapshot is due after step `steps`.
    pub(super) fn due(&self, steps: u64) -> bool {
        self.budget_bytes > 0 && steps.is_multiple_of(self.interval_steps)
    }

    /// Keeps `frozen`, thinning the older ones first if it would not fit.
    pub(super) fn push(&mut self, frozen: Frozen) {
        let bytes = frozen.bytes();
        while self.bytes + bytes > self.budget_bytes && self.snapshots.len() > 1 {
            self.interval_steps *= 2;
            let every = self.interval_steps;
            self.snapshots
                .retain(|s| s.frozen.steps.is_multiple_of(every));
            self.bytes = self.snapshots.iter().map(|s| s.bytes).sum();
        }
        // A snapshot larger than what is left beside the first is not kept (paper 5 deep in a
        // long dropout at a fine step): a seek there re-simulates from an earlier one.
        if !frozen.steps.is_multiple_of(self.interval_steps)
            || self.bytes + bytes > self.budget_bytes
        {
            return;
        }
        self.bytes += bytes;
        self.snapshots.push(FrozenEntry { frozen, bytes });
    }

    /// Keeps `frozen` as the first snapshot, at whatever step (the run's history starts
    /// there; a later thinning may drop it if its step is not a multiple of the interval).
    pub(super) fn push_first(&mut self, frozen: Frozen) {
        let bytes = frozen.bytes();
        self.bytes = bytes;
        self.snapshots = vec![FrozenEntry { frozen, bytes }];
    }

    /// The latest snapshot at or before time `t_s`.
    pub(super) fn at_or_before(&self, t_s: f64) -> Option<&Frozen> {
        let i = self.snapshots.partition_point(|s| s.frozen.t_s <= t_s);
        i.checked_sub(1).map(|i| &self.snapshots[i].frozen)
    }

    /// Every snapshot's step, oldest first.
    pub(super) fn steps(&self) -> impl Iterator<Item = u64> + '_ {
        self.snapshots.iter().map(|s| s.frozen.steps)
    }

    /// What the snapshots hold now (bytes).
    pub(super) fn bytes(&self) -> usize {
        self.bytes
    }

    /// Steps between snapshots now.
    pub(super) fn interval_steps(&self) -> u64 {
        self.interval_steps
    }
}

/// How much the time-travel snapshots of a run hold, for the page and the bench.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct HistoryUse {
    /// Snapshots kept.
    pub snapshots: usize,
    /// Bytes they hold.
    pub bytes: usize,
    /// Steps between them now (at most this many are re-simulated by a seek).
    pub interval_steps: u64,
    /// The budget (bytes).
    pub budget_bytes: usize,
}

impl Simulation {
    /// Keeps snapshots of this run within `budget_bytes` from now on (the page uses
    /// [`HISTORY_BUDGET_BYTES`]), so it can be seeked and branched; the first is taken now.
    /// Re-runs and resets of this run keep the same budget.
    pub fn keep_history(&mut self, budget_bytes: usize) {
        self.history = History::new(budget_bytes);
        if budget_bytes > 0 {
            let frozen = self.freeze();
            self.history.push_first(frozen);
        }
    }

    /// The snapshots this run keeps.
    pub fn history_use(&self) -> HistoryUse {
        HistoryUse {
            snapshots: self.history.steps().count(),
            bytes: self.history.bytes(),
            interval_steps: self.history.interval_steps(),
            budget_bytes: self.history.budget_bytes(),
        }
    }

    /// The first time the run can be seeked to: its oldest snapshot's (None without one).
    pub fn history_start_s(&self) -> Option<f64> {
        self.history.snapshots.first().map(|s| s.frozen.t_s)
    }

    /// The state a step changes, copied.
    pub(super) fn freeze(&self) -> Frozen {
        Frozen {
            params: self.params.clone(),
            applied: self.applied.clone(),
            rng: self.rng.clone(),
            run: self.run.clone(),
            t_s: self.t_s,
            dt_s: self.dt_s,
            steps: self.steps,
            estimates: self.estimates.clone(),
            health: self.health.clone(),
            tally: self.tally.clone(),
        }
    }

    /// Takes a snapshot now if one is due.
    pub(super) fn take_snapshot(&mut self) {
        if self.history.due(self.steps) {
            let frozen = self.freeze();
            self.history.push(frozen);
        }
    }

    /// A run in the state of `frozen`, with this run's lab, layout, log and the changes of
    /// its journal made before that step, recording its rows in a two-row recorder (the
    /// caller gives it a real one when it keeps it). No snapshots, no accuracy window yet.
    pub(super) fn thaw(&self, frozen: &Frozen) -> Simulation {
        let frozen = frozen.clone();
        let mut sim = Simulation {
            lab: self.lab,
            params: frozen.params,
            applied: frozen.applied,
            initial_params: self.initial_params.clone(),
            seed: self.seed,
            rng: frozen.rng,
            run: frozen.run,
            t_s: frozen.t_s,
            dt_s: frozen.dt_s,
            steps: frozen.steps,
            layout: self.layout.clone(),
            recorder: Recorder::with_window(self.layout.specs().to_vec(), 2),
            row: Vec::new(),
            estimates: frozen.estimates,
            health: frozen.health,
            tally: frozen.tally,
            options: self.options.clone(),
            replay: self.replay.clone(),
            journal: self.journal.before(frozen.steps),
            accuracy: None,
            history: History::default(),
        };
        sim.refill_row();
        sim
    }

    /// Starts the accuracy window afresh (with the current sample), as the run did at t = 0.
    pub(super) fn restart_accuracy(&mut self) {
        let n = self.run.estimators.len();
        self.accuracy = self
            .lab
            .accuracy_table()
            .map(|t| AccuracyTracker::new(t, n));
        if let Some(a) = &mut self.accuracy {
            a.push(&self.run.truth.state(), &self.estimates);
        }
    }

    /// The snapshot a seek to `t_s` starts from: the latest one at or before `t_s`, or at
    /// or before one accuracy window earlier when the lab has an accuracy table (so the
    /// window is whole at `t_s`).
    pub(super) fn snapshot_for(&self, t_s: f64) -> Option<&Frozen> {
        let window_s = self.lab.accuracy_table().map_or(0.0, |t| t.window_s);
        self.history
            .at_or_before(t_s - window_s)
            .or_else(|| self.history.at_or_before(t_s).filter(|_| window_s == 0.0))
            .or_else(|| self.history.snapshots.first().map(|s| &s.frozen))
    }
}
