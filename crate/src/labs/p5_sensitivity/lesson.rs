//! The lesson of paper 5: correcting measured rates by one Gauss–Newton step through the
//! sensitivity matrix U = ∂Λ/∂p at every reference attitude. Steps are data (see
//! crate::page::Lesson); the Russian is in this folder's ru.ftl.

use crate::estimators::sensitivity::WITHIN_TOL;
use crate::estimators::sensitivity::{P_X_DEG_S, P_Y_DEG_S, P_Z_DEG_S};
use crate::model::{PlotTab, SeriesKey, q};
use crate::page::{Lesson, LessonStep, Question, Quote, Reading};

/// When method `id` first comes within the tolerance (its flag rises), in a 30-s run.
const fn first_within(id: &'static str) -> Reading {
    Reading::FirstAbove(SeriesKey::new(id, &WITHIN_TOL), 0.5, 0.0, 30.0)
}

pub(super) static LESSON: Lesson = Lesson {
    title: "Paper 5: correcting measured rates through the sensitivity matrix U = ∂Λ/∂p",
    showcase: "method-9",
    steps: &[
        LessonStep {
            preset: Some("gyro-bias"),
            set: &[("interval_s", 0.5)],
            tab: Some(PlotTab::Figure("error")),
            show: &["raw"],
            highlight: &["gyro_bias_deg_s"],
            speed: Some(2.0),
            pause_at_s: Some(30.0),
            tiles: &[SeriesKey::new("raw", &q::ERR_DEG)],
            quotes: &[
                Quote::param("10 °/s", "rate_deg_s"),
                Quote::param("2 °/s", "gyro_bias_deg_s"),
                Quote::paper("(1, −1, 2)/√6"),
                Quote::param("0.5 s", "interval_s"),
            ],
            ..LessonStep::new(
                "drift",
                "Integrated rates drift",
                "The body turns at 10 °/s, and the gyro adds a bias b of 2 °/s along (1, −1, 2)/√6. \
                 Integrating the measured rates, 2Λ̇ = Λ∘ω, carries the bias into the quaternion Λ: the attitude error of the uncorrected integration grows with time. \
                 Paper 5 adds a correction p to the rates, 2Λ̇ = Λ∘(ω + p), and chooses p from reference attitudes that arrive every Δt, here every 0.5 s.",
            )
        },
        LessonStep {
            preset: Some("paper-case"),
            tab: Some(PlotTab::Figure("angles")),
            show: &["gn9"],
            highlight: &["interval_s"],
            speed: Some(0.5),
            pause_at_s: Some(2.4),
            tiles: &[SeriesKey::new("gn9", &q::ERR_DEG)],
            question: Some(Question {
                ask: "When do the angles of method (9) first come within 0.01 rad of the reference?",
                answers: &[
                    "At the first reference, t = 1.17 s",
                    "Just after the second, t ≈ 2.36 s",
                    "Never",
                ],
                answer: 1,
                why: "During the first interval p = p₀ = 0 and nothing moves; the first update sets the p that turns Λ onto the reference during the second interval. So the tolerance is met just after 2Δt: at 2.36 s, the paper's number.",
            }),
            quotes: &[
                Quote::param("0.01 rad", "tolerance_rad"),
                Quote::param("1.17 s", "interval_s"),
                Quote::run("2.36 s", first_within("gn9")),
                Quote::param("(0.5", "init_1_rad"),
                Quote::param("0.7", "init_2_rad"),
                Quote::param("0.2)", "init_3_rad"),
                Quote::param("(0.01", "ref_1_rad"),
                Quote::param("0.02", "ref_2_rad"),
                Quote::param("0.01)", "ref_3_rad"),
                Quote::paper("2.36"),
            ],
            ..LessonStep::new(
                "paper-case",
                "The paper's case",
                "The paper's only experiment (§3): the body holds still, ω = 0, starts at Krylov angles (0.5, 0.7, 0.2) rad and must reach the reference (0.01, 0.02, 0.01) rad within 0.01 rad per angle. \
                 At each reference p takes one Gauss–Newton step, p⁽ⁱ⁺¹⁾ = p⁽ⁱ⁾ + (UᵀQU)⁻¹UᵀQΔΛ, method (9), with U = ∂Λ/∂p integrated beside Λ from U(tᵢ) = 0. \
                 The paper reports the tolerance reached at t = 2.36, its time unit unstated, and gives no Δt; here Δt = 1.17 s.",
            )
        },
        LessonStep {
            set: &[("interval_s", 1.0)],
            tab: Some(PlotTab::Figure("error")),
            show: &["gn9"],
            highlight: &["interval_s"],
            speed: Some(2.0),
            pause_at_s: Some(30.0),
            tiles: &[SeriesKey::new("gn9", &q::ERR_DEG)],
            question: Some(Question {
                ask: "Δt = 1 s. After it first meets the tolerance at 2.02 s, what does the error of method (9) do over 30 s?",
                answers: &[
                    "It stays within the tolerance",
                    "It shrinks slowly, update by update",
                    "It keeps swinging back to large values, again and again",
                ],
                answer: 2,
                why: "Linearised with q = pΔt, the update is e ← e + q, q ← q − k(e + q) with k = 1: its determinant is 1, so both eigenvalues lie on the unit circle, at ±60°: the error turns 60° an update, once round in 6, and its size dips twice a turn, every 3 updates. The largest angle error at the updates cycles 0.68, 0.019, 0.67, 0.70, 0.058, 0.64 rad and never settles.",
            }),
            quotes: &[
                Quote::param("1 s", "interval_s"),
                Quote::run("2.02 s", first_within("gn9")),
                Quote::pause("30 s"),
                Quote::run("60°", Reading::Lab("gn9-eigen-angle")),
                Quote::run("0.68", Reading::Lab("gn9-update-1")),
                Quote::run("0.019", Reading::Lab("gn9-update-2")),
                Quote::run("0.67", Reading::Lab("gn9-update-3")),
                Quote::run("0.70", Reading::Lab("gn9-update-4")),
                Quote::run("0.058", Reading::Lab("gn9-update-5")),
                Quote::run("0.64 rad", Reading::Lab("gn9-update-6")),
            ],
            ..LessonStep::new(
                "method-9",
                "Method (9) never settles",
                "Method (9) continues the state: after an update Λ is not reset to the reference, and the new p acts from where Λ is. \
                 Watch the error after its first visit inside the tolerance, and the diagram beside the plots: the eigenvalues of the linearised update for the current Δt and ε.",
            )
        },
        LessonStep {
            set: &[("interval_s", 1.0), ("eps", 0.1)],
            tab: Some(PlotTab::Figure("error")),
            show: &["gn9", "lm10"],
            highlight: &["eps"],
            speed: Some(2.0),
            pause_at_s: Some(30.0),
            tiles: &[
                SeriesKey::new("gn9", &q::ERR_DEG),
                SeriesKey::new("lm10", &q::ERR_DEG),
            ],
            quotes: &[
                Quote::run("2.32 s", first_within("lm10")),
                Quote::run("2.02 s", first_within("gn9")),
            ],
            ..LessonStep::new(
                "method-10",
                "Method (10): ε does not damp it",
                "Method (10) adds ε to the normal equations, (UᵀQU + εI)⁻¹, the paper's remedy for a nearly singular UᵀQU. \
                 Here UᵀQU is well conditioned: over a short interval U ≈ (Δt/2)F with FᵀF = I₃, as the condition-number tab shows. \
                 Linearised, ε only lowers k to (Δt²/4)/(Δt²/4 + ε) while the determinant of the update stays 1: move ε and the eigenvalues of (10) slide along the unit circle, never inside it. \
                 So (10) keeps swinging too; it first meets the tolerance at 2.32 s instead of 2.02 s.",
            )
        },
        LessonStep {
            set: &[("interval_s", 1.0), ("eps", 0.1)],
            tab: Some(PlotTab::Figure("error")),
            show: &["gn9", "search11"],
            speed: Some(0.5),
            pause_at_s: Some(6.0),
            tiles: &[
                SeriesKey::new("gn9", &q::ERR_DEG),
                SeriesKey::new("search11", &q::ERR_DEG),
            ],
            question: Some(Question {
                ask: "Δt = 1 s. When does method (11) first come within the tolerance?",
                answers: &[
                    "At the first reference, t = 1 s",
                    "Just after 2Δt, like method (9)",
                    "Never",
                ],
                answer: 0,
                why: "Its search integrates the interval just measured again with the corrected p, so the error is removed at the update itself: within 0.01 rad at 1 s. After update 10 its largest angle error stays below 10⁻¹⁵ rad.",
            }),
            quotes: &[
                Quote::param("1 s", "interval_s"),
                Quote::run("1 s", first_within("search11")),
                Quote::param("0.01 rad", "tolerance_rad"),
                Quote::run("10⁻¹⁵ rad", Reading::Lab("search11-after-10")).at_most(),
            ],
            ..LessonStep::new(
                "method-11",
                "Method (11): a step-size search",
                "Method (11) scales the step, p(i, s) = p⁽ⁱ⁾ + s(UᵀQU + εI)⁻¹UᵀQΔΛ, and picks the s that minimises J. \
                 Every trial s needs the last interval integrated again with p(i, s); the paper names no search rule, and this lab uses a golden-section search. \
                 The run then continues from the end of the best trial.",
            )
        },
        LessonStep {
            set: &[("interval_s", 1.0)],
            tab: Some(PlotTab::Figure("error")),
            show: &["gn9", "reint"],
            speed: Some(0.5),
            pause_at_s: Some(6.0),
            tiles: &[
                SeriesKey::new("gn9", &q::ERR_DEG),
                SeriesKey::new("reint", &q::ERR_DEG),
            ],
            quotes: &[
                Quote::param("1 s", "interval_s"),
                Quote::run("0.019", Reading::Lab("reint-update-1")),
                Quote::run("0.016", Reading::Lab("reint-update-2")),
                Quote::run("7.7·10⁻⁶", Reading::Lab("reint-update-3")),
                Quote::run("2.4·10⁻⁷ rad", Reading::Lab("reint-update-4")),
            ],
            ..LessonStep::new(
                "reintegrate",
                "Re-integrate, and it converges",
                "Beyond the paper: after each update, integrate the last interval again with the new p, ε = 0, and continue from its end. \
                 Linearised, the update becomes e ← (1 − k)(e + q), q ← q − k(e + q); with k = 1 both eigenvalues are 0, at the centre of the diagram, so the error dies out instead of circling. \
                 At Δt = 1 s the largest angle error at updates 1 to 4 is 0.019, 0.016, 7.7·10⁻⁶ and 2.4·10⁻⁷ rad. \
                 Method (11) re-integrates too; linearised, its best s makes it this same update.",
            )
        },
        LessonStep {
            preset: Some("gyro-bias"),
            set: &[("interval_s", 0.5)],
            tab: Some(PlotTab::Figure("correction-variant")),
            show: &["reint"],
            highlight: &["gyro_bias_deg_s"],
            speed: Some(2.0),
            pause_at_s: Some(30.0),
            tiles: &[
                SeriesKey::new("reint", &P_X_DEG_S),
                SeriesKey::new("reint", &P_Y_DEG_S),
                SeriesKey::new("reint", &P_Z_DEG_S),
            ],
            question: Some(Question {
                ask: "The gyro adds b = 2 °/s along (1, −1, 2)/√6. Where does the correction p of the re-integrating variant go?",
                answers: &[
                    "To 0 °/s",
                    "To +b = (0.82, −0.82, 1.63) °/s",
                    "To −b = (−0.82, 0.82, −1.63) °/s",
                ],
                answer: 2,
                why: "Λ stays on the references only when ω + p is the true rate, so p must cancel the bias: after 30 s |p + b|/|b| is below 10⁻¹³, the rounding of the arithmetic. Method (10) instead keeps swinging about −b, with |p + b|/|b| = 1.7.",
            }),
            quotes: &[
                Quote::param("2 °/s", "gyro_bias_deg_s"),
                Quote::paper("(1, −1, 2)/√6"),
                Quote::posed("0 °/s"),
                Quote::paper("(0.82, −0.82, 1.63)"),
                Quote::run(
                    "(−0.82",
                    Reading::At(SeriesKey::new("reint", &P_X_DEG_S), 30.0),
                ),
                Quote::run(
                    "0.82,",
                    Reading::At(SeriesKey::new("reint", &P_Y_DEG_S), 30.0),
                ),
                Quote::run(
                    "−1.63)",
                    Reading::At(SeriesKey::new("reint", &P_Z_DEG_S), 30.0),
                ),
                Quote::pause("30 s"),
                Quote::run("10⁻¹³", Reading::Lab("reint-p-plus-b")).at_most(),
                Quote::run("1.7", Reading::Lab("lm10-p-plus-b")),
                Quote::param("0.5 s", "interval_s"),
            ],
            ..LessonStep::new(
                "gyro-bias",
                "A biased gyro: p learns −b",
                "Back to the turning body and the biased gyro of step 1, now corrected. \
                 The variant updates p every Δt = 0.5 s from the reference attitudes and integrates each interval again with the new p. \
                 The plot shows the three components of its p; the tiles read them.",
            )
        },
    ],
};
