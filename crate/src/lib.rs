//! # Attitude Lab core
//!
//! Pure simulation code for the Attitude Lab teaching simulator: rotations and attitude
//! parameterisations ([`math`]), truth dynamics ([`dynamics`]), sensor models
//! ([`sensors`]), estimators ([`estimators`]), the paper labs ([`labs`]), the fixed-step
//! loop ([`sim`]) and the recorder ([`record`]). No UI, no clock, no global RNG: randomness
//! comes in as a seeded ChaCha RNG, so one `(lab, parameters, seed)` gives one run.

pub mod dynamics;
pub mod estimators;
pub mod labs;
pub mod math;
pub mod params;
pub mod record;
pub mod sensors;
pub mod sim;
pub mod state;
pub mod sweep;
