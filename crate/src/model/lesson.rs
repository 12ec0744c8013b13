//! A lab's lesson, as data: a few guided steps written from the paper, each a short text, the
//! state it sets (parameters, plot tab, shown filters, speed, where to pause) and, optionally,
//! a question asked before the run shows the answer ("predict, then see").
//!
//! Every step is absolute: its state is the lab's defaults, then its preset, then its own
//! values, so `lesson=p2&step=4` opens exactly what walking to step 4 shows. The page words
//! the texts through the catalogue (`lesson-<lab>-<step>-title`, `-text`, `-ask`, `-answer-<k>`,
//! `-why`, numbered from 1); the English here is the fallback and the source of the
//! translations.

use super::key::SeriesKey;
use super::series::PlotTab;

/// A lab's guided lesson.
#[derive(Clone, Copy, Debug)]
pub struct Lesson {
    /// What the lesson shows, in one line.
    pub title: &'static str,
    /// The steps, in order (5–8).
    pub steps: &'static [LessonStep],
}

/// One step of a lesson.
#[derive(Clone, Copy, Debug)]
pub struct LessonStep {
    /// A heading of a few words.
    pub title: &'static str,
    /// 2–5 sentences in the paper's notation, with its equation and figure numbers.
    pub text: &'static str,
    /// A preset of the lab applied on top of its defaults, by name.
    pub preset: Option<&'static str>,
    /// Parameter values set on top of the defaults and the preset.
    pub set: &'static [(&'static str, f64)],
    /// The plot tab shown (the lab's default tab when `None`).
    pub tab: Option<PlotTab>,
    /// The estimators shown, by id; every other one is hidden (all shown when empty).
    pub show: &'static [&'static str],
    /// Parameters whose sliders the step points at (outlined in the controls).
    pub highlight: &'static [&'static str],
    /// Simulated seconds per wall-clock second (the lab's link speed when `None`).
    pub speed: Option<f64>,
    /// The run pauses when it reaches this time (s), so the class looks at the same picture.
    pub pause_at_s: Option<f64>,
    /// The values the back row reads in presenter mode, as large tiles.
    pub tiles: &'static [SeriesKey],
    /// A question asked before the step runs.
    pub question: Option<Question>,
    /// The terms of the filter's cycle the step talks about (highlighted in the page's
    /// step-through panel, which the step opens when it names any).
    pub terms: &'static [CycleTerm],
    /// The lab's sweep (by index in its study's sweeps) the step starts in the background.
    pub sweep: Option<usize>,
}

/// A term of the Kalman filter's cycle (see [`super::KalmanCycle`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CycleTerm {
    /// x̂⁻ = Φx̂.
    PriorState,
    /// P⁻ = ΦPΦᵀ + Q.
    PriorCovariance,
    /// Q.
    ProcessNoise,
    /// R.
    MeasurementNoise,
    /// The innovation z − Hx̂⁻ and its covariance S.
    Innovation,
    /// K = P⁻HᵀS⁻¹.
    Gain,
    /// x̂⁺ = x̂⁻ + K(z − Hx̂⁻).
    PosteriorState,
    /// P⁺.
    PosteriorCovariance,
}

impl LessonStep {
    /// A step with a title and a text and nothing else set: the base that steps in a lab's
    /// lesson file update (`..LessonStep::new("…", "…")`).
    pub const fn new(title: &'static str, text: &'static str) -> Self {
        Self {
            title,
            text,
            preset: None,
            set: &[],
            tab: None,
            show: &[],
            highlight: &[],
            speed: None,
            pause_at_s: None,
            tiles: &[],
            question: None,
            terms: &[],
            sweep: None,
        }
    }
}

/// A question with 2–4 answers: the page records the reader's choice, then runs the step and
/// shows which answer the run supports, with one sentence of why. Nothing is graded.
#[derive(Clone, Copy, Debug)]
pub struct Question {
    /// The question.
    pub ask: &'static str,
    /// The answers offered.
    pub answers: &'static [&'static str],
    /// The index of the answer the run shows.
    pub answer: usize,
    /// One or two sentences of why, shown after the run.
    pub why: &'static str,
}

impl Lesson {
    /// The step with this 1-based number, if the lesson has it.
    pub fn step(&self, number: usize) -> Option<&'static LessonStep> {
        number.checked_sub(1).and_then(|i| self.steps.get(i))
    }
}
