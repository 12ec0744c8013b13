//! The lesson of paper 2: which sensors TabletSat's Kalman filter needs (Tables 2–3), what
//! happens when one fails, and the bias and disturbance estimates. Steps are data (see
//! crate::page::Lesson); the Russian is in this folder's ru.ftl.

use super::sensors::{GYRO_BIAS, STAR_AVAILABLE};
use crate::estimators::mekf;
use crate::model::{PlotTab, SeriesKey, q};
use crate::page::{Lesson, LessonStep, Question, Quote, Reading};

/// The last minute of a 200-s step, where its σ is measured (the accuracy table's window).
const LAST_MINUTE: (f64, f64) = (140.0, 200.0);

/// The σ of the accuracy table for `source` over the last minute of a 200-s step.
const fn sigma(source: &'static str) -> Reading {
    Reading::WorstAxisRms(source, LAST_MINUTE.0, LAST_MINUTE.1)
}

/// The plot of every filter's attitude error (log scale).
const EVERY_FILTER: Option<PlotTab> = Some(PlotTab::Figure("every-filter"));

pub(super) static LESSON: Lesson = Lesson {
    title: "Paper 2: TabletSat — which sensors the Kalman filter needs, and what happens when one fails",
    showcase: "star-tracker-blind",
    steps: &[
        LessonStep {
            tab: EVERY_FILTER,
            show: &["mag-sun"],
            speed: Some(20.0),
            pause_at_s: Some(200.0),
            tiles: &[SeriesKey::new("mag-sun", &q::ERR_DEG)],
            quotes: &[
                Quote::param("250 nT", "mag_noise_nt"),
                Quote::param("0.1°", "sun_noise_deg"),
                Quote::paper("0.12°"),
                Quote::param("2°", "filter_init_err_deg"),
            ],
            ..LessonStep::new(
                "mag-sun",
                "Two directions: Mag+Sun",
                "TabletSat holds the orbital frame with reaction wheels, and every filter of Table 2 runs at once on the same measurements. \
                 Set 10 uses only the magnetometer (250 nT) and the sun sensors (0.1°, Table 1): z = [b, s], x = [λ, ω], H = [W_b 0; W_s 0]. \
                 Two non-parallel directions fix the attitude, to 0.12° in Table 3. \
                 The filter starts 2° off and settles at the first measurement; the plot is logarithmic.",
            )
        },
        LessonStep {
            tab: EVERY_FILTER,
            show: &["mag-sun", "mag-sun-gyro"],
            speed: Some(20.0),
            pause_at_s: Some(200.0),
            tiles: &[
                SeriesKey::new("mag-sun", &q::ERR_DEG),
                SeriesKey::new("mag-sun-gyro", &q::ERR_DEG),
            ],
            question: Some(Question {
                ask: "How does the attitude error of Mag+Sun+Gyro compare with Mag+Sun?",
                answers: &[
                    "Smaller",
                    "About the same: a gyro measures rate, not attitude",
                    "Larger: one more noisy sensor",
                ],
                answer: 0,
                why: "The measured rate carries the attitude between the noisy vector readings and against the unmodelled torque. Table 3 gives 0.02° against 0.12°; here, with every sensor read at 1 Hz, the measured σ over the last minute is about 0.06° against 0.095°.",
            }),
            quotes: &[
                Quote::paper("0.02°"),
                Quote::paper("0.12°"),
                Quote::param("1 Hz", "gyro_rate_hz"),
                Quote::param("1 Hz", "vector_rate_hz"),
                Quote::run("0.06°", sigma("mag-sun-gyro")).about(0.1),
                Quote::run("0.095°", sigma("mag-sun")).about(0.05),
                Quote::param("0.005 °/s", "gyro_noise_deg_s"),
                Quote::param("8·10⁻⁷ N·m", "dist_torque_n_m"),
            ],
            ..LessonStep::new(
                "add-gyro",
                "Add the gyro",
                "Set 5 adds the gyro, 0.005 °/s (Table 1): z = [b, s, ω], H = [W_b 0; W_s 0; 0 E]. \
                 Without it the rate ω is only predicted by the dynamics (6), which do not know the unmodelled torque of 8·10⁻⁷ N·m.",
            )
        },
        LessonStep {
            tab: EVERY_FILTER,
            show: &["mag-sun-gyro", "st", "st-gyro", "st-gyro-mag-sun"],
            speed: Some(20.0),
            pause_at_s: Some(200.0),
            tiles: &[
                SeriesKey::new("st-gyro", &q::ERR_DEG),
                SeriesKey::new("mag-sun-gyro", &q::ERR_DEG),
            ],
            question: Some(Question {
                ask: "Which set is the most accurate?",
                answers: &[
                    "ST+Gyro+Mag+Sun: more sensors, smaller error",
                    "Mag+Sun+Gyro",
                    "The three star-tracker sets, about equally",
                ],
                answer: 2,
                why: "The 0.001° star tracker dominates: Table 3 gives 5·10⁻⁴–8·10⁻⁴° for every star-tracker set, about 40 times below the 0.02° of Mag+Sun+Gyro. The paper concludes that next to a star tracker the magnetometer and the sun sensor add nothing, and the gyro mainly improves the rate.",
            }),
            quotes: &[
                Quote::param("0.001°", "star_noise_deg"),
                Quote::paper("5·10⁻⁴–8·10⁻⁴°"),
                Quote::paper("0.02°"),
            ],
            ..LessonStep::new(
                "add-star-tracker",
                "Add the star tracker",
                "The star tracker measures the attitude quaternion itself, to 0.001° (set 12: H = [E 0]). \
                 Compare three sets with it (ST alone, ST+Gyro and ST+Gyro+Mag+Sun) with the best set without it, Mag+Sun+Gyro.",
            )
        },
        LessonStep {
            preset: Some("star-tracker-blinded"),
            tab: EVERY_FILTER,
            show: &["st", "st-gyro", "st-gyro-mag-sun"],
            highlight: &["star_sun_exclusion_deg"],
            speed: Some(100.0),
            pause_at_s: Some(1380.0),
            tiles: &[
                SeriesKey::new("st-gyro", &q::ERR_DEG),
                SeriesKey::new("st-gyro-mag-sun", &q::ERR_DEG),
            ],
            question: Some(Question {
                ask: "While the star tracker is out, which star-tracker set keeps its attitude?",
                answers: &["ST alone", "ST+Gyro", "ST+Gyro+Mag+Sun"],
                answer: 2,
                why: "Its magnetometer and sun sensor still give two directions, so it falls back to about the accuracy of Mag+Sun+Gyro, under 0.2°. ST+Gyro only integrates the gyro and drifts to about 8°; ST alone has nothing but the dynamics and stops, reported as diverged. Run on: when the stars return at about 1390 s, ST+Gyro snaps back to the star tracker's accuracy.",
            }),
            quotes: &[
                Quote::run(
                    "0.2°",
                    Reading::Max(
                        SeriesKey::new("st-gyro-mag-sun", &q::ERR_DEG),
                        100.0,
                        1380.0,
                    ),
                )
                .at_most(),
                Quote::run(
                    "8°",
                    Reading::At(SeriesKey::new("st-gyro", &q::ERR_DEG), 1380.0),
                )
                .about(0.2),
                Quote::run(
                    "1390 s",
                    Reading::FirstAbove(SeriesKey::sensors(&STAR_AVAILABLE), 0.5, 0.0, 3000.0),
                )
                .about(0.01),
                Quote::param("90°", "star_sun_exclusion_deg"),
                Quote::param("2°", "filter_init_err_deg"),
            ],
            ..LessonStep::new(
                "star-tracker-blind",
                "The star tracker goes blind",
                "A star tracker fails when the sun is in its field of view. \
                 With a 90° sun exclusion it is out whenever the sun is within 90° of its boresight; in this orbit that is from the start until about 1390 s (the shaded band). \
                 The filters start 2° off.",
            )
        },
        LessonStep {
            preset: Some("sun-along-field"),
            tab: EVERY_FILTER,
            show: &["mag-sun", "mag-sun-gyro", "st-gyro"],
            highlight: &["sun_along_field", "sun_field_angle_deg"],
            speed: Some(20.0),
            pause_at_s: Some(300.0),
            tiles: &[
                SeriesKey::new("mag-sun", &q::ERR_DEG),
                SeriesKey::new("mag-sun-gyro", &q::ERR_DEG),
            ],
            question: Some(Question {
                ask: "What happens to Mag+Sun?",
                answers: &[
                    "Nothing: it still has two sensors",
                    "Its error grows to degrees, and it reports the attitude as unobservable",
                    "Its estimate turns into NaN and the run stops",
                ],
                answer: 1,
                why: "With s ∥ b, H is degenerate and the rotation about that line is not observed; the paper notes that the filter then diverges. Here Mag+Sun wanders by degrees and says so; Mag+Sun+Gyro holds better, since its gyro carries that rotation for a while, and the star tracker does not care.",
            }),
            quotes: &[Quote::param("0.5°", "sun_field_angle_deg")],
            ..LessonStep::new(
                "sun-along-field",
                "Sun along the field",
                "A thought experiment: the sun is put 0.5° from the direction of the magnetic field. \
                 The rows W_b and W_s of H become nearly the same, and a turn about the common direction changes neither measurement.",
            )
        },
        LessonStep {
            set: &[("gyro_bias_deg_s", 0.05)],
            tab: Some(PlotTab::Figure("fig6-gyro-bias")),
            show: &["st-gyro-gbias", "st-gyro-reduced"],
            highlight: &["gyro_bias_deg_s"],
            speed: Some(5.0),
            pause_at_s: Some(60.0),
            tiles: &[
                SeriesKey::sensors(&GYRO_BIAS[0]),
                SeriesKey::new("st-gyro-gbias", &mekf::GBIAS_X_DEG_S),
            ],
            question: Some(Question {
                ask: "How soon do the estimates reach the true bias?",
                answers: &[
                    "Within seconds",
                    "After about one orbit",
                    "Never: a bias looks just like a rate",
                ],
                answer: 0,
                why: "The star tracker pins the attitude, so a steady difference between the gyro and the attitude's change must be bias: the estimate comes within 0.005 °/s of it in about 2 s, well inside the paper's under a minute (Figs. 6–7).",
            }),
            quotes: &[
                Quote::run(
                    "2 s",
                    Reading::FirstClose(
                        SeriesKey::new("st-gyro-gbias", &mekf::GBIAS_X_DEG_S),
                        SeriesKey::sensors(&GYRO_BIAS[0]),
                        0.005,
                        0.0,
                        60.0,
                    ),
                )
                .about(0.5),
                Quote::paper("0.005 °/s"),
                Quote::param("0.05 °/s", "gyro_bias_deg_s"),
                Quote::run(
                    "0.03 °/s",
                    Reading::At(SeriesKey::sensors(&GYRO_BIAS[0]), 0.0),
                ),
                Quote::run(
                    "0.04 °/s",
                    Reading::At(SeriesKey::sensors(&GYRO_BIAS[1]), 0.0),
                ),
            ],
            ..LessonStep::new(
                "gyro-bias",
                "Estimating the gyro bias",
                "Give the gyro a bias of 0.05 °/s: 0.03 °/s about x and 0.04 °/s about y. \
                 Set 9 adds it to the state, ω̃ = ω + Δω + n_ω with H = [E 0 0; 0 E E], and the reduced variant drops ω to keep x = [λ, Δω]. \
                 Both start from Δω̂ = 0.",
            )
        },
        LessonStep {
            tab: EVERY_FILTER,
            show: &["mag-sun", "mag-sun-dist"],
            highlight: &["dist_torque_n_m", "alpha", "rd_scale"],
            speed: Some(20.0),
            pause_at_s: Some(200.0),
            tiles: &[
                SeriesKey::new("mag-sun", &q::ERR_DEG),
                SeriesKey::new("mag-sun-dist", &q::ERR_DEG),
            ],
            question: Some(Question {
                ask: "With the disturbance filter beside it, what happens to the attitude error of Mag+Sun?",
                answers: &[
                    "It falls",
                    "It stays the same: d is not attitude",
                    "It grows: more states, more noise",
                ],
                answer: 0,
                why: "Knowing d, the prediction no longer lags behind the real motion between measurements. The paper gives 0.12° → 0.03°; here the measured σ over the last minute goes from about 0.095° to 0.058°.",
            }),
            quotes: &[
                Quote::paper("0.12°"),
                Quote::paper("0.03°"),
                Quote::run("0.095°", sigma("mag-sun")).about(0.05),
                Quote::run("0.058°", sigma("mag-sun-dist")).about(0.05),
                Quote::param("8·10⁻⁷ N·m", "dist_torque_n_m"),
            ],
            ..LessonStep::new(
                "disturbance-filter",
                "The disturbance filter",
                "A constant torque of 8·10⁻⁷ N·m, unknown to the filters' dynamics (6), acts on the satellite, as in the paper's tuning runs. \
                 §3.2 runs a second filter beside the EKF that estimates the disturbance d in ω̇ = f(ω, Λ) + d from the innovations, with a fading memory α.",
            )
        },
        LessonStep {
            set: &[("dist_from_s", 100.0)],
            tab: Some(PlotTab::Figure("fig8-disturbance")),
            show: &["mag-sun-dist", "st-dist"],
            highlight: &["dist_from_s", "alpha"],
            speed: Some(40.0),
            pause_at_s: Some(600.0),
            tiles: &[
                SeriesKey::new("st-dist", &mekf::D_X_S2),
                SeriesKey::new("mag-sun-dist", &mekf::D_X_S2),
            ],
            quotes: &[
                Quote::param("100 s", "dist_from_s"),
                Quote::run(
                    "10⁻⁶ s⁻²",
                    Reading::MaxAbs(SeriesKey::truth(&super::truth::DIST_TRUE[0]), 600.0, 600.0),
                )
                .about(0.7),
            ],
            ..LessonStep::new(
                "torque-on",
                "A torque switched on",
                "Now the same torque switches on at 100 s. \
                 The disturbance estimates d̂ of Fig. 8 leave zero and climb towards J⁻¹M_d, of the order of 10⁻⁶ s⁻². \
                 The fading memory inflates P_d by 1/α every second, so d̂ keeps listening: a smaller α forgets faster and follows a change sooner, but is noisier.",
            )
        },
    ],
};
