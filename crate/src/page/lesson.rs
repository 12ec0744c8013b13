//! A lab's lesson, as data: a few guided steps written from the paper, each a short text, the
//! state it sets (parameters, plot tab, shown filters, speed, where to pause) and, optionally,
//! a question asked before the run shows the answer ("predict, then see").
//!
//! Every step is absolute: its state is the lab's defaults, then its preset, then its own
//! values, so `lesson=p2&step=4` opens exactly what walking to step 4 shows. The page words
//! the texts through the catalogue (`lesson-<lab>-<step>-title`, `-text`, `-ask`, `-answer-<k>`,
//! `-why`, numbered from 1); the English here is the fallback and the source of the
//! translations.

use crate::model::{PlotTab, SeriesKey};

/// A lab's guided lesson.
#[derive(Clone, Copy, Debug)]
pub struct Lesson {
    /// What the lesson shows, in one line.
    pub title: &'static str,
    /// The steps, in order (5–8).
    pub steps: &'static [LessonStep],
    /// The step, by id, that the lesson's screenshot shows (docs/lessons.md, taken by the
    /// page test on a projector): one that asks a question.
    pub showcase: &'static str,
}

/// One step of a lesson.
#[derive(Clone, Copy, Debug)]
pub struct LessonStep {
    /// Stable id within the lesson (`small-gamma`): its messages name it; a link and the
    /// page number steps by their place.
    pub id: &'static str,
    /// A heading of a few words.
    pub title: &'static str,
    /// 2–5 sentences in the paper's notation, with its equation and figure numbers.
    pub text: &'static str,
    /// A preset of the lab applied on top of its defaults, by its id.
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
    /// The lab's sweep (by its id) the step starts in the background.
    pub sweep: Option<&'static str>,
    /// Every number the step's words quote, and where it comes from: a test reads each one
    /// off the run the step opens (or the run it names), so the words hold for the screen.
    pub quotes: &'static [Quote],
}

/// A term of the Kalman filter's cycle (see [`crate::model::KalmanCycle`]).
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
    /// lesson file update (`..LessonStep::new("id", "…", "…")`).
    pub const fn new(id: &'static str, title: &'static str, text: &'static str) -> Self {
        Self {
            id,
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
            quotes: &[],
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

/// A number a step's words quote ("0.19°", "2.36 s", "6·10⁻¹³ °"), as the English writes
/// it (the Russian writes the same number with a decimal comma), and where it comes from.
#[derive(Clone, Copy, Debug)]
pub struct Quote {
    /// The number with its unit, as the English text, question, answers or why write it.
    pub shown: &'static str,
    /// Where it comes from.
    pub source: QuoteSource,
}

/// Where a quoted number comes from.
#[derive(Clone, Copy, Debug)]
pub enum QuoteSource {
    /// The value of parameter `key` in the step's run (in the parameter's unit).
    Param(&'static str),
    /// The time the step pauses at (s).
    Pause,
    /// The paper's number, or a constant of the lab's model the words explain: not read off
    /// the run.
    Paper,
    /// A number the question or a wrong answer poses ("About 0.1°: the bias is tiny"), or a
    /// round figure the words compare with: not a claim about the run.
    Posed,
    /// Read off a run: the step's own, or it with `with` on top (a value the words compare
    /// with), at seed 1, as the page opens it.
    Run {
        /// Parameter values on top of the step's.
        with: &'static [(&'static str, f64)],
        /// What is read.
        reading: Reading,
        /// How the reading must compare with the number.
        holds: Holds,
        /// What the reading is multiplied by to be in the words' unit (1 but where the words
        /// give a degree reading in radians, π/180).
        scale: f64,
    },
}

/// How a reading must compare with the number the words write.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Holds {
    /// It rounds to the digits written.
    Digits,
    /// Within a share of the number: for words that say "about" or "≈".
    About(f64),
    /// At most the number: "under 0.2°", "within 0.1°".
    AtMost,
}

/// What a quote reads off a run, a series by its key over a span of time (s).
#[derive(Clone, Copy, Debug)]
pub enum Reading {
    /// The value at time `t`.
    At(SeriesKey, f64),
    /// The last finite value at or before time `t` (where the plot's line ends: w near ∞).
    LastFinite(SeriesKey, f64),
    /// The root mean square over [from, to].
    Rms(SeriesKey, f64, f64),
    /// The standard deviation about the mean over [from, to].
    Std(SeriesKey, f64, f64),
    /// The mean over [from, to].
    Mean(SeriesKey, f64, f64),
    /// The least value over [from, to].
    Min(SeriesKey, f64, f64),
    /// The greatest value over [from, to].
    Max(SeriesKey, f64, f64),
    /// The largest |value − value at `from`| over [from, to], as a share of |value at
    /// `from`| (a conserved quantity's drift).
    Drift(SeriesKey, f64, f64),
    /// The square root of the value at `t` (a standard deviation from a variance).
    SqrtAt(SeriesKey, f64),
    /// The largest |value| over [from, to].
    MaxAbs(SeriesKey, f64, f64),
    /// The largest |a − b| over [from, to].
    MaxAbsDiff(SeriesKey, SeriesKey, f64, f64),
    /// The root mean square of a − b over [from, to].
    RmsDiff(SeriesKey, SeriesKey, f64, f64),
    /// The first time in [from, to] at which |value| is at most `bound`.
    FirstWithin(SeriesKey, f64, f64, f64),
    /// The first time in [from, to] at which |a − b| is at most `bound`.
    FirstClose(SeriesKey, SeriesKey, f64, f64, f64),
    /// The first time in [from, to] at which the value exceeds `level`.
    FirstAbove(SeriesKey, f64, f64, f64),
    /// The largest of an estimator's per-axis RMS attitude errors over [from, to]: the σ of
    /// the accuracy table.
    WorstAxisRms(&'static str, f64, f64),
    /// A reading of the lab's own, by a name its study knows (the updates' errors of paper
    /// 5, a settling time): see `Study::lesson_reading`.
    Lab(&'static str),
}

impl Quote {
    /// A parameter's value.
    pub const fn param(shown: &'static str, key: &'static str) -> Self {
        Self {
            shown,
            source: QuoteSource::Param(key),
        }
    }

    /// The paper's number or the model's constant.
    pub const fn paper(shown: &'static str) -> Self {
        Self {
            shown,
            source: QuoteSource::Paper,
        }
    }

    /// A number a question or an answer poses.
    pub const fn posed(shown: &'static str) -> Self {
        Self {
            shown,
            source: QuoteSource::Posed,
        }
    }

    /// The time the step pauses at.
    pub const fn pause(shown: &'static str) -> Self {
        Self {
            shown,
            source: QuoteSource::Pause,
        }
    }

    /// Read off the step's run, to the digits shown.
    pub const fn run(shown: &'static str, reading: Reading) -> Self {
        Self::run_with(shown, &[], reading)
    }

    /// Read off the step's run with `with` on top, to the digits shown.
    pub const fn run_with(
        shown: &'static str,
        with: &'static [(&'static str, f64)],
        reading: Reading,
    ) -> Self {
        Self {
            shown,
            source: QuoteSource::Run {
                with,
                reading,
                holds: Holds::Digits,
                scale: 1.0,
            },
        }
    }

    /// The same, within a share `share` of the number: for words that say "about".
    pub const fn about(self, share: f64) -> Self {
        self.holding(Holds::About(share))
    }

    /// The same, at most the number: for words that say "under" or "within".
    pub const fn at_most(self) -> Self {
        self.holding(Holds::AtMost)
    }

    const fn holding(mut self, holds: Holds) -> Self {
        if let QuoteSource::Run { holds: h, .. } = &mut self.source {
            *h = holds;
        }
        self
    }

    /// The same, the reading multiplied by `scale` into the words' unit (a degree reading
    /// written in radians: π/180).
    pub const fn scaled(mut self, scale: f64) -> Self {
        if let QuoteSource::Run { scale: s, .. } = &mut self.source {
            *s = scale;
        }
        self
    }
}

impl Lesson {
    /// The 1-based number of the step with this id, if the lesson has it.
    pub fn number_of(&self, step_id: &str) -> Option<usize> {
        self.steps
            .iter()
            .position(|s| s.id == step_id)
            .map(|i| i + 1)
    }

    /// The step with this 1-based number, if the lesson has it.
    pub fn step(&self, number: usize) -> Option<&'static LessonStep> {
        number.checked_sub(1).and_then(|i| self.steps.get(i))
    }
}
