//! The lesson of the foundation lab: Euler's equations of a free body, then what integrating a
//! gyro can and cannot do (bias → drift, noise → random walk). Steps are data (see
//! crate::page::Lesson); the Russian is in this folder's ru.ftl.

use super::truth::{ENERGY_J, MOMENTUM_N_M_S};
use crate::estimators::ATTITUDE_AXES;
use crate::model::{PlotTab, SeriesGroup, SeriesKey, q};
use crate::page::{Lesson, LessonStep, Question, Quote, Reading};

pub(super) static LESSON: Lesson = Lesson {
    title: "Free rotation: Euler's equations, and what integrating a gyro can and cannot do",
    showcase: "constant-bias",
    steps: &[
        LessonStep {
            set: &[("spin_axis", 0.0)],
            tab: Some(PlotTab::Group(SeriesGroup::Rate)),
            highlight: &["spin_axis"],
            speed: Some(5.0),
            pause_at_s: Some(60.0),
            tiles: &[SeriesKey::truth(&q::RATE_X_DEG_S)],
            quotes: &[
                Quote::paper("(1, 2, 3) kg·m²"),
                Quote::param("40 °/s", "spin_deg_s"),
                Quote::run(
                    "40 °/s",
                    Reading::Mean(SeriesKey::truth(&q::RATE_X_DEG_S), 0.0, 60.0),
                )
                .about(0.1),
            ],
            ..LessonStep::new(
                "stable-spin",
                "A stable spin",
                "A rigid body with principal moments I = (1, 2, 3) kg·m² turns with no torque, by Euler's equations Jω̇ + ω × Jω = 0. \
                 Here it starts spinning at 40 °/s about x, the axis of the smallest moment, tipped slightly off that axis. \
                 The plot shows the body rates: ω_x stays near 40 °/s while ω_y and ω_z only wobble. \
                 A spin about the axis of the smallest or of the largest moment is stable.",
            )
        },
        LessonStep {
            tab: Some(PlotTab::Group(SeriesGroup::Rate)),
            highlight: &["spin_axis"],
            speed: Some(5.0),
            pause_at_s: Some(60.0),
            tiles: &[SeriesKey::truth(&q::RATE_Y_DEG_S)],
            question: Some(Question {
                ask: "Spun about the intermediate axis, what does ω_y do within a minute?",
                answers: &[
                    "It stays near 40 °/s, as the spin about x did",
                    "It reverses to about −40 °/s and back, again and again",
                    "It decays to zero as the energy moves to ω_x and ω_z",
                ],
                answer: 1,
                why: "The intermediate axis is unstable (the Dzhanibekov effect): the body flips over and back, and each flip reverses ω_y. With no torque nothing is lost, so it never settles.",
            }),
            quotes: &[
                Quote::param("40 °/s", "spin_deg_s"),
                Quote::param("2 kg·m²", "inertia_y_kg_m2"),
                Quote::run(
                    "−40 °/s",
                    Reading::Min(SeriesKey::truth(&q::RATE_Y_DEG_S), 0.0, 60.0),
                )
                .about(0.1),
            ],
            ..LessonStep::new(
                "intermediate-axis",
                "The intermediate axis flips",
                "Now the same 40 °/s spin is about y, the intermediate moment I_y = 2 kg·m² (the lab's default). \
                 Linearised about this spin, Euler's equations give a small wobble that grows exponentially instead of oscillating. \
                 Watch ω_y on the plot and the body in the 3D view.",
            )
        },
        LessonStep {
            tab: Some(PlotTab::Figure("energy-momentum")),
            speed: Some(5.0),
            pause_at_s: Some(60.0),
            tiles: &[
                SeriesKey::truth(&ENERGY_J),
                SeriesKey::truth(&MOMENTUM_N_M_S),
            ],
            quotes: &[
                Quote::run(
                    "10⁻¹²",
                    Reading::Drift(SeriesKey::truth(&ENERGY_J), 0.0, 60.0),
                )
                .about(0.9),
                Quote::pause("60 s"),
            ],
            ..LessonStep::new(
                "invariants",
                "What stays constant",
                "While the rates swap between the axes, two quantities do not change: the kinetic energy T = ½ωᵀJω and the length of the angular momentum |Jω|. \
                 The plot shows both flat; the lab's check finds a relative energy drift of about 10⁻¹² over 60 s. \
                 They are the first test of any simulation of a free rigid body.",
            )
        },
        LessonStep {
            set: &[("gyro_noise_deg_s", 0.0), ("gyro_bias_deg_s", 0.0)],
            tab: Some(PlotTab::Figure("errors")),
            highlight: &["gyro_noise_deg_s", "gyro_bias_deg_s"],
            speed: Some(5.0),
            pause_at_s: Some(60.0),
            tiles: &[
                SeriesKey::new("quat-rk4", &q::ERR_DEG),
                SeriesKey::new("uvz-rk4", &q::ERR_DEG),
            ],
            quotes: &[
                Quote::pause("60 s"),
                Quote::run(
                    "10⁻⁵ rad",
                    Reading::At(SeriesKey::new("quat-rk4", &q::ERR_DEG), 60.0),
                )
                .about(0.15)
                .scaled(std::f64::consts::PI / 180.0),
                Quote::run(
                    "0.0006°",
                    Reading::At(SeriesKey::new("quat-rk4", &q::ERR_DEG), 60.0),
                )
                .about(0.15),
                Quote::param("100 Hz", "rate_hz"),
            ],
            ..LessonStep::new(
                "perfect-gyro",
                "Integrating a perfect gyro",
                "Two estimators know only the initial attitude and the gyro: one integrates the quaternion, q̇ = ½ q⊗ω, the other paper 3's (u, v, z) by its eq. 21, switching to the chart s = 1/w whenever the body is upside down; both use Runge–Kutta 4. \
                 With the gyro's noise and bias at zero both follow the truth: after 60 s the error is about 10⁻⁵ rad (0.0006°). \
                 It comes only from sampling ω at 100 Hz: halving the step quarters it. \
                 The two error curves coincide, the same kinematics in two parametrisations.",
            )
        },
        LessonStep {
            set: &[
                ("spin_deg_s", 0.0),
                ("gyro_noise_deg_s", 0.0),
                ("gyro_bias_deg_s", 0.1),
            ],
            tab: Some(PlotTab::Figure("errors")),
            highlight: &["gyro_bias_deg_s", "spin_deg_s"],
            speed: Some(5.0),
            pause_at_s: Some(60.0),
            tiles: &[SeriesKey::new("quat-rk4", &q::ERR_DEG)],
            question: Some(Question {
                ask: "What is the whole-angle error after 60 s?",
                answers: &["About 0.1°: the bias is tiny", "About 6°", "About 10°"],
                answer: 2,
                why: "A body at rest never turns its bias, so the error grows linearly, b·t: 6° about each axis after 60 s, and √3 · 0.1 °/s · 60 s ≈ 10.4° as a whole angle.",
            }),
            quotes: &[
                Quote::pause("60 s"),
                Quote::posed("0.1°"),
                Quote::posed("6°"),
                Quote::posed("10°"),
                Quote::run(
                    "6°",
                    Reading::MaxAbs(SeriesKey::new("quat-rk4", &q::ERR_X_DEG), 60.0, 60.0),
                )
                .about(0.05),
                Quote::param("0.1 °/s", "gyro_bias_deg_s"),
                Quote::run(
                    "10.4°",
                    Reading::At(SeriesKey::new("quat-rk4", &q::ERR_DEG), 60.0),
                ),
                Quote::param("0 °/s", "spin_deg_s"),
            ],
            ..LessonStep::new(
                "constant-bias",
                "A constant bias",
                "Now the body is at rest (initial spin 0 °/s) and the gyro has a constant bias of 0.1 °/s on each axis, with signs (+, −, +). \
                 The integrator adds the bias to the true rate at every step and has nothing to correct it with. \
                 The plot shows the error about each body axis and as a whole angle.",
            )
        },
        LessonStep {
            set: &[("gyro_noise_deg_s", 0.0), ("gyro_bias_deg_s", 0.1)],
            tab: Some(PlotTab::Figure("errors")),
            highlight: &["gyro_bias_deg_s"],
            speed: Some(5.0),
            pause_at_s: Some(60.0),
            tiles: &[SeriesKey::new("quat-rk4", &q::ERR_DEG)],
            question: Some(Question {
                ask: "With the body tumbling, how large is the whole-angle error after 60 s?",
                answers: &[
                    "The same, about 10°",
                    "Much smaller: a few degrees at most",
                    "Larger: the turning adds to it",
                ],
                answer: 1,
                why: "Turned around with the body, the bias partly cancels itself: the error is about 0.7° at 60 s, against the 10.4° of a body that never turns. It still grows, just not in a straight line.",
            }),
            quotes: &[
                Quote::pause("60 s"),
                Quote::posed("10°"),
                Quote::run(
                    "0.7°",
                    Reading::At(SeriesKey::new("quat-rk4", &q::ERR_DEG), 60.0),
                )
                .about(0.15),
                Quote::run_with(
                    "10.4°",
                    &[("spin_deg_s", 0.0)],
                    Reading::At(SeriesKey::new("quat-rk4", &q::ERR_DEG), 60.0),
                ),
                Quote::param("0.1 °/s", "gyro_bias_deg_s"),
            ],
            ..LessonStep::new(
                "turning-averages",
                "Turning averages the bias",
                "The same bias of 0.1 °/s, but the body tumbles about its intermediate axis again. \
                 The bias is fixed in the body, so as the body turns, the bias points in changing directions in space: the error now grows as |∫R(t)·b dt|.",
            )
        },
        LessonStep {
            set: &[("gyro_noise_deg_s", 0.2), ("gyro_bias_deg_s", 0.0)],
            tab: Some(PlotTab::Figure("errors")),
            highlight: &["gyro_noise_deg_s"],
            speed: Some(20.0),
            pause_at_s: Some(240.0),
            tiles: &[
                SeriesKey::new("quat-rk4", &q::ERR_X_DEG),
                SeriesKey::new("quat-rk4", &q::ERR_DEG),
            ],
            quotes: &[
                Quote::param("0.2 °/s", "gyro_noise_deg_s"),
                Quote::paper("0.01 s"),
                Quote::run(
                    "0.155°",
                    Reading::SqrtAt(SeriesKey::variance("quat-rk4", &ATTITUDE_AXES[0]), 60.0),
                )
                .scaled(180.0 / std::f64::consts::PI),
                Quote::paper("60 s"),
                Quote::pause("240 s"),
            ],
            ..LessonStep::new(
                "random-walk",
                "Noise: a random walk",
                "Now the gyro has no bias but a white noise of σ = 0.2 °/s on every sample. \
                 Each step adds a random angle, so the error random-walks: its standard deviation about each axis is σ√(t·Δt) with Δt = 0.01 s, 0.155° after 60 s and twice that after 240 s. \
                 It grows as √t, not as t. \
                 The ±3σ bands on the per-axis errors are this prediction, published by the integrators as their covariance.",
            )
        },
        LessonStep {
            set: &[
                ("spin_deg_s", 0.0),
                ("gyro_noise_deg_s", 0.0),
                ("gyro_bias_deg_s", 0.1),
                ("rate_hz", 1000.0),
            ],
            tab: Some(PlotTab::Figure("errors")),
            highlight: &["rate_hz"],
            speed: Some(5.0),
            pause_at_s: Some(60.0),
            tiles: &[SeriesKey::new("quat-rk4", &q::ERR_DEG)],
            question: Some(Question {
                ask: "What is the whole-angle error after 60 s now?",
                answers: &[
                    "About ten times smaller, ≈ 1°",
                    "About √10 times smaller, ≈ 3°",
                    "Unchanged, ≈ 10.4°",
                ],
                answer: 2,
                why: "The bias error is b·t whatever the step, and nothing inside the gyro tells a bias from a true rate. To stop the drift a filter needs an absolute reference, a measured direction such as the sun, the magnetic field or the stars (paper 2); paper 1 shows how far a gyro and a model alone can go.",
            }),
            quotes: &[
                Quote::pause("60 s"),
                Quote::posed("1°"),
                Quote::posed("3°"),
                Quote::run(
                    "10.4°",
                    Reading::At(SeriesKey::new("quat-rk4", &q::ERR_DEG), 60.0),
                ),
                Quote::param("0.1 °/s", "gyro_bias_deg_s"),
                Quote::param("1000 Hz", "rate_hz"),
            ],
            ..LessonStep::new(
                "faster-gyro",
                "A faster gyro does not help",
                "Back to the body at rest with a bias of 0.1 °/s and no noise, but now the gyro is sampled ten times faster, at 1000 Hz. \
                 A shorter step shrinks the sampling error of step 4 and the noise walk σ√(t·Δt) of step 7.",
            )
        },
    ],
};
