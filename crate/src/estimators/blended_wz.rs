//! Paper 3's open-loop blend (Fig. 9): the gyro channel integrates (u, v) by eqs. (18–19),
//! the accelerometer channel gives (uᵃ, vᵃ) by eq. (28), and
//! `uᵏ = HPF(u) + LPF(uᵃ)`, `vᵏ = HPF(v) + LPF(vᵃ)` with `W_HPF = Ts/(Ts + 1)`,
//! `W_LPF = 1/(Ts + 1)`.
//!
//! Since HPF + LPF = 1 this is computed as `wᵏ = w + LPF(wᵃ − w)` (digest §4), one
//! first-order low-pass on the difference, discretised by backward Euler
//! (`e ← e + dt/(T + dt)·(x − e)`). The gyro channel keeps running open loop (no feedback,
//! as in the paper). When the gyro channel switches chart (body upside down) the blended point
//! is carried into the new chart, so the blend works on the whole sphere. The separate
//! channels HPF(u), HPF(v), LPF(uᵃ), LPF(vᵃ) are published for the paper's Fig. 10.

use crate::math::{RateSegment, WzAttitude, chart_coords_of_vertical, step_uvz_rk4};
use crate::model::{
    Attitude, Estimate, Estimator, Extras, Measurements, ParamValues, Quantity, Tuner,
};
use nalgebra::Vector3;

// The series this estimator records besides the catalogue's (figures name them).
/// gyro channel HPF(u).
pub const HPF_U: Quantity = Quantity::new("hpf_u", "gyro channel HPF(u)", "");
/// gyro channel HPF(v).
pub const HPF_V: Quantity = Quantity::new("hpf_v", "gyro channel HPF(v)", "");
/// accelerometer channel LPF(uᵃ).
pub const LPF_UA: Quantity = Quantity::new("lpf_ua", "accelerometer channel LPF(uᵃ)", "");
/// accelerometer channel LPF(vᵃ).
pub const LPF_VA: Quantity = Quantity::new("lpf_va", "accelerometer channel LPF(vᵃ)", "");

/// First-order low-pass `y ← y + dt/(T + dt)·(x − y)`.
fn low_pass(y: &mut f64, x: f64, dt_s: f64, t_s: f64) {
    *y += dt_s / (t_s.max(0.0) + dt_s) * (x - *y);
}

/// The complementary (HPF + LPF) blend of paper 3.
#[derive(Clone, Debug)]
pub struct BlendedWz {
    gyro: WzAttitude,
    last_rate_rad_s: Option<Vector3<f64>>,
    /// LPF(wᵃ − w) in the gyro channel's chart.
    correction: (f64, f64),
    /// Display channels: LPF(u), LPF(v), LPF(uᵃ), LPF(vᵃ).
    channels: [f64; 4],
    time_constant_s: f64,
    tuner: Option<Tuner<f64>>,
}

impl BlendedWz {
    /// Starts from the attitude `wz0` with time constant `time_constant_s`.
    pub fn new(wz0: WzAttitude, time_constant_s: f64) -> Self {
        // Filters start at rest, as in the paper: HPF(v) starts at v₀ and LPF(vᵃ) at 0.
        Self {
            gyro: wz0,
            last_rate_rad_s: None,
            correction: (0.0, 0.0),
            channels: [0.0; 4],
            time_constant_s,
            tuner: None,
        }
    }

    /// Takes the time constant T (s) from the lab's parameters on every change.
    #[must_use]
    pub fn tuned_by(mut self, tuner: Tuner<f64>) -> Self {
        self.tuner = Some(tuner);
        self
    }

    fn blended(&self) -> WzAttitude {
        WzAttitude {
            u: self.gyro.u + self.correction.0,
            v: self.gyro.v + self.correction.1,
            ..self.gyro
        }
    }

    /// Carries the blended point into the gyro channel's new chart after a switch.
    fn rebase(&mut self, before: &WzAttitude) {
        let blended = WzAttitude {
            u: before.u + self.correction.0,
            v: before.v + self.correction.1,
            ..*before
        };
        self.correction =
            match chart_coords_of_vertical(&blended.vertical_in_body(), self.gyro.chart) {
                Some((u, v)) => (u - self.gyro.u, v - self.gyro.v),
                None => (0.0, 0.0),
            };
        self.channels = [
            self.gyro.u,
            self.gyro.v,
            self.gyro.u + self.correction.0,
            self.gyro.v + self.correction.1,
        ];
    }
}

impl Estimator for BlendedWz {
    fn id(&self) -> &'static str {
        "blend"
    }

    fn label(&self) -> &'static str {
        "Blend HPF(u) + LPF(uᵃ), Fig. 9"
    }

    fn extra_quantities(&self) -> &'static [Quantity] {
        const QUANTITIES: &[Quantity] = &[HPF_U, HPF_V, LPF_UA, LPF_VA];
        QUANTITIES
    }

    fn apply_params(&mut self, params: &ParamValues) {
        if let Some(f) = self.tuner {
            self.time_constant_s = f(params);
        }
    }

    fn step(&mut self, m: &Measurements, dt_s: f64) {
        if let Some(rate) = m.gyro_body_rad_s {
            let seg = RateSegment {
                start_rad_s: self.last_rate_rad_s.unwrap_or(rate),
                end_rad_s: rate,
            };
            let before = self.gyro;
            self.gyro = step_uvz_rk4(&self.gyro, |f| seg.at(f), dt_s);
            self.last_rate_rad_s = Some(rate);
            if self.gyro.chart != before.chart {
                self.rebase(&before);
            }
        }
        let Some(n) = m.accel_body_g else { return };
        // The accelerometer point in the gyro channel's chart; skipped near that chart's
        // pole, where it carries no usable information.
        let Some((ua, va)) =
            chart_coords_of_vertical(&n, self.gyro.chart).filter(|(u, v)| u.hypot(*v) < 10.0)
        else {
            return;
        };
        let t = self.time_constant_s;
        low_pass(&mut self.correction.0, ua - self.gyro.u, dt_s, t);
        low_pass(&mut self.correction.1, va - self.gyro.v, dt_s, t);
        let [lu, lv, lua, lva] = &mut self.channels;
        low_pass(lu, self.gyro.u, dt_s, t);
        low_pass(lv, self.gyro.v, dt_s, t);
        low_pass(lua, ua, dt_s, t);
        low_pass(lva, va, dt_s, t);
    }

    fn estimate(&self) -> Estimate {
        let wz = self.blended();
        Estimate {
            attitude: Attitude::Wz(wz),
            rate_body_rad_s: self.last_rate_rad_s,
            ..Estimate::default()
        }
    }

    fn extras(&self, out: &mut Extras<'_>) {
        let [lu, lv, lua, lva] = self.channels;
        out.put(&HPF_U, self.gyro.u - lu);
        out.put(&HPF_V, self.gyro.v - lv);
        out.put(&LPF_UA, lua);
        out.put(&LPF_VA, lva);
    }
}
