//! The truth: a torque-free rigid body (Euler's equations), its energy and momentum.

use crate::dynamics::{RigidBody, RigidBodyState};
use crate::math::EulerYpr;
use crate::model::{
    Extras, LabData, ParamValues, Quantity, SeriesGroup, SeriesKey, SeriesSpec, TruthModel,
    TruthState,
};
use nalgebra::Vector3;

/// The truth's kinetic energy (J): constant in free rotation.
pub(super) const ENERGY_J: Quantity = Quantity::new("energy_j", "kinetic energy T = ½ωᵀJω", "J");
/// The truth's angular momentum (N·m·s): constant in free rotation.
pub(super) const MOMENTUM_N_M_S: Quantity =
    Quantity::new("momentum_n_m_s", "angular momentum |Jω|", "N·m·s");

/// The tumbling body.
#[derive(Clone)]
pub(super) struct Tumble {
    body: RigidBody,
    t_s: f64,
}

impl Tumble {
    pub(super) fn new(params: &ParamValues) -> Self {
        let spin = params.get("spin_deg_s").to_radians();
        // A 2 % perturbation off the spin axis makes the intermediate axis visibly unstable.
        let axis = match params.index("spin_axis") {
            0 => Vector3::new(1.0, 0.02, 0.02),
            2 => Vector3::new(0.02, 0.02, 1.0),
            _ => Vector3::new(0.02, 1.0, 0.02),
        };
        let q0 = EulerYpr::new(0.0, 0.0, params.get("tilt_deg").to_radians()).to_quaternion();
        let state = RigidBodyState {
            q_ref_from_body: q0,
            rate_body_rad_s: axis.normalize() * spin,
        };
        Self {
            body: RigidBody::new(Vector3::new(1.0, 2.0, 3.0), state),
            t_s: 0.0,
        }
    }
}

impl TruthModel for Tumble {
    fn apply_params(&mut self, params: &ParamValues) {
        self.body.inertia_kg_m2 = Vector3::new(
            params.get("inertia_x_kg_m2"),
            params.get("inertia_y_kg_m2"),
            params.get("inertia_z_kg_m2"),
        );
    }

    fn step(&mut self, dt_s: f64) {
        self.body.step(dt_s);
        self.t_s += dt_s;
    }

    fn state(&self) -> TruthState {
        let s = self.body.state;
        TruthState {
            t_s: self.t_s,
            q_ref_from_body: s.q_ref_from_body,
            rate_body_rad_s: s.rate_body_rad_s,
            angle_rad: None,
            lab: LabData::default(),
        }
    }

    fn extra_series(&self) -> Vec<SeriesSpec> {
        vec![
            SeriesSpec::of(SeriesKey::truth(&ENERGY_J), SeriesGroup::Lab),
            SeriesSpec::of(SeriesKey::truth(&MOMENTUM_N_M_S), SeriesGroup::Lab),
        ]
    }

    fn extra_values(&self, out: &mut Extras<'_>) {
        out.put(&ENERGY_J, self.body.kinetic_energy_j());
        out.put(&MOMENTUM_N_M_S, self.body.angular_momentum_ref().norm());
    }
}
