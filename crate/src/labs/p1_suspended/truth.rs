//! Paper 1's truth: the body on the string with its disturbances, as one of two models — the
//! twist alone (§3.3's 1-DOF model, the filters' own, with a prescribed swing) or the 5-DOF
//! body of §3.2 (eq. 3.2), which rocks on a free suspension point by itself, so that the
//! swing reaches the gyro through the dynamics.

use super::params::pendulum;
use crate::dynamics::{SuspendedBody, TorsionPendulum};
use crate::model::{
    Extras, LabData, ParamValues, Quantity, SeriesGroup, SeriesKey, SeriesSpec, TruthModel,
    TruthState,
};
use crate::sensors::WhiteNoise;
use nalgebra::{UnitQuaternion, Vector2, Vector3};
use rand_chacha::ChaCha8Rng;

/// The torsion pendulum's period (s), a truth series.
pub(super) const PERIOD_S: Quantity = Quantity::new("period_s", "torsion period T", "s");
/// The string's swing (deg), a truth series.
const SWING_DEG: Quantity = Quantity::new("swing_deg", "swing angle of the string", "deg");
/// The body's mechanical energy (mJ), a truth series: constant without damping and pushes.
pub(super) const ENERGY_MJ: Quantity = Quantity::new(
    "energy_mj",
    "mechanical energy of the body on the string E",
    "mJ",
);

/// g (m/s²) for the prescribed swing's frequency √(g/L).
const G_M_S2: f64 = 9.81;

/// How the body moves.
#[derive(Clone)]
enum Body {
    /// §3.3: the twist as a damped torsion pendulum; the swing a sinusoid of (amplitude
    /// rad, angular frequency rad/s) about the body's x axis.
    Twist {
        pendulum: TorsionPendulum,
        swing: (f64, f64),
    },
    /// §3.2: the rocking, twisting body.
    Rocking(Box<SuspendedBody>),
}

/// The body on the string with its disturbances.
#[derive(Clone)]
pub(super) struct Suspended {
    body: Body,
    t_s: f64,
    /// (time s, rate jump rad/s) of the torque impulse.
    kick: (f64, f64),
    kicked: bool,
    shake_n_m: f64,
    rng_torque: f64,
}

impl Suspended {
    /// At twist and twist rate `x0` (rad, rad/s), with the body model `p` chooses; the 5-DOF
    /// body starts tilted by the swing's amplitude.
    pub(super) fn new(p: &ParamValues, x0: Vector2<f64>) -> Self {
        let body = if p.index("body_model") == 1 {
            let tilt_rad = p.get("swing_amp_deg").to_radians();
            Body::Rocking(Box::new(SuspendedBody::new(x0[0], x0[1], tilt_rad)))
        } else {
            Body::Twist {
                pendulum: pendulum(p, x0),
                swing: (0.0, 1.0),
            }
        };
        let mut truth = Self {
            body,
            t_s: 0.0,
            kick: (0.0, 0.0),
            kicked: false,
            shake_n_m: 0.0,
            rng_torque: 0.0,
        };
        truth.apply_params(p);
        truth
    }

    /// Mechanical energy (J): of the twist alone for the 1-DOF model (its swing is
    /// prescribed, not a motion with energy of its own), of the whole body for the 5-DOF.
    fn energy_j(&self) -> f64 {
        match &self.body {
            Body::Twist { pendulum: p, .. } => {
                0.5 * (p.inertia_kg_m2 * p.state[1].powi(2)
                    + p.stiffness_n_m_per_rad * p.state[0].powi(2))
            }
            Body::Rocking(b) => b.energy_j(),
        }
    }

    fn swing_angle_and_rate(&self) -> (f64, f64) {
        match &self.body {
            Body::Twist {
                swing: (amp, w), ..
            } => ((w * self.t_s).sin() * amp, (w * self.t_s).cos() * amp * w),
            Body::Rocking(b) => (b.tilt_rad(), 0.0),
        }
    }
}

/// Sets the 5-DOF body's settings from `p`: the twist's inertia, stiffness and damping as
/// the 1-DOF pendulum has them, the rocking's from the mass, the tilt inertia and d.
fn set_rocking(body: &mut SuspendedBody, p: &ParamValues) {
    let twist = pendulum(p, Vector2::zeros());
    let (inertia, stiffness) = (twist.inertia_kg_m2, twist.stiffness_n_m_per_rad);
    let tilt_inertia = p.get("tilt_inertia_kg_m2");
    body.mass_kg = p.get("body_mass_kg");
    body.inertia_kg_m2 = Vector3::new(tilt_inertia, tilt_inertia, inertia);
    body.com_offset_m = p.get("com_offset_mm") * 1e-3;
    body.stiffness_n_m_per_rad = stiffness;
    body.damping_n_m_s = 2.0 * twist.damping_ratio * (stiffness * inertia).sqrt();
}

impl TruthModel for Suspended {
    fn apply_params(&mut self, p: &ParamValues) {
        match &mut self.body {
            Body::Twist {
                pendulum: now,
                swing,
            } => {
                let fresh = pendulum(p, now.state);
                now.inertia_kg_m2 = fresh.inertia_kg_m2;
                now.stiffness_n_m_per_rad = fresh.stiffness_n_m_per_rad;
                now.damping_ratio = fresh.damping_ratio;
                // A pendulum of the string's length: ω = √(g/L).
                *swing = (
                    p.get("swing_amp_deg").to_radians(),
                    (G_M_S2 / p.get("string_length_m")).sqrt(),
                );
            }
            Body::Rocking(body) => set_rocking(body, p),
        }
        let kick = (p.get("impulse_time_s"), p.get("impulse_deg_s").to_radians());
        if kick != self.kick {
            self.kicked = self.t_s >= kick.0 && kick.0 > 0.0;
            self.kick = kick;
        }
        self.shake_n_m = p.get("shake_torque_n_m");
    }

    fn step(&mut self, dt_s: f64) {
        let torque = self.shake_n_m * self.rng_torque;
        self.t_s += dt_s;
        let kick = (!self.kicked && self.kick.1 != 0.0 && self.t_s >= self.kick.0).then(|| {
            self.kicked = true;
            self.kick.1
        });
        match &mut self.body {
            Body::Twist { pendulum, .. } => {
                pendulum.torque_n_m = torque;
                pendulum.step(dt_s);
                pendulum.state[1] += kick.unwrap_or(0.0);
            }
            Body::Rocking(body) => {
                body.torque_n_m = torque;
                body.step(dt_s);
                body.kick(kick.unwrap_or(0.0));
            }
        }
    }

    fn state(&self) -> TruthState {
        let (q, rate, twist) = match &self.body {
            Body::Twist { pendulum, .. } => {
                let (theta, theta_dot) = self.swing_angle_and_rate();
                let phi = pendulum.state[0];
                let q = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), phi)
                    * UnitQuaternion::from_axis_angle(&Vector3::x_axis(), theta);
                (q, Vector3::new(theta_dot, 0.0, pendulum.state[1]), phi)
            }
            Body::Rocking(b) => (b.attitude(), b.rate_body_rad_s(), b.twist_rad()),
        };
        TruthState {
            t_s: self.t_s,
            q_ref_from_body: q,
            rate_body_rad_s: rate,
            angle_rad: Some(twist),
            lab: LabData::default(),
        }
    }

    fn extra_series(&self) -> Vec<SeriesSpec> {
        vec![
            SeriesSpec::of(SeriesKey::truth(&PERIOD_S), SeriesGroup::Lab),
            SeriesSpec::of(SeriesKey::truth(&SWING_DEG), SeriesGroup::Lab),
            SeriesSpec::of(SeriesKey::truth(&ENERGY_MJ), SeriesGroup::Lab),
        ]
    }

    fn extra_values(&self, out: &mut Extras<'_>) {
        let period_s = match &self.body {
            Body::Twist { pendulum, .. } => pendulum.period_s(),
            Body::Rocking(b) => {
                std::f64::consts::TAU * (b.inertia_kg_m2.z / b.stiffness_n_m_per_rad).sqrt()
            }
        };
        out.put(&PERIOD_S, period_s);
        out.put(&SWING_DEG, self.swing_angle_and_rate().0.to_degrees());
        out.put(&ENERGY_MJ, 1e3 * self.energy_j());
    }

    fn draw_noise(&mut self, rng: &mut ChaCha8Rng) {
        self.rng_torque = WhiteNoise { sigma: 1.0 }.sample(rng);
    }
}
