//! The registry fuzzer: every lab, random parameter sets drawn inside the declared ranges
//! (log-uniform where the slider is logarithmic, both ends included), random seeds, a live
//! change half-way, a few thousand steps. It asserts what must hold for any input: no panic;
//! every estimate finite unless its status says why not; every covariance symmetric and
//! positive semi-definite; the recorder's memory fixed within its budget; and, where the
//! binary counts its heap ([`count_heap_with`]: the CLI does), a set's whole heap within
//! its recorder's budget and [`HEAP_ALLOWANCE_BYTES`].
//! `cargo xtask test` runs it over 1 000 sets, `attlab fuzz --sets N` for longer.

mod error;

pub use error::{FuzzError, Rule};

use crate::model::{ParamKind, ParamSpec, ParamValues, Scale};
use crate::page::Lab;
use crate::sim::{SimOptions, Simulation};
use nalgebra::DMatrix;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::sync::OnceLock;

/// The heap a set may use beyond its recorder's budget (estimators, windows, messages).
pub const HEAP_ALLOWANCE_BYTES: usize = 16 << 20;

/// How the process counts its live heap bytes, if it does.
static LIVE_HEAP: OnceLock<fn() -> usize> = OnceLock::new();

/// Makes every later set measure the process's heap with `live_bytes` (the bytes allocated
/// and not freed, from a counting global allocator). Only a single-threaded run should: the
/// count is process-wide.
pub fn count_heap_with(live_bytes: fn() -> usize) {
    let _ = LIVE_HEAP.set(live_bytes);
}

/// Live bytes from `stats_alloc`'s counts (of a process or of a region): allocated less
/// freed, plus what reallocations added (its `bytes_reallocated` is already net, signed).
#[cfg(not(target_arch = "wasm32"))]
pub fn live_bytes(s: &stats_alloc::Stats) -> isize {
    s.bytes_allocated as isize - s.bytes_deallocated as isize + s.bytes_reallocated
}

/// How long and how many.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FuzzConfig {
    /// Parameter sets, spread over the labs in turn.
    pub sets: usize,
    /// Steps per set.
    pub steps: usize,
    /// Seed of the parameter draws.
    pub seed: u64,
}

impl Default for FuzzConfig {
    fn default() -> Self {
        Self {
            sets: 1000,
            steps: 2000,
            seed: 1,
        }
    }
}

/// One set that broke a rule.
#[derive(Clone, Debug, PartialEq)]
pub struct FuzzFailure {
    /// Lab id.
    pub lab: &'static str,
    /// Simulation seed.
    pub seed: u64,
    /// The parameters, as `key=value`.
    pub params: String,
    /// What went wrong, and at which step.
    pub what: FuzzError,
}

impl std::fmt::Display for FuzzFailure {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{} seed {}: {} (reproduce: attlab run --lab {} --seed {} {})",
            self.lab,
            self.seed,
            self.what,
            self.lab,
            self.seed,
            self.params
                .split(' ')
                .filter(|s| !s.is_empty())
                .map(|s| format!("--set {s}"))
                .collect::<Vec<_>>()
                .join(" ")
        )
    }
}

/// What a fuzz run found.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct FuzzReport {
    /// Sets run per lab id.
    pub sets_per_lab: Vec<(&'static str, usize)>,
    /// Sets in which some estimator said it diverged or is unobservable (allowed, counted).
    pub flagged: usize,
    /// Rule violations.
    pub failures: Vec<FuzzFailure>,
    /// Largest recorder memory seen (bytes) and the budget.
    pub max_memory_bytes: usize,
    /// Largest heap a set grew by (bytes), where the heap is counted.
    pub max_heap_bytes: Option<usize>,
}

/// A random value of `spec`: an end of the range with probability 1/10 each, otherwise
/// uniform (log-uniform on a log slider; a log slider starting at 0 draws from 1e-4 up and
/// hits 0 as its left end).
pub fn random_value(spec: &ParamSpec, rng: &mut ChaCha8Rng) -> f64 {
    let (lo, hi) = (spec.min, spec.max);
    let end: f64 = rng.random();
    let v = match spec.kind {
        ParamKind::Toggle => f64::from(u8::from(rng.random::<bool>())),
        ParamKind::Choice(options) => rng.random_range(0..options.len().max(1)) as f64,
        _ if end < 0.1 => lo,
        _ if end < 0.2 => hi,
        _ if spec.scale == Scale::Log => {
            let a = if lo > 0.0 { lo } else { (1e-4_f64).min(hi) };
            if a >= hi {
                hi
            } else {
                (rng.random_range(a.ln()..=hi.ln())).exp()
            }
        }
        _ => rng.random_range(lo..=hi),
    };
    let v = if spec.kind == ParamKind::Integer {
        v.round()
    } else {
        v
    };
    v.clamp(lo, hi)
}

/// A random valid parameter set of `lab`.
pub fn random_params(lab: &dyn Lab, rng: &mut ChaCha8Rng) -> ParamValues {
    let mut p = ParamValues::defaults(lab.params());
    for spec in lab.params() {
        let v = random_value(spec, rng);
        // Values drawn inside the declared range are valid by construction; a refusal here
        // would be a bug in the spec (the conformance tests check the specs).
        let _ = p.set(lab.params(), spec.key, v);
    }
    p
}

fn describe(p: &ParamValues) -> String {
    p.iter()
        .map(|(k, v)| format!("{k}={v}"))
        .collect::<Vec<_>>()
        .join(" ")
}

/// Checks the rules on the simulation's current state; the first violation, if any.
/// `peaks` holds, per estimator, the largest |P| element seen so far: an update that cancels
/// a large prior leaves rounding of that size, so positive semi-definiteness is judged to
/// 1e-9 of it.
fn violation(sim: &Simulation, budget: usize, memory0: usize, peaks: &mut [f64]) -> Option<Rule> {
    let step = sim.steps();
    for (((e, est), status), peak) in sim
        .estimators()
        .iter()
        .zip(sim.estimates())
        .zip(sim.statuses())
        .zip(peaks)
    {
        if !status.is_ok() {
            continue;
        }
        let estimator = e.id();
        if !est.is_finite() {
            return Some(Rule::EstimateNotFinite { step, estimator });
        }
        if let Some(c) = e.covariance() {
            let n = c.dim();
            if c.matrix.len() != n * n {
                return Some(Rule::CovarianceShape {
                    estimator,
                    elements: c.matrix.len(),
                    states: n,
                });
            }
            let p = DMatrix::from_column_slice(n, n, c.matrix);
            let scale = p.amax();
            if !scale.is_finite() {
                return Some(Rule::CovarianceNotFinite { step, estimator });
            }
            *peak = peak.max(scale);
            let asymmetry = (&p - p.transpose()).amax();
            if asymmetry > 1e-9 * scale.max(f64::MIN_POSITIVE) {
                return Some(Rule::NotSymmetric {
                    step,
                    estimator,
                    asymmetry,
                    scale,
                });
            }
            // Positive semi-definite to rounding: P/peak + 1e-9·I has a Cholesky factor (an
            // eigenvalue below −1e-9·peak makes it fail). Bounded time, unlike an eigen
            // solver fed extreme values.
            let unit = peak.max(f64::MIN_POSITIVE);
            let shifted = &p / unit + DMatrix::identity(n, n) * 1e-9;
            if shifted.cholesky().is_none() {
                return Some(Rule::NotPositive {
                    step,
                    estimator,
                    scale,
                    peak: unit,
                });
            }
        }
    }
    let memory = sim.recorder().memory_bytes();
    if memory != memory0 || memory > budget {
        return Some(Rule::RecorderMemory {
            step,
            memory,
            memory0,
            budget,
        });
    }
    None
}

/// What one set used and said.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SetOutcome {
    /// Some estimator flagged itself (diverged, unobservable).
    pub flagged: bool,
    /// The recorder's memory (bytes).
    pub recorder_bytes: usize,
    /// How far the heap grew during the set (bytes), where it is counted.
    pub heap_bytes: Option<usize>,
}

/// Runs one set: the first rule it breaks, or what it used and said.
pub fn fuzz_one(
    lab: &'static dyn Lab,
    params: ParamValues,
    seed: u64,
    steps: usize,
    rng: &mut ChaCha8Rng,
) -> Result<SetOutcome, FuzzError> {
    let live_heap = LIVE_HEAP.get().copied();
    let heap0 = live_heap.map(|f| f());
    let mut heap_peak = heap0;
    let options = SimOptions::default();
    let budget = options.budget_bytes;
    let mut sim = Simulation::with_options(lab, params, seed, options)?;
    let memory0 = sim.recorder().memory_bytes();
    let mut peaks = vec![0.0; sim.estimators().len()];
    let specs = lab.params();
    let live = (!specs.is_empty()).then(|| {
        let spec = &specs[rng.random_range(0..specs.len())];
        (spec.key, random_value(spec, rng))
    });
    let (live_key, live_value) = live.unwrap_or(("—", f64::NAN));
    for k in 0..steps {
        if k == steps / 2 && live.is_some() {
            sim.set_param(live_key, live_value)
                .map_err(|source| FuzzError::LiveChange {
                    key: live_key,
                    value: live_value,
                    source,
                })?;
        }
        sim.step();
        if let Some(rule) = violation(&sim, budget, memory0, &mut peaks) {
            return Err(FuzzError::Broke {
                rule,
                live_step: steps / 2,
                key: live_key,
                value: live_value,
            });
        }
        if let Some(f) = live_heap.filter(|_| k % 64 == 63 || k + 1 == steps) {
            heap_peak = heap_peak.max(Some(f()));
        }
    }
    let heap_bytes = heap0.zip(heap_peak).map(|(a, b)| b.saturating_sub(a));
    if let Some(grown_bytes) = heap_bytes.filter(|g| *g > budget + HEAP_ALLOWANCE_BYTES) {
        return Err(FuzzError::HeapGrew {
            grown_bytes,
            steps,
            budget_bytes: budget,
            allowance_bytes: HEAP_ALLOWANCE_BYTES,
        });
    }
    Ok(SetOutcome {
        flagged: sim.statuses().iter().any(|s| !s.is_ok()),
        recorder_bytes: memory0,
        heap_bytes,
    })
}

/// Runs `config.sets` sets over every lab in `labs` in turn; `progress` is told each set.
/// A set that panics is a failure with its reproduction line (the release profile unwinds
/// for this), and the sets after it still run.
pub fn run(
    labs: &[&'static dyn Lab],
    config: FuzzConfig,
    progress: impl FnMut(usize, &str),
) -> FuzzReport {
    run_with(labs, config, progress, fuzz_one)
}

/// What one set runs: [`fuzz_one`]'s signature.
type OneSet =
    fn(&'static dyn Lab, ParamValues, u64, usize, &mut ChaCha8Rng) -> Result<SetOutcome, FuzzError>;

/// [`run`] with `one` running each set.
fn run_with(
    labs: &[&'static dyn Lab],
    config: FuzzConfig,
    mut progress: impl FnMut(usize, &str),
    one: OneSet,
) -> FuzzReport {
    let mut rng = ChaCha8Rng::seed_from_u64(config.seed);
    let mut report = FuzzReport {
        sets_per_lab: labs.iter().map(|l| (l.id(), 0)).collect(),
        ..FuzzReport::default()
    };
    for set in 0..config.sets {
        let which = set % labs.len().max(1);
        let Some(&lab) = labs.get(which) else { break };
        let params = random_params(lab, &mut rng);
        let seed: u64 = rng.random();
        let described = describe(&params);
        progress(set, lab.id());
        let mut set_rng = ChaCha8Rng::seed_from_u64(rng.random());
        let outcome = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            one(lab, params, seed, config.steps, &mut set_rng)
        }));
        report.sets_per_lab[which].1 += 1;
        let what = match outcome {
            Ok(Ok(outcome)) => {
                report.flagged += usize::from(outcome.flagged);
                report.max_memory_bytes = report.max_memory_bytes.max(outcome.recorder_bytes);
                report.max_heap_bytes = report.max_heap_bytes.max(outcome.heap_bytes);
                None
            }
            Ok(Err(failed)) => Some(failed),
            Err(panic) => Some(FuzzError::Panicked(
                panic
                    .downcast_ref::<String>()
                    .cloned()
                    .or_else(|| panic.downcast_ref::<&str>().map(|s| s.to_string()))
                    .unwrap_or_default(),
            )),
        };
        if let Some(what) = what {
            report.failures.push(FuzzFailure {
                lab: lab.id(),
                seed,
                params: described,
                what,
            });
        }
    }
    report
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A set runner with a bug: the third set panics.
    fn panics_on_the_third_set(
        lab: &'static dyn Lab,
        params: ParamValues,
        seed: u64,
        steps: usize,
        rng: &mut ChaCha8Rng,
    ) -> Result<SetOutcome, FuzzError> {
        thread_local!(static CALLS: std::cell::Cell<usize> = const { std::cell::Cell::new(0) });
        let n = CALLS.with(|c| {
            c.set(c.get() + 1);
            c.get()
        });
        if n == 3 {
            panic!("injected at set {n}");
        }
        fuzz_one(lab, params, seed, steps, rng)
    }

    #[test]
    fn a_panicking_set_is_reported_with_its_reproduction_line_and_the_rest_still_run() {
        let labs = crate::labs::all();
        let config = FuzzConfig {
            sets: 5,
            steps: 20,
            seed: 7,
        };
        let report = run_with(labs, config, |_, _| {}, panics_on_the_third_set);
        assert_eq!(report.failures.len(), 1, "{:?}", report.failures);
        let line = report.failures[0].to_string();
        let lab = labs[2 % labs.len()].id();
        assert!(line.contains("panicked: injected at set 3"), "{line}");
        assert!(
            line.contains(&format!("(reproduce: attlab run --lab {lab} --seed ")),
            "{line}"
        );
        let ran: usize = report.sets_per_lab.iter().map(|(_, n)| n).sum();
        assert_eq!(ran, 5, "the sets after the panic still ran");
    }
}
