//! The lesson of paper 3: the vertical as w = u + jv on the Riemann sphere, the gyro's drift,
//! the accelerometers' noise and their blend. Steps are data (see crate::page::Lesson); the
//! Russian is in this folder's ru.ftl.

use crate::estimators::wz_kalman;
use crate::model::{PlotTab, SeriesKey, q};
use crate::page::{Lesson, LessonStep, Question, Quote, Reading};

/// The (u, v, z) integration's and the truth's `quantity`.
const fn uvz_and_truth(quantity: &'static crate::model::Quantity) -> (SeriesKey, SeriesKey) {
    (
        SeriesKey::new("uvz-rk4", quantity),
        SeriesKey::truth(quantity),
    )
}

/// A tilt error over [5 s, 100 s], after the blend's first time constants.
const fn tilt_rms(source: &'static str) -> Reading {
    Reading::Rms(SeriesKey::new(source, &q::TILT_ERR_DEG), 5.0, 100.0)
}

pub(super) static LESSON: Lesson = Lesson {
    title: "Paper 3: the vertical as w = u + jv on the Riemann sphere, and the gyro blended with the accelerometers",
    showcase: "upside-down",
    steps: &[
        LessonStep {
            set: &[("gyro_bias_deg_s", 0.0)],
            tab: Some(PlotTab::Figure("fig5-angles")),
            show: &["uvz-rk4"],
            speed: Some(10.0),
            pause_at_s: Some(100.0),
            tiles: &[SeriesKey::new("uvz-rk4", &q::ERR_DEG)],
            quotes: &[
                Quote::param("1 °/s", "yaw_rate_deg_s"),
                Quote::param("30°", "pitch_amp_deg"),
                Quote::param("25°", "roll_amp_deg"),
                Quote::param("0.05 rad/s", "pitch_freq_rad_s"),
                Quote::param("0.05 rad/s", "roll_freq_rad_s"),
                Quote::param("0 °/s", "gyro_bias_deg_s"),
                Quote::paper("15°"),
                Quote::run("100°", Reading::At(SeriesKey::truth(&q::YAW_DEG), 100.0)).about(0.01),
                Quote::run(
                    "30°",
                    Reading::MaxAbs(SeriesKey::truth(&q::PITCH_DEG), 0.0, 100.0),
                ),
                Quote::run(
                    "25°",
                    Reading::MaxAbs(SeriesKey::truth(&q::ROLL_DEG), 0.0, 100.0),
                ),
            ],
            ..LessonStep::new(
                "fig5-euler",
                "Eq. 21 reproduces Fig. 5",
                "The paper's motion (§5): yaw ψ = ω_ψ·t with ω_ψ = 1 °/s, pitch ϑ = A_ϑ·cos ω_ϑt and roll γ = A_γ·sin ω_γt with A_ϑ = 30°, A_γ = 25°, ω_ϑ = ω_γ = 0.05 rad/s. \
                 The gyro is perfect here (bias 0 °/s): the (u, v, z) integration solves eq. 21 from u₀ = 0, v₀ = tan 15°, z₀ = 0, and eqs. 23–25 turn (u, v, z) back into ψ, ϑ, γ. \
                 Its curves lie on the truth's: yaw ramps to 100°, pitch swings ±30° and roll ±25°, as in Fig. 5. \
                 Three parameters carry the whole attitude, one fewer than the quaternion's four.",
            )
        },
        LessonStep {
            set: &[("gyro_bias_deg_s", 0.0), ("pitch_amp_deg", 89.0)],
            tab: Some(PlotTab::Figure("fig4-uv")),
            show: &["uvz-rk4"],
            highlight: &["pitch_amp_deg"],
            speed: Some(10.0),
            pause_at_s: Some(62.8),
            tiles: &[SeriesKey::new("uvz-rk4", &q::ERR_DEG)],
            quotes: &[
                Quote::paper("90°"),
                Quote::param("89°", "pitch_amp_deg"),
                Quote::run("89°", Reading::At(SeriesKey::truth(&q::PITCH_DEG), 0.0)),
                Quote::paper("0 s"),
                Quote::run("−89°", Reading::At(SeriesKey::truth(&q::PITCH_DEG), 62.8)),
                Quote::pause("62.8 s"),
            ],
            ..LessonStep::new(
                "pitch-90",
                "Pitch near 90°: trouble for Euler, not for w",
                "At ϑ = ±90° the Euler angles lock: yaw and roll turn about the same axis and eq. 25 becomes 0/0. \
                 For w it is only c′ = 0, the unit circle |w| = 1 by eq. 13, an ordinary point of eq. 21. \
                 With A_ϑ = 89° (the slider's end) pitch reaches +89° at 0 s and −89° at 62.8 s: v comes close to ±1 in Fig. 4 and the path on the w plane touches the unit circle. \
                 The integration goes through as if nothing happened.",
            )
        },
        LessonStep {
            set: &[("profile", 2.0)],
            tab: Some(PlotTab::Figure("fig4-uv")),
            show: &["uvz-rk4", "quat-rk4"],
            highlight: &["profile", "tumble_rate_deg_s"],
            speed: Some(3.0),
            pause_at_s: Some(30.0),
            tiles: &[
                SeriesKey::truth(&q::K_Z),
                SeriesKey::new("uvz-rk4", &q::ERR_DEG),
                SeriesKey::new("quat-rk4", &q::ERR_DEG),
            ],
            question: Some(Question {
                ask: "The slow tumble rolls at 6 °/s, so at 30 s the body is upside down: c′ = −1 and w = (a′ + jb′)/(1 + c′) goes to infinity. What does the (u, v, z) integration do?",
                answers: &[
                    "It blows up at w = ∞",
                    "It switches to s = 1/w and stays as accurate as the quaternion",
                    "It stops until the body turns back",
                ],
                answer: 1,
                why: "Turned 180° about ξ′, the body sees the same eq. 21 for s = 1/w, projected from the north pole (an addition to the paper). Over this 100-s tumble its attitude error differs from the quaternion's by 6·10⁻¹³ ° at most.",
            }),
            quotes: &[
                Quote::run(
                    "3.7",
                    Reading::LastFinite(SeriesKey::new("uvz-rk4", &q::V), 30.0),
                ),
                Quote::run("1.3", Reading::LastFinite(SeriesKey::truth(&q::V), 30.0)),
                Quote::run(
                    "3.7°",
                    Reading::At(SeriesKey::new("uvz-rk4", &q::ERR_DEG), 30.0),
                ),
                Quote::param("6 °/s", "tumble_rate_deg_s"),
                Quote::pause("30 s"),
                Quote::paper("90°"),
                Quote::paper("180°"),
                Quote::run(
                    "6·10⁻¹³ °",
                    Reading::MaxAbsDiff(
                        SeriesKey::new("uvz-rk4", &q::ERR_DEG),
                        SeriesKey::new("quat-rk4", &q::ERR_DEG),
                        0.0,
                        100.0,
                    ),
                )
                .about(0.5),
                Quote::param("0.1 °/s", "gyro_bias_deg_s"),
            ],
            ..LessonStep::new(
                "upside-down",
                "Upside down: w = ∞",
                "The projection from the south pole S in eq. 12 sends the vertical pointing to S, c′ = −1, to w = ∞; the terms uω_ξ + vω_η of ż grow without bound. \
                 Watch the sphere and the w plane as the roll passes 90° (|w| = 1) and 180°: the plane's caption names the chart each filter is in. \
                 In Fig. 4 u and v run off the plot while |w| is large, and there a small attitude error is a large one in w: at the pause the estimate's v is 3.7 against the truth's 1.3, with its attitude only 3.7° off. \
                 The tiles read the true c′ and the attitude errors of (u, v, z) and of the quaternion, both carrying the gyro's 0.1 °/s bias.",
            )
        },
        LessonStep {
            tab: Some(PlotTab::Figure("fig8-v")),
            show: &["uvz-rk4"],
            highlight: &["gyro_bias_deg_s", "bias_axes"],
            speed: Some(10.0),
            pause_at_s: Some(100.0),
            tiles: &[SeriesKey::new("uvz-rk4", &q::TILT_ERR_DEG)],
            question: Some(Question {
                ask: "The gyro has the paper's zero offset, 0.1 °/s on all three axes. How large is the gyro-only tilt error at 100 s?",
                answers: &["Below 1°", "Between 5° and 20°", "Above 45°"],
                answer: 1,
                why: "Eq. 21 integrates the offset with the rates and nothing pulls it back: 0.1 °/s for 100 s is 10° per axis. The run ends 11.2° off, with v off by 0.104 and z by 5.65°.",
            }),
            quotes: &[
                Quote::param("0.1 °/s", "gyro_bias_deg_s"),
                Quote::posed("1°"),
                Quote::posed("5°"),
                Quote::posed("20°"),
                Quote::posed("45°"),
                Quote::pause("100 s"),
                Quote::paper("10°"),
                Quote::run(
                    "11.2°",
                    Reading::At(SeriesKey::new("uvz-rk4", &q::TILT_ERR_DEG), 100.0),
                ),
                Quote::run("0.104", {
                    let (est, truth) = uvz_and_truth(&q::V);
                    Reading::MaxAbsDiff(est, truth, 100.0, 100.0)
                }),
                Quote::run("5.65°", {
                    let (est, truth) = uvz_and_truth(&q::Z_DEG);
                    Reading::MaxAbsDiff(est, truth, 100.0, 100.0)
                }),
            ],
            ..LessonStep::new(
                "gyro-drift",
                "The gyro channel drifts",
                "Now the gyro reads the true rate plus 0.1 °/s on every axis (the paper does not say which axes; the lab assumes all three, positive). \
                 In Fig. 8 v of the gyro channel leaves the truth, and on the w plane its path creeps away, as in Fig. 7. \
                 The tile reads the tilt error: the angle between the true and the estimated vertical, pitch and roll together.",
            )
        },
        LessonStep {
            tab: Some(PlotTab::Figure("fig8-v")),
            show: &["uvz-rk4", "accel"],
            highlight: &["accel_noise_g", "bump_g"],
            speed: Some(10.0),
            pause_at_s: Some(100.0),
            tiles: &[
                SeriesKey::new("uvz-rk4", &q::TILT_ERR_DEG),
                SeriesKey::new("accel", &q::TILT_ERR_DEG),
            ],
            quotes: &[
                Quote::param("0.01 g", "accel_noise_g"),
                Quote::run(
                    "0.0053",
                    Reading::RmsDiff(
                        SeriesKey::new("accel", &q::V),
                        SeriesKey::truth(&q::V),
                        0.5,
                        100.0,
                    ),
                ),
                Quote::run(
                    "0.81°",
                    Reading::Rms(SeriesKey::new("accel", &q::TILT_ERR_DEG), 0.5, 100.0),
                ),
            ],
            ..LessonStep::new(
                "accel-noise",
                "The accelerometers are noisy, not drifting",
                "At rest the accelerometers measure the vertical itself: n = f/g is the third column of A by eq. 27, so uᵃ = n_ξ/(1 + n_ζ) and vᵃ = n_η/(1 + n_ζ) of eq. 28 need no integration and cannot drift. \
                 But every reading carries noise, σ = 0.01 g as in the paper: vᵃ is a noisy band around the truth in Fig. 8 and a cloud on the w plane. \
                 Near the level attitude 1 + n_ζ ≈ 2, so the noise of uᵃ and vᵃ is about σ/(1 + c′): 0.0053 rms in this run, a tilt error of 0.81° rms. \
                 A lateral acceleration (the bump slider) enters n exactly like a tilt.",
            )
        },
        LessonStep {
            tab: Some(PlotTab::Figure("fig10-filters")),
            show: &["uvz-rk4", "accel", "blend"],
            highlight: &["blend_time_const_s"],
            speed: Some(10.0),
            pause_at_s: Some(100.0),
            tiles: &[
                SeriesKey::new("uvz-rk4", &q::TILT_ERR_DEG),
                SeriesKey::new("accel", &q::TILT_ERR_DEG),
                SeriesKey::new("blend", &q::TILT_ERR_DEG),
            ],
            question: Some(Question {
                ask: "The blend adds the gyro channel after a high-pass filter and the accelerometer channel after a low-pass filter. How does its tilt error compare with the two channels'?",
                answers: &[
                    "Between the two",
                    "Below both: no drift and much less noise",
                    "Worse than both",
                ],
                answer: 1,
                why: "HPF removes the gyro channel's slow drift and LPF the accelerometers' fast noise. After 5 s its tilt error is 0.13° rms against the accelerometers' 0.81°, and 0.065° at 100 s against the gyro's 11.2°.",
            }),
            quotes: &[
                Quote::param("1 s", "blend_time_const_s"),
                Quote::paper("5 s"),
                Quote::run("0.13°", tilt_rms("blend")),
                Quote::run("0.81°", tilt_rms("accel")),
                Quote::run(
                    "0.065°",
                    Reading::At(SeriesKey::new("blend", &q::TILT_ERR_DEG), 100.0),
                ),
                Quote::pause("100 s"),
                Quote::run(
                    "11.2°",
                    Reading::At(SeriesKey::new("uvz-rk4", &q::TILT_ERR_DEG), 100.0),
                ),
            ],
            ..LessonStep::new(
                "fig9-blend",
                "The blend of Fig. 9",
                "Fig. 9 blends the channels: uᵏ = HPF(u) + LPF(uᵃ) and vᵏ = HPF(v) + LPF(vᵃ), with W_HPF = Ts/(Ts + 1), W_LPF = 1/(Ts + 1) and T = 1 s. \
                 The gyro channel is right over short times, the accelerometer channel on average; since HPF + LPF = 1, the truth passes unchanged. \
                 Fig. 10 shows HPF(v), LPF(vᵃ) and their sum vᵏ on the truth; the tiles read the three tilt errors.",
            )
        },
        LessonStep {
            tab: Some(PlotTab::Figure("kf-variances")),
            show: &["blend", "kf-uv"],
            highlight: &["kf_q_scale"],
            speed: Some(10.0),
            pause_at_s: Some(100.0),
            tiles: &[
                SeriesKey::new("blend", &q::TILT_ERR_DEG),
                SeriesKey::new("kf-uv", &q::TILT_ERR_DEG),
                SeriesKey::variance("kf-uv", &wz_kalman::STATE_V),
            ],
            quotes: &[
                Quote::run("0.11°", tilt_rms("kf-uv")),
                Quote::run("0.13°", tilt_rms("blend")),
            ],
            ..LessonStep::new(
                "kalman-gain",
                "A Kalman filter chooses its own gain",
                "Beyond the paper: a Kalman filter in (u, v) takes the Riccati kinematics of eqs. 17–19 as its process and (uᵃ, vᵃ) of eq. 28 as its measurement. \
                 It has no T to choose: its gain follows from the noise it is told (the gyro's, its bias as extra process noise, the accelerometers' σ). \
                 The plot shows the variances of u and v in its covariance matrix P, which the w plane and the sphere draw as a 3σ ellipse. \
                 Its tilt error, 0.11° rms in this run, is a little below the blend's 0.13°; a larger process-noise scale trusts the accelerometers more.",
            )
        },
    ],
};
