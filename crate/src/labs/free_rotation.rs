//! Foundation lab "free rotation": a torque-free rigid body tumbling, a three-axis gyro, and
//! two gyro-only integrators — quaternion and paper 3's (u, v, z). It exercises every part
//! of the pipeline and shows how a gyro bias makes pure integration drift. Spun about the
//! intermediate axis the body flips over and over (Dzhanibekov effect), which sends w
//! through ∞ and exercises the chart switch of the (u, v, z) integrator.

use crate::analysis::scenario::{Trace, run_trace};
use crate::analysis::stats;
use crate::analysis::{AnalysisError, StatsContext};
use crate::dynamics::{RigidBody, RigidBodyState};
use crate::estimators::{IntegrationErrorModel, QuaternionIntegration, WzIntegration};
use crate::math::{EulerYpr, WzAttitude};
use crate::model::{
    Estimator, Expectation, Figure, Lab, LabRun, Measurements, ParamSpec, ParamValues, ReproError,
    Reproduction, Row, SensorModel, SeriesGroup, SeriesSpec, TruthModel, TruthState,
};
use crate::sensors::{Gyro3, Gyro3Config};
use nalgebra::Vector3;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

/// The free-rotation lab.
pub struct FreeRotation;

const SPIN_AXES: &[&str] = &[
    "x (smallest I: stable)",
    "y (intermediate I: flips)",
    "z (largest I: stable)",
];

const PARAMS: &[ParamSpec] = &[
    ParamSpec::real("inertia_x_kg_m2", "Inertia Ixx", "kg·m²", 0.1, 10.0, 1.0)
        .log()
        .help("Principal moment of inertia about body x."),
    ParamSpec::real("inertia_y_kg_m2", "Inertia Iyy", "kg·m²", 0.1, 10.0, 2.0)
        .log()
        .help("Principal moment of inertia about body y."),
    ParamSpec::real("inertia_z_kg_m2", "Inertia Izz", "kg·m²", 0.1, 10.0, 3.0)
        .log()
        .help("Principal moment of inertia about body z."),
    ParamSpec::real("spin_deg_s", "Initial spin", "°/s", 0.0, 360.0, 40.0)
        .on_reset()
        .help("Initial rotation rate (applies at reset)."),
    ParamSpec::choice("spin_axis", "Spin axis", SPIN_AXES, 1)
        .on_reset()
        .help("Axis of the initial spin; the intermediate axis is unstable and the body flips."),
    ParamSpec::real("tilt_deg", "Initial tilt", "°", 0.0, 180.0, 20.0)
        .on_reset()
        .help("Initial roll of the body from level (applies at reset)."),
    ParamSpec::real("gyro_noise_deg_s", "Gyro noise σ", "°/s", 0.0, 2.0, 0.02)
        .log()
        .help("White noise of each gyro sample; it accumulates as an angle random walk."),
    ParamSpec::real("gyro_bias_deg_s", "Gyro bias", "°/s", 0.0, 2.0, 0.1)
        .log()
        .help("Constant zero offset on each axis (+, −, +); integration turns it into a drift."),
    ParamSpec::real(
        "gyro_walk_deg_s_sqrt_s",
        "Bias random walk",
        "°/s/√s",
        0.0,
        0.1,
        0.0,
    )
    .log()
    .help("Bias instability: the bias itself drifts as a random walk."),
    ParamSpec::real("rate_hz", "Sample rate", "Hz", 10.0, 1000.0, 100.0)
        .log()
        .integer()
        .help("Gyro sample rate = simulation rate."),
];

impl Lab for FreeRotation {
    fn id(&self) -> &'static str {
        "free-rotation"
    }

    fn title(&self) -> &'static str {
        "Free rotation (gyro integration)"
    }

    fn paper(&self) -> &'static str {
        "Foundation lab; kinematics of paper 3 (Matveev et al. 2025), eq. 21"
    }

    fn summary(&self) -> &'static str {
        "A rigid body tumbles without torque (Euler's equations). A three-axis gyro measures its \
         rate with noise and bias, and two estimators integrate the gyro: quaternions \
         (q̇ = ½ q⊗ω) and paper 3's (u, v, z) (eq. 21), which switches to the flipped chart \
         s = 1/w when the body turns upside down. Without noise and bias both follow the truth; \
         the bias slider makes both drift the same way, the noise slider adds a random walk. \
         The inertia sliders change the tumbling live; spin, axis and tilt apply at reset."
    }

    fn params(&self) -> &'static [ParamSpec] {
        PARAMS
    }

    fn dt_s(&self, params: &ParamValues) -> f64 {
        1.0 / params.get("rate_hz").clamp(1.0, 1e4)
    }

    fn build(&self, params: &ParamValues, _rng: &mut ChaCha8Rng) -> LabRun {
        let mut truth = Tumble::new(params);
        truth.apply_params(params);
        let state = truth.state();
        let mut sensors = GyroSensors {
            gyro: Gyro3::new(Gyro3Config::default()),
        };
        sensors.apply_params(params);
        let model = IntegrationErrorModel::new(0.0, 0.0);
        let mut estimators: Vec<Box<dyn Estimator>> = vec![
            Box::new(QuaternionIntegration::new(state.q_ref_from_body, model)),
            Box::new(WzIntegration::new(
                WzAttitude::from_quaternion(&state.q_ref_from_body),
                model,
            )),
        ];
        estimators.iter_mut().for_each(|e| e.apply_params(params));
        LabRun {
            truth: Box::new(truth),
            sensors: Box::new(sensors),
            estimators,
        }
    }

    fn default_duration_s(&self) -> f64 {
        60.0
    }

    fn reproduce(&self) -> Result<Reproduction, ReproError> {
        Ok(reproduce()?)
    }

    fn figures(&self) -> &'static [Figure] {
        FIGURES
    }
}

const FIGURES: &[Figure] = &[
    Figure::new(
        "Attitude (yaw, pitch, roll)",
        &[
            "truth.yaw_deg",
            "truth.pitch_deg",
            "truth.roll_deg",
            "quat-rk4.yaw_deg",
            "quat-rk4.pitch_deg",
            "quat-rk4.roll_deg",
        ],
    ),
    Figure::new(
        "Attitude errors (body axes)",
        &[
            "quat-rk4.err_x_deg",
            "quat-rk4.err_y_deg",
            "quat-rk4.err_z_deg",
            "uvz-rk4.err_deg",
            "quat-rk4.err_deg",
        ],
    ),
    Figure::new(
        "Energy and momentum (truth)",
        &["truth.energy_j", "truth.momentum_n_m_s"],
    ),
];

/// Which sign the gyro bias has on each body axis (the bias slider sets its size).
const BIAS_PATTERN: Vector3<f64> = Vector3::new(1.0, -1.0, 1.0);

/// The tumbling body.
struct Tumble {
    body: RigidBody,
    t_s: f64,
}

impl Tumble {
    fn new(params: &ParamValues) -> Self {
        let spin = params.get("spin_deg_s").to_radians();
        // A 2 % perturbation off the spin axis makes the intermediate axis visibly unstable.
        let axis = match params.index("spin_axis") {
            0 => Vector3::new(1.0, 0.02, 0.02),
            2 => Vector3::new(0.02, 0.02, 1.0),
            _ => Vector3::new(0.02, 1.0, 0.02),
        };
        let q0 = EulerYpr::new(0.0, 0.0, params.get("tilt_deg").to_radians()).to_quaternion();
        let state = RigidBodyState {
            q_ref_from_body: q0,
            rate_body_rad_s: axis.normalize() * spin,
        };
        Self {
            body: RigidBody::new(Vector3::new(1.0, 2.0, 3.0), state),
            t_s: 0.0,
        }
    }
}

impl TruthModel for Tumble {
    fn apply_params(&mut self, params: &ParamValues) {
        self.body.inertia_kg_m2 = Vector3::new(
            params.get("inertia_x_kg_m2"),
            params.get("inertia_y_kg_m2"),
            params.get("inertia_z_kg_m2"),
        );
    }

    fn step(&mut self, dt_s: f64) {
        self.body.step(dt_s);
        self.t_s += dt_s;
    }

    fn state(&self) -> TruthState {
        let s = self.body.state;
        TruthState {
            t_s: self.t_s,
            q_ref_from_body: s.q_ref_from_body,
            rate_body_rad_s: s.rate_body_rad_s,
            angle_rad: None,
            wheel_momentum_body: None,
            wheel_torque_body: None,
            control: None,
        }
    }

    fn extra_series(&self) -> Vec<SeriesSpec> {
        vec![
            SeriesSpec::new("truth.energy_j", "J", SeriesGroup::Lab)
                .labelled("kinetic energy T = ½ωᵀJω"),
            SeriesSpec::new("truth.momentum_n_m_s", "N·m·s", SeriesGroup::Lab)
                .labelled("angular momentum |Jω|"),
        ]
    }

    fn extra_values(&self, out: &mut [f64]) {
        out[0] = self.body.kinetic_energy_j();
        out[1] = self.body.angular_momentum_ref().norm();
    }
}

struct GyroSensors {
    gyro: Gyro3,
}

impl SensorModel for GyroSensors {
    fn apply_params(&mut self, params: &ParamValues) {
        let b = params.get("gyro_bias_deg_s").to_radians();
        self.gyro.config = Gyro3Config {
            bias_rad_s: BIAS_PATTERN * b,
            noise_sigma_rad_s: params.get("gyro_noise_deg_s").to_radians(),
            bias_walk_rad_s_per_sqrt_s: params.get("gyro_walk_deg_s_sqrt_s").to_radians(),
            ..Gyro3Config::default()
        };
    }

    fn sample(&mut self, truth: &TruthState, dt_s: f64, rng: &mut ChaCha8Rng) -> Measurements {
        let rate = self.gyro.sample(&truth.rate_body_rad_s, dt_s, rng);
        Measurements {
            t_s: truth.t_s,
            gyro_body_rad_s: Some(rate),
            ..Measurements::default()
        }
    }
}

fn run(assignments: &[&str], duration_s: f64, series: &[&str]) -> Result<Trace, AnalysisError> {
    run_trace(&FreeRotation, assignments, 1, duration_s, series)
}

/// An independent first-order prediction of the attitude error a constant gyro bias causes:
/// the error in the reference frame grows as dδ/dt = R_ref_from_body(t)·b, so
/// |δ(T)| = |∫₀ᵀ R(t) b dt|, integrated (trapezoid) along the true motion alone — no
/// estimator code involved.
fn bias_error_first_order(assignments: &[&str], duration_s: f64) -> Result<f64, AnalysisError> {
    let p = crate::analysis::scenario::params_with(&FreeRotation, assignments)?;
    let b = BIAS_PATTERN * p.get("gyro_bias_deg_s").to_radians();
    let dt = FreeRotation.dt_s(&p);
    let mut rng = ChaCha8Rng::seed_from_u64(1);
    let mut truth = FreeRotation.build(&p, &mut rng).truth;
    let mut delta = Vector3::zeros();
    let mut prev = truth.state().q_ref_from_body * b;
    let steps = (duration_s / dt).round() as usize;
    for _ in 0..steps {
        truth.step(dt);
        let now = truth.state().q_ref_from_body * b;
        delta += (prev + now) * (0.5 * dt);
        prev = now;
    }
    Ok(delta.norm())
}

fn reproduce() -> Result<Reproduction, AnalysisError> {
    let mut rows = Vec::new();
    let clean_set = ["gyro_noise_deg_s=0", "gyro_bias_deg_s=0"];
    let series = [
        "quat-rk4.err_deg",
        "quat-rk4.k_x",
        "quat-rk4.k_y",
        "quat-rk4.k_z",
        "uvz-rk4.k_x",
        "uvz-rk4.k_y",
        "uvz-rk4.k_z",
        "truth.energy_j",
        "truth.k_z",
    ];
    let clean = run(&clean_set, 60.0, &series)?;
    let fine = run(
        &[clean_set[0], clean_set[1], "rate_hz=200"],
        60.0,
        &["quat-rk4.err_deg"],
    )?;
    let q_err = stats::max_abs(clean.series("quat-rk4.err_deg")?)
        .of("error-free quaternion error")?
        .to_radians();
    let q_err_fine = stats::max_abs(fine.series("quat-rk4.err_deg")?)
        .of("error-free error at 200 Hz")?
        .to_radians();
    rows.push(Row::check(
        "error-free: max quaternion error, 100 Hz, 60 s",
        "— (perfect model)",
        q_err,
        "rad",
        Expectation::below(1e-4),
    ));
    // The integrators see the rate only at the samples (linear in between) while the truth
    // integrates the exact rate, so the error-free error is O(dt²): halving dt quarters it.
    rows.push(Row::check(
        "error-free: error ratio 100 Hz / 200 Hz",
        "— (O(dt²): 4)",
        q_err / q_err_fine,
        "",
        Expectation::Near {
            value: 4.0,
            tol: 0.5,
        },
    ));
    let mut k_diff = Vec::new();
    for axis in ["k_x", "k_y", "k_z"] {
        let a = clean.series(&format!("quat-rk4.{axis}"))?;
        let b = clean.series(&format!("uvz-rk4.{axis}"))?;
        k_diff.extend(a.iter().zip(b).map(|(x, y)| x - y));
    }
    rows.push(Row::check(
        "quaternion vs (u,v,z) on the same samples: max |Δk|",
        "— (same kinematics)",
        stats::max_abs(&k_diff).of("quaternion vs (u, v, z)")?,
        "",
        Expectation::below(1e-9),
    ));
    let energy = clean.series("truth.energy_j")?;
    let e0 = *energy
        .first()
        .ok_or_else(|| AnalysisError::UnknownSeries("no energy rows".into()))?;
    rows.push(Row::check(
        "truth: relative energy drift, 60 s",
        "— (torque free: 0)",
        ((clean.last("truth.energy_j")? - e0) / e0).abs(),
        "",
        Expectation::below(1e-9),
    ));
    let kz = clean.series("truth.k_z")?;
    rows.push(Row::check(
        "intermediate-axis tumble: lowest vertical k_z",
        "— (Dzhanibekov: flips)",
        stats::min(kz).of("truth k_z")?,
        "",
        Expectation::below(-0.9),
    ));
    rows.push(Row::check(
        "intermediate-axis tumble: highest vertical k_z",
        "— (and back)",
        stats::max(kz).of("truth k_z")?,
        "",
        Expectation::above(0.9),
    ));
    let biased_set = ["gyro_noise_deg_s=0", "gyro_bias_deg_s=0.1"];
    let biased = run(&biased_set, 60.0, &["quat-rk4.err_deg"])?;
    let b_err = biased.last("quat-rk4.err_deg")?;
    let reference = bias_error_first_order(&biased_set, 60.0)?.to_degrees();
    rows.push(Row::check(
        "bias 0.1 °/s: quaternion error at 60 s vs first-order |∫R b dt|",
        "— (independent reference computation)",
        b_err,
        "deg",
        Expectation::Near {
            value: reference,
            tol: 0.05 * reference,
        },
    ));
    rows.push(Row::check(
        "bias 0.1 °/s: quaternion error at 60 s vs √3·b·t",
        "— (closed-form bound: a body that never turns)",
        b_err,
        "deg",
        Expectation::below(3f64.sqrt() * 0.1 * 60.0),
    ));
    Ok(Reproduction {
        lab: "free-rotation".into(),
        rows,
        notes: vec![
            "no paper anchors: this foundation lab checks the perfect model, conservation laws, the chart switch and the bias drift against an independent first-order computation".into(),
        ],
    })
}
