//! The truth: the reference attitude, held still (the paper's experiment) or turned at a
//! constant or harmonic rate about a fixed axis.

use crate::estimators::sensitivity::{ANGLE_1_RAD, ANGLE_2_RAD, ANGLE_3_RAD};
use crate::model::{
    Extras, ParamValues, Quantity, SeriesGroup, SeriesKey, SeriesSpec, TruthModel, TruthState,
};
use nalgebra::{UnitQuaternion, Vector3};

/// The three angles of the rotation sequence (rad): the truth's and each method's.
pub(super) const ANGLES: [&Quantity; 3] = [&ANGLE_1_RAD, &ANGLE_2_RAD, &ANGLE_3_RAD];

/// The fixed rate axis of the turning profiles.
fn rate_axis() -> Vector3<f64> {
    Vector3::new(1.0, 2.0, 3.0).normalize()
}

/// The truth: the reference attitude turned by the profile's rate.
#[derive(Clone)]
pub(super) struct Turning {
    q: UnitQuaternion<f64>,
    t_s: f64,
    profile: usize,
    rate_rad_s: f64,
    freq_rad_s: f64,
    axes: [usize; 3],
}

impl Turning {
    /// At `reference` (the sequence `axes`), moving as `p`'s profile says.
    pub(super) fn new(p: &ParamValues, reference: UnitQuaternion<f64>, axes: [usize; 3]) -> Self {
        Self {
            q: reference,
            t_s: 0.0,
            profile: p.index("profile"),
            rate_rad_s: p.get("rate_deg_s").to_radians(),
            freq_rad_s: p.get("rate_freq_rad_s"),
            axes,
        }
    }

    fn rate(&self, t: f64) -> Vector3<f64> {
        match self.profile {
            0 => Vector3::zeros(),
            1 => rate_axis() * self.rate_rad_s,
            _ => rate_axis() * self.rate_rad_s * (self.freq_rad_s * t).sin(),
        }
    }
}

impl TruthModel for Turning {
    fn apply_params(&mut self, _p: &ParamValues) {}

    fn step(&mut self, dt_s: f64) {
        let t0 = self.t_s;
        self.q = crate::math::step_quaternion_rk4(&self.q, |f| self.rate(t0 + f * dt_s), dt_s);
        self.t_s += dt_s;
    }

    fn state(&self) -> TruthState {
        TruthState::new(self.t_s, self.q, self.rate(self.t_s))
    }

    fn extra_series(&self) -> Vec<SeriesSpec> {
        ANGLES
            .iter()
            .map(|q| SeriesSpec::of(SeriesKey::truth(q), SeriesGroup::Attitude))
            .collect()
    }

    fn extra_values(&self, out: &mut Extras<'_>) {
        let angles = crate::math::sequence_from_quaternion(self.axes, &self.q);
        out.put_all(ANGLES, angles);
    }
}
