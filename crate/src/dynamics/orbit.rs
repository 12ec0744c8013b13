//! A circular orbit and the orbital frame of paper 2 (TabletSat): the satellite's position,
//! the local vertical and the rotation of the orbital frame.
//!
//! Frames: `eci` is the inertial frame (J2000-like, x to the vernal equinox, z to the north
//! pole); the **orbital frame** `orbit` has e₃ along the local vertical (zenith, r/|r|), e₂
//! along the orbit normal (r × v), e₁ = e₂ × e₃ along the velocity of the circular orbit. It
//! turns about e₂ at the mean motion n.

use nalgebra::{Rotation3, UnitQuaternion, Vector3};

/// Earth's gravitational parameter μ (m³/s²).
pub const MU_EARTH_M3_S2: f64 = 3.986_004_418e14;
/// WGS 84 equatorial radius (m).
pub const EARTH_RADIUS_M: f64 = 6_378_137.0;
/// Earth's rotation rate (rad/s).
pub const EARTH_RATE_RAD_S: f64 = 7.292_115e-5;
/// Earth's J2.
pub const J2: f64 = 1.082_63e-3;
/// The mean sun's motion in right ascension (rad/s): the node of a sun-synchronous orbit
/// turns this fast.
pub const SUN_SYNCHRONOUS_RATE_RAD_S: f64 = std::f64::consts::TAU / (365.2422 * 86_400.0);

/// A circular orbit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CircularOrbit {
    /// Radius (m).
    pub radius_m: f64,
    /// Inclination (rad).
    pub inclination_rad: f64,
    /// Right ascension of the ascending node at t = 0 (rad).
    pub raan_rad: f64,
    /// Argument of latitude at t = 0 (rad).
    pub arg_lat0_rad: f64,
}

impl CircularOrbit {
    /// An orbit at `altitude_m` above the equatorial radius. The node is held fixed: over the
    /// few orbits a lab runs, a sun-synchronous node moves by well under a degree.
    pub fn new(altitude_m: f64, inclination_rad: f64, raan_rad: f64, arg_lat0_rad: f64) -> Self {
        Self {
            radius_m: EARTH_RADIUS_M + altitude_m,
            inclination_rad,
            raan_rad,
            arg_lat0_rad,
        }
    }

    /// The inclination (rad) at which the J2 node drift follows the mean sun.
    ///
    /// ```
    /// # use attlab::dynamics::CircularOrbit;
    /// let i = CircularOrbit::sun_synchronous_inclination_rad(600e3).to_degrees();
    /// assert!((i - 97.79).abs() < 0.05, "{i}");
    /// ```
    pub fn sun_synchronous_inclination_rad(altitude_m: f64) -> f64 {
        let r = EARTH_RADIUS_M + altitude_m;
        let n = (MU_EARTH_M3_S2 / r.powi(3)).sqrt();
        let c = -SUN_SYNCHRONOUS_RATE_RAD_S / (1.5 * J2 * (EARTH_RADIUS_M / r).powi(2) * n);
        c.clamp(-1.0, 1.0).acos()
    }

    /// Mean motion n (rad/s).
    pub fn mean_motion_rad_s(&self) -> f64 {
        (MU_EARTH_M3_S2 / self.radius_m.powi(3)).sqrt()
    }

    /// Orbital period (s).
    pub fn period_s(&self) -> f64 {
        std::f64::consts::TAU / self.mean_motion_rad_s()
    }

    /// `q_eci_from_orbit` at time `t_s`: the orbital frame's axes in inertial coordinates.
    pub fn q_eci_from_orbit(&self, t_s: f64) -> UnitQuaternion<f64> {
        let u = self.arg_lat0_rad + self.mean_motion_rad_s() * t_s;
        let raan = self.raan_rad;
        // The orbit plane: node line, then inclination, then the argument of latitude about the
        // normal. In the perifocal-like frame (x to the satellite, z along the normal) the
        // orbital axes are e₃ = x, e₂ = z, e₁ = y.
        let plane = Rotation3::from_axis_angle(&Vector3::z_axis(), raan)
            * Rotation3::from_axis_angle(&Vector3::x_axis(), self.inclination_rad)
            * Rotation3::from_axis_angle(&Vector3::z_axis(), u);
        let (x, y, z) = (
            plane * Vector3::x(),
            plane * Vector3::y(),
            plane * Vector3::z(),
        );
        let m = nalgebra::Matrix3::from_columns(&[y, z, x]);
        UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(m))
    }

    /// Position in the inertial frame (m).
    pub fn position_eci_m(&self, t_s: f64) -> Vector3<f64> {
        self.q_eci_from_orbit(t_s) * Vector3::z() * self.radius_m
    }

    /// The orbital frame's angular velocity, in orbital axes (rad/s): n about e₂.
    pub fn frame_rate_orbit_rad_s(&self) -> Vector3<f64> {
        Vector3::new(0.0, self.mean_motion_rad_s(), 0.0)
    }

    /// 3μ/r³ (1/s²): the gravity-gradient torque is 3μ/r³ · η × (J η).
    pub fn gravity_gradient_coeff(&self) -> f64 {
        3.0 * MU_EARTH_M3_S2 / self.radius_m.powi(3)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_orbital_frame_follows_the_satellite() {
        let o = CircularOrbit::new(600e3, 1.7, 0.3, 0.2);
        let dt = 1.0;
        let (r0, r1) = (o.position_eci_m(100.0), o.position_eci_m(100.0 + dt));
        let v = (r1 - r0) / dt;
        let q = o.q_eci_from_orbit(100.0 + dt / 2.0);
        // e₁ along the velocity, e₃ along r, e₂ along r × v.
        assert!((q * Vector3::x() - v.normalize()).norm() < 1e-3);
        assert!((q * Vector3::z() - ((r0 + r1) / 2.0).normalize()).norm() < 1e-6);
        assert!((q * Vector3::y() - r0.cross(&r1).normalize()).norm() < 1e-6);
        assert!((v.norm() - (MU_EARTH_M3_S2 / o.radius_m).sqrt()).abs() < 1.0);
    }
}
