//! The registry of labs: one folder (or file) per paper, all listed in [`all`]. The UI's lab
//! picker, the CLI and the conformance tests iterate this one list; registering a lab is
//! one line.

pub mod free_rotation;
pub mod p1_suspended;
pub mod p2_tabletsat;
pub mod p3_wz_sphere;
pub mod p4_quadrotor;
pub mod p5_sensitivity;

pub use free_rotation::FreeRotation;
pub use p1_suspended::SuspendedMockup;
pub use p2_tabletsat::TabletSat;
pub use p3_wz_sphere::WzSphere;
pub use p4_quadrotor::QuadrotorRoll;
pub use p5_sensitivity::SensitivityLab;

use crate::model::Lab;

/// Every lab, in menu order.
pub fn all() -> &'static [&'static dyn Lab] {
    &[
        &FreeRotation,
        &SuspendedMockup,
        &TabletSat,
        &WzSphere,
        &QuadrotorRoll,
        &SensitivityLab,
    ]
}

/// The lab with this id.
pub fn find(id: &str) -> Option<&'static dyn Lab> {
    all().iter().copied().find(|l| l.id() == id)
}

/// Comma-separated ids of all labs (for error messages).
pub fn ids() -> String {
    all().iter().map(|l| l.id()).collect::<Vec<_>>().join(", ")
}
