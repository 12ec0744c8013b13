//! Truth models: how the body really moves, and the environment it moves in.

mod environment;
mod orbit;
mod prescribed;
mod rigid_body;
mod suspended_body;
mod torsion;

pub use environment::{
    Epoch, FieldModel, ecef_from_eci, eci_from_ecef, geodetic_from_ecef, gmst_rad, in_shadow,
    sun_direction_eci,
};
pub use orbit::{
    CircularOrbit, EARTH_RADIUS_M, EARTH_RATE_RAD_S, J2, MU_EARTH_M3_S2, SUN_SYNCHRONOUS_RATE_RAD_S,
};
pub use prescribed::{AngleProfile, EulerMotion};
pub use rigid_body::{RigidBody, RigidBodyState};
pub use suspended_body::SuspendedBody;
pub use torsion::{
    STRING_MATERIALS, StringMaterial, TorsionPendulum, min_string_diameter_m, string_safety_factor,
    string_stiffness_n_m_per_rad,
};
