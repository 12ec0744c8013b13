//! Lab "p3": paper 3 — (w, z) kinematic parameters on the Riemann sphere, gyro and
//! accelerometer blending (Matveev et al., Devices and Methods of Measurements 2025;16(3)).
//!
//! Truth: the paper's motion (yaw ramp, harmonic pitch and roll), classic coning, a slow
//! tumble that turns the body upside down, or free rotation; true rates from the exact
//! relations (digest §5). Sensors: gyro with bias and noise, accelerometer with noise and an
//! optional lateral bump. Estimators: gyro-only (u, v, z) (eq. 21), accelerometer-only
//! (eq. 28), the paper's HPF/LPF blend (Fig. 9), a Kalman filter in (u, v), and quaternion
//! integration for comparison.

mod lesson;
mod params;
mod reproduce;

use params::PARAMS;

use crate::dynamics::{AngleProfile, EulerMotion, RigidBody, RigidBodyState};
use crate::estimators::{
    AccelWz, BlendedWz, GyroErrors, IntegrationErrorModel, QuaternionIntegration, WzIntegration,
    WzKalman, WzKalmanTuning,
};
use crate::estimators::{blended_wz, wz_kalman};
use crate::math::{WzAttitude, vertical_in_body};
use crate::model::{
    Estimator, LabData, LabRun, LabSpec, Measurements, ParamValues, SensorModel, SeriesKey, Study,
    TruthModel, TruthState, q,
};
use crate::page::{Figure, Lab, Page};
use crate::sensors::{Gyro3, Gyro3Config, WhiteNoise};
use nalgebra::{Matrix2, Vector3};
use rand_chacha::ChaCha8Rng;

/// The paper-3 lab.
pub struct WzSphere;

/// Which axes carry the bias, and with which sign.
fn bias_pattern(index: usize) -> Vector3<f64> {
    match index {
        1 => Vector3::x(),
        2 => Vector3::y(),
        3 => Vector3::z(),
        4 => Vector3::new(1.0, -1.0, 1.0),
        _ => Vector3::repeat(1.0),
    }
}

const FIGURES: &[Figure] = &[
    Figure::new(
        "fig4-uv",
        "Fig. 4: u, v",
        &[
            SeriesKey::truth(&q::U),
            SeriesKey::truth(&q::V),
            SeriesKey::new("uvz-rk4", &q::U),
            SeriesKey::new("uvz-rk4", &q::V),
        ],
    ),
    Figure::new(
        "fig4-z",
        "Fig. 4: z",
        &[
            SeriesKey::truth(&q::Z_DEG),
            SeriesKey::new("uvz-rk4", &q::Z_DEG),
        ],
    ),
    Figure::new(
        "fig5-angles",
        "Fig. 5: yaw, pitch, roll",
        &[
            SeriesKey::truth(&q::YAW_DEG),
            SeriesKey::truth(&q::PITCH_DEG),
            SeriesKey::truth(&q::ROLL_DEG),
            SeriesKey::new("uvz-rk4", &q::YAW_DEG),
            SeriesKey::new("uvz-rk4", &q::PITCH_DEG),
            SeriesKey::new("uvz-rk4", &q::ROLL_DEG),
        ],
    ),
    Figure::new(
        "fig8-v",
        "Fig. 8: v, vᵃ",
        &[
            SeriesKey::new("uvz-rk4", &q::V),
            SeriesKey::new("accel", &q::V),
            SeriesKey::truth(&q::V),
        ],
    ),
    Figure::new(
        "fig10-filters",
        "Fig. 10: HPF(v), LPF(vᵃ), vᵏ",
        &[
            SeriesKey::new("blend", &blended_wz::HPF_V),
            SeriesKey::new("blend", &blended_wz::LPF_VA),
            SeriesKey::new("blend", &q::V),
            SeriesKey::truth(&q::V),
        ],
    ),
    Figure::new(
        "tilt-errors",
        "Tilt errors",
        &[
            SeriesKey::new("uvz-rk4", &q::TILT_ERR_DEG),
            SeriesKey::new("accel", &q::TILT_ERR_DEG),
            SeriesKey::new("blend", &q::TILT_ERR_DEG),
            SeriesKey::new("kf-uv", &q::TILT_ERR_DEG),
            SeriesKey::new("quat-rk4", &q::TILT_ERR_DEG),
        ],
    ),
    Figure::new(
        "kf-variances",
        "KF variances (log10)",
        &[
            SeriesKey::variance("kf-uv", &wz_kalman::STATE_U),
            SeriesKey::variance("kf-uv", &wz_kalman::STATE_V),
        ],
    )
    .log(),
];

/// The gyro's error budget the integrators publish their covariance from.
fn gyro_errors(p: &ParamValues) -> GyroErrors {
    GyroErrors::from_deg_s(p.get("gyro_noise_deg_s"), p.get("gyro_bias_deg_s"))
}

/// The (u, v) Kalman filter's noise: the gyro's, the accelerometer's and the Q scale.
fn kf_tuning(p: &ParamValues) -> WzKalmanTuning {
    let g = gyro_errors(p);
    WzKalmanTuning {
        gyro_sigma_rad_s: g.noise_sigma_rad_s,
        bias_sigma_rad_s: g.bias_sigma_rad_s,
        accel_sigma_g: p.get("accel_noise_g"),
        q_scale: p.get("kf_q_scale"),
    }
}

const SPEC: LabSpec = LabSpec {
    id: "p3",
    title: "Paper 3: (w, z) on the Riemann sphere",
    paper: "Matveev et al., Devices and Methods of Measurements 2025;16(3):202–211",
    reference: "Matveev V. V. et al. Study of new kinematic parameters for strapdown orientation systems. Devices and Methods of Measurements, 2025, vol. 16, no. 3, pp. 202–211 (in Russian).",
    summary: "The vertical seen from the body, k = (a′, b′, c′), projected from the pole S onto the body plane gives \
         w = u + jv = (a′ + jb′)/(1 + c′) (eq. 12); z is the turn about the vertical, A = A(w)·A(z). \
         The gyro drives u̇ = vω_ζ + uvω_ξ − ½ω_η(1 + u² − v²), v̇ = −uω_ζ − uvω_η + ½ω_ξ(1 − u² + v²), \
         ż = ω_ζ + uω_ξ + vω_η (eq. 21) — (u, v) without z. Accelerometers give uᵃ = n_ξ/(1 + n_ζ), \
         vᵃ = n_η/(1 + n_ζ) (eq. 28) with no integration. The gyro channel drifts with the bias, the \
         accelerometer channel is noisy and is fooled by the lateral bump; the blend \
         wᵏ = HPF(w) + LPF(wᵃ) with time constant T keeps the best of both, and the Kalman filter \
         chooses its own gain from the noise levels (its 3σ ellipse is drawn on the plane and the sphere). \
         Sliders: bias, noise, bump, T and the KF scale act live; the motion sliders apply at Reset. \
         The slow tumble turns the body upside down: watch the chart switch to s = 1/w.",
    params: PARAMS,
    presets: &[],
    default_duration_s: 100.0,
    words: crate::model::lab_words!(),
};

const PAGE: Page = Page {
    figures: FIGURES,
    // An IMU's log, or a live phone or Arduino: the three gyro axes and the accelerometer.
    log_format: Some(&crate::sensors::IMU_LOG),
    ..Page::DEFAULT
};

impl Lab for WzSphere {
    fn lesson(&self) -> Option<&'static crate::page::Lesson> {
        Some(&lesson::LESSON)
    }
    fn spec(&self) -> &'static LabSpec {
        &SPEC
    }

    fn dt_s(&self, params: &ParamValues) -> f64 {
        1.0 / params.get("rate_hz").clamp(1.0, 1e4)
    }

    fn build(&self, params: &ParamValues, _rng: &mut ChaCha8Rng) -> LabRun {
        let truth = P3Truth::new(params);
        let q0 = truth.state().q_ref_from_body;
        build_from(params, truth, q0)
    }

    /// A log's run: the estimators start level (a phone held flat, screen up).
    fn build_for_log(&self, params: &ParamValues, _rng: &mut ChaCha8Rng) -> LabRun {
        build_from(
            params,
            P3Truth::new(params),
            nalgebra::UnitQuaternion::identity(),
        )
    }

    fn page(&self) -> &'static Page {
        &PAGE
    }

    fn study(&self) -> Option<&dyn Study> {
        Some(self)
    }
}

/// The run of `truth` with the estimators started at attitude `q0`.
fn build_from(params: &ParamValues, truth: P3Truth, q0: nalgebra::UnitQuaternion<f64>) -> LabRun {
    let wz0 = WzAttitude::from_quaternion(&q0);
    let mut sensors = GyroAccel {
        gyro: Gyro3::new(Gyro3Config::default()),
        accel_sigma_g: 0.0,
        bump: (0.0, 0.0),
    };
    sensors.apply_params(params);
    let model = IntegrationErrorModel::new(0.0, 0.0);
    let p0 = Matrix2::identity() * 1e-6;
    let mut estimators: Vec<Box<dyn Estimator>> = vec![
        Box::new(WzIntegration::new(wz0, model).tuned_by(gyro_errors)),
        Box::new(AccelWz::new()),
        Box::new(BlendedWz::new(wz0, 1.0).tuned_by(|p| p.get("blend_time_const_s"))),
        Box::new(WzKalman::new(wz0, p0).tuned_by(kf_tuning)),
        Box::new(QuaternionIntegration::new(q0, model).tuned_by(gyro_errors)),
    ];
    estimators.iter_mut().for_each(|e| e.apply_params(params));
    LabRun {
        truth: Box::new(truth),
        sensors: Box::new(sensors),
        estimators,
    }
}

impl Study for WzSphere {
    fn golden_assignments(&self) -> &'static [&'static str] {
        &["gyro_noise_deg_s=0.05"]
    }

    // The page never reproduces a paper (the CLI and the tests do): the `study` feature.
    #[cfg(feature = "study")]
    fn reproduce(&self) -> Result<crate::model::Reproduction, crate::model::ReproError> {
        Ok(reproduce::reproduce()?)
    }

    #[cfg(feature = "study")]
    fn chapter(&self) -> crate::model::Chapter {
        crate::model::lab_chapter!()
    }

    #[cfg(feature = "study")]
    fn timing_items(&self) -> Vec<crate::model::TimingItem> {
        reproduce::timing_items()
    }
}

/// The motion of the selected profile.
#[derive(Clone)]
enum Motion {
    Prescribed(EulerMotion),
    Free(Box<RigidBody>),
}

/// Truth: a prescribed Euler-angle motion or a free rigid body, plus the lateral bump.
#[derive(Clone)]
struct P3Truth {
    motion: Motion,
    t_s: f64,
    /// The state at `t_s` (computed once per step: the prescribed motion costs trig).
    state: TruthState,
}

/// The prescribed motion of profile `index` with the slider values in `p`.
pub fn motion_of(p: &ParamValues) -> Option<EulerMotion> {
    let deg = |k: &str| p.get(k).to_radians();
    let harmonic = |amp: f64, freq: f64, phase: f64| AngleProfile {
        amplitude_rad: amp,
        frequency_rad_s: freq,
        phase_rad: phase,
        ..AngleProfile::default()
    };
    let half_pi = std::f64::consts::FRAC_PI_2;
    match p.index("profile") {
        0 => Some(EulerMotion {
            yaw: AngleProfile {
                rate_rad_s: deg("yaw_rate_deg_s"),
                ..AngleProfile::default()
            },
            pitch: harmonic(deg("pitch_amp_deg"), p.get("pitch_freq_rad_s"), half_pi),
            roll: harmonic(deg("roll_amp_deg"), p.get("roll_freq_rad_s"), 0.0),
        }),
        1 => Some(EulerMotion {
            yaw: AngleProfile::default(),
            pitch: harmonic(deg("pitch_amp_deg"), p.get("pitch_freq_rad_s"), half_pi),
            roll: harmonic(deg("pitch_amp_deg"), p.get("pitch_freq_rad_s"), 0.0),
        }),
        2 => Some(EulerMotion {
            yaw: AngleProfile {
                rate_rad_s: deg("yaw_rate_deg_s"),
                ..AngleProfile::default()
            },
            pitch: harmonic(
                deg("pitch_amp_deg") * 0.3,
                p.get("pitch_freq_rad_s"),
                half_pi,
            ),
            roll: AngleProfile {
                rate_rad_s: deg("tumble_rate_deg_s"),
                ..AngleProfile::default()
            },
        }),
        _ => None,
    }
}

impl P3Truth {
    fn new(p: &ParamValues) -> Self {
        let motion = match motion_of(p) {
            Some(m) => Motion::Prescribed(m),
            None => {
                let q0 = crate::math::EulerYpr::new(0.0, 20f64.to_radians(), 10f64.to_radians())
                    .to_quaternion();
                let rate = Vector3::new(0.02, 1.0, 0.02).normalize() * 20f64.to_radians();
                Motion::Free(Box::new(RigidBody::new(
                    Vector3::new(1.0, 2.0, 3.0),
                    RigidBodyState {
                        q_ref_from_body: q0,
                        rate_body_rad_s: rate,
                    },
                )))
            }
        };
        let mut truth = Self {
            motion,
            t_s: 0.0,
            state: TruthState {
                t_s: 0.0,
                q_ref_from_body: nalgebra::UnitQuaternion::identity(),
                rate_body_rad_s: Vector3::zeros(),
                angle_rad: None,
                lab: LabData::default(),
            },
        };
        truth.state = truth.compute_state();
        truth
    }

    fn compute_state(&self) -> TruthState {
        let (q, w) = match &self.motion {
            Motion::Prescribed(m) => (m.attitude(self.t_s), m.body_rate_rad_s(self.t_s)),
            Motion::Free(b) => (b.state.q_ref_from_body, b.state.rate_body_rad_s),
        };
        TruthState {
            t_s: self.t_s,
            q_ref_from_body: q,
            rate_body_rad_s: w,
            angle_rad: None,
            lab: LabData::default(),
        }
    }
}

impl TruthModel for P3Truth {
    fn apply_params(&mut self, _params: &ParamValues) {}

    fn step(&mut self, dt_s: f64) {
        if let Motion::Free(body) = &mut self.motion {
            body.step(dt_s);
        }
        self.t_s += dt_s;
        self.state = self.compute_state();
    }

    fn state(&self) -> TruthState {
        self.state.clone()
    }
}

/// Gyro + accelerometer. The accelerometer measures n = f/g = k_body + A·a_ref/g + noise.
#[derive(Clone)]
struct GyroAccel {
    gyro: Gyro3,
    accel_sigma_g: f64,
    /// (peak g, time of peak s) of the lateral bump along the reference ξ axis.
    bump: (f64, f64),
}

impl SensorModel for GyroAccel {
    fn apply_params(&mut self, p: &ParamValues) {
        let b = p.get("gyro_bias_deg_s").to_radians();
        self.gyro.config = Gyro3Config {
            bias_rad_s: bias_pattern(p.index("bias_axes")) * b,
            noise_sigma_rad_s: p.get("gyro_noise_deg_s").to_radians(),
            ..Gyro3Config::default()
        };
        self.accel_sigma_g = p.get("accel_noise_g");
        self.bump = (p.get("bump_g"), p.get("bump_time_s"));
    }

    fn sample(&mut self, truth: &TruthState, dt_s: f64, rng: &mut ChaCha8Rng) -> Measurements {
        let gyro = self.gyro.sample(&truth.rate_body_rad_s, dt_s, rng);
        let (peak, t_peak) = self.bump;
        let a_ref_g = Vector3::new(peak * (-0.5 * (truth.t_s - t_peak).powi(2)).exp(), 0.0, 0.0);
        let noise = WhiteNoise {
            sigma: self.accel_sigma_g,
        };
        let specific_force = vertical_in_body(&truth.q_ref_from_body)
            + truth.q_ref_from_body.inverse_transform_vector(&a_ref_g);
        let accel = specific_force + Vector3::from_fn(|_, _| noise.sample(rng));
        Measurements {
            t_s: truth.t_s,
            gyro_body_rad_s: Some(gyro),
            accel_body_g: Some(accel),
            ..Measurements::default()
        }
    }
}
