//! The space environment of paper 2's lab: the sun's direction (a low-precision ephemeris),
//! the Earth's shadow (cylindrical), the Earth's rotation, WGS 84 geodetic coordinates and
//! the geomagnetic field — NOAA's World Magnetic Model (the `world_magnetic_model` crate,
//! WMM 2025) as the truth, and an onboard model that may be worse.

use super::orbit::EARTH_RADIUS_M;
use nalgebra::Vector3;
use world_magnetic_model::GeomagneticField;
use world_magnetic_model::time::{Date, Month};
use world_magnetic_model::uom::si::angle::radian;
use world_magnetic_model::uom::si::f32::{Angle, Length};
use world_magnetic_model::uom::si::length::meter;
use world_magnetic_model::uom::si::magnetic_flux_density::nanotesla;

/// The epoch of a run: midnight UT of a day of 2026.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Epoch {
    /// Day of the year 2026 (1 = 1 January).
    pub day_of_year: u16,
}

impl Epoch {
    /// Julian date at `t_s` seconds after the epoch.
    pub fn julian_date(&self, t_s: f64) -> f64 {
        // JD of 2026-01-01 00:00 UT is 2461041.5.
        2_461_041.5 + f64::from(self.day_of_year - 1) + t_s / 86_400.0
    }

    /// The calendar date (the field model changes over years, not within a run).
    pub fn date(&self) -> Date {
        Date::from_ordinal_date(2026, self.day_of_year.clamp(1, 365)).unwrap_or_else(|_| {
            Date::from_calendar_date(2026, Month::January, 1).unwrap_or(Date::MIN)
        })
    }
}

/// Unit vector to the sun in the inertial frame at Julian date `jd` (the Astronomical
/// Almanac's low-precision formulae: about 0.01° over 1950–2050).
///
/// ```
/// # use attlab::dynamics::sun_direction_eci;
/// // Near the March equinox the sun is close to the vernal equinox direction.
/// let s = sun_direction_eci(2_461_119.1);
/// assert!(s.x > 0.999 && s.z.abs() < 0.01, "{s:?}");
/// ```
pub fn sun_direction_eci(jd: f64) -> Vector3<f64> {
    let n = jd - 2_451_545.0;
    let l = (280.460 + 0.985_647_4 * n).to_radians();
    let g = (357.528 + 0.985_600_3 * n).to_radians();
    let lambda = l + (1.915f64.to_radians()) * g.sin() + (0.020f64.to_radians()) * (2.0 * g).sin();
    let eps = (23.439 - 0.000_000_4 * n).to_radians();
    Vector3::new(
        lambda.cos(),
        eps.cos() * lambda.sin(),
        eps.sin() * lambda.sin(),
    )
}

/// Whether a satellite at `r_eci_m` is in the Earth's cylindrical shadow for the sun
/// direction `sun_eci`.
pub fn in_shadow(r_eci_m: &Vector3<f64>, sun_eci: &Vector3<f64>) -> bool {
    let along = r_eci_m.dot(sun_eci);
    along < 0.0 && (r_eci_m - sun_eci * along).norm() < EARTH_RADIUS_M
}

/// Greenwich mean sidereal time (rad) at Julian date `jd` (IAU 1982, UT1 ≈ UT).
pub fn gmst_rad(jd: f64) -> f64 {
    let d = jd - 2_451_545.0;
    let gmst_deg = 280.460_618_37 + 360.985_647_366_29 * d;
    gmst_deg.rem_euclid(360.0).to_radians()
}

/// Geodetic latitude, longitude (rad) and height (m) of an Earth-fixed position (WGS 84,
/// Bowring's method — accurate to millimetres at orbital heights after one iteration).
pub fn geodetic_from_ecef(r: &Vector3<f64>) -> (f64, f64, f64) {
    const A: f64 = EARTH_RADIUS_M;
    const F: f64 = 1.0 / 298.257_223_563;
    let b = A * (1.0 - F);
    let e2 = F * (2.0 - F);
    let ep2 = e2 / (1.0 - e2);
    let p = r.x.hypot(r.y);
    let lon = r.y.atan2(r.x);
    let theta = (r.z * A).atan2(p * b);
    let (st, ct) = theta.sin_cos();
    let lat = (r.z + ep2 * b * st.powi(3)).atan2(p - e2 * A * ct.powi(3));
    let n = A / (1.0 - e2 * lat.sin().powi(2)).sqrt();
    let h = if lat.cos().abs() > 1e-9 {
        p / lat.cos() - n
    } else {
        r.z.abs() - b
    };
    (lat, lon, h)
}

/// A field vector given north, east, down at (`lat`, `lon`) in Earth-fixed axes.
fn ecef_from_ned(ned: &Vector3<f64>, lat: f64, lon: f64) -> Vector3<f64> {
    let (sl, cl) = lat.sin_cos();
    let (so, co) = lon.sin_cos();
    let north = Vector3::new(-sl * co, -sl * so, cl);
    let east = Vector3::new(-so, co, 0.0);
    let down = Vector3::new(-cl * co, -cl * so, -sl);
    north * ned.x + east * ned.y + down * ned.z
}

/// What a geomagnetic field model is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FieldModel {
    /// NOAA's World Magnetic Model 2025 (degree 12).
    Wmm,
    /// WMM plus a fixed Earth-fixed error vector of this size (nT): the "model error up to
    /// 400 nT" of an onboard model.
    WmmWithError(f64),
    /// A tilted dipole (the degree-1 part of the field): errors of several thousand nT.
    TiltedDipole,
}

/// Direction (Earth-fixed, unit) of the error vector of [`FieldModel::WmmWithError`].
const MODEL_ERROR_DIRECTION: [f64; 3] = [0.48, -0.64, 0.6];

/// The degree-1 Gauss coefficients of WMM 2025 (nT): g₁₀, g₁₁, h₁₁.
const DIPOLE_NT: [f64; 3] = [-29_351.8, -1_410.8, 4_545.4];

impl FieldModel {
    /// The field (nT) at the Earth-fixed position `r_ecef_m` on `date`, in Earth-fixed axes;
    /// `None` where the model is not defined (WMM: heights over 850 km).
    pub fn field_ecef_nt(&self, r_ecef_m: &Vector3<f64>, date: Date) -> Option<Vector3<f64>> {
        match self {
            Self::Wmm => wmm_ecef_nt(r_ecef_m, date),
            Self::WmmWithError(e) => {
                let dir = Vector3::from(MODEL_ERROR_DIRECTION).normalize();
                wmm_ecef_nt(r_ecef_m, date).map(|b| b + dir * *e)
            }
            Self::TiltedDipole => Some(dipole_ecef_nt(r_ecef_m)),
        }
    }
}

fn wmm_ecef_nt(r_ecef_m: &Vector3<f64>, date: Date) -> Option<Vector3<f64>> {
    let (lat, lon, h) = geodetic_from_ecef(r_ecef_m);
    let field = GeomagneticField::new(
        Length::new::<meter>(h as f32),
        Angle::new::<radian>(lat as f32),
        Angle::new::<radian>(lon as f32),
        date,
    )
    .ok()?;
    let ned = Vector3::new(
        f64::from(field.x().get::<nanotesla>()),
        f64::from(field.y().get::<nanotesla>()),
        f64::from(field.z().get::<nanotesla>()),
    );
    Some(ecef_from_ned(&ned, lat, lon))
}

/// The tilted dipole B = (R/r)³ [3(m·r̂)r̂ − m] with m from g₁₀, g₁₁, h₁₁ (Earth-fixed).
fn dipole_ecef_nt(r: &Vector3<f64>) -> Vector3<f64> {
    let [g10, g11, h11] = DIPOLE_NT;
    let m = Vector3::new(g11, h11, g10);
    let rh = r.normalize();
    (rh * 3.0 * m.dot(&rh) - m) * (EARTH_RADIUS_M / r.norm()).powi(3)
}

/// Earth-fixed coordinates of an inertial vector at Julian date `jd` (rotation by GMST).
pub fn ecef_from_eci(v: &Vector3<f64>, jd: f64) -> Vector3<f64> {
    let (s, c) = gmst_rad(jd).sin_cos();
    Vector3::new(c * v.x + s * v.y, -s * v.x + c * v.y, v.z)
}

/// Inertial coordinates of an Earth-fixed vector at Julian date `jd`.
pub fn eci_from_ecef(v: &Vector3<f64>, jd: f64) -> Vector3<f64> {
    let (s, c) = gmst_rad(jd).sin_cos();
    Vector3::new(c * v.x - s * v.y, s * v.x + c * v.y, v.z)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wmm_and_its_dipole_agree_on_the_field_size_in_orbit() {
        let date = Epoch { day_of_year: 170 }.date();
        // Over the equator at 600 km and over the north pole.
        for r in [
            Vector3::new(EARTH_RADIUS_M + 600e3, 0.0, 0.0),
            Vector3::new(0.0, 0.0, 6_356_752.0 + 600e3),
        ] {
            let wmm = FieldModel::Wmm.field_ecef_nt(&r, date).unwrap();
            let dip = FieldModel::TiltedDipole.field_ecef_nt(&r, date).unwrap();
            assert!((15_000.0..60_000.0).contains(&wmm.norm()), "{}", wmm.norm());
            // The dipole has the field's size but misses its non-dipole part (over the
            // South Atlantic the direction is ~30° off): a poor onboard model on purpose.
            assert!(
                (wmm.norm() / dip.norm() - 1.0).abs() < 0.25,
                "{wmm:?} vs {dip:?}"
            );
        }
        let with = FieldModel::WmmWithError(400.0)
            .field_ecef_nt(&Vector3::new(7e6, 0.0, 0.0), date)
            .unwrap();
        let without = FieldModel::Wmm
            .field_ecef_nt(&Vector3::new(7e6, 0.0, 0.0), date)
            .unwrap();
        assert!(((with - without).norm() - 400.0).abs() < 1e-6);
    }

    #[test]
    fn geodetic_round_trip_at_the_equator_and_a_pole() {
        let (lat, lon, h) = geodetic_from_ecef(&Vector3::new(EARTH_RADIUS_M + 600e3, 0.0, 0.0));
        assert!(lat.abs() < 1e-12 && lon.abs() < 1e-12 && (h - 600e3).abs() < 1e-6);
        let (lat, _, h) = geodetic_from_ecef(&Vector3::new(0.0, 1e-3, 6_356_752.314_2 + 600e3));
        assert!(
            (lat - std::f64::consts::FRAC_PI_2).abs() < 1e-9 && (h - 600e3).abs() < 1e-3,
            "{lat} {h}"
        );
    }

    #[test]
    fn a_low_orbit_spends_about_a_third_in_shadow_at_noon_midnight() {
        let sun = Vector3::x();
        let r = EARTH_RADIUS_M + 600e3;
        let shadowed = (0..3600)
            .filter(|k| {
                let u = f64::from(*k) / 3600.0 * std::f64::consts::TAU;
                in_shadow(&Vector3::new(u.cos() * r, u.sin() * r, 0.0), &sun)
            })
            .count();
        // Half-angle asin(R/r) ≈ 66.1°: 132°/360° ≈ 0.367 of the orbit.
        assert!((1250..1400).contains(&shadowed), "{shadowed}");
    }
}
