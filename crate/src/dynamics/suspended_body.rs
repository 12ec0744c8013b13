//! Paper 1's §3.2 model: a rigid body on an infinitely long vertical string. The suspension
//! point A slides freely in a horizontal plane (the string stays vertical and its reaction N
//! points up), the centre of mass C sits a distance d below A on the body's z axis, and the
//! string resists the twist with stiffness f. Five degrees of freedom: A's x and y, and three
//! of attitude (the paper's Euler angles ψ, θ, φ).
//!
//! * **No horizontal force** acts, so C drifts at a constant horizontal velocity (the
//!   paper's momentum integrals, dv_cx/dt = dv_cy/dt = 0), and A's position follows from C's
//!   and the attitude: x and y need no integration.
//! * **The attitude** obeys Euler's equations about C with the torques of N (at A) and of
//!   the string. N follows from C's vertical motion, M z̈_C = N − M g, which is linear in the
//!   angular acceleration α, so α solves (I + M v vᵀ) α = τ − ω × Iω − M v (g + u·(ω×(ω×c)))
//!   with c = (0, 0, −d) the body-frame vector from A to C, u the vertical in the body frame
//!   and v = c × u.
//! * **The twist** is the swing–twist angle about the vertical, 2 atan2(q_z, q_w): ψ + φ in
//!   the paper's z-x-z angles. The paper writes the string's energy as f ψ²/2, which leaves φ
//!   cyclic and is not a function of the attitude at the equilibrium θ = 0 (where only ψ + φ
//!   is defined); f (ψ + φ)²/2 is, reduces to the paper's 1-DOF model C φ̈ = −f φ at small θ,
//!   and makes the string's torque −f·twist·∇twist conservative. The twist is integrated as
//!   a state (twist′ = ∇twist·ω), so it counts whole turns.
//! * **Losses and pushes** act on the twist only: damping −k·twist′ and an external torque,
//!   both along ∇twist. Undamped and unpushed, the energy
//!   E = M|v_C|²/2 + ωᵀIω/2 + M g d (1 − u_z) + f·twist²/2 is conserved.

use crate::math::rk4_step;
use nalgebra::{Matrix3, Quaternion, SVector, UnitQuaternion, Vector2, Vector3, Vector4};

/// g (m/s²).
const G_M_S2: f64 = 9.81;

/// The most a sub-step may turn the rocking's phase or the body (rad).
const MAX_ANGLE_PER_STEP_RAD: f64 = 0.05;

/// The state: [q_w, q_x, q_y, q_z, ω_x, ω_y, ω_z, twist] (q from body to the fixed frame,
/// ω in the body frame, rad/s; twist in rad).
type State = SVector<f64, 8>;

/// The body on the string (§3.2).
#[derive(Clone, Debug, PartialEq)]
pub struct SuspendedBody {
    /// Mass M (kg).
    pub mass_kg: f64,
    /// Principal moments of inertia about C, (A, B, C) (kg·m²); C about the string.
    pub inertia_kg_m2: Vector3<f64>,
    /// Distance d from the suspension point down to the centre of mass (m).
    pub com_offset_m: f64,
    /// Torsion stiffness f (N·m/rad).
    pub stiffness_n_m_per_rad: f64,
    /// Damping of the twist (N·m·s/rad).
    pub damping_n_m_s: f64,
    /// External torque on the twist, held over a step (N·m).
    pub torque_n_m: f64,
    state: State,
    /// C's horizontal position (m) and its constant velocity (m/s).
    com_m: Vector2<f64>,
    com_velocity_m_s: Vector2<f64>,
}

impl SuspendedBody {
    /// At rest apart from `twist_rate_rad_s` about the body axis, twisted by `twist_rad`
    /// and tilted by `tilt_rad` about the body's x axis, with C over the origin and the
    /// other settings zero (set them before stepping).
    pub fn new(twist_rad: f64, twist_rate_rad_s: f64, tilt_rad: f64) -> Self {
        let q = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), twist_rad)
            * UnitQuaternion::from_axis_angle(&Vector3::x_axis(), tilt_rad);
        let mut state = State::zeros();
        state
            .fixed_rows_mut::<4>(0)
            .copy_from(&wxyz(q.quaternion()));
        state[6] = twist_rate_rad_s;
        state[7] = twist_rad;
        Self {
            mass_kg: 1.0,
            inertia_kg_m2: Vector3::new(1.0, 1.0, 1.0),
            com_offset_m: 0.0,
            stiffness_n_m_per_rad: 0.0,
            damping_n_m_s: 0.0,
            torque_n_m: 0.0,
            state,
            com_m: Vector2::zeros(),
            com_velocity_m_s: Vector2::zeros(),
        }
    }

    /// The attitude (body to the fixed frame).
    pub fn attitude(&self) -> UnitQuaternion<f64> {
        UnitQuaternion::from_quaternion(quaternion(&self.state))
    }

    /// Body rates (rad/s).
    pub fn rate_body_rad_s(&self) -> Vector3<f64> {
        self.state.fixed_rows::<3>(4).into()
    }

    /// The string's twist (rad), whole turns counted.
    pub fn twist_rad(&self) -> f64 {
        self.state[7]
    }

    /// The twist rate (rad/s): not the body's z rate when it is tilted.
    pub fn twist_rate_rad_s(&self) -> f64 {
        twist_gradient(&quaternion(&self.state)).dot(&self.rate_body_rad_s())
    }

    /// The tilt of the body's z axis from the vertical (rad).
    pub fn tilt_rad(&self) -> f64 {
        vertical_in_body(&self.attitude()).z.clamp(-1.0, 1.0).acos()
    }

    /// Adds `rate_rad_s` to the body's rate about its own z axis (an impulse).
    pub fn kick(&mut self, rate_rad_s: f64) {
        self.state[6] += rate_rad_s;
    }

    /// The suspension point's horizontal position (m): C's less the horizontal part of c.
    pub fn suspension_point_m(&self) -> Vector2<f64> {
        let c = self.attitude() * self.c_body();
        self.com_m - Vector2::new(c.x, c.y)
    }

    /// Total mechanical energy (J): kinetic, of the lifted centre of mass, and of the string.
    pub fn energy_j(&self) -> f64 {
        let (w, u) = (self.rate_body_rad_s(), vertical_in_body(&self.attitude()));
        let c = self.c_body();
        let vz = u.dot(&w.cross(&c));
        let kinetic = 0.5 * self.mass_kg * (self.com_velocity_m_s.norm_squared() + vz * vz)
            + 0.5 * w.dot(&self.inertia_kg_m2.component_mul(&w));
        let lift = self.mass_kg * G_M_S2 * (u.dot(&c) + self.com_offset_m);
        kinetic + lift + 0.5 * self.stiffness_n_m_per_rad * self.twist_rad().powi(2)
    }

    /// The rocking's angular frequency √(M g d / A) (rad/s), A the smaller tilt inertia.
    pub fn rocking_rad_s(&self) -> f64 {
        let tilt_inertia = self.inertia_kg_m2.x.min(self.inertia_kg_m2.y);
        (self.mass_kg * G_M_S2 * self.com_offset_m / tilt_inertia).sqrt()
    }

    /// Advances by `dt_s`: RK4 in as many equal sub-steps as keep each under 1/20 of a
    /// radian of the rocking or of the body's own rotation (a heavy, low body rocks fast),
    /// the quaternion renormalised after each.
    pub fn step(&mut self, dt_s: f64) {
        let fastest = self.rocking_rad_s().max(self.rate_body_rad_s().norm());
        let n = (dt_s * fastest / MAX_ANGLE_PER_STEP_RAD)
            .ceil()
            .clamp(1.0, 1e4) as usize;
        let h = dt_s / n as f64;
        for _ in 0..n {
            self.state = rk4_step(0.0, &self.state, h, |_, x| self.derivative(x));
            let q = quaternion(&self.state).normalize();
            self.state.fixed_rows_mut::<4>(0).copy_from(&wxyz(&q));
        }
        self.com_m += self.com_velocity_m_s * dt_s;
    }

    /// c: from the suspension point to the centre of mass, body frame (m).
    fn c_body(&self) -> Vector3<f64> {
        Vector3::new(0.0, 0.0, -self.com_offset_m)
    }

    fn derivative(&self, x: &State) -> State {
        let q = quaternion(x);
        let w: Vector3<f64> = x.fixed_rows::<3>(4).into();
        let qdot = q * Quaternion::from_imag(w) * 0.5;
        let unit = UnitQuaternion::from_quaternion(q);
        let (u, c, gradient) = (vertical_in_body(&unit), self.c_body(), twist_gradient(&q));
        let twist_rate = gradient.dot(&w);
        let twist_torque =
            -self.stiffness_n_m_per_rad * x[7] - self.damping_n_m_s * twist_rate + self.torque_n_m;
        let inertia = Matrix3::from_diagonal(&self.inertia_kg_m2);
        let v = c.cross(&u);
        let lhs = inertia + v * v.transpose() * self.mass_kg;
        let rhs = -w.cross(&(inertia * w))
            - v * (self.mass_kg * (G_M_S2 + u.dot(&w.cross(&w.cross(&c)))))
            + gradient * twist_torque;
        let alpha = lhs.cholesky().map_or(Vector3::zeros(), |ch| ch.solve(&rhs));
        let mut out = State::zeros();
        out.fixed_rows_mut::<4>(0).copy_from(&wxyz(&qdot));
        out.fixed_rows_mut::<3>(4).copy_from(&alpha);
        out[7] = twist_rate;
        out
    }
}

/// The quaternion in `x`'s first four elements (w, x, y, z).
fn quaternion(x: &State) -> Quaternion<f64> {
    Quaternion::new(x[0], x[1], x[2], x[3])
}

/// The fixed frame's vertical in the body frame.
fn vertical_in_body(q: &UnitQuaternion<f64>) -> Vector3<f64> {
    q.inverse_transform_vector(&Vector3::z())
}

/// ∇twist: twist′ = ∇twist · ω for the twist 2 atan2(q_z, q_w) (from q̇ = ½ q ⊗ (0, ω)).
fn twist_gradient(q: &Quaternion<f64>) -> Vector3<f64> {
    let (w, x, y, z) = (q.w, q.i, q.j, q.k);
    let n = (w * w + z * z).max(f64::MIN_POSITIVE);
    Vector3::new((z * x - w * y) / n, (w * x + z * y) / n, 1.0)
}

/// `q`'s elements as (w, x, y, z), the state's order.
fn wxyz(q: &Quaternion<f64>) -> Vector4<f64> {
    Vector4::new(q.w, q.i, q.j, q.k)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dynamics::TorsionPendulum;

    /// A disc-like body on the paper's steel string, T ≈ 400 s, rocking at ≈ 10 s.
    fn body(twist_deg: f64, tilt_deg: f64) -> SuspendedBody {
        let mut b = SuspendedBody::new(twist_deg.to_radians(), 0.0, tilt_deg.to_radians());
        b.inertia_kg_m2 = Vector3::new(0.24, 0.24, 0.48);
        b.com_offset_m = 0.01;
        b.stiffness_n_m_per_rad = 1.1786e-4;
        b
    }

    #[test]
    fn undamped_energy_is_conserved_to_1e_6_over_600_s() {
        let mut b = body(360.0, 5.0);
        b.com_velocity_m_s = Vector2::new(0.01, -0.02);
        let e0 = b.energy_j();
        let mut worst: f64 = 0.0;
        for _ in 0..60_000 {
            b.step(0.01);
            worst = worst.max((b.energy_j() - e0).abs() / e0);
        }
        assert!(worst < 1e-6, "relative energy change {worst:e}");
        // Not a trivial motion: the body rocked and twisted through the run.
        assert!(b.tilt_rad().to_degrees() > 0.1, "{}", b.tilt_rad());
        assert!((b.twist_rad().to_degrees() - 360.0).abs() > 100.0);
    }

    #[test]
    fn damping_only_takes_energy_away() {
        let mut b = body(360.0, 5.0);
        b.damping_n_m_s = 1e-3;
        let mut last = b.energy_j();
        for _ in 0..20_000 {
            b.step(0.01);
            let e = b.energy_j();
            assert!(e <= last + 1e-12 * last, "{e} after {last}");
            last = e;
        }
    }

    #[test]
    fn without_tilt_it_is_the_one_dof_model_of_section_3_3() {
        let (mut b, inertia) = (body(360.0, 0.0), 0.48);
        let mut p = TorsionPendulum {
            inertia_kg_m2: inertia,
            stiffness_n_m_per_rad: b.stiffness_n_m_per_rad,
            damping_ratio: 0.0,
            torque_n_m: 0.0,
            state: nalgebra::Vector2::new(360f64.to_radians(), 0.0),
        };
        for _ in 0..30_000 {
            b.step(0.01);
            p.step(0.01);
        }
        assert!(
            (b.twist_rad() - p.state[0]).abs() < 1e-9,
            "{} vs {}",
            b.twist_rad(),
            p.state[0]
        );
        let twist = 2.0 * b.attitude().k.atan2(b.attitude().w);
        let wrapped = (b.twist_rad() - twist).rem_euclid(std::f64::consts::TAU);
        assert!(wrapped.min(std::f64::consts::TAU - wrapped) < 1e-9);
    }

    #[test]
    fn the_rocking_period_is_that_of_a_compound_pendulum_about_c() {
        // A slides freely, so C stays put and the body rocks about it: ω² = M g d / A.
        let mut b = body(0.0, 1.0);
        let expected_s = std::f64::consts::TAU * (0.24 / (G_M_S2 * 0.01)).sqrt();
        let mut crossings = Vec::new();
        let mut last = b.rate_body_rad_s().x;
        for k in 1..=25_000 {
            b.step(0.001);
            let now = b.rate_body_rad_s().x;
            if last < 0.0 && now >= 0.0 {
                crossings.push(k as f64 * 0.001);
            }
            last = now;
        }
        let period = crossings[1] - crossings[0];
        assert!(
            (period - expected_s).abs() < 2e-3 * expected_s,
            "{period} vs {expected_s}"
        );
    }

    #[test]
    fn a_tilted_twisting_body_shows_the_rocking_in_its_z_rate() {
        // The twist rate and the body's z rate differ once it rocks: a z gyro sees the swing
        // through the dynamics, with no misalignment.
        let mut b = body(360.0, 5.0);
        let mut differs: f64 = 0.0;
        for _ in 0..2_000 {
            b.step(0.01);
            differs = differs.max((b.twist_rate_rad_s() - b.rate_body_rad_s().z).abs());
        }
        assert!(differs.to_degrees() > 1e-3, "{differs}");
    }
}
