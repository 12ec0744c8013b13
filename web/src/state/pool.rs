//! A sweep on every core: its points handed to Web Workers ([`crate::sweep_workers`]) and
//! their answers put back in order, every frame, while the page draws at full rate. Where
//! no worker starts, or one fails, the sweep goes on in per-frame slices from the first
//! point not yet answered (the same numbers: each point is the same code either way).

use super::AppState;
use crate::sweep_workers;
use attlab::analysis::sweep::PointDone;
use std::collections::BTreeMap;
use web_time::Instant;

/// The workers running the sweep.
pub struct Pool {
    /// Answers that came before an earlier point's.
    waiting: BTreeMap<usize, PointDone>,
    /// The next point the sweep takes.
    next: usize,
    started: Instant,
}

/// How the last sweep ran, for the status line and the page test.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SweepTiming {
    /// Workers used (0: slices on the page's thread).
    pub workers: usize,
    /// Wall time from start to the last point (s), once done.
    pub wall_s: Option<f64>,
}

impl AppState {
    /// Hands the new sweep's points to workers, where the page can start them.
    pub(super) fn start_pool(&mut self) {
        self.run.pool = None;
        self.run.sweep_timing = SweepTiming::default();
        self.run.sweep_started = Some(Instant::now());
        let Some((i, sweep)) = self.run.sweep.as_ref() else {
            return;
        };
        let Some(jobs) = sweep.point_jobs(*i) else {
            return;
        };
        let jobs: Vec<String> = jobs
            .iter()
            .filter_map(|j| serde_json::to_string(j).ok())
            .collect();
        let workers = sweep_workers::start(&jobs, sweep_workers::cores());
        if workers > 0 {
            self.run.sweep_timing.workers = workers;
            self.run.pool = Some(Pool {
                waiting: BTreeMap::new(),
                next: 0,
                started: Instant::now(),
            });
        }
    }

    /// The running sweep's finished fraction. With workers every answered point counts, in
    /// order or not: a point answered early waits for the one before it before the sweep
    /// takes it, and the bar would lag the work done.
    pub fn sweep_progress(&self) -> Option<f64> {
        let (_, sweep) = self.run.sweep.as_ref()?;
        Some(match &self.run.pool {
            Some(pool) if !sweep.is_done() => {
                let answered = pool.next + pool.waiting.len();
                answered as f64 / sweep.point_count().max(1) as f64
            }
            _ => sweep.progress(),
        })
    }

    /// Takes the workers' answers in order; true while they run the sweep (no slices).
    pub(super) fn advance_pool(&mut self) -> bool {
        let Some(pool) = self.run.pool.as_mut() else {
            return false;
        };
        let Some((_, sweep)) = self.run.sweep.as_mut() else {
            sweep_workers::cancel();
            self.run.pool = None;
            return false;
        };
        let answers = sweep_workers::poll();
        let mut failed = answers.failed;
        for (id, text) in answers.done {
            match sweep_workers::read_answer(&text) {
                Ok(done) => {
                    pool.waiting.insert(id, done);
                }
                Err(why) => {
                    failed.get_or_insert(why);
                }
            }
        }
        while let Some(done) = pool.waiting.remove(&pool.next) {
            sweep.take_point(done);
            pool.next += 1;
        }
        if sweep.is_done() {
            sweep_workers::cancel();
            self.run.sweep_timing.wall_s = Some(pool.started.elapsed().as_secs_f64());
            self.run.pool = None;
            return true;
        }
        if let Some(why) = failed {
            sweep_workers::cancel();
            self.run.pool = None;
            self.run.sweep_timing.workers = 0;
            self.warn("msg-workers-failed", &[("why", self.why(&why))]);
            return false;
        }
        true
    }
}
