//! Truth models: how the body really moves.

mod prescribed;
mod rigid_body;
mod torsion;

pub use prescribed::{AngleProfile, EulerMotion};
pub use rigid_body::{RigidBody, RigidBodyState};
pub use torsion::{STRING_MATERIALS, TorsionPendulum, string_stiffness_n_m_per_rad};
