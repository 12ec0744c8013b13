//! Foundation lab "free rotation": a torque-free rigid body tumbling, a three-axis gyro, and
//! two gyro-only integrators — quaternion and paper 3's (u, v, z). It exercises every part
//! of the pipeline and shows how a gyro bias makes pure integration drift. Spun about the
//! intermediate axis the body flips over and over (Dzhanibekov effect), which sends w
//! through ∞ and exercises the chart switch of the (u, v, z) integrator.

use super::scenario::{last_value, max_abs, run_scenario, series_after};
use super::{AnchorRow, Lab, LabRun, Reproduction, SensorModel, TruthModel, TruthState};
use crate::dynamics::{RigidBody, RigidBodyState};
use crate::estimators::{
    IntegrationErrorModel, Measurements, QuaternionIntegration, WzIntegration,
};
use crate::math::{EulerYpr, WzAttitude};
use crate::params::{ParamSpec, ParamValues};
use crate::record::{SeriesGroup, SeriesSpec};
use crate::sensors::{Gyro3, Gyro3Config};
use crate::sim::Simulation;
use nalgebra::Vector3;
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
        let mut estimators: Vec<Box<dyn crate::estimators::Estimator>> = vec![
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

    fn reproduce(&self) -> Reproduction {
        reproduce()
    }
}

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
        }
    }

    fn extra_series(&self) -> Vec<SeriesSpec> {
        vec![
            SeriesSpec::new("truth.energy_j", "J", SeriesGroup::Lab),
            SeriesSpec::new("truth.momentum_n_m_s", "N·m·s", SeriesGroup::Lab),
        ]
    }

    fn extra_values(&self, out: &mut Vec<f64>) {
        out.push(self.body.kinetic_energy_j());
        out.push(self.body.angular_momentum_ref().norm());
    }
}

struct GyroSensors {
    gyro: Gyro3,
}

impl SensorModel for GyroSensors {
    fn apply_params(&mut self, params: &ParamValues) {
        let b = params.get("gyro_bias_deg_s").to_radians();
        self.gyro.config = Gyro3Config {
            bias_rad_s: Vector3::new(b, -b, b),
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

fn run(assignments: &[&str], duration_s: f64) -> Simulation {
    run_scenario(&FreeRotation, assignments, 1, duration_s)
}

fn reproduce() -> Reproduction {
    let mut rows = Vec::new();
    let clean = run(&["gyro_noise_deg_s=0", "gyro_bias_deg_s=0"], 60.0);
    let fine = run(
        &["gyro_noise_deg_s=0", "gyro_bias_deg_s=0", "rate_hz=200"],
        60.0,
    );
    let q_err = max_abs(&series_after(&clean, "quat-rk4.err_deg", -1.0)).to_radians();
    let q_err_fine = max_abs(&series_after(&fine, "quat-rk4.err_deg", -1.0)).to_radians();
    // The integrators see the rate only at the samples (linear in between) while the truth
    // integrates the exact rate, so the error-free error is O(dt²): halving dt quarters it.
    let ratio = q_err / q_err_fine;
    rows.push(AnchorRow::new(
        "error-free: max quaternion error, 100 Hz, 60 s",
        "small, O(dt²)",
        q_err,
        "rad",
        q_err < 1e-4,
    ));
    rows.push(AnchorRow::new(
        "error-free: error ratio 100 Hz / 200 Hz",
        "4 ± 0.5 (O(dt²))",
        ratio,
        "",
        (ratio - 4.0).abs() < 0.5,
    ));
    let mut k_diff = 0.0_f64;
    for axis in ["k_x", "k_y", "k_z"] {
        let a = series_after(&clean, &format!("quat-rk4.{axis}"), -1.0);
        let b = series_after(&clean, &format!("uvz-rk4.{axis}"), -1.0);
        k_diff = a
            .iter()
            .zip(&b)
            .fold(k_diff, |m, (x, y)| m.max((x - y).abs()));
    }
    rows.push(AnchorRow::new(
        "quaternion vs (u,v,z) on the same samples: max |Δk|",
        "≤ 1e-9",
        k_diff,
        "",
        k_diff <= 1e-9,
    ));
    let energy = series_after(&clean, "truth.energy_j", -1.0);
    let (e0, e1) = (
        energy.first().copied().unwrap_or(f64::NAN),
        last_value(&clean, "truth.energy_j"),
    );
    let drift = ((e1 - e0) / e0).abs();
    rows.push(AnchorRow::new(
        "truth: relative energy drift, 60 s",
        "< 1e-9",
        drift,
        "",
        drift < 1e-9,
    ));
    let kz = series_after(&clean, "truth.k_z", -1.0);
    let (min_kz, max_kz) = kz
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(*v), hi.max(*v))
        });
    rows.push(AnchorRow::new(
        "intermediate-axis tumble: lowest vertical k_z",
        "< -0.9 (upside down)",
        min_kz,
        "",
        min_kz < -0.9 && max_kz > 0.9,
    ));
    let biased = run(&["gyro_noise_deg_s=0", "gyro_bias_deg_s=0.1"], 60.0);
    let b_err = last_value(&biased, "quat-rk4.err_deg");
    let sigma = last_value(&biased, "quat-rk4.P_axis_rad2")
        .sqrt()
        .to_degrees();
    rows.push(AnchorRow::new(
        "bias 0.1 °/s: quaternion error at 60 s",
        format!("≤ 3σ·√3 = {:.2} deg", 3.0 * sigma * 3f64.sqrt()),
        b_err,
        "deg",
        b_err > 0.1 && b_err <= 3.0 * sigma * 3f64.sqrt(),
    ));
    Reproduction {
        lab: "free-rotation".into(),
        rows,
        notes: vec![
            "no paper anchors: this foundation lab checks the perfect model, conservation laws and the chart switch".into(),
        ],
    }
}
