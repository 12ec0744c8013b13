//! Why a sweep's run could not be scored, and why a statistic could not be taken: typed
//! here with their facts, worded in the reader's language by the catalogue
//! (`i18n::errors`). They cross the sweep workers' boundary, so they are plain data.

use thiserror::Error;

/// Why a statistic could not be computed.
#[derive(Clone, Copy, Debug, Error, PartialEq, serde::Serialize, serde::Deserialize)]
pub enum StatsError {
    /// No values.
    #[error("no values to take a statistic of")]
    Empty,
    /// A NaN at this index.
    #[error("value {index} is NaN")]
    NotANumber {
        /// Position of the first NaN.
        index: usize,
    },
}

/// What a lab's scoring was computing when a statistic failed.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Scored {
    /// The mean squared error.
    Mse,
    /// The transient time t_tr.
    TransientTime,
    /// The offset before the step.
    OffsetBefore,
    /// The offset after the step.
    OffsetAfter,
    /// The noise.
    Noise,
    /// The RMS against a reference.
    Rms,
    /// The jitter.
    Jitter,
}

impl Scored {
    /// Its name in the catalogue's select (`$of`).
    pub fn key(self) -> &'static str {
        match self {
            Scored::Mse => "mse",
            Scored::TransientTime => "t-tr",
            Scored::OffsetBefore => "offset-before",
            Scored::OffsetAfter => "offset-after",
            Scored::Noise => "noise",
            Scored::Rms => "rms",
            Scored::Jitter => "jitter",
        }
    }
}

impl std::fmt::Display for Scored {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Scored::Mse => "MSE",
            Scored::TransientTime => "t_tr",
            Scored::OffsetBefore => "offset before the step",
            Scored::OffsetAfter => "offset after the step",
            Scored::Noise => "noise",
            Scored::Rms => "RMS",
            Scored::Jitter => "jitter",
        })
    }
}

/// Why one run of a sweep could not be scored.
#[derive(Clone, Copy, Debug, Error, PartialEq, serde::Serialize, serde::Deserialize)]
pub enum ScoreError {
    /// The scoring was handed another number of series than it scores.
    #[error("expected {expected} series, got {got}")]
    Columns {
        /// Series it scores.
        expected: usize,
        /// Series handed.
        got: usize,
    },
    /// The run has no samples.
    #[error("an empty run")]
    EmptyRun,
    /// The filter's error is not a number at the end of the run.
    #[error("the tuned filter's error is not a number (diverged)")]
    Diverged,
    /// No set-point step, so no transient to time.
    #[error("the set-point step is 0°, so there is no transient to time")]
    NoStep,
    /// The run ends too soon after the step to time the transient.
    #[error("the run ends at {end_s:.1} s, too soon after the step at {step_s:.1} s")]
    EndsTooSoon {
        /// When the run ends (s).
        end_s: f64,
        /// When the step comes (s).
        step_s: f64,
    },
    /// Too few samples have both series.
    #[error("only {n} samples have both θ̂ and the accelerometer angle")]
    FewSamples {
        /// Samples that have both.
        n: usize,
    },
    /// A statistic of the scoring failed.
    #[error("{of}: {source}")]
    Stat {
        /// What was being computed.
        of: Scored,
        /// Why it failed.
        source: StatsError,
    },
    /// The scoring returned another number of scores than it names.
    #[error("the scoring gave {got} numbers for {expected} scores")]
    Count {
        /// Numbers returned.
        got: usize,
        /// Scores named.
        expected: usize,
    },
}

impl ScoreError {
    /// One of each kind (the match fails to compile when a kind is added and not listed):
    /// the catalogue's test words every one in both languages.
    pub fn examples() -> Vec<ScoreError> {
        let all = vec![
            ScoreError::Columns {
                expected: 3,
                got: 2,
            },
            ScoreError::EmptyRun,
            ScoreError::Diverged,
            ScoreError::NoStep,
            ScoreError::EndsTooSoon {
                end_s: 4.5,
                step_s: 4.0,
            },
            ScoreError::FewSamples { n: 12 },
            ScoreError::Stat {
                of: Scored::TransientTime,
                source: StatsError::NotANumber { index: 7 },
            },
            ScoreError::Stat {
                of: Scored::Mse,
                source: StatsError::Empty,
            },
            ScoreError::Count {
                got: 2,
                expected: 4,
            },
        ];
        for e in &all {
            match e {
                ScoreError::Columns { .. }
                | ScoreError::EmptyRun
                | ScoreError::Diverged
                | ScoreError::NoStep
                | ScoreError::EndsTooSoon { .. }
                | ScoreError::FewSamples { .. }
                | ScoreError::Stat { .. }
                | ScoreError::Count { .. } => {}
            }
        }
        all
    }
}

/// A run of a sweep that could not be scored: its seed and why.
#[derive(Clone, Copy, Debug, Error, PartialEq, serde::Serialize, serde::Deserialize)]
#[error("seed {seed}: {why}")]
pub struct Unscored {
    /// The run's seed.
    pub seed: u64,
    /// Why.
    pub why: ScoreError,
}
