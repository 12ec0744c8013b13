//! Replaying a recorded gyro log (paper 1's laboratory mode) or IMU log (paper 4's rig)
//! through a lab's estimators: the log stands in for the truth model and the sensors.

use super::{SimError, SimOptions, Simulation, layout_of};
use crate::model::{
    Extras, LabData, Measurements, ParamValues, Quantity, SensorModel, SeriesGroup, SeriesKey,
    SeriesSpec, TruthModel, TruthState,
};
use crate::page::{LOGGED_SAMPLE, Lab};
use crate::sensors::RateLog;
use nalgebra::{Quaternion, UnitQuaternion, Vector3};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use std::sync::{Arc, PoisonError, RwLock, RwLockReadGuard};

/// A log a replay reads, shared by the replay's truth, sensor and simulation. A replayed
/// file never changes; a live session's log grows as its samples become final
/// ([`SharedLog::append`]), and the replay steps only onto samples it already has.
#[derive(Clone, Debug, Default)]
pub struct SharedLog(Arc<RwLock<RateLog>>);

impl SharedLog {
    /// Shares `log`.
    pub fn new(log: RateLog) -> Self {
        Self(Arc::new(RwLock::new(log)))
    }

    /// The log as it is now.
    pub fn read(&self) -> RwLockReadGuard<'_, RateLog> {
        self.0.read().unwrap_or_else(PoisonError::into_inner)
    }

    /// Appends samples (times after the last one) and takes the log's lines, gaps and
    /// counts as they are now: `more` holds only the new samples.
    pub fn append(&self, more: &RateLog) {
        let mut log = self.0.write().unwrap_or_else(PoisonError::into_inner);
        log.t_s.extend_from_slice(&more.t_s);
        log.rate_rad_s.extend_from_slice(&more.rate_rad_s);
        log.accel_g.extend_from_slice(&more.accel_g);
        log.gyro_body_rad_s.extend_from_slice(&more.gyro_body_rad_s);
        log.errors.clone_from(&more.errors);
        log.notes.clone_from(&more.notes);
        log.gaps.clone_from(&more.gaps);
        log.counts = more.counts;
        log.period_s = more.period_s;
        log.widths.clone_from(&more.widths);
    }
}

/// The logged gyro reading (deg/s), a series of the replayed sensors (labelled as paper
/// 4's simulated MPU-6050 labels its own: one key, one label, one translation).
const LOGGED_GYRO_DEG_S: Quantity = Quantity::new("gyro_deg_s", "gyro reading ω", "deg/s");
/// The logged accelerometer's angle (deg), where the log has an accelerometer.
const LOGGED_ACCEL_ANGLE_DEG: Quantity = Quantity::new(
    "accel_angle_deg",
    "accelerometer angle θ_acc = atan2(a_y, a_z)",
    "deg",
);

impl Simulation {
    /// Runs `lab`'s estimators on a recorded gyro log instead of simulated truth and sensors
    /// (paper 1's laboratory mode). The clock is the log's (less its first time), starting
    /// one period P before the first sample; each step goes to the next sample and delivers
    /// it, so every sample is delivered once (a gap is stepped through at P, without
    /// samples). There is no truth, so every error series is missing.
    pub fn replay(
        lab: &'static dyn Lab,
        params: ParamValues,
        log: RateLog,
        options: SimOptions,
    ) -> Result<Self, SimError> {
        Self::live(lab, params, SharedLog::new(log), options)
    }

    /// [`Simulation::replay`] of a log that may still grow (a live session appends its
    /// samples as they become final): [`Simulation::step`] goes onto samples the log has,
    /// and [`Simulation::can_step`] says whether the next step's sample has arrived.
    pub fn live(
        lab: &'static dyn Lab,
        params: ParamValues,
        log: SharedLog,
        options: SimOptions,
    ) -> Result<Self, SimError> {
        log.read()
            .median_dt_s()
            .filter(|d| *d > 0.0)
            .ok_or(SimError::FewSamples)?;
        let mut rng = ChaCha8Rng::seed_from_u64(0);
        let mut run = lab.build_for_log(&params, &mut rng);
        // The lab's own truth says whether it turns about one axis (p1, p4) or three (p3):
        // a log's series are laid out the same way.
        let single_axis = run.truth.state().angle_rad.is_some();
        run.truth = Box::new(LogTruth::new(log.clone(), single_axis));
        run.sensors = Box::new(LogSensor::new(log.clone()));
        let layout = layout_of(lab, &run, &options)?;
        Ok(Self::assemble(
            lab,
            params,
            0,
            rng,
            run,
            options,
            layout,
            Some(log),
        ))
    }

    /// Whether the run has a truth: a replayed or live log holds only readings.
    pub fn has_truth(&self) -> bool {
        self.replay.is_none()
    }

    /// The log being replayed, if this is a replay.
    pub fn replay_log(&self) -> Option<std::sync::RwLockReadGuard<'_, RateLog>> {
        self.replay.as_ref().map(SharedLog::read)
    }

    /// Whether a step can be taken now: always, except in a replay whose log has no sample
    /// after the current time yet (a live session waiting for its data).
    pub fn can_step(&self) -> bool {
        self.replay.as_ref().is_none_or(|log| {
            let log = log.read();
            let tol = 1e-6 * log.period_s;
            log.t_s
                .last()
                .zip(log.t_s.first())
                .is_some_and(|(b, a)| b - a > self.t_s + tol)
        })
    }
}

/// "Truth" of a replay: time runs on the log's clock (from one period before its first
/// sample); the attitude, the angle and the rate are unknown (the logged rate is the
/// sensors' reading, with its noise and bias), so every error and every series of the
/// truth is missing.
#[derive(Clone)]
pub struct LogTruth {
    log: SharedLog,
    t_s: f64,
    index: Option<usize>,
    single_axis: bool,
}

impl LogTruth {
    /// Starts one period before the log's first sample; `single_axis` for a lab that turns
    /// about one axis (its truth has an angle, unknown here).
    pub fn new(log: SharedLog, single_axis: bool) -> Self {
        let period_s = log.read().period_s;
        Self {
            t_s: -period_s,
            log,
            index: None,
            single_axis,
        }
    }
}

/// Times closer than this many periods are one time (a step lands on its sample exactly).
const SNAP_PERIODS: f64 = 1e-6;

impl TruthModel for LogTruth {
    fn apply_params(&mut self, _params: &ParamValues) {}

    fn step(&mut self, dt_s: f64) {
        self.t_s += dt_s;
        let log = self.log.read();
        let tol = SNAP_PERIODS * log.period_s;
        let next = self.index.map_or(0, |k| k + 1);
        if let Some(t) = log.replay_time_s(next) {
            if (t - self.t_s).abs() <= tol {
                self.t_s = t;
            }
            if t <= self.t_s + tol {
                self.index = Some(next);
            }
        }
    }

    fn state(&self) -> TruthState {
        TruthState {
            t_s: self.t_s,
            q_ref_from_body: UnitQuaternion::new_unchecked(Quaternion::new(
                f64::NAN,
                f64::NAN,
                f64::NAN,
                f64::NAN,
            )),
            // The logged rate is a reading, not the truth: it is the sensors' series.
            rate_body_rad_s: Vector3::repeat(f64::NAN),
            angle_rad: self.single_axis.then_some(f64::NAN),
            lab: LabData::default(),
        }
    }
}

/// Delivers each logged sample once, in order, at the step that lands on its time (the
/// replay's steps go from sample to sample; see [`RateLog::step_after`]). Two samples are
/// never delivered in one step, so none is overwritten.
///
/// Its own series are what was logged at this step: the gyro rate and, for an IMU log, the
/// roll the accelerometer gives, atan2(a_y, a_z); missing at a step without a sample (a
/// gap shows as a break).
#[derive(Clone)]
pub struct LogSensor {
    log: SharedLog,
    next: usize,
    current: Option<usize>,
}

impl LogSensor {
    /// Starts before the log's first sample.
    pub fn new(log: SharedLog) -> Self {
        Self {
            log,
            next: 0,
            current: None,
        }
    }
}

impl SensorModel for LogSensor {
    fn apply_params(&mut self, _params: &ParamValues) {}

    fn sample(&mut self, truth: &TruthState, _dt_s: f64, _rng: &mut ChaCha8Rng) -> Measurements {
        let log = self.log.read();
        let tol = SNAP_PERIODS * log.period_s;
        self.current = log
            .replay_time_s(self.next)
            .filter(|t| *t <= truth.t_s + tol)
            .map(|_| self.next);
        if self.current.is_some() {
            self.next += 1;
        }
        Measurements {
            t_s: truth.t_s,
            gyro_axis_rad_s: self.current.map(|k| log.rate_rad_s[k]),
            accel_body_g: self.current.and_then(|k| log.accel_g.get(k).copied()),
            gyro_body_rad_s: self
                .current
                .and_then(|k| log.gyro_body_rad_s.get(k).copied()),
            ..Default::default()
        }
    }

    fn extra_series(&self) -> Vec<SeriesSpec> {
        let mut s = vec![
            SeriesSpec::of(SeriesKey::sensors(&LOGGED_GYRO_DEG_S), SeriesGroup::Rate),
            SeriesSpec::of(SeriesKey::sensors(&LOGGED_SAMPLE), SeriesGroup::Lab),
        ];
        if !self.log.read().accel_g.is_empty() {
            s.push(SeriesSpec::of(
                SeriesKey::sensors(&LOGGED_ACCEL_ANGLE_DEG),
                SeriesGroup::Attitude,
            ));
        }
        s
    }

    fn extra_values(&self, out: &mut Extras<'_>) {
        let k = self.current;
        let log = self.log.read();
        let rate = k.and_then(|k| log.rate_rad_s.get(k));
        out.put(
            &LOGGED_GYRO_DEG_S,
            rate.map_or(f64::NAN, |w| w.to_degrees()),
        );
        out.put(&LOGGED_SAMPLE, if k.is_some() { 1.0 } else { 0.0 });
        if !log.accel_g.is_empty() {
            let angle = k
                .and_then(|k| log.accel_g.get(k))
                .map_or(f64::NAN, |a| a.y.atan2(a.z).to_degrees());
            out.put(&LOGGED_ACCEL_ANGLE_DEG, angle);
        }
    }
}
