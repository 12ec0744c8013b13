//! The truth of paper 2's lab: TabletSat on a circular orbit, its attitude relative to the
//! orbital frame driven by gravity gradient, the reaction wheels' PD law and an unmodelled
//! disturbance torque (eqs. 6–7).

use crate::dynamics::{CircularOrbit, Epoch};
use crate::model::{
    Extras, LabData, ParamValues, Quantity, SeriesGroup, SeriesKey, SeriesSpec, TruthModel,
    TruthState,
};
use nalgebra::{Matrix3, Quaternion, UnitQuaternion, Vector3};
use rand::Rng;
use rand_chacha::ChaCha8Rng;

/// The reaction wheels' state the truth hands the sensors (the onboard computer reads the
/// wheels' tachometers and its own torque command).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(super) struct Wheels {
    /// Angular momentum in body axes (N·m·s).
    pub(super) momentum_body: Vector3<f64>,
    /// Its rate ḣ, the torque the wheels take from the body (N·m).
    pub(super) torque_body: Vector3<f64>,
}

/// The wheels' angular momentum in body axes (N·m·s), truth series.
pub(super) const WHEEL_H: [Quantity; 3] = [
    Quantity::new("wheel_h_x_n_m_s", "wheel momentum h_x", "N·m·s"),
    Quantity::new("wheel_h_y_n_m_s", "wheel momentum h_y", "N·m·s"),
    Quantity::new("wheel_h_z_n_m_s", "wheel momentum h_z", "N·m·s"),
];

/// The unmodelled disturbance as the filters' d = J⁻¹M_d (1/s²), truth series.
pub(super) const DIST_TRUE: [Quantity; 3] = [
    Quantity::new("dist_x_s2", "true disturbance d_x = (J⁻¹M_d)_x", "1/s²"),
    Quantity::new("dist_y_s2", "true disturbance d_y = (J⁻¹M_d)_y", "1/s²"),
    Quantity::new("dist_z_s2", "true disturbance d_z = (J⁻¹M_d)_z", "1/s²"),
];

/// Largest momentum of one wheel (N·m·s), paper 2 §1.
pub const WHEEL_MAX_N_M_S: f64 = 0.17;

/// Direction (body) of the unmodelled disturbance torque.
pub const DISTURBANCE_DIRECTION: [f64; 3] = [0.6, -0.48, 0.64];

/// Orbit and epoch from the parameters (applied at reset).
pub fn orbit_of(p: &ParamValues) -> (CircularOrbit, Epoch) {
    let epoch = Epoch {
        day_of_year: p.index("day_of_year").clamp(1, 365) as u16,
    };
    let jd = epoch.julian_date(0.0);
    let sun = crate::dynamics::sun_direction_eci(jd);
    let sun_ra = sun.y.atan2(sun.x);
    // The ascending node's local time: RAAN = sun's right ascension + (LTAN − 12 h)·15°/h.
    let raan = sun_ra + (p.get("ltan_h") - 12.0) * std::f64::consts::PI / 12.0;
    let orbit = CircularOrbit::new(
        p.get("altitude_km") * 1e3,
        p.get("inclination_deg").to_radians(),
        raan,
        p.get("arg_lat0_deg").to_radians(),
    );
    (orbit, epoch)
}

/// The satellite.
#[derive(Clone)]
pub struct Spacecraft {
    /// Orbit (fixed until reset).
    pub orbit: CircularOrbit,
    j: Matrix3<f64>,
    j_inv: Matrix3<f64>,
    q: UnitQuaternion<f64>,
    w: Vector3<f64>,
    h: Vector3<f64>,
    h_dot: Vector3<f64>,
    t_s: f64,
    k_att: f64,
    k_rate: f64,
    disturbance_n_m: f64,
    disturbance_from_s: f64,
}

/// (q̇, ω̇, ḣ) of the closed loop.
struct Rates {
    q: Quaternion<f64>,
    w: Vector3<f64>,
    h: Vector3<f64>,
}

impl Spacecraft {
    /// At t = 0: the attitude off the orbital frame by `p`'s initial error about a random
    /// axis, the rate off the orbital rate by its rate error.
    pub fn new(p: &ParamValues, rng: &mut ChaCha8Rng) -> Self {
        let (orbit, _) = orbit_of(p);
        let j = super::INERTIA_KG_M2;
        let axis = random_unit(rng);
        let q = UnitQuaternion::from_scaled_axis(axis * p.get("init_att_err_deg").to_radians());
        let w_rel = random_unit(rng) * p.get("init_rate_err_deg_s").to_radians();
        let w = w_rel + q.inverse_transform_vector(&orbit.frame_rate_orbit_rad_s());
        let mut s = Self {
            orbit,
            j,
            j_inv: j.try_inverse().unwrap_or_else(Matrix3::identity),
            q,
            w,
            h: Vector3::zeros(),
            h_dot: Vector3::zeros(),
            t_s: 0.0,
            k_att: 0.0,
            k_rate: 0.0,
            disturbance_n_m: 0.0,
            disturbance_from_s: 0.0,
        };
        s.apply_params(p);
        s.h_dot = s.rates(&s.q, &s.w, &s.h, 0.0).h;
        s
    }

    /// The unmodelled torque M_d at time `t` (N·m, body axes).
    fn disturbance_torque(&self, t: f64) -> Vector3<f64> {
        if t >= self.disturbance_from_s {
            Vector3::from(DISTURBANCE_DIRECTION).normalize() * self.disturbance_n_m
        } else {
            Vector3::zeros()
        }
    }

    /// The closed loop at (q, ω, h) at time t: J ω̇ = M_gg + M_d − K_λλ − K_ω ω_rel, with the
    /// wheels taking ḣ = K_λλ + K_ω ω_rel − ω × (Jω + h) (the paper's law, which cancels the
    /// gyroscopic term), held at zero on a saturated wheel.
    fn rates(&self, q: &UnitQuaternion<f64>, w: &Vector3<f64>, h: &Vector3<f64>, t: f64) -> Rates {
        let frame_rate = q.inverse_transform_vector(&self.orbit.frame_rate_orbit_rad_s());
        let w_rel = w - frame_rate;
        let mut lambda = q.imag();
        if q.w < 0.0 {
            lambda = -lambda;
        }
        let eta = q.inverse_transform_vector(&Vector3::z());
        let m_gg = eta.cross(&(self.j * eta)) * self.orbit.gravity_gradient_coeff();
        let m_d = self.disturbance_torque(t);
        let mut h_dot = lambda * self.k_att + w_rel * self.k_rate - w.cross(&(self.j * w + h));
        for i in 0..3 {
            if (h[i] >= WHEEL_MAX_N_M_S && h_dot[i] > 0.0)
                || (h[i] <= -WHEEL_MAX_N_M_S && h_dot[i] < 0.0)
            {
                h_dot[i] = 0.0;
            }
        }
        let w_dot = self.j_inv * (m_gg + m_d - w.cross(&(self.j * w + h)) - h_dot);
        let q_dot = q.into_inner() * Quaternion::from_imag(w_rel) * 0.5;
        Rates {
            q: q_dot,
            w: w_dot,
            h: h_dot,
        }
    }

    /// Wheel momentum (N·m·s).
    pub fn wheel_momentum(&self) -> Vector3<f64> {
        self.h
    }
}

/// A random unit vector.
fn random_unit(rng: &mut ChaCha8Rng) -> Vector3<f64> {
    loop {
        let v = Vector3::new(
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
        );
        let n = v.norm();
        if n > 1e-3 && n <= 1.0 {
            return v / n;
        }
    }
}

impl TruthModel for Spacecraft {
    fn apply_params(&mut self, p: &ParamValues) {
        self.k_att = p.get("k_att");
        self.k_rate = p.get("k_rate");
        self.disturbance_n_m = p.get("dist_torque_n_m");
        self.disturbance_from_s = p.get("dist_from_s");
    }

    fn step(&mut self, dt: f64) {
        let (q0, w0, h0, t0) = (self.q, self.w, self.h, self.t_s);
        let at = |q: &Quaternion<f64>| UnitQuaternion::new_normalize(*q);
        let k1 = self.rates(&q0, &w0, &h0, t0);
        let k2 = self.rates(
            &at(&(q0.into_inner() + k1.q * dt / 2.0)),
            &(w0 + k1.w * dt / 2.0),
            &(h0 + k1.h * dt / 2.0),
            t0 + dt / 2.0,
        );
        let k3 = self.rates(
            &at(&(q0.into_inner() + k2.q * dt / 2.0)),
            &(w0 + k2.w * dt / 2.0),
            &(h0 + k2.h * dt / 2.0),
            t0 + dt / 2.0,
        );
        let k4 = self.rates(
            &at(&(q0.into_inner() + k3.q * dt)),
            &(w0 + k3.w * dt),
            &(h0 + k3.h * dt),
            t0 + dt,
        );
        self.q = at(&(q0.into_inner() + (k1.q + k2.q * 2.0 + k3.q * 2.0 + k4.q) * (dt / 6.0)));
        self.w = w0 + (k1.w + k2.w * 2.0 + k3.w * 2.0 + k4.w) * (dt / 6.0);
        self.h = h0 + (k1.h + k2.h * 2.0 + k3.h * 2.0 + k4.h) * (dt / 6.0);
        self.t_s += dt;
        self.h_dot = self.rates(&self.q, &self.w, &self.h, self.t_s).h;
    }

    fn state(&self) -> TruthState {
        TruthState {
            lab: LabData::new(Wheels {
                momentum_body: self.h,
                torque_body: self.h_dot,
            }),
            ..TruthState::new(self.t_s, self.q, self.w)
        }
    }

    fn extra_series(&self) -> Vec<SeriesSpec> {
        WHEEL_H
            .iter()
            .chain(&DIST_TRUE)
            .map(|q| SeriesSpec::of(SeriesKey::truth(q), SeriesGroup::Lab))
            .collect()
    }

    fn extra_values(&self, out: &mut Extras<'_>) {
        out.put_all(&WHEEL_H, self.h.iter().copied());
        let d = self.j_inv * self.disturbance_torque(self.t_s);
        out.put_all(&DIST_TRUE, d.iter().copied());
    }
}
