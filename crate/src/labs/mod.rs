//! The registry of labs: one folder (or file) per paper, all listed in [`all`]. The UI's lab
//! picker, the CLI and the conformance tests iterate this one list; registering a lab is
//! one line.

pub mod free_rotation;
pub mod p1_suspended;
pub mod p3_wz_sphere;

pub use free_rotation::FreeRotation;
pub use p1_suspended::SuspendedMockup;
pub use p3_wz_sphere::WzSphere;

use crate::model::Lab;

/// Every lab, in menu order.
pub fn all() -> &'static [&'static dyn Lab] {
    &[&FreeRotation, &SuspendedMockup, &WzSphere]
}

/// The lab with this id.
pub fn find(id: &str) -> Option<&'static dyn Lab> {
    all().iter().copied().find(|l| l.id() == id)
}

/// Comma-separated ids of all labs (for error messages).
pub fn ids() -> String {
    all().iter().map(|l| l.id()).collect::<Vec<_>>().join(", ")
}
