//! The fixed-step loop: truth → sensors → estimators → recorder.

use crate::estimators::{Estimate, EstimatorStatus};
use crate::labs::{Lab, LabRun, TruthState};
use crate::math::{
    EulerYpr, WzAttitude, WzChart, rotation_angle_between, small_angle_error_body, vertical_in_body,
};
use crate::params::{ParamError, ParamValues};
use crate::record::{Recorder, SeriesGroup, SeriesSpec};
use crate::sensors::RateLog;
use nalgebra::{UnitQuaternion, Vector3};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

/// Rows the recorder keeps by default: 60 000 rows × 8 bytes × series (≈ 45 MB for paper 1's
/// 94 series) — 200 s of paper 1 at its 300-Hz gyro rate, 600 s at 100 Hz.
pub const DEFAULT_HISTORY_ROWS: usize = 60_000;

/// A running lab: one `(lab, parameters, seed)` always gives the same run.
pub struct Simulation {
    lab: &'static dyn Lab,
    params: ParamValues,
    seed: u64,
    rng: ChaCha8Rng,
    run: LabRun,
    t_s: f64,
    steps: u64,
    recorder: Recorder,
    row: Vec<f64>,
    statuses: Vec<EstimatorStatus>,
    history_rows: usize,
    replay: Option<std::sync::Arc<RateLog>>,
}

impl Simulation {
    /// Starts `lab` with `params` (already validated) and `seed`.
    pub fn new(lab: &'static dyn Lab, params: ParamValues, seed: u64) -> Self {
        Self::with_history(lab, params, seed, DEFAULT_HISTORY_ROWS)
    }

    /// Same, keeping `history_rows` rows of every series.
    pub fn with_history(
        lab: &'static dyn Lab,
        params: ParamValues,
        seed: u64,
        history_rows: usize,
    ) -> Self {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let run = lab.build(&params, &mut rng);
        let recorder = Recorder::new(series_for(&run), history_rows);
        let statuses = vec![EstimatorStatus::Ok; run.estimators.len()];
        let mut sim = Self {
            lab,
            params,
            seed,
            rng,
            run,
            t_s: 0.0,
            steps: 0,
            recorder,
            row: Vec::new(),
            statuses,
            history_rows,
            replay: None,
        };
        sim.record();
        sim
    }

    /// Runs `lab`'s estimators on a recorded gyro log instead of simulated truth and sensors
    /// (paper 1's laboratory mode). The step is the log's median sample interval; each step
    /// delivers the newest logged sample not yet delivered. There is no truth: the "truth"
    /// series carry the logged rate and NaN angles, so errors are NaN.
    pub fn replay(
        lab: &'static dyn Lab,
        params: ParamValues,
        log: RateLog,
        history_rows: usize,
    ) -> Result<Self, String> {
        log.median_dt_s()
            .filter(|d| *d > 0.0)
            .ok_or("the log needs at least two samples with increasing times")?;
        let mut sim = Self::with_history(lab, params, 0, history_rows);
        let log = std::sync::Arc::new(log);
        sim.run.truth = Box::new(LogTruth {
            log: log.clone(),
            t_s: 0.0,
            index: 0,
        });
        sim.run.sensors = Box::new(LogSensor {
            log: log.clone(),
            next: 0,
        });
        sim.replay = Some(log);
        sim.recorder = Recorder::new(series_for(&sim.run), history_rows);
        sim.record();
        Ok(sim)
    }

    /// The log being replayed, if this is a replay.
    pub fn replay_log(&self) -> Option<&RateLog> {
        self.replay.as_deref()
    }

    /// The lab.
    pub fn lab(&self) -> &'static dyn Lab {
        self.lab
    }

    /// Current parameter values.
    pub fn params(&self) -> &ParamValues {
        &self.params
    }

    /// The seed of this run.
    pub fn seed(&self) -> u64 {
        self.seed
    }

    /// Simulation time (s).
    pub fn t_s(&self) -> f64 {
        self.t_s
    }

    /// Steps taken since the last reset.
    pub fn steps(&self) -> u64 {
        self.steps
    }

    /// Current step length (s): the lab's, or a replayed log's median sample interval.
    pub fn dt_s(&self) -> f64 {
        match self.replay.as_ref().and_then(|l| l.median_dt_s()) {
            Some(dt) => dt,
            None => self.lab.dt_s(&self.params),
        }
    }

    /// The recorded series.
    pub fn recorder(&self) -> &Recorder {
        &self.recorder
    }

    /// The row recorded last (same order as the recorder's series).
    pub fn last_row(&self) -> &[f64] {
        &self.row
    }

    /// The true state now.
    pub fn truth(&self) -> TruthState {
        self.run.truth.state()
    }

    /// (id, label, estimate) of every estimator now.
    pub fn estimates(&self) -> Vec<(&'static str, &'static str, Estimate)> {
        self.run
            .estimators
            .iter()
            .map(|e| (e.id(), e.label(), e.estimate()))
            .collect()
    }

    /// Ids of the estimators, in order.
    pub fn estimator_ids(&self) -> Vec<&'static str> {
        self.run.estimators.iter().map(|e| e.id()).collect()
    }

    /// Covariance element names of estimator `index`.
    pub fn covariance_names(&self, index: usize) -> Option<&'static [&'static str]> {
        self.run.estimators.get(index).map(|e| e.covariance_names())
    }

    /// Health of every estimator (by position).
    pub fn statuses(&self) -> &[EstimatorStatus] {
        &self.statuses
    }

    /// Sets one parameter; takes effect on the next step without a restart (parameters
    /// marked `needs_reset` take effect at the next reset).
    pub fn set_param(&mut self, key: &str, value: f64) -> Result<(), ParamError> {
        self.params.set(self.lab.params(), key, value)?;
        self.run.truth.apply_params(&self.params);
        self.run.sensors.apply_params(&self.params);
        for e in &mut self.run.estimators {
            e.apply_params(&self.params);
        }
        Ok(())
    }

    /// Restarts from t = 0 with `seed` (reseeds the RNG, rebuilds truth and estimators); a
    /// replay restarts from the start of its log.
    pub fn reset(&mut self, seed: u64) {
        let fresh = match self.replay.take() {
            Some(log) => Self::replay(
                self.lab,
                self.params.clone(),
                (*log).clone(),
                self.history_rows,
            ),
            None => Ok(Self::with_history(
                self.lab,
                self.params.clone(),
                seed,
                self.history_rows,
            )),
        };
        if let Ok(fresh) = fresh {
            *self = fresh;
        }
    }

    /// One fixed step.
    pub fn step(&mut self) {
        let dt_s = self.dt_s();
        self.run.truth.draw_noise(&mut self.rng);
        self.run.truth.step(dt_s);
        let truth = self.run.truth.state();
        let measurements = self.run.sensors.sample(&truth, dt_s, &mut self.rng);
        for e in &mut self.run.estimators {
            e.step(&measurements, dt_s);
        }
        self.t_s = truth.t_s;
        self.steps += 1;
        self.record();
    }

    /// Steps until `duration_s` more simulated time has passed.
    pub fn run_for(&mut self, duration_s: f64) {
        let end = self.t_s + duration_s;
        while self.t_s < end - 1e-9 * self.dt_s() {
            self.step();
        }
    }

    fn record(&mut self) {
        let truth = self.run.truth.state();
        self.row.clear();
        self.row.push(truth.t_s);
        push_attitude(&mut self.row, Some(&truth.q_ref_from_body), None);
        push_rate(&mut self.row, Some(&truth.rate_body_rad_s));
        push_angle(&mut self.row, truth.angle_rad, None);
        for (i, e) in self.run.estimators.iter().enumerate() {
            let est = e.estimate();
            self.statuses[i] = health(&est);
            push_attitude(&mut self.row, est.q_ref_from_body.as_ref(), est.wz.as_ref());
            push_rate(&mut self.row, est.rate_body_rad_s.as_ref());
            push_angle(&mut self.row, est.angle_rad, truth.angle_rad);
            if truth.angle_rad.is_some() {
                let rate_err = est
                    .rate_body_rad_s
                    .map_or(f64::NAN, |r| (r.z - truth.rate_body_rad_s.z).to_degrees());
                self.row.push(rate_err);
            }
            push_errors(&mut self.row, &truth, &est);
            pad(&mut self.row, &est.covariance, e.covariance_names().len());
            pad(&mut self.row, &est.innovation, e.innovation_names().len());
            pad(&mut self.row, &est.extras, e.extra_names().len());
            self.row.push(self.statuses[i].code());
        }
        self.run.truth.extra_values(&mut self.row);
        self.recorder.push(&self.row);
    }
}

fn health(est: &Estimate) -> EstimatorStatus {
    if est.status != EstimatorStatus::Ok {
        return est.status.clone();
    }
    let q_bad = est
        .q_ref_from_body
        .is_some_and(|q| !q.coords.iter().all(|c| c.is_finite()));
    let a_bad = est.angle_rad.is_some_and(|a| !a.is_finite());
    let p_bad = est.covariance.iter().any(|c| !c.is_finite());
    if q_bad || a_bad || p_bad {
        EstimatorStatus::Diverged("state or covariance is not finite".into())
    } else {
        EstimatorStatus::Ok
    }
}

const ATTITUDE: [(&str, &str, SeriesGroup); 9] = [
    ("yaw_deg", "deg", SeriesGroup::Attitude),
    ("pitch_deg", "deg", SeriesGroup::Attitude),
    ("roll_deg", "deg", SeriesGroup::Attitude),
    ("k_x", "", SeriesGroup::Sphere),
    ("k_y", "", SeriesGroup::Sphere),
    ("k_z", "", SeriesGroup::Sphere),
    ("u", "", SeriesGroup::Sphere),
    ("v", "", SeriesGroup::Sphere),
    ("z_deg", "deg", SeriesGroup::Sphere),
];
const RATE: [(&str, &str, SeriesGroup); 3] = [
    ("rate_x_deg_s", "deg/s", SeriesGroup::Rate),
    ("rate_y_deg_s", "deg/s", SeriesGroup::Rate),
    ("rate_z_deg_s", "deg/s", SeriesGroup::Rate),
];
const ERRORS: [(&str, &str, SeriesGroup); 7] = [
    ("err_deg", "deg", SeriesGroup::Error),
    ("tilt_err_deg", "deg", SeriesGroup::Error),
    ("pitch_err_deg", "deg", SeriesGroup::Error),
    ("roll_err_deg", "deg", SeriesGroup::Error),
    ("err_x_deg", "deg", SeriesGroup::Error),
    ("err_y_deg", "deg", SeriesGroup::Error),
    ("err_z_deg", "deg", SeriesGroup::Error),
];

/// |w| above which (u, v) are recorded as missing: the point is then within ~11° of the
/// pole S, where paper 3's chart has no numerical meaning (the (u, v, z) integrator has
/// switched to s = 1/w) and the values would swamp every plot. The chart-free vertical
/// k_x, k_y, k_z is always recorded.
const W_RECORD_LIMIT: f64 = 10.0;

fn push_attitude(row: &mut Vec<f64>, q: Option<&UnitQuaternion<f64>>, wz: Option<&WzAttitude>) {
    let wz = wz.copied().or_else(|| q.map(WzAttitude::from_quaternion));
    let Some(wz) = wz else {
        row.extend([f64::NAN; 9]);
        return;
    };
    // Pitch and roll depend on the vertical only (eqs. 24–25), so a tilt-only estimate
    // (q = None) still has them; yaw and z need the full attitude.
    let k = wz.vertical_in_body();
    let (pitch, roll) = pitch_roll_of_vertical(&k);
    let yaw = q.map_or(f64::NAN, |q| {
        EulerYpr::from_quaternion(q).yaw_rad.to_degrees()
    });
    row.extend([yaw, pitch.to_degrees(), roll.to_degrees(), k.x, k.y, k.z]);
    match wz.w() {
        Some((u, v)) if u.hypot(v) < W_RECORD_LIMIT => row.extend([u, v]),
        _ => row.extend([f64::NAN, f64::NAN]),
    }
    // z is chart dependent; record it in paper 3's chart where that chart exists.
    let z = match (wz.chart, q) {
        (WzChart::North, Some(_)) => wz.z_rad,
        (_, Some(q)) => {
            WzAttitude::from_dcm_in_chart(&crate::math::dcm_from_quaternion(q), WzChart::North)
                .map_or(f64::NAN, |w| w.z_rad)
        }
        (_, None) => f64::NAN,
    };
    row.push(z.to_degrees());
}

/// Pitch ϑ and roll γ of paper 3 from the vertical in body axes (eq. 27 solved).
pub fn pitch_roll_of_vertical(k_body: &Vector3<f64>) -> (f64, f64) {
    (
        k_body.y.clamp(-1.0, 1.0).asin(),
        (-k_body.x).atan2(k_body.z),
    )
}

fn push_rate(row: &mut Vec<f64>, rate: Option<&Vector3<f64>>) {
    match rate {
        Some(r) => row.extend(r.iter().map(|x| x.to_degrees())),
        None => row.extend([f64::NAN; 3]),
    }
}

fn push_angle(row: &mut Vec<f64>, angle: Option<f64>, truth: Option<f64>) {
    row.push(angle.map_or(f64::NAN, f64::to_degrees));
    if truth.is_some() {
        row.push(match (angle, truth) {
            (Some(a), Some(t)) => (a - t).to_degrees(),
            _ => f64::NAN,
        });
    }
}

fn push_errors(row: &mut Vec<f64>, truth: &TruthState, est: &Estimate) {
    match est.q_ref_from_body {
        Some(q) => row.push(rotation_angle_between(&truth.q_ref_from_body, &q).to_degrees()),
        None => row.push(f64::NAN),
    }
    let k_est = est
        .wz
        .map(|w| w.vertical_in_body())
        .or_else(|| est.q_ref_from_body.map(|q| vertical_in_body(&q)));
    match k_est {
        Some(k) => {
            let k_true = vertical_in_body(&truth.q_ref_from_body);
            let (p_t, r_t) = pitch_roll_of_vertical(&k_true);
            let (p_e, r_e) = pitch_roll_of_vertical(&k);
            let tilt = k_true.cross(&k).norm().atan2(k_true.dot(&k));
            row.extend([
                tilt.to_degrees(),
                (p_e - p_t).to_degrees(),
                wrap_pi(r_e - r_t).to_degrees(),
            ]);
        }
        None => row.extend([f64::NAN; 3]),
    }
    match est.q_ref_from_body {
        Some(q) => row.extend(
            small_angle_error_body(&truth.q_ref_from_body, &q)
                .iter()
                .map(|x| x.to_degrees()),
        ),
        None => row.extend([f64::NAN; 3]),
    }
}

/// `a` wrapped to (−π, π].
pub fn wrap_pi(a: f64) -> f64 {
    let t = a.rem_euclid(std::f64::consts::TAU);
    if t > std::f64::consts::PI {
        t - std::f64::consts::TAU
    } else {
        t
    }
}

fn pad(row: &mut Vec<f64>, values: &[f64], n: usize) {
    row.extend((0..n).map(|i| values.get(i).copied().unwrap_or(f64::NAN)));
}

fn series_for(run: &LabRun) -> Vec<SeriesSpec> {
    let truth = run.truth.state();
    let mut s = vec![SeriesSpec::new("t_s", "s", SeriesGroup::Time)];
    let add = |s: &mut Vec<SeriesSpec>, src: &str, list: &[(&str, &'static str, SeriesGroup)]| {
        s.extend(
            list.iter()
                .map(|(n, u, g)| SeriesSpec::new(format!("{src}.{n}"), u, *g)),
        );
    };
    add(&mut s, "truth", &ATTITUDE);
    add(&mut s, "truth", &RATE);
    s.push(SeriesSpec::new(
        "truth.angle_deg",
        "deg",
        SeriesGroup::Attitude,
    ));
    for e in &run.estimators {
        let id = e.id();
        add(&mut s, id, &ATTITUDE);
        add(&mut s, id, &RATE);
        s.push(SeriesSpec::new(
            format!("{id}.angle_deg"),
            "deg",
            SeriesGroup::Attitude,
        ));
        if truth.angle_rad.is_some() {
            s.push(SeriesSpec::new(
                format!("{id}.angle_err_deg"),
                "deg",
                SeriesGroup::Error,
            ));
            s.push(SeriesSpec::new(
                format!("{id}.rate_err_deg_s"),
                "deg/s",
                SeriesGroup::Error,
            ));
        }
        add(&mut s, id, &ERRORS);
        for c in e.covariance_names() {
            s.push(SeriesSpec::new(
                format!("{id}.{c}"),
                "",
                SeriesGroup::Covariance,
            ));
        }
        for c in e.innovation_names() {
            s.push(SeriesSpec::new(
                format!("{id}.{c}"),
                "",
                SeriesGroup::Innovation,
            ));
        }
        for c in e.extra_names() {
            s.push(SeriesSpec::new(format!("{id}.{c}"), "", SeriesGroup::Lab));
        }
        s.push(SeriesSpec::new(
            format!("{id}.status"),
            "",
            SeriesGroup::Lab,
        ));
    }
    s.extend(run.truth.extra_series());
    s
}

/// "Truth" of a replay: time runs, the logged rate stands in for the true rate, the angle is
/// unknown.
struct LogTruth {
    log: std::sync::Arc<RateLog>,
    t_s: f64,
    index: usize,
}

impl crate::labs::TruthModel for LogTruth {
    fn apply_params(&mut self, _params: &ParamValues) {}

    fn step(&mut self, dt_s: f64) {
        self.t_s += dt_s;
        while self.index + 1 < self.log.t_s.len()
            && self.log.t_s[self.index + 1] - self.log.t_s[0] <= self.t_s + 1e-9
        {
            self.index += 1;
        }
    }

    fn state(&self) -> TruthState {
        let rate = self
            .log
            .rate_rad_s
            .get(self.index)
            .copied()
            .unwrap_or(f64::NAN);
        TruthState {
            t_s: self.t_s,
            q_ref_from_body: UnitQuaternion::identity(),
            rate_body_rad_s: Vector3::new(0.0, 0.0, rate),
            angle_rad: Some(f64::NAN),
        }
    }
}

/// Delivers each logged sample once, at the first step at or after its time.
struct LogSensor {
    log: std::sync::Arc<RateLog>,
    next: usize,
}

impl crate::labs::SensorModel for LogSensor {
    fn apply_params(&mut self, _params: &ParamValues) {}

    fn sample(
        &mut self,
        truth: &TruthState,
        _dt_s: f64,
        _rng: &mut ChaCha8Rng,
    ) -> crate::estimators::Measurements {
        let t0 = self.log.t_s.first().copied().unwrap_or(0.0);
        let mut latest = None;
        while self.next < self.log.t_s.len() && self.log.t_s[self.next] - t0 <= truth.t_s + 1e-9 {
            latest = Some(self.log.rate_rad_s[self.next]);
            self.next += 1;
        }
        crate::estimators::Measurements {
            t_s: truth.t_s,
            gyro_axis_rad_s: latest,
            ..Default::default()
        }
    }
}
