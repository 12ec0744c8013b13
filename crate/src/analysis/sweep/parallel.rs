//! A sweep's points on every core (native only, rayon). Each point — its seeds one after
//! another, the same code as the page's frame-by-frame slices — runs in a sweep of its own
//! that starts at that point's first run, and the points are put back in their order, so
//! every number is the same in any number of threads and in the page.

use super::{Gathered, Sweep, SweepPoint};
use rayon::prelude::*;

/// What one point's sweep leaves.
struct PointDone {
    points: Vec<SweepPoint>,
    skipped: Vec<String>,
    legends: Vec<String>,
}

impl Sweep {
    /// Runs every point of a sweep that has not started, on rayon's pool.
    pub(super) fn run_points_in_parallel(mut self) -> Self {
        let seeds = self.seeds();
        let points = self.values.len() * self.grid_len();
        let (lab, spec, base, seed, values, log) = (
            self.lab,
            self.spec,
            &self.base,
            self.seed,
            &self.values,
            &self.log,
        );
        let done: Vec<PointDone> = (0..points)
            .into_par_iter()
            .map(|k| {
                let one = Sweep {
                    lab,
                    spec,
                    base: base.clone(),
                    seed,
                    values: values.clone(),
                    log: log.clone(),
                    next_run: k * seeds,
                    runs_end: Some((k + 1) * seeds),
                    current: None,
                    gathered: Gathered::default(),
                    legends: Vec::new(),
                    points: Vec::new(),
                    skipped: Vec::new(),
                }
                .run_in_order();
                PointDone {
                    points: one.points,
                    skipped: one.skipped,
                    legends: one.legends,
                }
            })
            .collect();
        for d in done {
            if self.legends.is_empty() {
                self.legends = d.legends;
            }
            self.points.extend(d.points);
            self.skipped.extend(d.skipped);
        }
        self.next_run = self.total_runs();
        self
    }
}
