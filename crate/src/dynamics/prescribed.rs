//! Prescribed motion given as paper 3's Euler angles (eq. 22) with exact body rates
//! (digest §5) — the truth of the paper's experiments and of the integrator tests.

use crate::math::EulerYpr;
use nalgebra::{UnitQuaternion, Vector3};

/// One angle as `rate·t + amplitude·sin(frequency·t + phase)`.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct AngleProfile {
    /// Constant rate (rad/s).
    pub rate_rad_s: f64,
    /// Amplitude of the harmonic part (rad).
    pub amplitude_rad: f64,
    /// Angular frequency of the harmonic part (rad/s).
    pub frequency_rad_s: f64,
    /// Phase of the harmonic part (rad).
    pub phase_rad: f64,
}

impl AngleProfile {
    /// Angle at `t_s` (rad).
    pub fn angle(&self, t_s: f64) -> f64 {
        self.rate_rad_s * t_s
            + self.amplitude_rad * (self.frequency_rad_s * t_s + self.phase_rad).sin()
    }

    /// Its time derivative (rad/s).
    pub fn rate(&self, t_s: f64) -> f64 {
        self.rate_rad_s
            + self.amplitude_rad
                * self.frequency_rad_s
                * (self.frequency_rad_s * t_s + self.phase_rad).cos()
    }
}

/// Yaw, pitch and roll each following an [`AngleProfile`].
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct EulerMotion {
    /// Yaw ψ.
    pub yaw: AngleProfile,
    /// Pitch ϑ.
    pub pitch: AngleProfile,
    /// Roll γ.
    pub roll: AngleProfile,
}

impl EulerMotion {
    /// Paper 3's experiment: ψ = ω_ψ t, ϑ = A_ϑ cos(ω_ϑ t), γ = A_γ sin(ω_γ t) with
    /// A_γ = 25°, A_ϑ = 30°, ω_ψ = 1 °/s, ω_ϑ = ω_γ = 0.05 rad/s.
    pub fn paper3() -> Self {
        Self {
            yaw: AngleProfile {
                rate_rad_s: 1f64.to_radians(),
                ..AngleProfile::default()
            },
            pitch: AngleProfile {
                amplitude_rad: 30f64.to_radians(),
                frequency_rad_s: 0.05,
                phase_rad: std::f64::consts::FRAC_PI_2,
                ..AngleProfile::default()
            },
            roll: AngleProfile {
                amplitude_rad: 25f64.to_radians(),
                frequency_rad_s: 0.05,
                ..AngleProfile::default()
            },
        }
    }

    /// Euler angles at `t_s`.
    pub fn euler(&self, t_s: f64) -> EulerYpr {
        EulerYpr::new(
            self.yaw.angle(t_s),
            self.pitch.angle(t_s),
            self.roll.angle(t_s),
        )
    }

    /// `q_ref_from_body` at `t_s`.
    pub fn attitude(&self, t_s: f64) -> UnitQuaternion<f64> {
        self.euler(t_s).to_quaternion()
    }

    /// Exact body rates (ω_ξ, ω_η, ω_ζ) at `t_s` (digest §5).
    ///
    /// ```
    /// # use attlab::dynamics::EulerMotion;
    /// // At t = 0 of paper 3: ϑ = 30°, γ = 0, ψ̇ = 1 °/s, ϑ̇ = 0, γ̇ = 25°·0.05/s.
    /// let w = EulerMotion::paper3().body_rate_rad_s(0.0);
    /// let psi_dot = 1f64.to_radians();
    /// assert!((w.y - (25f64.to_radians() * 0.05 + psi_dot * 0.5)).abs() < 1e-15);
    /// ```
    pub fn body_rate_rad_s(&self, t_s: f64) -> Vector3<f64> {
        let (psi_d, th_d, ga_d) = (
            self.yaw.rate(t_s),
            self.pitch.rate(t_s),
            self.roll.rate(t_s),
        );
        let (sth, cth) = self.pitch.angle(t_s).sin_cos();
        let (sga, cga) = self.roll.angle(t_s).sin_cos();
        Vector3::new(
            th_d * cga - psi_d * cth * sga,
            ga_d + psi_d * sth,
            psi_d * cth * cga + th_d * sga,
        )
    }
}
