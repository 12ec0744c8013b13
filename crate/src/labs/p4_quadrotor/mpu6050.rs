//! An InvenSense MPU-6050 on the rig, from its datasheet (PS-MPU-6000A-00 rev. 3.4):
//!
//! * gyro: rate noise density 0.005 °/s/√Hz, a zero-rate offset (±20 °/s before
//!   calibration; a slider), full-scale ranges ±250/500/1000/2000 °/s = 131/65.5/32.8/16.4
//!   LSB per °/s;
//! * accelerometer: noise density 400 µg/√Hz, full scale ±2/4/8/16 g = 16384/8192/4096/2048
//!   LSB per g;
//! * both through the digital low-pass filter (DLPF) of the chosen bandwidth: the noise σ
//!   of a sample is density·√(1.57·bandwidth) (a first-order filter's noise bandwidth), and
//!   16-bit two's-complement counts, clipped at full scale.
//!
//! On a rig the propellers shake the chip: a vibration of `vibration_g` (RMS, per axis,
//! white at the sample rate — ours; the paper gives none) adds to the accelerometer's noise,
//! which is what makes trusting the accelerometer costly.
//!
//! The chip sits on the lever (or the quadrotor) at `imu_offset_m` from the pivot, so it
//! feels the tangential r·θ̈ and the centripetal r·θ̇² besides gravity; the accelerometer
//! angle atan2(a_y, a_z) = atan2(g sin θ − rθ̇², g cos θ + rθ̈) is therefore wrong while the
//! rig moves fast, as on the real bench.

use crate::model::{
    Extras, Measurements, ParamValues, Quantity, SensorModel, SeriesGroup, SeriesKey, SeriesSpec,
    TruthState,
};
use crate::sensors::WhiteNoise;
use nalgebra::Vector3;
use rand_chacha::ChaCha8Rng;

// The series this model records besides the catalogue's.
/// accelerometer angle θ_acc = atan2(a_y, a_z) (deg).
pub(super) const ACCEL_ANGLE_DEG: Quantity = Quantity::new(
    "accel_angle_deg",
    "accelerometer angle θ_acc = atan2(a_y, a_z)",
    "deg",
);
/// gyro reading ω (deg/s).
pub(super) const GYRO_DEG_S: Quantity = Quantity::new("gyro_deg_s", "gyro reading ω", "deg/s");

/// Standard gravity (m/s²).
const G_MPS2: f64 = 9.80665;

/// Gyro full-scale choices (°/s) and accelerometer ones (g).
pub const GYRO_RANGES: &[&str] = &["±250 °/s (power-on)", "±500 °/s", "±1000 °/s", "±2000 °/s"];
/// Accelerometer full-scale choices.
pub const ACCEL_RANGES: &[&str] = &["±2 g (power-on)", "±4 g", "±8 g", "±16 g"];

/// Full scale of choice `index` of the gyro (°/s) and of the accelerometer (g).
pub fn full_scales(gyro_index: usize, accel_index: usize) -> (f64, f64) {
    let k = |i: usize| f64::from(1u32 << i.min(3));
    (250.0 * k(gyro_index), 2.0 * k(accel_index))
}

/// `value` read as a 16-bit count of a ±`full_scale` range, and back.
pub fn quantise(value: f64, full_scale: f64) -> f64 {
    let lsb = full_scale / 32768.0;
    (value / lsb).round().clamp(-32768.0, 32767.0) * lsb
}

/// The chip.
#[derive(Clone, Debug)]
pub struct Mpu6050 {
    gyro_fs_deg_s: f64,
    accel_fs_g: f64,
    gyro_sigma_deg_s: f64,
    accel_sigma_g: f64,
    gyro_offset_deg_s: f64,
    vibration_g: f64,
    offset_m: f64,
    last_rate_rad_s: Option<f64>,
    last: (f64, f64),
}

impl Mpu6050 {
    /// The chip with the parameters `p`.
    pub fn new(p: &ParamValues) -> Self {
        let mut s = Self {
            gyro_fs_deg_s: 250.0,
            accel_fs_g: 2.0,
            gyro_sigma_deg_s: 0.0,
            accel_sigma_g: 0.0,
            gyro_offset_deg_s: 0.0,
            vibration_g: 0.0,
            offset_m: 0.0,
            last_rate_rad_s: None,
            last: (0.0, 0.0),
        };
        s.apply_params(p);
        s
    }
}

/// σ of one sample of a density (per √Hz) through a DLPF of `bandwidth_hz`.
pub fn sample_sigma(density: f64, bandwidth_hz: f64) -> f64 {
    density * (1.57 * bandwidth_hz).sqrt()
}

impl SensorModel for Mpu6050 {
    fn apply_params(&mut self, p: &ParamValues) {
        (self.gyro_fs_deg_s, self.accel_fs_g) =
            full_scales(p.index("gyro_range"), p.index("accel_range"));
        let bw = p.get("dlpf_hz");
        self.gyro_sigma_deg_s = sample_sigma(p.get("gyro_density_deg_s"), bw);
        self.accel_sigma_g = sample_sigma(p.get("accel_density_ug") * 1e-6, bw);
        self.gyro_offset_deg_s = p.get("gyro_offset_deg_s");
        self.vibration_g = p.get("vibration_g");
        self.offset_m = p.get("imu_offset_m");
    }

    fn sample(&mut self, truth: &TruthState, dt_s: f64, rng: &mut ChaCha8Rng) -> Measurements {
        let theta = truth.angle_rad.unwrap_or(0.0);
        let omega = truth.rate_body_rad_s.z;
        // θ̈ over the last step (the rig's own is not part of the truth's state).
        let alpha = self
            .last_rate_rad_s
            .map_or(0.0, |w| (omega - w) / dt_s.max(1e-9));
        self.last_rate_rad_s = Some(omega);
        let r = self.offset_m;
        let f_y = (G_MPS2 * theta.sin() - r * omega * omega) / G_MPS2;
        let f_z = (G_MPS2 * theta.cos() + r * alpha) / G_MPS2;
        // The chip's own noise and the propellers' vibration, independent per sample.
        let acc_noise = WhiteNoise {
            sigma: self.accel_sigma_g.hypot(self.vibration_g),
        };
        let gyro_noise = WhiteNoise {
            sigma: self.gyro_sigma_deg_s,
        };
        let accel = Vector3::new(
            quantise(acc_noise.sample(rng), self.accel_fs_g),
            quantise(f_y + acc_noise.sample(rng), self.accel_fs_g),
            quantise(f_z + acc_noise.sample(rng), self.accel_fs_g),
        );
        let gyro_deg_s = quantise(
            omega.to_degrees() + self.gyro_offset_deg_s + gyro_noise.sample(rng),
            self.gyro_fs_deg_s,
        );
        self.last = (accel.y.atan2(accel.z).to_degrees(), gyro_deg_s);
        Measurements {
            t_s: truth.t_s,
            accel_body_g: Some(accel),
            gyro_axis_rad_s: Some(gyro_deg_s.to_radians()),
            // The flight computer knows its controller's command.
            lab: truth.lab.clone(),
            ..Measurements::default()
        }
    }

    fn extra_series(&self) -> Vec<SeriesSpec> {
        vec![
            SeriesSpec::of(SeriesKey::sensors(&ACCEL_ANGLE_DEG), SeriesGroup::Attitude),
            SeriesSpec::of(SeriesKey::sensors(&GYRO_DEG_S), SeriesGroup::Rate),
        ]
    }

    fn extra_values(&self, out: &mut Extras<'_>) {
        out.put(&ACCEL_ANGLE_DEG, self.last.0);
        out.put(&GYRO_DEG_S, self.last.1);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_clip_at_full_scale_and_round_to_one_lsb() {
        assert_eq!(quantise(300.0, 250.0), 32767.0 * 250.0 / 32768.0);
        assert_eq!(quantise(-300.0, 250.0), -250.0);
        let lsb = 250.0 / 32768.0;
        assert!((quantise(1.0, 250.0) - 1.0).abs() <= lsb / 2.0);
    }

    #[test]
    fn datasheet_sensitivities() {
        // LSB per unit: 131 LSB/(°/s) at ±250 °/s, 16384 LSB/g at ±2 g.
        let (g, a) = full_scales(0, 0);
        assert!((32768.0 / g - 131.072).abs() < 1e-9);
        assert!((32768.0 / a - 16384.0).abs() < 1e-9);
        let (g, a) = full_scales(3, 3);
        assert_eq!((g, a), (2000.0, 16.0));
    }
}
