//! The lesson of paper 4: one number γ = det Q / det R tunes the roll Kalman filter of an
//! asymmetric rig. Steps are data (see crate::page::Lesson); the Russian is in
//! this folder's ru.ftl.

use super::keys;
use super::plant::{U0_NEEDED_RAD_S2, U0_RAD_S2};
use crate::estimators::roll_kf;
use crate::model::{PlotTab, SeriesKey, q};
use crate::page::{CycleTerm, Lesson, LessonStep, Question, Quote, Reading};

/// The KF's roll error and its variance of θ (rad²).
const ROLL_ERROR: SeriesKey = SeriesKey::new("kf", &q::ANGLE_ERR_DEG);
const ROLL_VARIANCE: SeriesKey = SeriesKey::variance("kf", &roll_kf::STATE_THETA);
/// The rig at rest before the first step at 4 s, after the filter's first half second.
const AT_REST: (f64, f64) = (0.5, 4.0);

/// γ* of the paper, the value the steps compare with.
const GAMMA_STAR: &[(&str, f64)] = &[(keys::GAMMA, 2e-3)];

pub(super) static LESSON: Lesson = Lesson {
    title: "Paper 4: one number γ = det Q / det R tunes the Kalman filter of an asymmetric rig's roll",
    showcase: "small-gamma",
    steps: &[
        LessonStep {
            tab: Some(PlotTab::Figure("roll")),
            show: &["kf"],
            highlight: &["vibration_g"],
            speed: Some(1.0),
            pause_at_s: Some(8.0),
            tiles: &[SeriesKey::new("kf", &q::ANGLE_ERR_DEG)],
            quotes: &[
                Quote::paper("0°"),
                Quote::param("20°", "setpoint_deg"),
                Quote::param("4 s", "step_period_s"),
                Quote::param("0.2 g", "vibration_g"),
            ],
            ..LessonStep::new(
                "bench",
                "The bench of Fig. 3 and its filter",
                "The paper's bench of Fig. 3: a lever on a bearing with one motor and propeller, an MPU-6050 and an Arduino; the set-point steps between 0° and 20° every 4 s. \
                 The Kalman filter of eq. 5 estimates x = [θ, ω] from the accelerometer angle θ_acc = atan2(a_y, a_z) and the gyro rate, with the model x⁺ = Ax + Bu fed the controller's u_v. \
                 θ_acc is far noisier than the truth: the propellers shake the accelerometer by 0.2 g, our assumption, since the paper gives no noise at all. \
                 The filter's θ̂ follows the truth through it; the tile reads its roll error.",
            )
        },
        LessonStep {
            preset: Some("gamma-small"),
            tab: Some(PlotTab::Figure("roll-error")),
            terms: &[CycleTerm::ProcessNoise, CycleTerm::Gain],
            show: &["kf"],
            highlight: &[keys::GAMMA],
            speed: Some(1.0),
            pause_at_s: Some(8.0),
            tiles: &[SeriesKey::new("kf", &q::ANGLE_ERR_DEG)],
            question: Some(Question {
                ask: "γ = 10⁻⁵: the filter trusts its model far more than its sensors. What does its roll error look like after the step at 4 s?",
                answers: &[
                    "Noisy around zero",
                    "Smooth, but off by an offset and slow to settle",
                    "Zero: a trusted model is always right",
                ],
                answer: 1,
                why: "The model knows neither the gyro's 0.5 °/s offset nor what u_v leaves out, and it listens to the sensors slowly. Offset 0.67° against 0.57° at γ = 2·10⁻³; and the rig, which the controller drives by θ̂ as in Fig. 1, settles within 5 % of the step in 2.95 s against 1.6 s at 2·10⁻³.",
            }),
            quotes: &[
                Quote::param("4 s", "step_period_s"),
                Quote::param("0.5 °/s", "gyro_offset_deg_s"),
                Quote::run("0.67°", Reading::Lab("offset")),
                Quote::run_with("0.57°", GAMMA_STAR, Reading::Lab("offset")),
                Quote::paper("2·10⁻³"),
                Quote::paper("5 %"),
                Quote::run("2.95 s", Reading::Lab("settling")),
                Quote::run_with("1.6 s", GAMMA_STAR, Reading::Lab("settling")),
            ],
            ..LessonStep::new(
                "small-gamma",
                "Small γ: offset and a slow transient",
                "γ = det Q / det R is the filter's one tuning number (§3). \
                 R = diag(σ_θ², σ_ω²) from the datasheet stays fixed, and Q = q·diag(dt³/3, dt) is scaled until det Q = γ·det R, our mapping, since the paper gives none. \
                 A small γ means little process noise: the filter believes its model x⁺ = Ax + Bu more than each new measurement.",
            )
        },
        LessonStep {
            preset: Some("gamma-large"),
            tab: Some(PlotTab::Figure("roll-error")),
            show: &["kf"],
            highlight: &[keys::GAMMA],
            speed: Some(0.5),
            pause_at_s: Some(4.0),
            tiles: &[SeriesKey::new("kf", &q::ANGLE_ERR_DEG)],
            question: Some(Question {
                ask: "γ = 0.2 trusts the sensors. At rest before the step, is θ̂ − θ smoother or noisier than at γ = 2·10⁻³?",
                answers: &["Smoother", "Noisier", "The same"],
                answer: 1,
                why: "A large Q lets each noisy θ_acc through to θ̂: from one sample to the next θ̂ − θ jumps by 0.19° against 0.062° at γ = 2·10⁻³ (medians over five runs), and it wanders by up to 2.4°, 0.99° RMS in this run against 0.65°. Both lie far outside the ±3σ band of ±0.087°: the band is the filter's own belief, from the datasheet's R, which knows nothing of the 0.2 g vibration, so the filter is overconfident.",
            }),
            quotes: &[
                Quote::param("0.2", keys::GAMMA),
                Quote::paper("2·10⁻³"),
                Quote::run("0.19°", Reading::Lab("scatter")),
                Quote::run_with("0.062°", GAMMA_STAR, Reading::Lab("scatter")),
                Quote::run("2.4°", Reading::MaxAbs(ROLL_ERROR, AT_REST.0, AT_REST.1)),
                Quote::run("0.99°", Reading::Rms(ROLL_ERROR, AT_REST.0, AT_REST.1)),
                Quote::run_with(
                    "0.65°",
                    GAMMA_STAR,
                    Reading::Rms(ROLL_ERROR, AT_REST.0, AT_REST.1),
                ),
                Quote::run("±0.087°", Reading::SqrtAt(ROLL_VARIANCE, AT_REST.1))
                    .scaled(3.0 * 180.0 / std::f64::consts::PI),
                Quote::param("0.2 g", "vibration_g"),
                Quote::paper("0°"),
                Quote::param("4 s", "step_period_s"),
            ],
            ..LessonStep::new(
                "large-gamma",
                "Large γ: noise",
                "γ = 0.2 is the largest value of the paper's grid: much process noise, so the filter follows its measurements closely and is fast. \
                 Watch the roll error while the rig rests at 0° before the first step at 4 s.",
            )
        },
        LessonStep {
            preset: Some("gamma-best"),
            tab: Some(PlotTab::Figure("roll-error")),
            show: &["kf"],
            highlight: &[keys::GAMMA, "vibration_g"],
            speed: Some(1.0),
            pause_at_s: Some(16.0),
            sweep: Some("gamma"),
            tiles: &[SeriesKey::new("kf", &q::ANGLE_ERR_DEG)],
            quotes: &[
                Quote::paper("0.2"),
                Quote::paper("0.02"),
                Quote::param("2·10⁻³", keys::GAMMA),
                Quote::paper("0.3"),
                Quote::paper("0.7"),
                Quote::paper("0.5"),
                Quote::run("0.91", Reading::Lab("mse")),
                Quote::run_with("1.18", &[(keys::GAMMA, 0.02)], Reading::Lab("mse")),
                Quote::run_with("1.73", &[(keys::GAMMA, 0.2)], Reading::Lab("mse")),
                Quote::run("2·10⁻³", Reading::Lab("best-of-sweep")),
                Quote::run_with(
                    "0.2",
                    &[("vibration_g", 0.05)],
                    Reading::Lab("best-of-grid"),
                ),
                Quote::posed("0.05 g"),
                Quote::posed("0.4 g"),
                Quote::run_with(
                    "10⁻⁵",
                    &[("vibration_g", 0.4)],
                    Reading::Lab("best-of-grid"),
                ),
            ],
            ..LessonStep::new(
                "gamma-star",
                "γ* = 2·10⁻³ and the sweep",
                "Table 1 scores the grid γ = 0.2, 0.02, 2·10⁻³, 10⁻ⁿ by J = α·MSE + β·t_tr of eq. 6 for (α, β) = (0.3, 0.7), (0.7, 0.3) and (0.5, 0.5), with MSE over the errors of θ and ω. \
                 In the paper and here 2·10⁻³ wins for all three pairs: here its MSE is 0.91 against 1.18 to 1.73 deg² + (deg/s)² for the others. \
                 The γ sweep this step starts in the left panel runs 11 values of γ over 5 seeds; with this rig its finer grid finds 2·10⁻³ too. \
                 Where the best γ lies depends on the vibration, which the paper does not report: with 0.05 g the grid's best is 0.2, with 0.4 g it is 10⁻⁵.",
            )
        },
        LessonStep {
            preset: Some("fast-motion"),
            tab: Some(PlotTab::Figure("roll")),
            show: &["kf", "cf"],
            highlight: &["imu_offset_m", "bandwidth_rad_s"],
            speed: Some(1.0),
            pause_at_s: Some(8.0),
            tiles: &[
                SeriesKey::new("kf", &q::ANGLE_ERR_DEG),
                SeriesKey::new("cf", &q::ANGLE_ERR_DEG),
            ],
            quotes: &[
                Quote::param("12 rad/s", "bandwidth_rad_s"),
                Quote::param("40°", "setpoint_deg"),
                Quote::param("0.25 m", "imu_offset_m"),
                Quote::param("0.98", keys::CF_GAIN),
            ],
            ..LessonStep::new(
                "fast-motion",
                "Fast motion fools the accelerometer",
                "Now ω_c = 12 rad/s, the steps are 40° and the IMU sits 0.25 m from the pivot. \
                 Besides gravity the accelerometer feels the rig's own motion, rθ̈ across the lever and rθ̇² towards the pivot, so θ_acc = atan2(a_y, a_z) swings away from θ in every step, though it is right on average at rest. \
                 Both filters weigh θ_acc against the gyro and follow its swings only in part: the Kalman filter through its model, the complementary filter θ ← a(θ + ω dt) + (1 − a)θ_acc through its gain a = 0.98.",
            )
        },
        LessonStep {
            preset: Some("asymmetric"),
            tab: Some(PlotTab::Figure("control")),
            highlight: &["rig", "asymmetry_pct"],
            speed: Some(1.0),
            pause_at_s: Some(8.0),
            tiles: &[
                SeriesKey::truth(&U0_RAD_S2),
                SeriesKey::truth(&U0_NEEDED_RAD_S2),
            ],
            question: Some(Question {
                ask: "The quadrotor's arms and motors differ, and the controller commands equal hover thrusts. What constant command u₀ does the integral hold?",
                answers: &[
                    "0 rad/s², as for the symmetric quadrotor of eq. 3",
                    "A constant u₀ ≠ 0, the one hover needs",
                ],
                answer: 1,
                why: "Unequal arms and thrust gains turn equal thrusts into a roll torque, so θ̈₀ ≠ 0 at equilibrium. The rate loop's integral holds exactly the u₀ that cancels it, and u_v stays zero-mean; choose the symmetric rig and u₀ = 0.",
            }),
            quotes: &[
                Quote::param("15 %", "asymmetry_pct"),
                Quote::posed("0 rad/s²"),
            ],
            ..LessonStep::new(
                "asymmetric-u0",
                "The asymmetric quadrotor's u₀",
                "The rig is now a quadrotor whose arms differ by a = 15 % and whose thrust gains differ by a/4, our version of eq. 2. \
                 Eq. 4 only bounds the u₀ that holds it, between f(ω_max, l_min, J_max) and f(ω_min, l_max, J_min), because the geometry is uncertain. \
                 The nested P–PI of Fig. 1 needs no value: its integral finds u₀, and the filter is fed the zero-mean rest u_v. \
                 The plot shows u_v, the integral's u₀ and the u₀ hover needs.",
            )
        },
    ],
};
