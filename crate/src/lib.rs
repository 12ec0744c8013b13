//! # Attitude Lab core
//!
//! Pure simulation code for the Attitude Lab teaching simulator. No UI, no clock, no global
//! RNG: randomness comes in as a seeded ChaCha RNG, so one `(lab, parameters, seed)` gives
//! one run. Dependencies point one way:
//!
//! ```text
//! math → model → dynamics, sensors, estimators → record, sim → analysis → labs → state
//! ```
//!
//! * [`math`]: rotations, attitude parameterisations, integrators, covariance helpers.
//! * [`model`]: the contracts (lab, truth, sensors, estimator, estimate, parameters,
//!   reports): a leaf.
//! * [`dynamics`], [`sensors`], [`estimators`]: the parts labs are built from.
//! * [`record`]: series over the whole run in a fixed memory budget.
//! * [`sim`]: the fixed-step loop, the row layout, replays of recorded logs, CSV.
//! * [`analysis`]: NaN-aware statistics, scenarios, sweeps, the registry fuzzer.
//! * [`labs`]: the registry `labs::all()`, one folder per paper.
//! * [`state`]: the shareable URL state.
//! * [`i18n`]: the message catalogue (English and Russian), a leaf.

// A panic in the product is a bug to report, not an answer: fallible paths return typed
// errors. Tests may unwrap (clippy.toml allows it in tests).
#![deny(clippy::unwrap_used, clippy::expect_used)]

pub mod analysis;
pub mod dynamics;
pub mod estimators;
pub mod i18n;
pub mod labs;
pub mod lessons;
pub mod math;
pub mod model;
pub mod page;
pub mod record;
pub mod sensors;
pub mod sim;
pub mod state;
#[cfg(all(feature = "study", not(target_arch = "wasm32")))]
pub mod teacher;
