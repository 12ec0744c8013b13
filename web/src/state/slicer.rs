//! Work on the page's thread sized by measured time, not by a step count: a sweep's steps
//! cost 20 µs in one lab and 2 µs in another, so a fixed count either overruns the frame or
//! wastes it. The slicer keeps the measured cost of a step and gives each chunk as many steps
//! as fit in the time the frame has left.

use std::time::Duration;

/// The cost per step assumed before anything is measured (ns): conservative, so the first
/// chunk is short.
const FIRST_GUESS_NS: f64 = 50_000.0;

/// Chunk sizes from the measured cost of a step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Slicer {
    ns_per_step: f64,
}

impl Default for Slicer {
    fn default() -> Self {
        Self {
            ns_per_step: FIRST_GUESS_NS,
        }
    }
}

impl Slicer {
    /// Steps that fit in `left` at the measured cost (at least one, so work always moves).
    pub fn chunk(&self, left: Duration) -> usize {
        let steps = left.as_nanos() as f64 / self.ns_per_step;
        (steps.floor() as usize).clamp(1, 100_000)
    }

    /// `steps` took `took`: the estimate follows (a step that costs more is believed at
    /// once, a cheaper one halfway, so a slow stretch does not overrun twice).
    pub fn measured(&mut self, steps: usize, took: Duration) {
        if steps == 0 {
            return;
        }
        let ns = took.as_nanos() as f64 / steps as f64;
        self.ns_per_step = if ns >= self.ns_per_step {
            ns
        } else {
            0.5 * (self.ns_per_step + ns)
        }
        .max(1.0);
    }

    /// The measured cost of a step (ns).
    #[cfg(test)]
    pub fn ns_per_step(&self) -> f64 {
        self.ns_per_step
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A frame of `budget` over work whose step costs `cost`: how long the frame ran.
    fn frame(slicer: &mut Slicer, budget: Duration, cost: Duration) -> Duration {
        let mut used = Duration::ZERO;
        while used < budget {
            let steps = slicer.chunk(budget - used);
            let took = cost * steps as u32;
            slicer.measured(steps, took);
            used += took;
        }
        used
    }

    #[test]
    fn after_the_first_chunk_no_frame_overruns_by_more_than_a_step() {
        let budget = Duration::from_millis(10);
        for cost_us in [2, 23, 400, 3000] {
            let cost = Duration::from_micros(cost_us);
            let mut slicer = Slicer::default();
            frame(&mut slicer, budget, cost);
            for k in 0..5 {
                let used = frame(&mut slicer, budget, cost);
                assert!(
                    used <= budget + cost,
                    "{cost_us} µs a step, frame {k}: {used:?} over a {budget:?} budget"
                );
            }
            assert!((slicer.ns_per_step() - cost.as_nanos() as f64).abs() < 1.0);
        }
    }

    #[test]
    fn the_slicer_follows_a_step_that_grows_dearer_at_once() {
        let mut slicer = Slicer::default();
        slicer.measured(1000, Duration::from_millis(2));
        assert_eq!(
            slicer.chunk(Duration::from_millis(10)),
            384,
            "a cheaper step: halfway"
        );
        for _ in 0..30 {
            slicer.measured(1000, Duration::from_millis(2));
        }
        let settled = slicer.chunk(Duration::from_millis(10));
        assert!(
            (4999..=5000).contains(&settled),
            "{settled} steps of 2 µs in 10 ms"
        );
        slicer.measured(10, Duration::from_millis(1));
        assert_eq!(slicer.chunk(Duration::from_millis(10)), 100);
    }
}
