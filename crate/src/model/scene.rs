//! What a truth model gives the 3D view beside the attitude: reference directions and where
//! the body is on its orbit, in the reference frame. Data, not drawing: the page picks each
//! direction's colour by its kind.

use nalgebra::Vector3;

/// A reference direction drawn from the body in the 3D view.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SceneVector {
    /// Short label at its tip.
    pub label: &'static str,
    /// Unit direction in the reference frame.
    pub dir_ref: Vector3<f64>,
    /// What it points at (the page picks its colour by this).
    pub kind: Direction,
}

/// What a reference direction points at.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Direction {
    /// The Sun.
    Sun,
    /// The magnetic field.
    MagneticField,
    /// The nadir (towards the Earth's centre).
    Nadir,
}

/// Where a satellite is on its orbit, for a small picture of the Earth beside the body.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OrbitPicture {
    /// Position (ECI, m).
    pub position_eci_m: Vector3<f64>,
    /// Unit orbit normal (ECI).
    pub normal_eci: Vector3<f64>,
    /// Unit sun direction (ECI).
    pub sun_eci: Vector3<f64>,
    /// In the Earth's shadow.
    pub eclipse: bool,
    /// Earth radius (m).
    pub earth_radius_m: f64,
}

/// What a lab's sensors add to the 3D view.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SceneExtras {
    /// Reference directions (sun, field, nadir …).
    pub vectors: Vec<SceneVector>,
    /// The orbit, if the lab flies one.
    pub orbit: Option<OrbitPicture>,
}
