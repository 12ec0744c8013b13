//! Truth models: how the body really moves.

mod prescribed;
mod rigid_body;

pub use prescribed::{AngleProfile, EulerMotion};
pub use rigid_body::{RigidBody, RigidBodyState};
