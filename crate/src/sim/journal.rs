//! The parameter journal: every live change of a run with the step it happened at, and the
//! one loop that replays a run from its start with the same changes at the same steps (for a
//! CSV export, a new selection of series, a paper's output file).

use super::Simulation;

/// A parameter change during a run: applied before step `step`.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Entry {
    step: u64,
    key: &'static str,
    value: f64,
}

/// How far a slice-at-a-time replay has got through a journal.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(super) struct Cursor {
    next: usize,
}

/// The changes of one run, in the order they were made.
#[derive(Clone, Debug, Default, PartialEq)]
pub(super) struct Journal {
    entries: Vec<Entry>,
}

/// A change that the run took but its re-run refused (the lab changed under it).
#[derive(Clone, Debug, PartialEq, thiserror::Error, serde::Serialize, serde::Deserialize)]
#[error("the change {key} = {value} at step {step} was refused on re-run: {reason}")]
pub struct Refused {
    /// Step of the change.
    pub step: u64,
    /// Parameter key.
    pub key: String,
    /// Value set.
    pub value: f64,
    /// What the re-run said.
    pub reason: crate::model::ParamError,
}

/// Why replaying a journal stopped.
#[derive(Debug, thiserror::Error)]
pub enum ReplayError<E> {
    /// A change of the journal was refused.
    #[error(transparent)]
    Refused(Refused),
    /// The caller's per-step work failed.
    #[error("{0}")]
    Step(E),
}

impl Journal {
    /// Records that `key` was set to `value` before step `step`.
    pub(super) fn push(&mut self, step: u64, key: &'static str, value: f64) {
        self.entries.push(Entry { step, key, value });
    }

    /// Brings `sim`, a fresh run from the same start, up to `steps` with every change at its
    /// step, calling `each_step` after every step; changes made after the last step apply at
    /// the end, so the re-run's parameters equal the original's.
    pub(super) fn replay<E>(
        &self,
        sim: &mut Simulation,
        steps: u64,
        each_step: impl FnMut(&Simulation) -> Result<(), E>,
    ) -> Result<(), ReplayError<E>> {
        let mut cursor = Cursor::default();
        self.replay_some(sim, steps, &mut cursor, u64::MAX, each_step)?;
        Ok(())
    }

    /// [`Journal::replay`] a slice at a time: at most `max_steps` more steps from where
    /// `cursor` left off. Returns true when `sim` has reached `steps` and every change is in.
    pub(super) fn replay_some<E>(
        &self,
        sim: &mut Simulation,
        steps: u64,
        cursor: &mut Cursor,
        max_steps: u64,
        mut each_step: impl FnMut(&Simulation) -> Result<(), E>,
    ) -> Result<bool, ReplayError<E>> {
        let mut taken = 0;
        while sim.steps() < steps {
            if taken == max_steps {
                return Ok(false);
            }
            cursor.next += self.apply_due(sim, cursor.next, Some(sim.steps()))?;
            sim.step();
            taken += 1;
            each_step(sim).map_err(ReplayError::Step)?;
        }
        cursor.next += self.apply_due(sim, cursor.next, None)?;
        Ok(true)
    }

    /// The changes made before step `step` (a run restored at that step has made these).
    pub(super) fn before(&self, step: u64) -> Journal {
        Journal {
            entries: self
                .entries
                .iter()
                .take_while(|e| e.step < step)
                .copied()
                .collect(),
        }
    }

    /// The change at `index`, as (step, key, value).
    pub(super) fn get(&self, index: usize) -> Option<(u64, &'static str, f64)> {
        self.entries.get(index).map(|e| (e.step, e.key, e.value))
    }

    /// Number of changes recorded.
    pub(super) fn len(&self) -> usize {
        self.entries.len()
    }

    /// The changes from entry `from` on, applied to `sim` now (those made to a run while a
    /// re-run of it was under way).
    pub(super) fn apply_from(&self, sim: &mut Simulation, from: usize) -> Result<(), Refused> {
        match self.apply_due::<()>(sim, from, None) {
            Ok(_) => Ok(()),
            Err(ReplayError::Refused(r)) => Err(r),
            Err(ReplayError::Step(())) => Ok(()),
        }
    }

    /// Applies the entries from `from` on that are due before step `step` (every remaining
    /// one when `None`); returns how many it applied.
    fn apply_due<E>(
        &self,
        sim: &mut Simulation,
        from: usize,
        step: Option<u64>,
    ) -> Result<usize, ReplayError<E>> {
        let due = self
            .entries
            .get(from..)
            .unwrap_or_default()
            .iter()
            .take_while(|e| step.is_none_or(|s| e.step == s));
        let mut applied = 0;
        for e in due {
            sim.set_param(e.key, e.value).map_err(|err| {
                ReplayError::Refused(Refused {
                    step: e.step,
                    key: e.key.to_string(),
                    value: e.value,
                    reason: err,
                })
            })?;
            applied += 1;
        }
        Ok(applied)
    }
}
