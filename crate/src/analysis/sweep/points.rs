//! A sweep's points as separate jobs: each point — its seeds one after another, the same
//! code as the page's frame-by-frame slices — runs in a sweep of its own that starts at that
//! point's first run. Natively rayon runs them on every core; in the page, Web Workers (each
//! with its own wasm instance) are handed a [`PointJob`] as a message and answer with a
//! [`PointDone`]. The points are put back in their order, so every number is the same in
//! any number of threads, in the workers and in the page's slices.

use super::{Gathered, Sweep, SweepPoint};
use crate::model::ParamValues;
use serde::{Deserialize, Serialize};

/// One point of a sweep, as a message: everything a fresh process needs to run it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PointJob {
    /// The lab's id.
    pub lab: String,
    /// The sweep's index in the lab's sweeps.
    pub sweep: usize,
    /// The parameters the sweep starts from.
    pub base: ParamValues,
    /// The seed of the sweep's first run.
    pub seed: u64,
    /// The values of the swept parameter.
    pub values: Vec<f64>,
    /// Which point (grid: row by row).
    pub point: usize,
}

/// What one point's runs leave.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PointDone {
    /// The point (none when it could not be run).
    pub points: Vec<SweepPoint>,
    /// Why it could not be run.
    pub skipped: Vec<super::Skipped>,
    /// The legends of the spec's series.
    pub legends: Vec<String>,
}

impl Sweep {
    /// How many points the sweep has.
    pub fn point_count(&self) -> usize {
        self.values.len() * self.grid_len()
    }

    /// The sweep's points as jobs for other threads, if it can be split: a sweep of the
    /// simulation that has not started (`None` on a log, whose run the page holds).
    pub fn point_jobs(&self, sweep: usize) -> Option<Vec<PointJob>> {
        if self.log.is_some() || self.next_run > 0 || self.current.is_some() {
            return None;
        }
        let job = |point| PointJob {
            lab: self.lab.id().to_string(),
            sweep,
            base: self.base.clone(),
            seed: self.seed,
            values: self.values.clone(),
            point,
        };
        Some((0..self.point_count()).map(job).collect())
    }

    /// What every point's own sweep starts from (shareable between threads).
    pub(super) fn template(&self) -> Template {
        Template {
            lab: self.lab,
            spec: self.spec,
            base: self.base.clone(),
            seed: self.seed,
            values: self.values.clone(),
            log: self.log.clone(),
            seeds: self.seeds(),
        }
    }

    /// Takes the next point's result (the points come back in their order): the sweep
    /// moves on by that point's runs.
    pub fn take_point(&mut self, done: PointDone) {
        if self.legends.is_empty() {
            self.legends = done.legends;
        }
        self.points.extend(done.points);
        self.skipped.extend(done.skipped);
        self.next_run = (self.next_run + self.seeds()).min(self.total_runs());
    }
}

/// A sweep before its first run, from which each point's own sweep is made.
pub(super) struct Template {
    lab: &'static dyn crate::page::Lab,
    spec: crate::model::SweepSpec,
    base: ParamValues,
    seed: u64,
    values: Vec<f64>,
    log: Option<crate::sensors::RateLog>,
    seeds: usize,
}

impl Template {
    /// The sweep of point `k` alone.
    pub(super) fn one_point(&self, k: usize) -> Sweep {
        Sweep {
            lab: self.lab,
            spec: self.spec,
            base: self.base.clone(),
            seed: self.seed,
            values: self.values.clone(),
            log: self.log.clone(),
            next_run: k * self.seeds,
            runs_end: Some((k + 1) * self.seeds),
            current: None,
            gathered: Gathered::default(),
            legends: Vec::new(),
            points: Vec::new(),
            skipped: Vec::new(),
        }
    }
}

impl From<Sweep> for PointDone {
    fn from(one: Sweep) -> Self {
        Self {
            points: one.points,
            skipped: one.skipped,
            legends: one.legends,
        }
    }
}

/// Runs `job` (in a worker) on `lab`, the lab it names (the caller looks it up in the
/// registry): its sweep from its base, to the end of its point.
pub fn run_point_job(
    lab: &'static dyn crate::page::Lab,
    job: &PointJob,
) -> Result<PointDone, super::SweepError> {
    if lab.id() != job.lab {
        return Err(super::SweepError::WrongLab {
            job: job.lab.clone(),
            lab: lab.id().to_string(),
        });
    }
    let spec = lab
        .sweeps()
        .get(job.sweep)
        .ok_or_else(|| super::SweepError::NoSweep {
            lab: job.lab.clone(),
            sweep: job.sweep,
        })?;
    let sweep = Sweep::new(lab, *spec, job.base.clone(), job.seed).with_values(job.values.clone());
    if job.point >= sweep.point_count() {
        return Err(super::SweepError::NoPoint {
            sweep: job.sweep,
            point: job.point,
        });
    }
    Ok(sweep.template().one_point(job.point).run_in_order().into())
}

/// Numbers as their bits in a message: NaN (a missing sample, an unscored run) and the
/// infinities go through JSON unchanged, and every number comes back to the last bit.
pub(super) mod f64_bits {
    use serde::{Deserialize, Deserializer, Serialize, Serializer};

    pub fn serialize<S: Serializer>(v: &[f64], s: S) -> Result<S::Ok, S::Error> {
        v.iter()
            .map(|x| x.to_bits())
            .collect::<Vec<u64>>()
            .serialize(s)
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Vec<f64>, D::Error> {
        Ok(Vec::<u64>::deserialize(d)?
            .into_iter()
            .map(f64::from_bits)
            .collect())
    }
}

/// [`f64_bits`] for pairs.
pub(super) mod pair_bits {
    use serde::{Deserialize, Deserializer, Serialize, Serializer};

    pub fn serialize<S: Serializer>(v: &[[f64; 2]], s: S) -> Result<S::Ok, S::Error> {
        let bits: Vec<[u64; 2]> = v.iter().map(|[a, b]| [a.to_bits(), b.to_bits()]).collect();
        bits.serialize(s)
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Vec<[f64; 2]>, D::Error> {
        let bits = Vec::<[u64; 2]>::deserialize(d)?;
        Ok(bits
            .into_iter()
            .map(|[a, b]| [f64::from_bits(a), f64::from_bits(b)])
            .collect())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_point_job_and_its_answer_go_through_json_to_the_last_bit() {
        let lab = crate::labs::find("p4").expect("p4");
        let base = ParamValues::defaults(lab.params());
        let spec = lab.sweeps()[0];
        let sweep =
            Sweep::new(lab, spec, base, 3).with_values(vec![spec.values[0], spec.values[1]]);
        let jobs = sweep.point_jobs(0).expect("a fresh sweep splits");
        let job: PointJob =
            serde_json::from_str(&serde_json::to_string(&jobs[1]).unwrap()).unwrap();
        assert_eq!(job, jobs[1]);
        let mut done = run_point_job(lab, &job).unwrap();
        // A missing score and an infinite one survive the trip.
        done.points[0].scores.push(f64::NAN);
        done.points[0]
            .score_range
            .push([f64::NEG_INFINITY, 1.0 / 3.0]);
        let back: PointDone = serde_json::from_str(&serde_json::to_string(&done).unwrap()).unwrap();
        assert!(back.points[0].scores.last().unwrap().is_nan());
        assert_eq!(back.points[0].score_range, done.points[0].score_range);
        assert_eq!(back.points[0].rms, done.points[0].rms);
        // The job's point is the sweep's own second point, run alone.
        let whole = sweep.run_in_order();
        assert_eq!(whole.points[1], run_point_job(lab, &job).unwrap().points[0]);
        assert!(run_point_job(lab, &PointJob { point: 2, ..job }).is_err());
    }
}
