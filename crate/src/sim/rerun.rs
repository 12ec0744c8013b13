//! Re-running a run from its start — same lab, initial parameters, seed (or log) and the
//! same parameter changes at the same steps ([`super::journal`]) — to hand every sample to a
//! sink, or to record another selection of series with their whole history.

use super::journal::{Cursor, Journal, Refused, ReplayError};
use super::{Selection, SimError, SimOptions, Simulation};
use crate::model::SeriesSpec;
use crate::record::Recorder;

/// What [`Simulation::rerun`] hands out: the specs once, then each row.
pub enum RerunItem<'a> {
    /// The series, before any row.
    Specs(&'a [SeriesSpec]),
    /// One row, in spec order.
    Row(&'a [f64]),
}

/// Why a re-run stopped.
#[derive(Debug, thiserror::Error)]
pub enum RerunError<E> {
    /// The run could not be rebuilt, or a change of its journal was refused.
    #[error("cannot rebuild the run: {0}")]
    Setup(SimError),
    /// The sink refused a row.
    #[error("export failed: {0}")]
    Sink(E),
}

impl Simulation {
    /// A fresh run from this run's start (t = 0, initial parameters, seed or log), recording
    /// what `options` selects.
    fn restart(&self, options: SimOptions) -> Result<Simulation, SimError> {
        match &self.replay {
            Some(log) => Self::live(self.lab, self.initial_params.clone(), log.clone(), options),
            None => Ok(Self::with_options(
                self.lab,
                self.initial_params.clone(),
                self.seed,
                options,
            )?),
        }
    }

    /// Re-runs this run from its start up to the current step, recording `selection`, and
    /// hands every row to `sink` (the specs first). Used to export every sample of a run
    /// whose recorder kept only a summary. Returns the number of rows.
    pub fn rerun<E>(
        &self,
        selection: Selection,
        mut sink: impl FnMut(RerunItem<'_>) -> Result<(), E>,
    ) -> Result<u64, RerunError<E>> {
        let options = SimOptions {
            selection,
            budget_bytes: 1 << 16,
        };
        let mut sim = self.restart(options).map_err(RerunError::Setup)?;
        sink(RerunItem::Specs(sim.specs())).map_err(RerunError::Sink)?;
        sink(RerunItem::Row(&sim.row)).map_err(RerunError::Sink)?;
        self.journal
            .replay(&mut sim, self.steps, |s| sink(RerunItem::Row(&s.row)))
            .map_err(|e| match e {
                ReplayError::Step(e) => RerunError::Sink(e),
                ReplayError::Refused(r) => RerunError::Setup(SimError::Refused(r)),
            })?;
        Ok(sim.steps + 1)
    }

    /// The same run recording `selection` instead: re-run from the start up to this step,
    /// so the new series have their whole history. Its cost is the run so far at the new
    /// selection's speed.
    pub fn reselected(&self, selection: Selection) -> Result<Simulation, SimError> {
        let options = SimOptions {
            selection,
            budget_bytes: self.options.budget_bytes,
        };
        let mut sim = self.restart(options)?;
        sim.keep_history(self.history.budget_bytes());
        self.journal.replay(&mut sim, self.steps, |_| {
            Ok::<(), std::convert::Infallible>(())
        })?;
        Ok(sim)
    }

    /// [`Self::reselected`] in place, holding one recorder's memory at a time: this run's
    /// recorder goes first (the re-run rebuilds every series), which keeps the page's
    /// high-water mark down on a lab with many series. On an error the run goes on recording
    /// what it did (re-run again, or from now on if that fails too) and the error is returned.
    pub fn reselect(&mut self, selection: Selection) -> Result<(), SimError> {
        let specs = self.recorder.specs().to_vec();
        self.release_recorder();
        match self.reselected(selection) {
            Ok(sim) => {
                *self = sim;
                Ok(())
            }
            Err(e) => {
                match self.reselected(self.options.selection.clone()) {
                    Ok(sim) => *self = sim,
                    Err(_) => {
                        self.recorder = Recorder::with_budget(specs, self.options.budget_bytes);
                    }
                }
                Err(e)
            }
        }
    }
}

/// A re-run advanced a slice at a time, so the page never stalls a frame on it: a fresh run
/// from the original's start, brought up to the step the original had reached when the job
/// began, with the same parameter changes at the same steps.
pub struct RerunJob {
    sim: Simulation,
    target_steps: u64,
    journal: Journal,
    cursor: Cursor,
}

impl RerunJob {
    /// The re-run so far.
    pub fn sim(&self) -> &Simulation {
        &self.sim
    }

    /// The re-run, done or not (a promoted branch becomes the main run).
    pub fn into_sim(self) -> Simulation {
        self.sim
    }

    /// Share of the steps done, 0 to 1.
    pub fn progress(&self) -> f64 {
        if self.target_steps == 0 {
            1.0
        } else {
            self.sim.steps as f64 / self.target_steps as f64
        }
    }

    /// At most `max_steps` more steps, calling `each_step` after every one; true when the
    /// re-run has caught up.
    pub fn advance<E>(
        &mut self,
        max_steps: u64,
        each_step: impl FnMut(&Simulation) -> Result<(), E>,
    ) -> Result<bool, ReplayError<E>> {
        self.journal.replay_some(
            &mut self.sim,
            self.target_steps,
            &mut self.cursor,
            max_steps,
            each_step,
        )
    }
}

impl Simulation {
    /// A [`RerunJob`] of this run recording `selection` within `budget_bytes`.
    pub fn rerun_job(
        &self,
        selection: Selection,
        budget_bytes: usize,
    ) -> Result<RerunJob, SimError> {
        self.rerun_job_keeping(selection, budget_bytes, self.history.budget_bytes())
    }

    /// [`Simulation::rerun_job`] keeping snapshots within `history_bytes` (0: none).
    pub(super) fn rerun_job_keeping(
        &self,
        selection: Selection,
        budget_bytes: usize,
        history_bytes: usize,
    ) -> Result<RerunJob, SimError> {
        let mut sim = self.restart(SimOptions {
            selection,
            budget_bytes,
        })?;
        sim.keep_history(history_bytes);
        Ok(RerunJob {
            sim,
            target_steps: self.steps,
            journal: self.journal.clone(),
            cursor: Cursor::default(),
        })
    }

    /// Takes a finished re-selection `job` of this run as the run: the job's series with
    /// their whole history, and the parameter changes made here while it ran (this run
    /// must not have stepped since the job began).
    pub fn adopt(&mut self, job: RerunJob) -> Result<(), Refused> {
        debug_assert_eq!(
            job.sim.steps, self.steps,
            "the run stepped during its re-run"
        );
        let mut sim = job.sim;
        self.journal.apply_from(&mut sim, job.journal.len())?;
        *self = sim;
        Ok(())
    }
}
