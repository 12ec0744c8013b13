//! Truth models: how the body really moves.

mod rigid_body;

pub use rigid_body::{RigidBody, RigidBodyState};
