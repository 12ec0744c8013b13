//! Lab "p4": paper 4 — a Kalman filter for the roll of an asymmetric quadrotor, tuned by
//! one number γ = det Q / det R (Pham, Shilin, Girnik, Nguyen, Inzhenernyj vestnik Dona
//! 2025). The paper gives the method, the γ grid and Table 1 but no plant numbers; every
//! number here that is not the paper's is marked "ours" in the help and the README.

pub mod keys;
mod lesson;
#[cfg(feature = "study")]
mod lesson_readings;
mod mpu6050;
mod mse_units;
mod plant;
mod reproduce;
mod tuning;
mod u0_range;

use crate::estimators::roll_kf;
use crate::estimators::{ComplementaryRoll, RollInput, RollKf, RollTuning};
use crate::model::{
    Estimator, ExampleLog, LabRun, LabSpec, ParamSpec, ParamValues, Preset, SeriesKey, Study,
    SweepSpec, q,
};
use crate::page::{Figure, Lab, Page, SINGLE_AXIS_VIEWS};
use mpu6050::{ACCEL_RANGES, GYRO_RANGES, Mpu6050, sample_sigma};
use plant::{CONTROLLERS, Plant, RIGS};
use rand_chacha::ChaCha8Rng;

pub use reproduce::{GammaScore, score_gamma, score_gamma_with};
pub use tuning::{PAIRS, SCORE_NAMES, score_run};

/// The paper-4 lab.
pub struct QuadrotorRoll;

const PARAMS: &[ParamSpec] = &[
    ParamSpec::choice("rig", "Rig", RIGS, 0).on_reset().help("The paper's test bench (a lever with one motor, Fig. 3) or a quadrotor's roll axis with four motors (eq. 2), asymmetric or symmetric (eq. 3)."),
    ParamSpec::real("asymmetry_pct", "Asymmetry a", "%", 0.0, 40.0, 15.0).requires("rig").help("Quadrotor (ours): arms differ by a, thrust gains by a/4, so equal hover thrusts make a roll torque and u₀ ≠ 0."),
    ParamSpec::real(u0_range::UNCERTAINTY_PCT, "Geometry known to ±", "%", 0.0, 30.0, 5.0).outside_run().help("Eq. 4: the arms, the thrusts and the inertia are known only within an interval, so is the u₀ that holds the rig level (ours: ±5 %)."),
    ParamSpec::real("lever_torque_n_m", "Lever weight torque M_g", "N·m", 0.0, 0.2, 0.05).help("Test bench (ours): the lever's weight about the bearing; holding it needs a constant thrust (u₀ = M_g/J)."),
    ParamSpec::real("motor_tau_s", "Motor lag T", "s", 0.005, 0.2, 0.04).log().help("1/(1 + T s) on each thrust (Fig. 1)."),
    ParamSpec::choice(plant::LOOP_KEY, "Controller acts on", plant::LOOP_NAMES, 0).help("Fig. 1 closes the loop on the KF's estimate, so a noisy or lagging θ̂ moves the rig itself; on the truth the rig's motion is the same whatever the filters do, and they are compared on one motion."),
    ParamSpec::choice("controller", "Controller", CONTROLLERS, 0).help("Fig. 1's nested P–PI, whose rate integral absorbs u₀ so the filter is fed the zero-mean u_v, or a plain PID."),
    ParamSpec::real("bandwidth_rad_s", "Controller bandwidth ω_c", "rad/s", 1.0, 20.0, 5.0).log().help("Poles at ω_c (ours): the transient time is a few 1/ω_c."),
    ParamSpec::real("setpoint_deg", "Set-point step", "°", 0.0, 60.0, 20.0).help("A square wave between 0 and this angle."),
    ParamSpec::real("step_period_s", "Steps every", "s", 1.0, 20.0, 4.0),
    ParamSpec::real("gust_rad_s2", "Gust / push", "rad/s²", -300.0, 300.0, 0.0).help("An angular-acceleration pulse of 0.1 s."),
    ParamSpec::real("gust_at_s", "Gust at", "s", 1.0, 60.0, 6.0).requires("gust_rad_s2"),
    ParamSpec::real("sample_hz", "Sample rate", "Hz", 20.0, 1000.0, 100.0).log().on_reset().help("The Arduino's loop rate (ours: 100 Hz); the filters run at it."),
    ParamSpec::real("dlpf_hz", "MPU-6050 DLPF bandwidth", "Hz", 5.0, 260.0, 44.0).log().help("The chip's digital low-pass filter: the noise of a sample grows with √bandwidth."),
    ParamSpec::choice("gyro_range", "Gyro full scale", GYRO_RANGES, 0),
    ParamSpec::choice("accel_range", "Accelerometer full scale", ACCEL_RANGES, 0),
    ParamSpec::real("gyro_density_deg_s", "Gyro noise density", "°/s/√Hz", 0.0, 0.05, 0.005).help("Datasheet: 0.005 °/s/√Hz."),
    ParamSpec::real("accel_density_ug", "Accelerometer noise density", "µg/√Hz", 0.0, 2000.0, 400.0).help("Datasheet: 400 µg/√Hz."),
    ParamSpec::real("vibration_g", "Propeller vibration at the IMU", "g", 0.0, 1.0, 0.2).help("Ours: the motors shake the accelerometer (RMS per axis); the datasheet noise alone is far smaller. It decides where the best γ lies: 0.2 g puts it at the paper's 2·10⁻³, a quieter rig favours larger γ."),
    ParamSpec::real("gyro_offset_deg_s", "Gyro zero-rate offset", "°/s", -20.0, 20.0, 0.5).help("Datasheet: up to ±20 °/s before calibration; what is left after a start-up calibration (ours: 0.5)."),
    ParamSpec::real("imu_offset_m", "IMU distance from the pivot", "m", 0.0, 0.3, 0.1).help("The accelerometer feels rθ̈ and rθ̇² besides gravity, so its angle is wrong during fast motion."),
    ParamSpec::real(keys::GAMMA, "γ = det Q / det R", "", 1e-8, 10.0, 2e-3).log().help("Small γ trusts the model (smooth, but an offset and a slow transient); large γ trusts the sensors (noisy). Paper's optimum: 2·10⁻³. Q = q·diag(dt³/3, dt) with q set so det Q = γ det R (ours)."),
    ParamSpec::choice(keys::Q_FROM, "KF's Q from", Q_FROM, 0).help("γ (the paper, with this project's mapping) or two elements set by hand (beyond the paper: the Q landscape sweep walks across lines of constant γ)."),
    ParamSpec::real(keys::Q_ANGLE, "Q angle element q_θ", "deg²", 1e-10, 1e-2, 2e-6).log().requires(keys::Q_FROM).help("Per step; γ* with the γ mapping is q_θ ≈ 2·10⁻⁶ deg²."),
    ParamSpec::real(keys::Q_RATE, "Q rate element q_ω", "(deg/s)²", 1e-6, 100.0, 0.06).log().requires(keys::Q_FROM).help("Per step; γ* with the γ mapping is q_ω ≈ 0.06 (deg/s)²."),
    ParamSpec::toggle(keys::INPUT, "Feed u_v to the KF", true).help("The paper's model x⁺ = Ax + Bu with the zero-mean u_v of the P–PI split."),
    ParamSpec::real(keys::SIGMA_ANGLE, "KF's R: accelerometer-angle σ", "°", 0.01, 5.0, 0.19).log().help("R = diag(σ_θ², σ_ω²), fixed while γ moves; the datasheet values at 44 Hz are 0.19° and 0.04 °/s."),
    ParamSpec::real(keys::SIGMA_RATE, "KF's R: gyro σ", "°/s", 0.005, 5.0, 0.04).log(),
    ParamSpec::real(keys::BIAS_WALK, "Bias KF: bias random walk", "°/s/√s", 1e-4, 1.0, 0.01).log().help("Beyond the paper: the [θ, ω, b] filter's bias process noise."),
    ParamSpec::real(keys::CF_GAIN, "Complementary gain a", "", 0.5, 0.999, 0.98).help("θ ← a(θ + ω dt) + (1 − a)θ_acc (ours: 0.98, τ ≈ 0.5 s at 100 Hz)."),
];

const Q_FROM: &[&str] = &["γ (the paper)", "two elements"];

const FIGURES: &[Figure] = &[
    Figure::new(
        "roll",
        "Roll: truth, set-point, accelerometer angle and estimates",
        &[
            SeriesKey::truth(&q::ANGLE_DEG),
            SeriesKey::truth(&plant::SETPOINT_DEG),
            SeriesKey::sensors(&mpu6050::ACCEL_ANGLE_DEG),
            SeriesKey::new("kf", &q::ANGLE_DEG),
            SeriesKey::new("cf", &q::ANGLE_DEG),
            SeriesKey::new("kf-bias", &q::ANGLE_DEG),
            SeriesKey::new("kf-u0", &q::ANGLE_DEG),
        ],
    ),
    Figure::new(
        "roll-error",
        "Roll error of each filter",
        &[
            SeriesKey::new("kf", &q::ANGLE_ERR_DEG),
            SeriesKey::new("cf", &q::ANGLE_ERR_DEG),
            SeriesKey::new("kf-bias", &q::ANGLE_ERR_DEG),
            SeriesKey::new("kf-u0", &q::ANGLE_ERR_DEG),
        ],
    ),
    Figure::new(
        "rate-error",
        "Rate error of each filter",
        &[
            SeriesKey::new("kf", &q::RATE_ERR_DEG_S),
            SeriesKey::new("cf", &q::RATE_ERR_DEG_S),
            SeriesKey::new("kf-bias", &q::RATE_ERR_DEG_S),
            SeriesKey::new("kf-u0", &q::RATE_ERR_DEG_S),
        ],
    ),
    Figure::new(
        "control",
        "Control: u_v, the integral's u₀ and the u₀ hover needs",
        &[
            SeriesKey::truth(&plant::U_V_RAD_S2),
            SeriesKey::truth(&plant::U0_RAD_S2),
            SeriesKey::truth(&plant::U0_NEEDED_RAD_S2),
        ],
    ),
    Figure::new(
        "gyro",
        "Gyro: reading and truth",
        &[
            SeriesKey::sensors(&mpu6050::GYRO_DEG_S),
            SeriesKey::truth(&q::RATE_DEG_S),
        ],
    ),
    Figure::new(
        "bias-kf",
        "Bias KF (beyond the paper): gyro-bias estimate",
        &[SeriesKey::new("kf-bias", &roll_kf::GYRO_BIAS_DEG_S)],
    ),
];

const PRESETS: &[Preset] = &[
    Preset {
        id: "gamma-best",
        name: "γ = 2·10⁻³: best of the paper's four values",
        help: "The argmin of J over the four γ of the paper's Table 1 (here too, for all three (α, β)). The page's γ sweep tries 11 values and finds 2·10⁻³ too with our rig and vibration",
        values: &[(keys::GAMMA, 2e-3)],
    },
    Preset {
        id: "gamma-small",
        name: "γ = 10⁻⁵: offset, slow",
        help: "The filter trusts its model: smooth, but behind in the steps and off by the gyro offset",
        values: &[(keys::GAMMA, 1e-5)],
    },
    Preset {
        id: "gamma-large",
        name: "γ = 0.2: noisy",
        help: "The filter trusts the sensors: fast, and it passes their noise",
        values: &[(keys::GAMMA, 0.2)],
    },
    Preset {
        id: "asymmetric",
        name: "quadrotor, asymmetric 15 %",
        help: "Four motors whose arms and thrusts differ: the integral holds u₀ ≠ 0 (Reset)",
        values: &[("rig", 2.0), ("asymmetry_pct", 15.0)],
    },
    Preset {
        id: "fast-motion",
        name: "fast motion fools the accelerometer",
        help: "A fast controller, big steps, the IMU far from the pivot: the accelerometer angle is wrong in every step",
        values: &[
            ("bandwidth_rad_s", 12.0),
            ("setpoint_deg", 40.0),
            ("imu_offset_m", 0.25),
        ],
    },
    Preset {
        id: "push",
        name: "push at 6 s",
        help: "A 0.1-s angular-acceleration pulse: the controller recovers, the filters follow",
        values: &[("gust_rad_s2", 200.0), ("gust_at_s", 6.0)],
    },
    Preset {
        id: "uncalibrated-gyro",
        name: "uncalibrated gyro (5 °/s offset)",
        help: "A large zero-rate offset: the paper's KF drifts off, the bias KF learns it",
        values: &[("gyro_offset_deg_s", 5.0)],
    },
];

/// The filters' settings in `p`: γ, the input switch, R's σ, the bias walk, and Q element
/// by element when the lab is set to.
pub fn tuning_of(p: &ParamValues) -> RollTuning {
    let deg2 = std::f64::consts::PI.powi(2) / 180f64.powi(2);
    RollTuning {
        gamma: p.get(keys::GAMMA),
        input_on: p.flag(keys::INPUT),
        sigma_angle_rad: p.get(keys::SIGMA_ANGLE).to_radians(),
        sigma_rate_rad_s: p.get(keys::SIGMA_RATE).to_radians(),
        bias_walk: p.get(keys::BIAS_WALK).to_radians(),
        q_elements: p
            .flag(keys::Q_FROM)
            .then(|| [p.get(keys::Q_ANGLE) * deg2, p.get(keys::Q_RATE) * deg2]),
    }
}

/// The datasheet σ of one sample at `p`'s DLPF: (accelerometer angle °, gyro °/s).
pub fn datasheet_sigmas(p: &ParamValues) -> (f64, f64) {
    let bw = p.get("dlpf_hz");
    (
        sample_sigma(p.get("accel_density_ug") * 1e-6, bw).to_degrees(),
        sample_sigma(p.get("gyro_density_deg_s"), bw),
    )
}

const SPEC: LabSpec = LabSpec {
    id: "p4",
    title: "Paper 4: quadrotor roll, KF tuned by γ = det Q/det R",
    paper: "Pham, Shilin, Girnik, Nguyen, Kalman filter synthesis for an asymmetric quadrotor, Inzhenernyj vestnik Dona 2025 No. 10",
    reference: "Pham Trong H., Shilin A. A., Girnik A. S., Nguyen M. T. Synthesis of a Kalman filter for the control of an asymmetric quadcopter with optimization of the ratio of the covariance matrices. Inzhenernyj vestnik Dona, 2025, no. 10, article 10456 (in Russian).",
    summary: "A rig rolls about one axis: the paper's test bench (a lever on a bearing with one motor, \
         Fig. 3) or a quadrotor whose arms and motors differ (eq. 2), so that holding any angle \
         needs a constant command u₀ ≠ 0. The controller — the nested P–PI of Fig. 1, or a plain \
         PID — splits its command into the integral's u₀ and a zero-mean u_v. An MPU-6050 (datasheet \
         noise, zero-rate offset, 16-bit counts, full-scale ranges) measures the rate and, through \
         atan2 of its accelerometer, an angle that is wrong while the rig moves fast. The paper's \
         Kalman filter on [θ, ω] is fed u_v and tuned by one number, γ = det Q / det R: small γ \
         trusts the model (smooth, but an offset and a slow transient), large γ the sensors \
         (noisy). Beside it a complementary filter (the baseline the paper names) and, beyond the \
         paper, a KF with a gyro-bias state and one that knows u₀. The paper gives no plant \
         numbers: the lever (J = 2·10⁻³ kg·m², arm 0.2 m), the quadrotor (J = 0.01 kg·m², arms \
         0.12 m, hover 2.45 N per motor), the 100-Hz loop, the controller gains, the γ → Q mapping \
         (Q = q·diag(dt³/3, dt), det Q = γ det R, R from the datasheet) and the 5 % band of the \
         transient time are ours. As in Fig. 1 the controller acts on the γ-tuned KF's θ̂, so a \
         noisy or lagging estimate moves the rig; switch it to the truth to compare every filter on \
         one motion. The sweeps below run the paper's tuning experiment: J = α·MSE + β·t_tr against \
         γ for its three (α, β) pairs (5 seeds, medians, argmin ringed), the Q landscape over two \
         elements of Q with the γ lines on it, and, while a log is replayed, the γ sweep on the \
         log. `attlab reproduce p4` measures Table 1.",
    params: PARAMS,
    presets: PRESETS,
    default_duration_s: 16.0,
    words: crate::model::lab_words!(en),
};

const PAGE: Page = Page {
    figures: FIGURES,
    views: SINGLE_AXIS_VIEWS,
    log_format: Some(&crate::sensors::IMU_LOG),
    // Synthetic (assets/make_p4_log.py): a lever's 20° steps with datasheet noise and a
    // 0.5 °/s gyro offset, in raw counts.
    example_log: Some(ExampleLog {
        name: "p4-arduino-mpu6050.csv",
        text: include_str!("../../../../assets/p4-arduino-mpu6050.csv"),
        units: &[],
    }),
    ..Page::DEFAULT
};

impl Lab for QuadrotorRoll {
    fn lesson(&self) -> Option<&'static crate::page::Lesson> {
        Some(&lesson::LESSON)
    }
    fn spec(&self) -> &'static LabSpec {
        &SPEC
    }

    fn dt_s(&self, p: &ParamValues) -> f64 {
        1.0 / p.get("sample_hz")
    }

    fn build(&self, p: &ParamValues, _rng: &mut ChaCha8Rng) -> LabRun {
        let t = tuning_of(p);
        let mut estimators: Vec<Box<dyn Estimator>> = vec![
            Box::new(
                RollKf::<2>::new(
                    "kf",
                    "KF [θ, ω] tuned by γ (the paper)",
                    RollInput::PaperSwitch,
                    t,
                )
                .tuned_by(tuning_of),
            ),
            Box::new(
                ComplementaryRoll::new(p.get(keys::CF_GAIN)).tuned_by(|p| p.get(keys::CF_GAIN)),
            ),
            Box::new(
                RollKf::<3>::new(
                    "kf-bias",
                    "Beyond the paper: KF [θ, ω, b]",
                    RollInput::PaperSwitch,
                    t,
                )
                .tuned_by(tuning_of),
            ),
            Box::new(
                RollKf::<2>::new(
                    "kf-u0",
                    "Beyond the paper: KF fed u_v + u₀",
                    RollInput::WithConstant,
                    t,
                )
                .tuned_by(tuning_of),
            ),
        ];
        estimators.iter_mut().for_each(|e| e.apply_params(p));
        LabRun {
            truth: Box::new(Plant::new(p)),
            sensors: Box::new(Mpu6050::new(p)),
            estimators,
        }
    }

    fn param_notes(&self, params: &ParamValues) -> Vec<crate::page::ParamNote> {
        vec![u0_range::note(params)]
    }

    fn page(&self) -> &'static Page {
        &PAGE
    }

    fn study(&self) -> Option<&dyn Study> {
        Some(self)
    }
}

impl Study for QuadrotorRoll {
    // The page never reproduces a paper (the CLI and the tests do): the `study` feature.
    #[cfg(feature = "study")]
    fn reproduce(&self) -> Result<crate::model::Reproduction, crate::model::ReproError> {
        Ok(reproduce::reproduce()?)
    }

    #[cfg(feature = "study")]
    fn chapter(&self) -> crate::model::Chapter {
        crate::model::lab_chapter!()
    }

    fn sweeps(&self) -> &'static [SweepSpec] {
        tuning::SWEEPS
    }

    #[cfg(feature = "study")]
    fn lesson_reading(
        &self,
        name: &str,
        params: &ParamValues,
        _seed: u64,
    ) -> Option<Result<f64, crate::model::ReadingError>> {
        lesson_readings::reading(name, params)
    }
}
