//! Seeking and branching: a run restored from a snapshot of the original
//! ([`super::history`]) and stepped on to a moment, with the original's parameter changes at
//! their steps — to show that moment again ([`Seek`]), or to run on from it with some
//! parameters changed ([`Branch`]: a "what if").
//!
//! A branch follows every change the original makes later except those of the parameters
//! it sets itself, and draws the same random numbers (the generator is part of the
//! snapshot): with no change it is the original run, bit for bit; with one, what differs is
//! the change alone, as long as the change does not change which random numbers a step
//! draws (a noise level scales the same draws; switching a sensor on or off changes them).

use super::Simulation;
use super::tally::{Stretch, Tally};
use crate::model::ParamError;
use crate::record::Recorder;

/// Why a run cannot be seeked or branched at a moment.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum TravelError {
    /// The run keeps no snapshots (time travel is off for it).
    #[error("this run keeps no snapshots")]
    NoHistory,
    /// The moment is before the oldest snapshot.
    #[error("t = {t_s} s is before the run's first snapshot at {first_s} s")]
    Before {
        /// The moment asked for (s).
        t_s: f64,
        /// The oldest snapshot's time (s).
        first_s: f64,
    },
    /// A branch's change names a parameter that takes effect only at a reset.
    #[error("{key} takes effect only at a reset, so a branch cannot change it")]
    NeedsReset {
        /// The parameter.
        key: &'static str,
    },
    /// A branch's change was refused.
    #[error(transparent)]
    Param(#[from] ParamError),
    /// The branch cannot record the series asked for.
    #[error(transparent)]
    Series(#[from] super::UnknownSeries),
}

/// A run restored from a snapshot, stepped on with the original's changes (less the
/// parameters in `overrides`) — the common part of a seek and a branch.
struct Follower {
    sim: Simulation,
    /// The original's next journal entry to apply.
    next_entry: usize,
    /// Parameters this run sets itself (the original's changes of them are skipped).
    overrides: Vec<&'static str>,
}

impl Follower {
    /// The original's changes due before this run's next step, applied (a change the
    /// original took is taken again; one it refused was never journalled).
    fn apply_due(&mut self, original: &Simulation) {
        while let Some((step, key, value)) = original.journal.get(self.next_entry) {
            if step != self.sim.steps {
                break;
            }
            if !self.overrides.contains(&key) {
                let _ = self.sim.set_param(key, value);
            }
            self.next_entry += 1;
        }
    }

    /// At most `max_steps` steps while `go_on` holds for the run; true when it no longer
    /// holds.
    fn advance(
        &mut self,
        original: &Simulation,
        max_steps: u64,
        go_on: impl Fn(&Simulation) -> bool,
    ) -> bool {
        for _ in 0..max_steps {
            if !go_on(&self.sim) {
                return true;
            }
            self.apply_due(original);
            self.sim.step();
        }
        !go_on(&self.sim)
    }
}

/// Whether `sim`'s next step ends at or before `t_s`.
fn next_step_reaches(sim: &Simulation, t_s: f64) -> bool {
    let dt_s = match &sim.replay {
        Some(log) => log.read().step_after(sim.t_s),
        None => sim.dt_s,
    };
    dt_s > 0.0 && sim.t_s + dt_s <= t_s + 1e-9 * dt_s
}

impl Simulation {
    /// A follower of this run at its latest snapshot at or before `t_s` (or one accuracy
    /// window earlier, `warm_accuracy`).
    fn follower_at(&self, t_s: f64, warm_accuracy: bool) -> Result<Follower, TravelError> {
        let first_s = self.history_start_s().ok_or(TravelError::NoHistory)?;
        if t_s < first_s {
            return Err(TravelError::Before { t_s, first_s });
        }
        let frozen = if warm_accuracy {
            self.snapshot_for(t_s)
        } else {
            self.history.at_or_before(t_s)
        }
        .ok_or(TravelError::NoHistory)?;
        let mut sim = self.thaw(frozen);
        if warm_accuracy {
            sim.restart_accuracy();
        }
        Ok(Follower {
            next_entry: sim.journal.len(),
            sim,
            overrides: Vec::new(),
        })
    }

    /// The run as it was at `t_s` (its last step at or before it, at most now), for showing
    /// that moment: a [`Seek`] to advance until [`Seek::done`].
    pub fn seek(&self, t_s: f64) -> Result<Seek, TravelError> {
        let t_s = t_s.min(self.t_s);
        Ok(Seek {
            follower: self.follower_at(t_s, true)?,
            t_s,
        })
    }

    /// A "what if" from `t_s`: this run as it was there (its last step at or before it),
    /// with `changes` made then, recording `options`. It follows this run's
    /// later changes of every other parameter; [`Branch::advance`] brings it up to now.
    pub fn branch(
        &self,
        t_s: f64,
        changes: &[(&str, f64)],
        options: super::SimOptions,
    ) -> Result<Branch, TravelError> {
        let mut keys = Vec::with_capacity(changes.len());
        for (key, _) in changes {
            let spec = crate::model::find_spec(self.lab.params(), key)?;
            if spec.needs_reset {
                return Err(TravelError::NeedsReset { key: spec.key });
            }
            keys.push(spec.key);
        }
        let t_s = t_s.min(self.t_s);
        let mut follower = self.follower_at(t_s, false)?;
        follower.advance(self, u64::MAX, |s| next_step_reaches(s, t_s));
        follower.apply_due(self);
        // The original from here on, stepped beside the branch: the same run as this one up
        // to now, so it is the original to the bit (tested), and both keep their errors'
        // tally only while there is a branch (the main run keeps none).
        let shadow_sim = follower.sim.thaw(&follower.sim.freeze());
        let mut shadow = Follower {
            sim: shadow_sim,
            next_entry: follower.next_entry,
            overrides: Vec::new(),
        };
        shadow.sim.tally = Some(Tally::new(&shadow.sim.run.estimators));
        follower.sim.tally = Some(Tally::new(&follower.sim.run.estimators));
        follower.overrides = keys;
        for (key, value) in changes {
            follower.sim.set_param(key, *value)?;
        }
        let sim = &mut follower.sim;
        // The run's own layout when it records the same series (a layout built now may
        // hold more: an estimator that had no rate at t = 0 has one now).
        if options.selection != sim.options.selection {
            sim.layout = super::layout_of(sim.lab, &sim.run, &options)?;
        }
        sim.recorder = Recorder::with_budget(sim.layout.specs().to_vec(), options.budget_bytes);
        sim.options = options;
        sim.refill_row();
        Ok(Branch {
            from_s: sim.t_s,
            from_step: sim.steps,
            shadow,
            changes: changes
                .iter()
                .zip(&follower.overrides)
                .map(|((_, v), k)| (*k, *v))
                .collect(),
            follower,
        })
    }
}

/// A seek under way: the run restored at a snapshot, stepped on to the moment asked for.
pub struct Seek {
    follower: Follower,
    t_s: f64,
}

impl Seek {
    /// At most `max_steps` more steps toward the moment (`original` is the run seeked);
    /// true when it is there.
    pub fn advance(&mut self, original: &Simulation, max_steps: u64) -> bool {
        let t_s = self.t_s;
        self.follower
            .advance(original, max_steps, |s| next_step_reaches(s, t_s))
    }

    /// Whether the run is at the moment.
    pub fn done(&self) -> bool {
        !next_step_reaches(&self.follower.sim, self.t_s)
    }

    /// The moment asked for (s).
    pub fn target_s(&self) -> f64 {
        self.t_s
    }

    /// The run so far (at the moment once [`Seek::done`]): its truth, estimates, estimators
    /// (the filter's cycle), accuracy window and last row are the original's there.
    pub fn sim(&self) -> &Simulation {
        &self.follower.sim
    }
}

/// A "what if": a second run from a moment of the original with some parameters changed.
pub struct Branch {
    follower: Follower,
    /// The original re-run beside the branch from its moment (for the comparison only).
    shadow: Follower,
    from_s: f64,
    from_step: u64,
    changes: Vec<(&'static str, f64)>,
}

/// How a branch and the original differ for one estimator since the branch began.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Difference {
    /// The estimator's position in the lab's list.
    pub estimator: usize,
    /// The original over the stretch.
    pub original: Stretch,
    /// The branch over the same stretch.
    pub branch: Stretch,
    /// The stretch's length (s).
    pub over_s: f64,
}

impl Branch {
    /// At most `max_steps` more steps toward the original's step; true when level with it.
    pub fn advance(&mut self, original: &Simulation, max_steps: u64) -> bool {
        let target = original.steps;
        let done = (self.follower).advance(original, max_steps, |s| s.steps < target);
        (self.shadow).advance(original, max_steps, |s| s.steps < target);
        done
    }

    /// The branch's run (its recorder starts at the branch's moment).
    pub fn sim(&self) -> &Simulation {
        &self.follower.sim
    }

    /// Where it began (s).
    pub fn from_s(&self) -> f64 {
        self.from_s
    }

    /// The step it began after.
    pub fn from_step(&self) -> u64 {
        self.from_step
    }

    /// What it changed, in the order given.
    pub fn changes(&self) -> &[(&'static str, f64)] {
        &self.changes
    }

    /// Each estimator's error since the branch began, in the original and in the branch,
    /// over the steps both have taken (None until the branch is level with the original).
    pub fn differences(&self, original: &Simulation) -> Option<Vec<Difference>> {
        let sim = &self.follower.sim;
        if sim.steps != original.steps || self.shadow.sim.steps != original.steps {
            return None;
        }
        let (ours, theirs) = (sim.tally.as_ref()?, self.shadow.sim.tally.as_ref()?);
        let start = Tally::new(&sim.run.estimators);
        Some(
            (0..sim.estimates.len())
                .map(|i| Difference {
                    estimator: i,
                    original: theirs.since(&start, i),
                    branch: ours.since(&start, i),
                    over_s: sim.t_s - self.from_s,
                })
                .collect(),
        )
    }

    /// The branch as a run of its own from t = 0: its whole history re-run, recording
    /// `selection` within `budget_bytes` and keeping snapshots within `history_bytes` (for promoting it
    /// to be the main run); a [`super::RerunJob`] to advance like any re-run.
    pub fn rerun_job(
        &self,
        selection: super::Selection,
        budget_bytes: usize,
        history_bytes: usize,
    ) -> Result<super::RerunJob, super::SimError> {
        let sim = &self.follower.sim;
        sim.rerun_job_keeping(selection, budget_bytes, history_bytes)
    }
}
