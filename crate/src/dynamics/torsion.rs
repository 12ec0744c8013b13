//! Paper 1's truth: a body on a thin string, twisting about the vertical as a damped torsion
//! pendulum, I φ̈ = −f φ − 2ζ√(fI) φ̇ + τ (the 1-DOF model of §3.3 plus damping and an
//! external torque), with the torsion stiffness from the string: f = G·I_p/L, I_p = πd⁴/32.

use crate::math::rk4_step;
use nalgebra::Vector2;

/// A string material: its shear modulus (the stiffness) and its tensile strength (whether
/// it holds the body).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StringMaterial {
    /// Name, e.g. "steel".
    pub name: &'static str,
    /// Shear modulus G (Pa).
    pub shear_modulus_pa: f64,
    /// Tensile strength σ_T (Pa): paper 1's §3.1 for steel (200 MPa) and the titanium alloy
    /// (900 MPa); handbook values (ours) for tungsten and nylon.
    pub tensile_strength_pa: f64,
}

/// The string materials the lab offers, in the order of its choice parameter.
pub const STRING_MATERIALS: &[StringMaterial] = &[
    StringMaterial {
        name: "steel",
        shear_modulus_pa: 8.0e10,
        tensile_strength_pa: 2.0e8,
    },
    StringMaterial {
        name: "titanium alloy",
        shear_modulus_pa: 4.1e10,
        tensile_strength_pa: 9.0e8,
    },
    StringMaterial {
        name: "tungsten",
        shear_modulus_pa: 1.61e11,
        tensile_strength_pa: 1.5e9,
    },
    StringMaterial {
        name: "nylon",
        shear_modulus_pa: 1.0e9,
        tensile_strength_pa: 7.5e7,
    },
];

/// g (m/s²) for the string's load.
const G_M_S2: f64 = 9.81;

/// The thinnest string (m) that holds `mass_kg` with safety factor `n` (§3.1):
/// M g / (π d²/4) ≤ σ_T / n, so d ≥ 2√(n M g / (π σ_T)).
///
/// ```
/// # use attlab::dynamics::{STRING_MATERIALS, min_string_diameter_m};
/// // Paper 1 states d > 0.35 mm for steel and 0.17 mm for the titanium alloy under 1 kg;
/// // both follow from n = 2 (its text says 1.5).
/// let steel = min_string_diameter_m(1.0, STRING_MATERIALS[0].tensile_strength_pa, 2.0);
/// let titanium = min_string_diameter_m(1.0, STRING_MATERIALS[1].tensile_strength_pa, 2.0);
/// assert!((steel * 1e3 - 0.35).abs() < 0.005, "{steel}");
/// assert!((titanium * 1e3 - 0.17).abs() < 0.005, "{titanium}");
/// ```
pub fn min_string_diameter_m(mass_kg: f64, tensile_strength_pa: f64, n: f64) -> f64 {
    2.0 * (n * mass_kg * G_M_S2 / (std::f64::consts::PI * tensile_strength_pa)).sqrt()
}

/// The safety factor σ_T / (M g / (π d²/4)) of a string of diameter `diameter_m` holding
/// `mass_kg`: the inverse of [`min_string_diameter_m`].
pub fn string_safety_factor(mass_kg: f64, tensile_strength_pa: f64, diameter_m: f64) -> f64 {
    tensile_strength_pa * std::f64::consts::PI * diameter_m.powi(2) / (4.0 * mass_kg * G_M_S2)
}

/// Torsion stiffness f = G·I_p/L (N·m/rad) of a round string.
///
/// ```
/// # use attlab::dynamics::string_stiffness_n_m_per_rad;
/// // Paper 1: steel, d = 0.35 mm gives G·I_p ≈ 1.18e-4 N·m².
/// let g_ip = string_stiffness_n_m_per_rad(8.0e10, 0.35e-3, 1.0);
/// assert!((g_ip - 1.18e-4).abs() < 0.01e-4);
/// ```
pub fn string_stiffness_n_m_per_rad(shear_modulus_pa: f64, diameter_m: f64, length_m: f64) -> f64 {
    let polar_moment_m4 = std::f64::consts::PI * diameter_m.powi(4) / 32.0;
    shear_modulus_pa * polar_moment_m4 / length_m
}

/// The damped torsion pendulum.
#[derive(Clone, Debug, PartialEq)]
pub struct TorsionPendulum {
    /// Moment of inertia about the string (kg·m²).
    pub inertia_kg_m2: f64,
    /// Torsion stiffness (N·m/rad).
    pub stiffness_n_m_per_rad: f64,
    /// Damping ratio ζ.
    pub damping_ratio: f64,
    /// External torque held over a step (N·m).
    pub torque_n_m: f64,
    /// (φ rad, φ̇ rad/s).
    pub state: Vector2<f64>,
}

impl TorsionPendulum {
    /// Natural angular frequency Ω = √(f/I) (rad/s).
    pub fn omega_rad_s(&self) -> f64 {
        (self.stiffness_n_m_per_rad / self.inertia_kg_m2).sqrt()
    }

    /// Period T = 2π/Ω (s).
    pub fn period_s(&self) -> f64 {
        std::f64::consts::TAU / self.omega_rad_s()
    }

    /// Advance by `dt_s` (RK4).
    pub fn step(&mut self, dt_s: f64) {
        let (w, zeta, accel) = (
            self.omega_rad_s(),
            self.damping_ratio,
            self.torque_n_m / self.inertia_kg_m2,
        );
        self.state = rk4_step(0.0, &self.state, dt_s, |_, x| {
            Vector2::new(x[1], -w * w * x[0] - 2.0 * zeta * w * x[1] + accel)
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn undamped_pendulum_returns_after_one_period() {
        let mut p = TorsionPendulum {
            inertia_kg_m2: 0.5,
            stiffness_n_m_per_rad: 5.9e-5,
            damping_ratio: 0.0,
            torque_n_m: 0.0,
            state: Vector2::new(1.0, 0.0),
        };
        let t = p.period_s();
        let n = 100_000;
        for _ in 0..n {
            p.step(t / n as f64);
        }
        assert!(
            (p.state[0] - 1.0).abs() < 1e-9 && p.state[1].abs() < 1e-9,
            "{:?}",
            p.state
        );
    }

    #[test]
    fn damped_motion_matches_the_analytic_solution() {
        let mut p = TorsionPendulum {
            inertia_kg_m2: 0.5,
            stiffness_n_m_per_rad: 5.9e-5,
            damping_ratio: 0.05,
            torque_n_m: 0.0,
            state: Vector2::new(1.0, 0.0),
        };
        let (w, t) = (p.omega_rad_s(), p.period_s());
        let n = 100_000;
        for _ in 0..n {
            p.step(t / n as f64);
        }
        // φ(t) = e^{−ζΩt}[cos Ω_d t + (ζΩ/Ω_d) sin Ω_d t], Ω_d = Ω√(1−ζ²), from φ = 1, φ̇ = 0.
        let wd = w * (1.0 - 0.05f64.powi(2)).sqrt();
        let expected = (-0.05 * w * t).exp() * ((wd * t).cos() + 0.05 * w / wd * (wd * t).sin());
        assert!(
            (p.state[0] - expected).abs() < 1e-9,
            "{} vs {expected}",
            p.state[0]
        );
    }
}
