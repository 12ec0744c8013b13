//! What the MEKF reads besides the attitude sensors, which its lab's flight computer
//! provides in [`crate::model::Measurements::lab`].

use nalgebra::Vector3;

/// What the onboard computer of paper 2's satellite knows each step besides its attitude
/// sensors: from the orbit (GPS or a TLE) and its models, the reference directions in the
/// orbital frame, and from the wheels the momentum and the commanded torque. Computed once
/// per step and shared by every filter.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Onboard {
    /// The orbital frame's angular velocity in orbital axes (rad/s).
    pub frame_rate_orbit_rad_s: Vector3<f64>,
    /// 3μ/r³ (1/s²) of the gravity-gradient torque.
    pub gravity_gradient_coeff: f64,
    /// The onboard field model's field in orbital axes (nT).
    pub mag_ref_orbit_nt: Vector3<f64>,
    /// The sun direction in orbital axes (unit), from the onboard ephemeris.
    pub sun_ref_orbit: Vector3<f64>,
    /// Wheel angular momentum in body axes (N·m·s).
    pub wheel_momentum_body: Vector3<f64>,
    /// Its rate ḣ, the torque the wheels take from the body (N·m).
    pub wheel_torque_body: Vector3<f64>,
}
