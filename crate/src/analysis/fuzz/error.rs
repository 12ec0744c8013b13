//! What the registry fuzzer finds wrong with a set: the rule a step broke, a live change
//! refused, a heap that grew, a panic.

use crate::model::ParamError;
use crate::sim::UnknownSeries;

/// Why a fuzzed set failed. Worded in English only because only the CLI and the tests meet
/// it: a page reader never runs the fuzzer.
#[derive(Clone, Debug, thiserror::Error, PartialEq)]
pub enum FuzzError {
    /// The simulation of the set could not be made.
    #[error(transparent)]
    Setup(#[from] UnknownSeries),
    /// The change made half-way was refused.
    #[error("live change {key}={value} refused: {source}")]
    LiveChange {
        /// The parameter changed.
        key: &'static str,
        /// The value it was given.
        value: f64,
        /// Why it was refused.
        #[source]
        source: ParamError,
    },
    /// A step broke a rule.
    #[error("{rule} (live change at step {live_step}: {key}={value})")]
    Broke {
        /// The rule, and the step that broke it.
        rule: Rule,
        /// The step of the change made half-way.
        live_step: usize,
        /// The parameter it changed ("—" for a lab without parameters).
        key: &'static str,
        /// The value it gave (NaN for a lab without parameters).
        value: f64,
    },
    /// The heap grew beyond the recorder's budget and the allowance for the rest.
    #[error(
        "the heap grew by {:.1} MiB in {steps} steps, beyond the recorder's {:.1} MiB and {:.0} MiB for the rest",
        mib(.grown_bytes),
        mib(.budget_bytes),
        mib(.allowance_bytes)
    )]
    HeapGrew {
        /// How far the heap grew (bytes).
        grown_bytes: usize,
        /// The steps the set ran.
        steps: usize,
        /// The recorder's budget (bytes).
        budget_bytes: usize,
        /// What the rest may use (bytes).
        allowance_bytes: usize,
    },
    /// The set panicked, with the panic's message.
    #[error("panicked: {0}")]
    Panicked(String),
}

/// Bytes in MiB, for the messages.
fn mib(bytes: &usize) -> f64 {
    *bytes as f64 / f64::from(1 << 20)
}

/// A rule every step of every set must keep, broken: at which step, by which estimator.
#[derive(Clone, Debug, thiserror::Error, PartialEq)]
pub enum Rule {
    /// An estimate that is not finite while its status is ok.
    #[error("step {step}: {estimator} estimate not finite but status ok")]
    EstimateNotFinite {
        /// The step.
        step: u64,
        /// The estimator's id.
        estimator: &'static str,
    },
    /// A covariance whose element count is not its states squared.
    #[error("{estimator}: covariance has {elements} elements for {states} states")]
    CovarianceShape {
        /// The estimator's id.
        estimator: &'static str,
        /// The elements it has.
        elements: usize,
        /// Its states.
        states: usize,
    },
    /// A covariance that is not finite while its status is ok.
    #[error("step {step}: {estimator} covariance not finite but status ok")]
    CovarianceNotFinite {
        /// The step.
        step: u64,
        /// The estimator's id.
        estimator: &'static str,
    },
    /// A covariance that is not symmetric to 1e-9 of its largest element.
    #[error(
        "step {step}: {estimator} covariance not symmetric (|P − Pᵀ| = {asymmetry:e}, |P| = {scale:e})"
    )]
    NotSymmetric {
        /// The step.
        step: u64,
        /// The estimator's id.
        estimator: &'static str,
        /// The largest |P − Pᵀ| element.
        asymmetry: f64,
        /// The largest |P| element.
        scale: f64,
    },
    /// A covariance that is not positive semi-definite to 1e-9 of the largest |P| so far.
    #[error(
        "step {step}: {estimator} covariance not positive semi-definite (|P| = {scale:e}, largest |P| so far {peak:e})"
    )]
    NotPositive {
        /// The step.
        step: u64,
        /// The estimator's id.
        estimator: &'static str,
        /// The largest |P| element now.
        scale: f64,
        /// The largest |P| element so far (at least the smallest positive number).
        peak: f64,
    },
    /// The recorder's memory changed, or passed its budget.
    #[error("step {step}: recorder memory {memory} B (started at {memory0} B, budget {budget} B)")]
    RecorderMemory {
        /// The step.
        step: u64,
        /// Its memory now (bytes).
        memory: usize,
        /// Its memory at the start (bytes).
        memory0: usize,
        /// Its budget (bytes).
        budget: usize,
    },
}
