//! A sweep's points on every core (native only, rayon), each in a sweep of its own
//! ([`super::points`]), put back in their order: every number is the same in any number of
//! threads, in the page's workers and in its slices.

use super::Sweep;
use super::points::PointDone;
use rayon::prelude::*;

impl Sweep {
    /// Runs every point of a sweep that has not started, on rayon's pool.
    pub(super) fn run_points_in_parallel(mut self) -> Self {
        let template = self.template();
        let done: Vec<PointDone> = (0..self.point_count())
            .into_par_iter()
            .map(|k| template.one_point(k).run_in_order().into())
            .collect();
        for d in done {
            self.take_point(d);
        }
        self.next_run = self.total_runs();
        self
    }
}
