//! The sensors: a gyro with bias and noise, and a reference attitude every Δt (with its own
//! noise, and lost during a dropout).

use crate::model::{
    Extras, Measurements, ParamValues, Quantity, SensorModel, SeriesGroup, SeriesKey, SeriesSpec,
    TruthState,
};
use crate::sensors::WhiteNoise;
use nalgebra::{UnitQuaternion, Vector3};
use rand_chacha::ChaCha8Rng;

/// 1 at a step where a reference attitude arrived.
pub(super) const REFERENCE: Quantity =
    Quantity::new("reference", "a reference attitude arrived (1 = yes)", "");

/// The gyro and the reference attitudes (every Δt, except during a dropout).
#[derive(Clone)]
pub(super) struct Sensors {
    interval_s: f64,
    since_s: f64,
    bias: Vector3<f64>,
    noise: f64,
    ref_noise: f64,
    dropout: (f64, f64),
    delivered: bool,
}

impl Sensors {
    /// The gyro and references `p` sets, no reference delivered yet.
    pub(super) fn new(p: &ParamValues) -> Self {
        let mut s = Self {
            interval_s: 1.0,
            since_s: 0.0,
            bias: Vector3::zeros(),
            noise: 0.0,
            ref_noise: 0.0,
            dropout: (0.0, 0.0),
            delivered: false,
        };
        s.apply_params(p);
        s
    }
}

impl SensorModel for Sensors {
    fn apply_params(&mut self, p: &ParamValues) {
        self.interval_s = p.get("interval_s");
        self.bias =
            Vector3::new(1.0, -1.0, 2.0).normalize() * p.get("gyro_bias_deg_s").to_radians();
        self.noise = p.get("gyro_noise_deg_s").to_radians();
        self.ref_noise = p.get("ref_noise_rad");
        let from = p.get("dropout_from_s");
        self.dropout = (from, from + p.get("dropout_s"));
    }

    fn sample(&mut self, truth: &TruthState, dt_s: f64, rng: &mut ChaCha8Rng) -> Measurements {
        let noise = WhiteNoise { sigma: self.noise };
        let gyro = truth.rate_body_rad_s + self.bias + Vector3::from_fn(|_, _| noise.sample(rng));
        self.since_s += dt_s;
        // A reference every Δt (to within half a step).
        let due = self.since_s >= self.interval_s - 0.5 * dt_s;
        let lost = truth.t_s >= self.dropout.0 && truth.t_s < self.dropout.1;
        let mut reference = None;
        if due {
            self.since_s = 0.0;
            if !lost {
                let n = WhiteNoise {
                    sigma: self.ref_noise,
                };
                let err = Vector3::from_fn(|_, _| n.sample(rng));
                reference = Some(truth.q_ref_from_body * UnitQuaternion::from_scaled_axis(err));
            }
        }
        self.delivered = reference.is_some();
        Measurements {
            t_s: truth.t_s,
            gyro_body_rad_s: Some(gyro),
            star_q_ref_from_body: reference,
            ..Measurements::default()
        }
    }

    fn extra_series(&self) -> Vec<SeriesSpec> {
        vec![SeriesSpec::of(
            SeriesKey::sensors(&REFERENCE),
            SeriesGroup::Lab,
        )]
    }

    fn extra_values(&self, out: &mut Extras<'_>) {
        out.put(&REFERENCE, f64::from(u8::from(self.delivered)));
    }
}
