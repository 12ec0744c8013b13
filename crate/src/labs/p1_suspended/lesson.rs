//! The lesson of paper 1: a body twisting on a string, a one-axis gyro, and the two adaptive
//! Kalman filters (Q = 0, then covariance matching over a window N). Steps are data (see
//! crate::page::Lesson); the Russian is in this folder's ru.ftl.

use super::PERIOD_S;
use crate::estimators::one_axis_kf::{ANGLE_MINUS_INT_DEG, STATE_PHIDOT};
use crate::model::{PlotTab, SeriesKey, q};
use crate::page::{CycleTerm, Lesson, LessonStep, Question, Quote, Reading};

/// Both filters' distance from the integrated angle φ_int (the paper's error panel).
const FROM_INT: &[SeriesKey] = &[
    SeriesKey::new("kf-rotation", &ANGLE_MINUS_INT_DEG),
    SeriesKey::new("kf-torsion", &ANGLE_MINUS_INT_DEG),
];

/// The rotation filter's distance from φ_int.
const ROT_FROM_INT: SeriesKey = FROM_INT[0];
/// The torsional filter's distance from φ_int.
const TOR_FROM_INT: SeriesKey = FROM_INT[1];

/// Both filters' rate variance c = P_φ̇φ̇.
const RATE_VARIANCE: &[SeriesKey] = &[
    SeriesKey::variance("kf-rotation", &STATE_PHIDOT),
    SeriesKey::variance("kf-torsion", &STATE_PHIDOT),
];

pub(super) static LESSON: Lesson = Lesson {
    title: "Paper 1: a suspended mock-up, a one-axis gyro and two adaptive Kalman filters",
    showcase: "q-zero",
    steps: &[
        LessonStep {
            tab: Some(PlotTab::Figure("angle")),
            highlight: &["string_diameter_mm", "string_length_m", "inertia_kg_m2"],
            speed: Some(50.0),
            pause_at_s: Some(600.0),
            tiles: &[SeriesKey::truth(&PERIOD_S), SeriesKey::truth(&q::ANGLE_DEG)],
            quotes: &[
                Quote::param("0.35 mm", "string_diameter_mm"),
                Quote::param("1 m", "string_length_m"),
                Quote::paper("1.18·10⁻⁴ N·m²"),
                Quote::param("0.48 kg·m²", "inertia_kg_m2"),
                Quote::run("400 s", Reading::At(SeriesKey::truth(&PERIOD_S), 0.0)).about(0.05),
                Quote::param("360°", "initial_angle_deg"),
                Quote::param("0.04 °/s", "gyro_noise_deg_s"),
                Quote::param("100 Hz", "filter_rate_hz"),
            ],
            ..LessonStep::new(
                "on-a-string",
                "A body on a string",
                "The mock-up hangs on a steel string 0.35 mm thick and 1 m long and twists about it by the one-degree-of-freedom model of eq. 3.3, Iφ̈ = −fφ, here with damping. \
                 The stiffness is f = G·I_p/L with G·I_p = 1.18·10⁻⁴ N·m², so with I = 0.48 kg·m² the period T = 2π√(I/f) is about 400 s (the paper states neither T nor the damping). \
                 The twist starts at φ₀ = 360°, and the only sensor is a one-axis rate gyro with σ = 0.04 °/s at 100 Hz. \
                 Three estimators follow it: the integrated angle φ_int, the permanent-rotation KF with φ̈ = 0 by eq. 4.1 and the torsional KF with Ω = 2π/T by eq. 4.6; at this scale all lie on the truth.",
            )
        },
        LessonStep {
            set: &[("kf_window", 0.0)],
            tab: Some(PlotTab::Figure("p-diagonal")),
            highlight: &["kf_window"],
            speed: Some(60.0),
            pause_at_s: Some(600.0),
            tiles: RATE_VARIANCE,
            terms: &[
                CycleTerm::ProcessNoise,
                CycleTerm::Gain,
                CycleTerm::PosteriorCovariance,
            ],
            question: Some(Question {
                ask: "With Q = 0, what does the rate variance c do over 600 s?",
                answers: &[
                    "It grows: the rate is not measured often enough",
                    "It falls by orders of magnitude towards zero",
                    "It stays at its initial value c₀",
                ],
                answer: 1,
                why: "Each update makes c smaller, c⁺ = cR/(c + R), and Q = 0 never adds uncertainty back, so c and with it the gain go to zero (Fig. 5.4): the filters stop listening to the gyro. The rotation filter's a even grows, because its angle is never measured (H = (0 1)).",
            }),
            quotes: &[Quote::pause("600 s")],
            ..LessonStep::new(
                "q-zero",
                "Q = 0: the covariance collapses",
                "Switch the adaptation off (N = 0): both filters propagate P = [[a, b], [b, c]] with Q = 0, the closed forms (4.2) and (4.7). \
                 Only the measurement update (4.5) changes P, and the gain (4.3) is K = (b, c)ᵀ/(c + R) with R = σ². \
                 The plot shows a and c of both filters on a log scale.",
            )
        },
        LessonStep {
            set: &[("kf_window", 0.0)],
            tab: Some(PlotTab::Figure("angle-error-vs-int")),
            highlight: &["kf_window"],
            speed: Some(60.0),
            pause_at_s: Some(600.0),
            tiles: FROM_INT,
            question: Some(Question {
                ask: "Which filter is farther from φ_int by 600 s?",
                answers: &[
                    "The permanent-rotation KF",
                    "The torsional KF",
                    "Neither: both stay within 0.1°",
                ],
                answer: 1,
                why: "The torsional model is undamped while the real twist is damped (ζ = 0.05): the torsional KF, no longer listening, drifts to about 120° from φ_int, the ±100° of Fig. 5.3. The permanent-rotation KF stays within about 2°, fairly good as the paper puts it.",
            }),
            quotes: &[
                Quote::pause("600 s"),
                Quote::posed("0.1°"),
                Quote::param("0.05", "damping_ratio"),
                Quote::run("120°", Reading::MaxAbs(TOR_FROM_INT, 600.0, 600.0)).about(0.15),
                Quote::paper("100°"),
                Quote::run("2°", Reading::MaxAbs(ROT_FROM_INT, 0.0, 600.0)).about(0.25),
            ],
            ..LessonStep::new(
                "stopped-listening",
                "A filter that stopped listening",
                "The same run in the paper's error panel: each filter's angle less the integrated angle φ_int, as in Fig. 5.3 (the paper's runs have no truth to compare with). \
                 With a gain near zero a filter follows its own model rather than the gyro.",
            )
        },
        LessonStep {
            set: &[("kf_window", 1000.0)],
            tab: Some(PlotTab::Figure("p-diagonal")),
            highlight: &["kf_window", "kf_adaptation"],
            speed: Some(5.0),
            pause_at_s: Some(60.0),
            tiles: RATE_VARIANCE,
            quotes: &[
                Quote::paper("10 s"),
                Quote::param("100 Hz", "filter_rate_hz"),
            ],
            ..LessonStep::new(
                "covariance-matching",
                "Covariance matching: the saw-tooth",
                "Now adapt with a window of N = 1000 measurements (Table 2.3): every 1000 samples, 10 s at 100 Hz, the filter sets P to the window's mean of q qᵀ and then lets it decay with Q = 0 until the next window. \
                 Here q = (φ_int − φ̂, z − φ̇̂), this lab's reading of the table. \
                 P jumps every 10 s and decays in between, the saw-tooth of Fig. 5.6, and each jump restores the gain.",
            )
        },
        LessonStep {
            set: &[("kf_window", 1000.0)],
            tab: Some(PlotTab::Figure("angle-error-vs-int")),
            speed: Some(3.0),
            pause_at_s: Some(30.0),
            tiles: FROM_INT,
            question: Some(Question {
                ask: "Which filter stays closer to φ_int?",
                answers: &[
                    "The permanent-rotation KF",
                    "The torsional KF",
                    "Both about equally",
                ],
                answer: 1,
                why: "The twisting body accelerates, which the φ̈ = 0 model cannot follow between resets: it swings up to about 0.18° from φ_int (Fig. 5.5 shows ±0.3–0.4°), while the torsional KF stays within about 0.01°. The paper reaches the same verdict from the rates (Fig. 5.8).",
            }),
            quotes: &[
                Quote::run("0.18°", Reading::MaxAbs(ROT_FROM_INT, 0.0, 30.0)).about(0.1),
                Quote::paper("0.3–0.4°"),
                Quote::run("0.01°", Reading::MaxAbs(TOR_FROM_INT, 0.0, 30.0)).about(0.3),
            ],
            ..LessonStep::new(
                "which-model",
                "Which model fits",
                "With N = 1000, compare the two models against φ_int over the first three windows. \
                 The permanent-rotation KF assumes φ̈ = 0 by eq. 4.1; the torsional KF knows φ̈ = −Ω²φ by eq. 4.6. \
                 Between resets the gain decays and each filter leans on its model.",
            )
        },
        LessonStep {
            set: &[("kf_window", 100.0)],
            tab: Some(PlotTab::Figure("angle-error-vs-int")),
            highlight: &["kf_window"],
            speed: Some(3.0),
            pause_at_s: Some(30.0),
            tiles: FROM_INT,
            question: Some(Question {
                ask: "How far does the permanent-rotation KF now get from φ_int, compared with N = 1000?",
                answers: &[
                    "About ten times closer",
                    "About as far",
                    "Farther: fewer samples make P noisier",
                ],
                answer: 0,
                why: "With a fresh P every second the gain never decays far, so the φ̈ = 0 model has no time to lag: about 0.02° instead of 0.18°, like the ±0.01–0.015° of Fig. 5.7. The paper finds N ≈ 100 best: N = 1 does no smoothing, and N above 2000 is poor.",
            }),
            quotes: &[
                Quote::run("0.02°", Reading::MaxAbs(ROT_FROM_INT, 0.0, 30.0)).about(0.3),
                Quote::run_with(
                    "0.18°",
                    &[("kf_window", 1000.0)],
                    Reading::MaxAbs(ROT_FROM_INT, 0.0, 30.0),
                )
                .about(0.1),
                Quote::paper("0.01–0.015°"),
                Quote::paper("10 s"),
                Quote::pause("30 s"),
            ],
            ..LessonStep::new(
                "short-window",
                "A shorter window: N = 100",
                "Now the paper's best window, N = 100: P is refreshed every second instead of every 10 s, as in Fig. 5.7. \
                 Same plot, same 30 s as before.",
            )
        },
        LessonStep {
            tab: Some(PlotTab::Figure("angle-error")),
            speed: Some(15.0),
            pause_at_s: Some(200.0),
            tiles: &[
                SeriesKey::new("integration", &q::ANGLE_ERR_DEG),
                SeriesKey::new("kf-rotation", &q::ANGLE_ERR_DEG),
                SeriesKey::new("kf-torsion", &q::ANGLE_ERR_DEG),
            ],
            question: Some(Question {
                ask: "Against the true angle, which estimate is best after 200 s?",
                answers: &[
                    "The torsional KF, by far",
                    "The permanent-rotation KF, by far",
                    "None: all three carry about the same error",
                ],
                answer: 2,
                why: "A rate gyro alone cannot observe the angle: the filters only smooth the same integrated noise, whose spread is σ√(t·Δt) = 0.04 °/s · √(200 s · 0.01 s) ≈ 0.057°. The 0.01° of Fig. 5.7 is the distance from φ_int, not from the truth.",
            }),
            quotes: &[
                Quote::pause("200 s"),
                Quote::param("0.04 °/s", "gyro_noise_deg_s"),
                Quote::paper("0.01 s"),
                Quote::paper("0.057°"),
                Quote::paper("0.01°"),
            ],
            ..LessonStep::new(
                "against-truth",
                "Against the truth",
                "The lab knows the true angle φ, which the paper's runs did not. \
                 This panel shows each estimate less the truth: φ_int and both filters, with N = 100.",
            )
        },
        LessonStep {
            set: &[("init_error_deg", 100.0)],
            tab: Some(PlotTab::Figure("angle-error")),
            highlight: &["init_error_deg"],
            speed: Some(15.0),
            pause_at_s: Some(200.0),
            tiles: &[
                SeriesKey::new("kf-torsion", &q::ANGLE_ERR_DEG),
                SeriesKey::new("integration", &q::ANGLE_ERR_DEG),
            ],
            question: Some(Question {
                ask: "After 200 s, how far is the torsional KF from the true angle?",
                answers: &[
                    "Back within 1°: its model knows where the equilibrium is",
                    "Still about 100°",
                    "It diverges",
                ],
                answer: 1,
                why: "The filters follow φ_int to within about 0.006°, which is what the paper calls accurate, but φ_int carries the same 100°. A rate gyro measures only changes of φ; to fix the angle itself the paper proposes adding a direction sensor, such as a sun sensor.",
            }),
            quotes: &[
                Quote::pause("200 s"),
                Quote::posed("1°"),
                Quote::run(
                    "100°",
                    Reading::MaxAbs(
                        SeriesKey::new("kf-torsion", &q::ANGLE_ERR_DEG),
                        200.0,
                        200.0,
                    ),
                )
                .about(0.05),
                Quote::run("0.006°", Reading::MaxAbs(TOR_FROM_INT, 100.0, 200.0)).about(0.3),
                Quote::param("100°", "init_error_deg"),
            ],
            ..LessonStep::new(
                "wrong-start",
                "A wrong start",
                "The paper tried an initial angle about 100° off and found the torsional KF still accurate. \
                 Here every estimator, φ_int included, starts 100° from the true angle, as when the string's equilibrium is poorly known.",
            )
        },
    ],
};
