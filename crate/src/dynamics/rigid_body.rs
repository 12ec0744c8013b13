//! Torque-free (or torqued) rigid body: Euler's equations `I ω̇ = τ − ω × (I ω)` with the
//! quaternion kinematics, integrated together by RK4.

use crate::math::{quaternion_derivative, rk4_step};
use nalgebra::{Quaternion, SVector, UnitQuaternion, Vector3};

/// Attitude and body rate of a rigid body.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RigidBodyState {
    /// Attitude `q_ref_from_body`.
    pub q_ref_from_body: UnitQuaternion<f64>,
    /// Angular velocity in body axes (rad/s).
    pub rate_body_rad_s: Vector3<f64>,
}

/// A rigid body with a diagonal inertia tensor (principal axes = body axes).
#[derive(Clone, Debug, PartialEq)]
pub struct RigidBody {
    /// Principal moments of inertia (kg·m²), all positive.
    pub inertia_kg_m2: Vector3<f64>,
    /// External torque in body axes (N·m), held over a step.
    pub torque_body_n_m: Vector3<f64>,
    /// Current state.
    pub state: RigidBodyState,
}

impl RigidBody {
    /// A body at `state`, torque free.
    pub fn new(inertia_kg_m2: Vector3<f64>, state: RigidBodyState) -> Self {
        Self {
            inertia_kg_m2,
            torque_body_n_m: Vector3::zeros(),
            state,
        }
    }

    fn derivative(&self, x: &SVector<f64, 7>) -> SVector<f64, 7> {
        let q = x.fixed_rows::<4>(0).into_owned();
        let w = Vector3::new(x[4], x[5], x[6]);
        let i = self.inertia_kg_m2;
        let h = i.component_mul(&w);
        let w_dot = (self.torque_body_n_m - w.cross(&h)).component_div(&i);
        let q_dot = quaternion_derivative(&q, &w);
        SVector::<f64, 7>::from_iterator(q_dot.iter().chain(w_dot.iter()).copied())
    }

    /// Advance by `dt_s` (one RK4 step).
    pub fn step(&mut self, dt_s: f64) {
        let q = self.state.q_ref_from_body.quaternion();
        let w = self.state.rate_body_rad_s;
        let x = SVector::<f64, 7>::from_column_slice(&[q.w, q.i, q.j, q.k, w.x, w.y, w.z]);
        let x = rk4_step(0.0, &x, dt_s, |_, x| self.derivative(x));
        self.state = RigidBodyState {
            q_ref_from_body: UnitQuaternion::from_quaternion(Quaternion::new(
                x[0], x[1], x[2], x[3],
            )),
            rate_body_rad_s: Vector3::new(x[4], x[5], x[6]),
        };
    }

    /// Rotational kinetic energy ½ ωᵀ I ω (J).
    pub fn kinetic_energy_j(&self) -> f64 {
        let w = self.state.rate_body_rad_s;
        0.5 * w.dot(&self.inertia_kg_m2.component_mul(&w))
    }

    /// Angular momentum in the reference frame (N·m·s); constant without torque.
    pub fn angular_momentum_ref(&self) -> Vector3<f64> {
        let h_body = self
            .inertia_kg_m2
            .component_mul(&self.state.rate_body_rad_s);
        self.state.q_ref_from_body * h_body
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn torque_free_motion_conserves_energy_and_momentum() {
        let state = RigidBodyState {
            q_ref_from_body: UnitQuaternion::from_euler_angles(0.2, -0.4, 1.0),
            rate_body_rad_s: Vector3::new(0.3, 1.0, -0.2),
        };
        let mut body = RigidBody::new(Vector3::new(1.0, 2.0, 3.0), state);
        let (e0, h0) = (body.kinetic_energy_j(), body.angular_momentum_ref());
        for _ in 0..60_000 {
            body.step(0.001);
        }
        assert!((body.kinetic_energy_j() - e0).abs() < 1e-9 * e0);
        assert!((body.angular_momentum_ref() - h0).norm() < 1e-9 * h0.norm());
        // And the motion is not trivial: the rate vector in body axes did change.
        assert!((body.state.rate_body_rad_s - state.rate_body_rad_s).norm() > 0.1);
    }

    #[test]
    fn symmetric_body_precesses_at_the_analytic_rate() {
        // Axisymmetric body (I1 = I2): body-frame rate precesses about z at
        // λ = (I3 − I1)/I1 · ω3 (ω̇₁ = −λω₂, ω̇₂ = λω₁).
        let (i1, i3, w3) = (2.0, 3.0, 1.5);
        let state = RigidBodyState {
            q_ref_from_body: UnitQuaternion::identity(),
            rate_body_rad_s: Vector3::new(0.4, 0.0, w3),
        };
        let mut body = RigidBody::new(Vector3::new(i1, i1, i3), state);
        let t = 3.0;
        for _ in 0..3000 {
            body.step(0.001);
        }
        let lambda = (i3 - i1) / i1 * w3;
        let angle = body
            .state
            .rate_body_rad_s
            .y
            .atan2(body.state.rate_body_rad_s.x);
        assert!(
            (angle - lambda * t).abs() < 1e-9,
            "angle {angle} vs {}",
            lambda * t
        );
    }
}
