//! Paper 4's two rigs and their controllers: the truth of the lab.
//!
//! * **Test bench** (Fig. 3): a lever on a bearing with one motor and propeller at its end,
//!   J θ̈ = L·F − M_g cos θ − c θ̇. Holding any angle needs a constant thrust against the
//!   lever's weight: u₀ ≠ 0.
//! * **Quadrotor roll** (eq. 2): four motors whose arms l_j and thrust gains differ by the
//!   asymmetry a, J θ̈ = Σ s_j l_j F_j − c θ̇ with s = (+, −, −, +) (the paper's θ row). The
//!   controller commands equal hover thrusts, so at hover the arms make a torque: u₀ ≠ 0.
//!   With a = 0 this is the symmetric eq. 3.
//! * Motors: first-order lag 1/(1 + T s) on each thrust, thrust between 0 and F_max (the
//!   lever: six times its weight's; the quadrotor: twice hover); the integral holds while
//!   they are at a limit (conditional integration, no wind-up).
//! * Controllers act on the γ-tuned KF's θ̂ and ω̂ as in Fig. 1 (read after each step, so
//!   one step late, as on a real loop), or on the true angle and rate (every filter then
//!   sees one motion), as an angular acceleration command u = u_v + u₀:
//!   a plain PID (u₀ = its integral part) or the nested P–PI of Fig. 1 (an angle P loop
//!   giving a rate set-point, a rate PI loop whose integral is u₀). Gains place the poles
//!   at the bandwidth slider ω_c: PID K_p = 3ω_c², K_d = 3ω_c, K_i = ω_c³; P–PI K_θ = ω_c
//!   (rate set-point at most 2 rad/s), K_ω = 4ω_c, K_ωi = 2ω_c².
//! * Set-point: a square wave between 0 and the step size; an optional gust, an angular
//!   acceleration pulse of 0.1 s.

use crate::estimators::ControlInput;
use crate::model::{
    Estimate, Estimator, Extras, LabData, ParamValues, Quantity, SeriesGroup, SeriesKey,
    SeriesSpec, TruthModel, TruthState,
};
use nalgebra::{UnitQuaternion, Vector3};

// The series this model records besides the catalogue's.
/// set-point θ_ref (deg).
pub(super) const SETPOINT_DEG: Quantity = Quantity::new("setpoint_deg", "set-point θ_ref", "deg");
/// angular acceleration θ̈ (deg/s²).
pub(super) const ACCEL_DEG_S2: Quantity =
    Quantity::new("accel_deg_s2", "angular acceleration θ̈", "deg/s²");
/// varying command u_v (rad/s²).
pub(super) const U_V_RAD_S2: Quantity =
    Quantity::new("u_v_rad_s2", "varying command u_v", "rad/s²");
/// constant command u₀ (rad/s²).
pub(super) const U0_RAD_S2: Quantity = Quantity::new("u0_rad_s2", "constant command u₀", "rad/s²");
/// u₀ that holds the rig level (rad/s²).
pub(super) const U0_NEEDED_RAD_S2: Quantity =
    Quantity::new("u0_needed_rad_s2", "u₀ that holds the rig level", "rad/s²");
/// total thrust (N).
pub(super) const THRUST_TOTAL_N: Quantity = Quantity::new("thrust_total_n", "total thrust", "N");

/// The rigs (parameter `rig`).
pub const RIGS: &[&str] = &[
    "test bench: 1-DOF lever, one motor (Fig. 3)",
    "quadrotor roll, symmetric (eq. 3)",
    "quadrotor roll, asymmetric arms and motors (eq. 2)",
];

/// The parameter choosing what the controller acts on.
pub const LOOP_KEY: &str = "loop_on";

/// What the controller can act on (parameter `loop_on`): the paper's Fig. 1 closes the loop
/// on the γ-tuned KF's θ̂; on the truth every filter is compared on one motion; or on any
/// other filter's estimate (the rest then run open on the same measurements).
pub const LOOP_ON: &[(&str, Option<&str>)] = &[
    ("the γ-tuned KF's θ̂, ω̂ (the paper's Fig. 1)", Some("kf")),
    ("the true θ, ω (every filter on one motion)", None),
    ("the complementary filter's θ̂, ω̂", Some("cf")),
    ("the bias-estimating KF's θ̂, ω̂", Some("kf-bias")),
    ("the KF fed u_v + u₀: its θ̂, ω̂", Some("kf-u0")),
];

/// The names of [`LOOP_ON`], for the choice parameter.
pub const LOOP_NAMES: &[&str] = &[
    LOOP_ON[0].0,
    LOOP_ON[1].0,
    LOOP_ON[2].0,
    LOOP_ON[3].0,
    LOOP_ON[4].0,
];

/// The controllers (parameter `controller`).
pub const CONTROLLERS: &[&str] = &["nested P–PI (Fig. 1)", "plain PID"];

/// Roll inertia of the quadrotor (kg·m²) and its arm (m), hover thrust per motor (N).
const QUAD_J: f64 = 0.01;
const QUAD_ARM_M: f64 = 0.12;
const QUAD_HOVER_N: f64 = 2.45;
/// The lever (the digest's assumption): inertia (kg·m²), arm (m).
const LEVER_J: f64 = 2e-3;
const LEVER_ARM_M: f64 = 0.2;
/// Viscous damping (N·m·s).
const DAMPING: f64 = 1e-4;
/// Gust pulse length (s).
const GUST_S: f64 = 0.1;
/// The P–PI angle loop's largest rate set-point (rad/s).
const MAX_RATE_RAD_S: f64 = 2.0;
/// Motor s_j of the roll row.
const ROLL_SIGNS: [f64; 4] = [1.0, -1.0, -1.0, 1.0];

/// Factors on the rig's nominal geometry: each arm, each motor's thrust (the lever's weight
/// torque in the first), the inertia.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Scales {
    pub arms: [f64; 4],
    pub thrusts: [f64; 4],
    pub inertia: f64,
}

impl Scales {
    /// The geometry as modelled.
    pub const NOMINAL: Self = Self {
        arms: [1.0; 4],
        thrusts: [1.0; 4],
        inertia: 1.0,
    };
}

/// The rig, its motors and its controller.
#[derive(Clone, Debug)]
pub struct Plant {
    rig: usize,
    controller: usize,
    asymmetry: f64,
    lever_torque_n_m: f64,
    motor_tau_s: f64,
    bandwidth_rad_s: f64,
    step_rad: f64,
    period_s: f64,
    gust_rad_s2: f64,
    gust_at_s: f64,
    theta_rad: f64,
    omega_rad_s: f64,
    accel_rad_s2: f64,
    forces_n: [f64; 4],
    integral: f64,
    t_s: f64,
    control: ControlInput,
    /// The estimator whose (θ̂, ω̂) the controller acts on; None: the truth.
    loop_on: Option<&'static str>,
    /// That estimator's last (θ̂ rad, ω̂ rad/s), once it has one.
    estimate: Option<(f64, f64)>,
}

impl Plant {
    /// A rig at rest on its set-point 0 with the parameters `p`.
    pub fn new(p: &ParamValues) -> Self {
        let mut plant = Self {
            rig: p.index("rig"),
            controller: 0,
            asymmetry: 0.0,
            lever_torque_n_m: 0.0,
            motor_tau_s: 0.04,
            bandwidth_rad_s: 4.0,
            step_rad: 0.0,
            period_s: 4.0,
            gust_rad_s2: 0.0,
            gust_at_s: 0.0,
            theta_rad: 0.0,
            omega_rad_s: 0.0,
            accel_rad_s2: 0.0,
            forces_n: [0.0; 4],
            integral: 0.0,
            t_s: 0.0,
            control: ControlInput::default(),
            loop_on: None,
            estimate: None,
        };
        plant.apply_params(p);
        // Start in equilibrium: motors at the thrust that holds θ = 0, the integral at u₀.
        let u0 = plant.hover_u0();
        plant.integral = match plant.controller {
            1 => u0 / plant.bandwidth_rad_s.powi(3),
            _ => u0 / (2.0 * plant.bandwidth_rad_s.powi(2)),
        };
        plant.forces_n = plant.commanded_forces(u0);
        plant.control = ControlInput {
            varying_rad_s2: 0.0,
            constant_rad_s2: u0,
            needed_rad_s2: u0,
        };
        plant
    }

    fn inertia(&self) -> f64 {
        if self.rig == 0 { LEVER_J } else { QUAD_J }
    }

    /// Arms (m) and thrust gains of the four motors (the quadrotor rigs).
    fn arms_and_gains(&self) -> ([f64; 4], [f64; 4]) {
        let a = if self.rig == 2 { self.asymmetry } else { 0.0 };
        (
            [1.0 + a, 1.0 - a / 2.0, 1.0, 1.0 + a / 2.0].map(|k| k * QUAD_ARM_M),
            [1.0, 1.0 + a / 4.0, 1.0 - a / 4.0, 1.0],
        )
    }

    /// The constant angular acceleration the controller must hold at θ = 0 (rad/s²).
    pub fn hover_u0(&self) -> f64 {
        self.needed_u0(0.0)
    }

    /// The constant angular acceleration that holds the rig at `theta` (rad/s²).
    fn needed_u0(&self, theta: f64) -> f64 {
        self.u0_scaled(theta, &Scales::NOMINAL)
    }

    /// The u₀ that holds the rig level if its geometry were off by `scales` (eq. 4's
    /// uncertain arms, thrusts and inertia).
    pub(super) fn level_u0_scaled(&self, scales: &Scales) -> f64 {
        self.u0_scaled(0.0, scales)
    }

    fn u0_scaled(&self, theta: f64, scales: &Scales) -> f64 {
        if self.rig == 0 {
            let torque = self.lever_torque_n_m * scales.thrusts[0];
            return torque * theta.cos() / (LEVER_J * scales.inertia);
        }
        let (arms, gains) = self.arms_and_gains();
        let torque: f64 = (0..4)
            .map(|j| {
                let thrust = gains[j] * scales.thrusts[j] * QUAD_HOVER_N;
                ROLL_SIGNS[j] * arms[j] * scales.arms[j] * thrust
            })
            .sum();
        -torque / (QUAD_J * scales.inertia)
    }

    /// Whether the rig is the lever (one motor and its weight) rather than a quadrotor.
    pub(super) fn is_lever(&self) -> bool {
        self.rig == 0
    }

    fn f_max(&self) -> f64 {
        if self.rig == 0 {
            6.0 * self.lever_torque_n_m.max(0.01) / LEVER_ARM_M
        } else {
            2.0 * QUAD_HOVER_N
        }
    }

    /// Thrust commands for the angular acceleration `u` (the controller assumes the nominal
    /// geometry: one arm length, equal motors, equal hover thrusts).
    fn commanded_forces(&self, u: f64) -> [f64; 4] {
        let torque = self.inertia() * u;
        let f_max = self.f_max();
        if self.rig == 0 {
            [(torque / LEVER_ARM_M).clamp(0.0, f_max), 0.0, 0.0, 0.0]
        } else {
            ROLL_SIGNS.map(|s| (QUAD_HOVER_N + s * torque / (4.0 * QUAD_ARM_M)).clamp(0.0, f_max))
        }
    }

    fn setpoint_rad(&self) -> f64 {
        let phase = (self.t_s / self.period_s.max(1e-3)).rem_euclid(2.0);
        if (1.0..2.0).contains(&phase) {
            self.step_rad
        } else {
            0.0
        }
    }

    fn angular_accel(&self, theta: f64, omega: f64, forces: &[f64; 4], t: f64) -> f64 {
        let gust =
            if self.gust_rad_s2 != 0.0 && (self.gust_at_s..self.gust_at_s + GUST_S).contains(&t) {
                self.gust_rad_s2
            } else {
                0.0
            };
        let torque = if self.rig == 0 {
            LEVER_ARM_M * forces[0] - self.lever_torque_n_m * theta.cos()
        } else {
            let (arms, gains) = self.arms_and_gains();
            (0..4)
                .map(|j| ROLL_SIGNS[j] * arms[j] * gains[j] * forces[j])
                .sum()
        };
        (torque - DAMPING * omega) / self.inertia() + gust
    }

    /// Whether a command `u` (rad/s²) would drive a motor into its limits.
    fn saturates(&self, u: f64) -> bool {
        let torque = self.inertia() * u;
        let f_max = self.f_max();
        let unclamped: Vec<f64> = if self.rig == 0 {
            vec![torque / LEVER_ARM_M]
        } else {
            ROLL_SIGNS
                .iter()
                .map(|s| QUAD_HOVER_N + s * torque / (4.0 * QUAD_ARM_M))
                .collect()
        };
        unclamped.iter().any(|f| !(0.0..=f_max).contains(f))
    }

    /// The controller's command at the current state (zero-order hold over the step), with
    /// conditional integration: the integral holds while the motors are at their limits (no
    /// wind-up, so a saturated step does not overshoot into a flip).
    fn control(&mut self, dt_s: f64) -> ControlInput {
        let before = self.integral;
        let c = self.control_law(dt_s);
        if self.saturates(c.varying_rad_s2 + c.constant_rad_s2) {
            self.integral = before;
            return self.control_law(0.0);
        }
        c
    }

    /// What the controller reads: the chosen estimate once there is one, else the truth.
    fn measured(&self) -> (f64, f64) {
        match (self.loop_on, self.estimate) {
            (Some(_), Some(estimate)) => estimate,
            _ => (self.theta_rad, self.omega_rad_s),
        }
    }

    fn control_law(&mut self, dt_s: f64) -> ControlInput {
        let w = self.bandwidth_rad_s;
        let (theta, omega) = self.measured();
        let e = self.setpoint_rad() - theta;
        match self.controller {
            1 => {
                self.integral += e * dt_s;
                ControlInput {
                    varying_rad_s2: 3.0 * w * w * e - 3.0 * w * omega,
                    constant_rad_s2: w.powi(3) * self.integral,
                    needed_rad_s2: self.needed_u0(self.theta_rad),
                }
            }
            _ => {
                // The angle loop asks for at most 2 rad/s: the lever can only brake by gravity.
                let rate_error = (w * e).clamp(-MAX_RATE_RAD_S, MAX_RATE_RAD_S) - omega;
                self.integral += rate_error * dt_s;
                ControlInput {
                    varying_rad_s2: 4.0 * w * rate_error,
                    constant_rad_s2: 2.0 * w * w * self.integral,
                    needed_rad_s2: self.needed_u0(self.theta_rad),
                }
            }
        }
    }
}

impl TruthModel for Plant {
    fn apply_params(&mut self, p: &ParamValues) {
        let controller = p.index("controller");
        if controller != self.controller {
            // Hand the integral over so the switch is bumpless: the same u₀.
            let w = self.bandwidth_rad_s;
            let u0 = self.control.constant_rad_s2;
            self.integral = if controller == 1 {
                u0 / w.powi(3)
            } else {
                u0 / (2.0 * w * w)
            };
        }
        self.controller = controller;
        self.asymmetry = p.get("asymmetry_pct") / 100.0;
        self.lever_torque_n_m = p.get("lever_torque_n_m");
        self.motor_tau_s = p.get("motor_tau_s");
        self.bandwidth_rad_s = p.get("bandwidth_rad_s");
        self.step_rad = p.get("setpoint_deg").to_radians();
        self.period_s = p.get("step_period_s");
        self.gust_rad_s2 = p.get("gust_rad_s2");
        self.gust_at_s = p.get("gust_at_s");
        self.loop_on = LOOP_ON.get(p.index(LOOP_KEY)).and_then(|(_, id)| *id);
    }

    fn feedback(&mut self, estimators: &[Box<dyn Estimator>]) {
        let Some(id) = self.loop_on else {
            return;
        };
        let estimate = estimators
            .iter()
            .find(|e| e.id() == id)
            .map(|e| e.estimate());
        // A diverged or silent filter leaves the controller on its last good reading.
        if let Some(Estimate {
            angle_rad: Some(theta),
            rate_body_rad_s: Some(rate),
            ..
        }) = estimate
            && theta.is_finite()
            && rate.z.is_finite()
        {
            self.estimate = Some((theta, rate.z));
        }
    }

    fn step(&mut self, dt_s: f64) {
        self.control = self.control(dt_s);
        let command =
            self.commanded_forces(self.control.varying_rad_s2 + self.control.constant_rad_s2);
        // Ten Euler substeps: the motor lag (T ≥ 5 ms) stays well resolved.
        let h = dt_s / 10.0;
        for k in 0..10 {
            let t = self.t_s + k as f64 * h;
            let lag = (h / self.motor_tau_s.max(1e-4)).min(1.0);
            for (f, c) in self.forces_n.iter_mut().zip(command) {
                *f += (c - *f) * lag;
            }
            let acc = self.angular_accel(self.theta_rad, self.omega_rad_s, &self.forces_n, t);
            self.omega_rad_s += acc * h;
            self.theta_rad += self.omega_rad_s * h;
            self.accel_rad_s2 = acc;
        }
        self.t_s += dt_s;
    }

    fn state(&self) -> TruthState {
        TruthState {
            t_s: self.t_s,
            q_ref_from_body: UnitQuaternion::from_axis_angle(&Vector3::z_axis(), self.theta_rad),
            rate_body_rad_s: Vector3::new(0.0, 0.0, self.omega_rad_s),
            angle_rad: Some(self.theta_rad),
            lab: LabData::new(self.control),
        }
    }

    fn extra_series(&self) -> Vec<SeriesSpec> {
        vec![
            SeriesSpec::of(SeriesKey::truth(&SETPOINT_DEG), SeriesGroup::Attitude),
            SeriesSpec::of(SeriesKey::truth(&ACCEL_DEG_S2), SeriesGroup::Lab),
            SeriesSpec::of(SeriesKey::truth(&U_V_RAD_S2), SeriesGroup::Lab),
            SeriesSpec::of(SeriesKey::truth(&U0_RAD_S2), SeriesGroup::Lab),
            SeriesSpec::of(SeriesKey::truth(&U0_NEEDED_RAD_S2), SeriesGroup::Lab),
            SeriesSpec::of(SeriesKey::truth(&THRUST_TOTAL_N), SeriesGroup::Lab),
        ]
    }

    fn extra_values(&self, out: &mut Extras<'_>) {
        out.put(&SETPOINT_DEG, self.setpoint_rad().to_degrees());
        out.put(&ACCEL_DEG_S2, self.accel_rad_s2.to_degrees());
        out.put(&U_V_RAD_S2, self.control.varying_rad_s2);
        out.put(&U0_RAD_S2, self.control.constant_rad_s2);
        out.put(&U0_NEEDED_RAD_S2, self.hover_u0());
        out.put(&THRUST_TOTAL_N, self.forces_n.iter().sum());
    }
}
