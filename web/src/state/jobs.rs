//! Long work as a job advanced a slice per frame, so the page never stalls on it: the
//! re-run a plot tab needs for series not recorded so far, and the CSV export of every
//! sample (a re-run from t = 0). While a job runs the simulation holds still; parameter
//! changes made meanwhile are kept. Jobs run one after the other, a new re-run for a plot
//! replacing one that has not finished.

use super::AppState;
use attlab::sim::{CsvSink, RerunJob, Selection, SimError};
use web_time::{Duration, Instant};

/// What a job is for.
enum Purpose {
    /// Record what the plot tab on screen draws (the run's new selection).
    Reselect,
    /// Re-run a branch from t = 0 to make it the main run.
    Promote,
    /// Write every sample to a CSV file of this name.
    ExportCsv {
        name: String,
        sink: Box<CsvSink<Vec<u8>>>,
    },
}

/// A job under way.
pub struct Job {
    purpose: Purpose,
    rerun: RerunJob,
    started: Instant,
}

impl Job {
    /// The catalogue's message for what the job is doing, for the progress line.
    pub fn title_id(&self) -> &'static str {
        match self.purpose {
            Purpose::Reselect => "job-reselect",
            Purpose::Promote => "job-promote",
            Purpose::ExportCsv { .. } => "job-export-csv",
        }
    }

    /// Share done, 0 to 1.
    pub fn progress(&self) -> f64 {
        self.rerun.progress()
    }
}

impl AppState {
    /// Starts re-running the simulation to record `selection` (the plots show the series
    /// as soon as it has caught up). The old recorder goes first, so the page holds one
    /// recorder's memory at a time.
    pub(super) fn start_reselect(&mut self, selection: Selection) {
        let budget = self.sim.options().budget_bytes;
        match self.sim.rerun_job(selection, budget) {
            Ok(rerun) => {
                self.sim.release_recorder();
                self.start_job(Purpose::Reselect, rerun);
            }
            Err(e) => self.warn("msg-plot-failed", &[("why", self.why(&e))]),
        }
    }

    /// Starts re-running a branch from t = 0 to make it the main run.
    pub(super) fn start_promote(&mut self, rerun: RerunJob) {
        self.start_job(Purpose::Promote, rerun);
    }

    /// Starts exporting every sample of the run so far as CSV.
    pub(super) fn start_csv_export(&mut self) {
        if self
            .run
            .jobs
            .iter()
            .any(|j| matches!(j.purpose, Purpose::ExportCsv { .. }))
        {
            return self.warn("msg-export-busy", &[]);
        }
        let name = self.csv_name();
        let made = self
            .sim
            .rerun_job(Selection::All, 1 << 16)
            .and_then(|rerun| {
                let mut sink = CsvSink::new(Vec::new(), rerun.sim().specs())?;
                sink.row(rerun.sim().last_row())?;
                Ok::<_, SimError>((sink, rerun))
            });
        match made {
            Ok((sink, rerun)) => {
                let sink = Box::new(sink);
                self.start_job(Purpose::ExportCsv { name, sink }, rerun)
            }
            Err(e) => self.warn("msg-export-failed", &[("why", self.why(&e))]),
        }
    }

    fn start_job(&mut self, purpose: Purpose, rerun: RerunJob) {
        if matches!(purpose, Purpose::Reselect) {
            self.run
                .jobs
                .retain(|j| !matches!(j.purpose, Purpose::Reselect));
        }
        self.run.jobs.push(Job {
            purpose,
            rerun,
            started: Instant::now(),
        });
    }

    /// Stops the job under way; a re-run for a plot leaves the run recording what it did
    /// before (re-run at once).
    pub(super) fn cancel_job(&mut self) {
        if self.run.jobs.is_empty() {
            return;
        }
        let job = self.run.jobs.remove(0);
        if matches!(job.purpose, Purpose::Reselect) {
            self.restore_recorder();
        }
    }

    /// Drops every job: the simulation is being replaced.
    pub(super) fn drop_jobs(&mut self) {
        self.run.jobs.clear();
    }

    /// The run's recorder back after a re-run for a plot failed or was stopped: the run
    /// records its previous selection again (re-run from its start at once).
    fn restore_recorder(&mut self) {
        let previous = self.sim.options().selection.clone();
        if let Err(e) = self.sim.reselect(previous) {
            self.warn("msg-plots-lost", &[("why", self.why(&e))]);
        }
    }

    /// Moves the job on for at most `budget` of wall time, in chunks sized by the measured
    /// cost of a step ([`super::slicer::Slicer`]).
    pub(super) fn advance_job(&mut self, budget: Duration) {
        let Some(job) = self.run.jobs.first_mut() else {
            return;
        };
        let slicer = &mut self.run.job_slicer;
        let start = Instant::now();
        let outcome = loop {
            let steps = slicer.chunk(budget.saturating_sub(start.elapsed()));
            let t0 = Instant::now();
            let stepped = match &mut job.purpose {
                Purpose::Reselect | Purpose::Promote => {
                    job.rerun.advance(steps as u64, |_| Ok::<(), SimError>(()))
                }
                Purpose::ExportCsv { sink, .. } => job.rerun.advance(steps as u64, |s| {
                    sink.row(s.last_row()).map_err(SimError::from)
                }),
            };
            slicer.measured(steps, t0.elapsed());
            match stepped {
                Ok(false) if start.elapsed() < budget => continue,
                Ok(false) => return,
                Ok(true) => break Ok(()),
                Err(e) => break Err(SimError::from(e)),
            }
        };
        let job = self.run.jobs.remove(0);
        self.finish_job(job, outcome);
    }

    fn finish_job(&mut self, job: Job, outcome: Result<(), SimError>) {
        let ms = job.started.elapsed().as_secs_f64() * 1e3;
        match (job.purpose, outcome) {
            (Purpose::Reselect, Ok(())) => {
                if let Err(e) = self.sim.adopt(job.rerun) {
                    self.warn(
                        "msg-plot-failed",
                        &[("why", self.why(&SimError::Refused(e)))],
                    );
                    self.restore_recorder();
                } else if ms > 1000.0 {
                    let t_s = self.sim.t_s();
                    let args = [
                        ("t", format!("{t_s:.0}").into()),
                        ("ms", format!("{ms:.0}").into()),
                    ];
                    self.say("msg-rerun-took", &args);
                }
            }
            (Purpose::Promote, Ok(())) => {
                self.sim = job.rerun.into_sim();
                self.say("msg-branch-promoted", &[]);
            }
            (Purpose::Promote, Err(e)) => self.warn("msg-plot-failed", &[("why", self.why(&e))]),
            (Purpose::Reselect, Err(e)) => {
                self.warn("msg-plot-failed", &[("why", self.why(&e))]);
                self.restore_recorder();
            }
            (Purpose::ExportCsv { name, sink }, Ok(())) => {
                let result = sink
                    .into_inner()
                    .map(|(bytes, rows)| (bytes, self.word("msg-csv-rows", &[("n", rows.into())])));
                match result {
                    Ok((bytes, what)) => self.save(&name, bytes, Ok(what)),
                    Err(e) => self.warn("msg-export-failed", &[("why", self.why(&e))]),
                }
            }
            (Purpose::ExportCsv { .. }, Err(e)) => {
                self.warn("msg-export-failed", &[("why", self.why(&e))]);
            }
        }
    }
}
