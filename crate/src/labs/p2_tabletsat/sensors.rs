//! Paper 2's sensors (Table 1) with their outages, and what the onboard computer knows.
//!
//! * Magnetometer: the WMM field in body axes + bias + 250 nT white noise, ±200 000 nT.
//! * Sun sensors: five heads (boresights ±x, ±y, +z) of ±45° field of view, 0.1° noise; no
//!   reading in eclipse or when the sun is outside every head's field.
//! * Gyro: rate + constant bias + bias random walk + 0.005 °/s white noise, ±250 °/s.
//! * Star tracker (boresight 45° off zenith toward +y in nominal attitude): 0.001°; no reading above
//!   2 °/s, with the sun inside its exclusion cone, or with the Earth's limb inside its
//!   exclusion cone.
//!
//! Each sensor delivers at its own rate. The onboard computer's references — the field from
//! its own model (which may be worse than the truth), the sun from the same ephemeris, the
//! orbit's rate and gravity-gradient coefficient, the wheels' momentum and torque — come
//! with every step in [`Onboard`].

use super::truth::Wheels;
use super::truth::orbit_of;
use crate::dynamics::{
    CircularOrbit, EARTH_RADIUS_M, Epoch, FieldModel, ecef_from_eci, eci_from_ecef, in_shadow,
    sun_direction_eci,
};
use crate::estimators::Onboard;
use crate::model::{
    Direction, Extras, LabData, Measurements, OrbitPicture, ParamValues, Quantity, SceneExtras,
    SceneVector, SensorModel, SeriesGroup, SeriesKey, SeriesSpec, TruthState,
};
use crate::sensors::{RandomWalk, WhiteNoise};
use nalgebra::{UnitQuaternion, Vector3};
use rand_chacha::ChaCha8Rng;

/// 1 while the satellite is in the Earth's shadow.
pub(super) const ECLIPSE: Quantity =
    Quantity::new("eclipse", "in the Earth's shadow (1 = yes)", "");
/// 1 while a sun-sensor head sees the sun.
pub(super) const SUN_SEEN: Quantity =
    Quantity::new("sun_seen", "a sun sensor sees the sun (1 = yes)", "");
/// 1 while the star tracker gives an attitude.
pub(super) const STAR_AVAILABLE: Quantity =
    Quantity::new("star_available", "star tracker available (1 = yes)", "");
/// The gyro's true bias (deg/s).
pub(super) const GYRO_BIAS: [Quantity; 3] = [
    Quantity::new("gyro_bias_x_deg_s", "true gyro bias Δω_x", "deg/s"),
    Quantity::new("gyro_bias_y_deg_s", "true gyro bias Δω_y", "deg/s"),
    Quantity::new("gyro_bias_z_deg_s", "true gyro bias Δω_z", "deg/s"),
];
/// The magnetometer's true bias (nT).
pub(super) const MAG_BIAS: [Quantity; 3] = [
    Quantity::new("mag_bias_x_nt", "true magnetometer bias Δb_x", "nT"),
    Quantity::new("mag_bias_y_nt", "true magnetometer bias Δb_y", "nT"),
    Quantity::new("mag_bias_z_nt", "true magnetometer bias Δb_z", "nT"),
];
/// The magnetometer's true bias as a turn of the field (deg; Fig. 7's model).
pub(super) const MAG_TURN: [Quantity; 3] = [
    Quantity::new(
        "mag_turn_x_deg",
        "true magnetometer bias: turn about x",
        "deg",
    ),
    Quantity::new(
        "mag_turn_y_deg",
        "true magnetometer bias: turn about y",
        "deg",
    ),
    Quantity::new(
        "mag_turn_z_deg",
        "true magnetometer bias: turn about z",
        "deg",
    ),
];

/// Sun-sensor head boresights (body axes).
const SUN_HEADS: [[f64; 3]; 5] = [
    [1.0, 0.0, 0.0],
    [-1.0, 0.0, 0.0],
    [0.0, 1.0, 0.0],
    [0.0, -1.0, 0.0],
    [0.0, 0.0, 1.0],
];

/// Star-tracker boresight (body axes): 45° off zenith toward +y (the orbit normal away from
/// the sun in the default 10:30 orbit), so that it sees stars around the whole default orbit;
/// the paper does not say where it looks.
const STAR_BORESIGHT: [f64; 3] = [
    0.0,
    std::f64::consts::FRAC_1_SQRT_2,
    std::f64::consts::FRAC_1_SQRT_2,
];

/// Direction (body) of the magnetometer bias.
const MAG_BIAS_DIRECTION: [f64; 3] = [0.36, 0.48, -0.8];

/// Direction (body) of the constant gyro bias.
const GYRO_BIAS_DIRECTION: [f64; 3] = [0.6, 0.8, 0.0];

/// The onboard field models, in menu order.
pub const FIELD_MODELS: &[&str] = &[
    "WMM, as the truth (no model error)",
    "tilted dipole (several µT off)",
    "WMM + model error of the size set below",
];

/// How to read the star tracker's 0.001°.
pub const STAR_READINGS: &[&str] = &[
    "0.001° per axis of rotation",
    "0.001° on each quaternion component (a 0.002° rotation)",
];

/// Samples every `1/rate` seconds on a step grid of `dt`.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Clock {
    every_steps: u64,
    step: u64,
}

impl Clock {
    fn new(rate_hz: f64, dt_s: f64) -> Self {
        let mut c = Self {
            every_steps: 1,
            step: 0,
        };
        c.set_rate(rate_hz, dt_s);
        c
    }

    /// A new rate from the next step on (a live slider): the count carries on.
    fn set_rate(&mut self, rate_hz: f64, dt_s: f64) {
        self.every_steps = ((1.0 / (rate_hz * dt_s)).round() as u64).max(1);
    }

    /// Advances one step; true when a sample is due.
    fn tick(&mut self) -> bool {
        self.step += 1;
        self.step.is_multiple_of(self.every_steps)
    }
}

/// The sensors and the onboard references.
#[derive(Clone)]
pub struct Sensors {
    dt_s: f64,
    orbit: CircularOrbit,
    epoch: Epoch,
    onboard_model: FieldModel,
    mag_clock: Clock,
    sun_clock: Clock,
    gyro_clock: Clock,
    star_clock: Clock,
    mag_sigma_nt: f64,
    mag_bias_nt: Vector3<f64>,
    /// The field's turn in the magnetometer (rotation vector, rad).
    mag_turn_rad: Vector3<f64>,
    sun_sigma_rad: f64,
    sun_fov_rad: f64,
    gyro_sigma_rad_s: f64,
    gyro_bias_rad_s: Vector3<f64>,
    gyro_walk: [RandomWalk; 3],
    star_sigma_rad: f64,
    star_max_rate_rad_s: f64,
    star_sun_exclusion_rad: f64,
    star_earth_exclusion_rad: f64,
    /// What the last step saw: (eclipse, sun seen, star tracker available).
    seen: (bool, bool, bool),
    /// Thought experiment: the sun put this far (rad) from the field direction.
    sun_along_field_rad: Option<f64>,
    /// The last field readings (truth, onboard model), orbital axes (nT).
    fields: (Vector3<f64>, Vector3<f64>),
    /// What the 3D view shows of the last sample.
    scene: SceneExtras,
}

impl Sensors {
    /// Sensors for `p` on the simulation step `dt_s`.
    pub fn new(p: &ParamValues, dt_s: f64) -> Self {
        let (orbit, epoch) = orbit_of(p);
        let mut s = Self {
            dt_s,
            orbit,
            epoch,
            onboard_model: FieldModel::Wmm,
            mag_clock: Clock::new(1.0, dt_s),
            sun_clock: Clock::new(1.0, dt_s),
            gyro_clock: Clock::new(1.0, dt_s),
            star_clock: Clock::new(1.0, dt_s),
            mag_sigma_nt: 0.0,
            mag_bias_nt: Vector3::zeros(),
            mag_turn_rad: Vector3::zeros(),
            sun_sigma_rad: 0.0,
            sun_fov_rad: 0.0,
            gyro_sigma_rad_s: 0.0,
            gyro_bias_rad_s: Vector3::zeros(),
            gyro_walk: [RandomWalk {
                value: 0.0,
                sigma_per_sqrt_s: 0.0,
            }; 3],
            star_sigma_rad: 0.0,
            star_max_rate_rad_s: 0.0,
            star_sun_exclusion_rad: 0.0,
            star_earth_exclusion_rad: 0.0,
            seen: (false, false, false),
            sun_along_field_rad: None,
            fields: (Vector3::repeat(f64::NAN), Vector3::repeat(f64::NAN)),
            scene: SceneExtras::default(),
        };
        s.dt_s = dt_s;
        s.apply_params(p);
        s
    }

    /// The sun in orbital axes: the real one, or (the degenerate-geometry experiment) the
    /// field direction turned by the chosen angle about an axis across it.
    fn sun_orbit(
        &self,
        b_true_orbit: &Vector3<f64>,
        q_eci_orbit: &UnitQuaternion<f64>,
        sun_eci: &Vector3<f64>,
    ) -> Vector3<f64> {
        match self.sun_along_field_rad {
            Some(angle) => {
                let b = b_true_orbit.normalize();
                let across = b
                    .cross(&Vector3::x())
                    .try_normalize(1e-9)
                    .unwrap_or_else(Vector3::y);
                UnitQuaternion::from_scaled_axis(across * angle) * b
            }
            None => q_eci_orbit.inverse_transform_vector(sun_eci),
        }
    }

    /// The gyro's reading when its clock ticks: rate + bias + bias walk + noise, clipped
    /// to ±250 °/s (the walk moves every step).
    fn gyro_reading(
        &mut self,
        truth: &TruthState,
        dt_s: f64,
        rng: &mut ChaCha8Rng,
    ) -> Option<Vector3<f64>> {
        for w in &mut self.gyro_walk {
            w.step(dt_s, rng);
        }
        let walk = Vector3::new(
            self.gyro_walk[0].value,
            self.gyro_walk[1].value,
            self.gyro_walk[2].value,
        );
        if !self.gyro_clock.tick() {
            return None;
        }
        let noise = WhiteNoise {
            sigma: self.gyro_sigma_rad_s,
        };
        let range = 250f64.to_radians();
        let g = truth.rate_body_rad_s
            + self.gyro_bias_rad_s
            + walk
            + Vector3::from_fn(|_, _| noise.sample(rng));
        Some(g.map(|x| x.clamp(-range, range)))
    }

    /// The magnetometer's reading of the true field: + bias + noise, clipped to ±200 µT;
    /// none if it is not finite.
    fn mag_reading(
        &self,
        q_orbit_from_body: &UnitQuaternion<f64>,
        b_true_orbit: &Vector3<f64>,
        rng: &mut ChaCha8Rng,
    ) -> Option<Vector3<f64>> {
        let noise = WhiteNoise {
            sigma: self.mag_sigma_nt,
        };
        let turn = UnitQuaternion::from_scaled_axis(self.mag_turn_rad);
        let b = turn * q_orbit_from_body.inverse_transform_vector(b_true_orbit)
            + self.mag_bias_nt
            + Vector3::from_fn(|_, _| noise.sample(rng));
        b.iter()
            .all(|x| x.is_finite())
            .then(|| b.map(|x| x.clamp(-200_000.0, 200_000.0)))
    }

    /// Whether the star tracker can give an attitude: slow enough, the sun outside its
    /// exclusion angle (or eclipsed), the Earth's limb outside its own.
    fn star_available(&self, truth: &TruthState, sun_body: &Vector3<f64>, eclipse: bool) -> bool {
        let q = truth.q_ref_from_body;
        let boresight = Vector3::from(STAR_BORESIGHT);
        let nadir_body = q.inverse_transform_vector(&-Vector3::z());
        let earth_radius_angle = (EARTH_RADIUS_M / self.orbit.radius_m).asin();
        let w_rel = truth.rate_body_rad_s
            - q.inverse_transform_vector(&self.orbit.frame_rate_orbit_rad_s());
        truth.rate_body_rad_s.norm().max(w_rel.norm()) <= self.star_max_rate_rad_s
            && (eclipse || boresight.angle(sun_body) > self.star_sun_exclusion_rad)
            && boresight.angle(&nadir_body) > earth_radius_angle + self.star_earth_exclusion_rad
    }

    /// The inertial position (m), the sun direction (unit, inertial) and `q_eci_from_orbit`.
    fn geometry(&self, t_s: f64) -> (Vector3<f64>, Vector3<f64>, UnitQuaternion<f64>) {
        let jd = self.epoch.julian_date(t_s);
        (
            self.orbit.position_eci_m(t_s),
            sun_direction_eci(jd),
            self.orbit.q_eci_from_orbit(t_s),
        )
    }

    /// The field of `model` at the satellite, in orbital axes (nT).
    fn field_orbit_nt(
        &self,
        model: FieldModel,
        r_eci: &Vector3<f64>,
        q_eci_from_orbit: &UnitQuaternion<f64>,
        t_s: f64,
    ) -> Vector3<f64> {
        let jd = self.epoch.julian_date(t_s);
        let b_ecef = model
            .field_ecef_nt(&ecef_from_eci(r_eci, jd), self.epoch.date())
            .unwrap_or_else(|| Vector3::repeat(f64::NAN));
        q_eci_from_orbit.inverse_transform_vector(&eci_from_ecef(&b_ecef, jd))
    }
}

/// The sun (unless in shadow), the field and the nadir from the body, and the orbit picture.
fn scene_of(
    r_eci: &Vector3<f64>,
    sun_eci: &Vector3<f64>,
    q_eci_orbit: &UnitQuaternion<f64>,
    sun_orbit: &Vector3<f64>,
    field_orbit_nt: &Vector3<f64>,
    eclipse: bool,
) -> SceneExtras {
    let mut vectors = Vec::with_capacity(3);
    if !eclipse {
        vectors.push(SceneVector {
            label: "sun",
            dir_ref: *sun_orbit,
            kind: Direction::Sun,
        });
    }
    if let Some(b) = field_orbit_nt.try_normalize(1e-9) {
        vectors.push(SceneVector {
            label: "field",
            dir_ref: b,
            kind: Direction::MagneticField,
        });
    }
    vectors.push(SceneVector {
        label: "nadir",
        dir_ref: -Vector3::z(),
        kind: Direction::Nadir,
    });
    SceneExtras {
        vectors,
        orbit: Some(OrbitPicture {
            position_eci_m: *r_eci,
            normal_eci: q_eci_orbit * Vector3::y(),
            sun_eci: *sun_eci,
            eclipse,
            earth_radius_m: EARTH_RADIUS_M,
        }),
    }
}

/// `v` turned by a small random rotation of σ per axis (a noisy direction reading).
fn noisy_direction(v: &Vector3<f64>, sigma_rad: f64, rng: &mut ChaCha8Rng) -> Vector3<f64> {
    let noise = WhiteNoise { sigma: sigma_rad };
    let rot = Vector3::new(noise.sample(rng), noise.sample(rng), noise.sample(rng));
    UnitQuaternion::from_scaled_axis(rot) * v
}

impl SensorModel for Sensors {
    fn apply_params(&mut self, p: &ParamValues) {
        let dt = self.dt_s;
        self.mag_clock.set_rate(p.get("vector_rate_hz"), dt);
        self.sun_clock.set_rate(p.get("vector_rate_hz"), dt);
        self.gyro_clock.set_rate(p.get("gyro_rate_hz"), dt);
        self.star_clock.set_rate(p.get("star_rate_hz"), dt);
        self.onboard_model = match p.index("onboard_field") {
            0 => FieldModel::Wmm,
            1 => FieldModel::TiltedDipole,
            _ => FieldModel::WmmWithError(p.get("model_error_nt")),
        };
        self.mag_sigma_nt = p.get("mag_noise_nt");
        let direction = Vector3::from(MAG_BIAS_DIRECTION).normalize();
        self.mag_bias_nt = direction * p.get("mag_bias_nt");
        self.mag_turn_rad = direction * p.get("mag_turn_deg").to_radians();
        self.sun_sigma_rad = p.get("sun_noise_deg").to_radians();
        self.sun_fov_rad = p.get("sun_fov_deg").to_radians();
        self.gyro_sigma_rad_s = p.get("gyro_noise_deg_s").to_radians();
        self.gyro_bias_rad_s =
            Vector3::from(GYRO_BIAS_DIRECTION).normalize() * p.get("gyro_bias_deg_s").to_radians();
        for w in &mut self.gyro_walk {
            w.sigma_per_sqrt_s = p.get("gyro_walk_deg_s_sqrt_s").to_radians();
        }
        let star = p.get("star_noise_deg").to_radians();
        // Per-axis rotation σ, or σ on each quaternion component (twice the rotation).
        self.star_sigma_rad = if p.index("star_reading") == 1 {
            2.0 * star
        } else {
            star
        };
        self.star_max_rate_rad_s = p.get("star_max_rate_deg_s").to_radians();
        self.star_sun_exclusion_rad = p.get("star_sun_exclusion_deg").to_radians();
        self.star_earth_exclusion_rad = p.get("star_earth_exclusion_deg").to_radians();
        self.sun_along_field_rad = p
            .flag("sun_along_field")
            .then(|| p.get("sun_field_angle_deg").to_radians());
    }

    fn sample(&mut self, truth: &TruthState, dt_s: f64, rng: &mut ChaCha8Rng) -> Measurements {
        let t = truth.t_s;
        let (r_eci, sun_eci, q_eci_orbit) = self.geometry(t);
        let q = truth.q_ref_from_body; // orbit_from_body
        let eclipse = in_shadow(&r_eci, &sun_eci);
        let mag_due = self.mag_clock.tick();
        if mag_due || self.fields.0.x.is_nan() || self.sun_along_field_rad.is_some() {
            self.fields = (
                self.field_orbit_nt(FieldModel::Wmm, &r_eci, &q_eci_orbit, t),
                self.field_orbit_nt(self.onboard_model, &r_eci, &q_eci_orbit, t),
            );
        }
        let (b_true_orbit, mag_ref) = self.fields;
        let sun_orbit = self.sun_orbit(&b_true_orbit, &q_eci_orbit, &sun_eci);
        let sun_body = q.inverse_transform_vector(&sun_orbit);
        // The random draws keep their order: gyro walk and noise, magnetometer, sun, star.
        let mut m = Measurements {
            t_s: t,
            gyro_body_rad_s: self.gyro_reading(truth, dt_s, rng),
            ..Measurements::default()
        };
        if mag_due {
            m.mag_body_nt = self.mag_reading(&q, &b_true_orbit, rng);
        }
        let sun_seen = !eclipse
            && SUN_HEADS
                .iter()
                .any(|h| Vector3::from(*h).dot(&sun_body) >= self.sun_fov_rad.cos());
        if self.sun_clock.tick() && sun_seen {
            m.sun_body = Some(noisy_direction(&sun_body, self.sun_sigma_rad, rng).normalize());
        }
        let star_ok = self.star_available(truth, &sun_body, eclipse);
        if self.star_clock.tick() && star_ok {
            let noise = WhiteNoise {
                sigma: self.star_sigma_rad,
            };
            let err = Vector3::from_fn(|_, _| noise.sample(rng));
            m.star_q_ref_from_body = Some(q * UnitQuaternion::from_scaled_axis(err));
        }
        self.seen = (eclipse, sun_seen, star_ok);
        self.scene = scene_of(
            &r_eci,
            &sun_eci,
            &q_eci_orbit,
            &sun_orbit,
            &b_true_orbit,
            eclipse,
        );
        let wheels = truth.lab.get::<Wheels>().copied().unwrap_or_default();
        m.lab = LabData::new(Onboard {
            frame_rate_orbit_rad_s: self.orbit.frame_rate_orbit_rad_s(),
            gravity_gradient_coeff: self.orbit.gravity_gradient_coeff(),
            mag_ref_orbit_nt: mag_ref,
            sun_ref_orbit: sun_orbit,
            wheel_momentum_body: wheels.momentum_body,
            wheel_torque_body: wheels.torque_body,
        });
        m
    }

    fn extra_series(&self) -> Vec<SeriesSpec> {
        [ECLIPSE, SUN_SEEN, STAR_AVAILABLE]
            .iter()
            .chain(&GYRO_BIAS)
            .chain(&MAG_BIAS)
            .chain(&MAG_TURN)
            .map(|q| SeriesSpec::of(SeriesKey::sensors(q), SeriesGroup::Lab))
            .collect()
    }

    fn scene(&self) -> SceneExtras {
        self.scene.clone()
    }

    fn extra_values(&self, out: &mut Extras<'_>) {
        let (e, sun, star) = self.seen;
        let b = self.gyro_bias_rad_s
            + Vector3::new(
                self.gyro_walk[0].value,
                self.gyro_walk[1].value,
                self.gyro_walk[2].value,
            );
        let flag = |on: bool| f64::from(u8::from(on));
        out.put(&ECLIPSE, flag(e));
        out.put(&SUN_SEEN, flag(sun));
        out.put(&STAR_AVAILABLE, flag(star));
        out.put_all(&GYRO_BIAS, b.iter().map(|v| v.to_degrees()));
        out.put_all(&MAG_BIAS, self.mag_bias_nt.iter().copied());
        out.put_all(&MAG_TURN, self.mag_turn_rad.iter().map(|v| v.to_degrees()));
    }
}
