//! Quantities derived from one source's attitude, rate or angle in one step — Euler
//! angles, the vertical k and w = u + jv, errors against the truth, the attitude NEES —
//! computed only for the quantities a recorded column needs.

use super::catalogue::{N_Q, Q, bit};
use crate::math::{
    EulerYpr, WzAttitude, WzChart, dcm_from_quaternion, pitch_roll_of_vertical,
    small_angle_error_body, wrap_pi,
};
use crate::model::{Attitude, Estimate, Estimator, StateKind, TruthState};
use nalgebra::{UnitQuaternion, Vector3};

/// Values derived from one attitude source in one step, computed only where needed.
#[derive(Clone, Copy, Debug)]
pub(super) struct Derived {
    pub(super) values: [f64; N_Q],
}

pub(super) const NAN_DERIVED: Derived = Derived {
    values: [f64::NAN; N_Q],
};

/// eᵀP⁻¹e of the attitude: e from the truth (rad), P the estimator's attitude block.
pub(super) fn nees_att(e: &dyn Estimator, d: &Derived) -> f64 {
    let Some(c) = e.covariance() else {
        return f64::NAN;
    };
    let idx: Vec<usize> = (0..3)
        .filter_map(|a| c.index_of(StateKind::AttitudeAxis(a)))
        .collect();
    if idx.len() != 3 {
        return f64::NAN;
    }
    let p = nalgebra::Matrix3::from_fn(|r, k| c.get(idx[r], idx[k]));
    let err = nalgebra::Vector3::new(
        d.values[Q::ErrX as usize],
        d.values[Q::ErrY as usize],
        d.values[Q::ErrZ as usize],
    )
    .map(f64::to_radians);
    p.cholesky().map_or(f64::NAN, |ch| err.dot(&ch.solve(&err)))
}

/// |w| above which (u, v) are recorded as missing: the point is then within ~11° of the
/// pole S, where paper 3's chart has no numerical meaning (the (u, v, z) integrator has
/// switched to s = 1/w) and the values would swamp every plot. The chart-free vertical
/// k_x, k_y, k_z is always recorded.
const W_RECORD_LIMIT: f64 = 10.0;

/// Computes the quantities in `needs` for one source; `truth` (with its derived values) is
/// given for estimates, whose errors need it.
pub(super) fn derive(
    needs: u32,
    e: &Estimate,
    truth: Option<(&TruthState, &Derived)>,
    single_axis: bool,
) -> Derived {
    let mut d = [f64::NAN; N_Q];
    if single_axis {
        single_axis_values(&mut d, e, truth.map(|(t, _)| t));
        return Derived { values: d };
    }
    if let Some(r) = e.rate_body_rad_s {
        rate_values(&mut d, needs, r, truth.map(|(t, _)| t));
    }
    // The full attitude as a quaternion, converted from (w, z) only if a column needs it.
    let has = |q: Q| needs & bit(q) != 0;
    let q_bits = bit(Q::Yaw) | bit(Q::ErrDeg) | bit(Q::ErrX) | bit(Q::ErrY) | bit(Q::ErrZ);
    let z_from_q = has(Q::Z) && !matches!(e.attitude, Attitude::Wz(w) if w.chart == WzChart::North);
    let q = if needs & q_bits != 0 || z_from_q {
        e.attitude.quaternion()
    } else {
        None
    };
    if has(Q::Yaw)
        && let Some(q) = q
    {
        d[Q::Yaw as usize] = EulerYpr::yaw_of(&q).to_degrees();
    }
    let sphere_bits =
        bit(Q::Pitch) | bit(Q::Roll) | bit(Q::Kx) | bit(Q::Ky) | bit(Q::Kz) | bit(Q::U) | bit(Q::V);
    if needs & (sphere_bits | TILT_BITS) != 0
        && let Some(k) = e.attitude.vertical_in_body()
    {
        vertical_values(&mut d, needs, &k, truth.map(|(_, td)| td));
    }
    if has(Q::Z) {
        d[Q::Z as usize] = z_deg(e, q);
    }
    if let (Some((t, _)), Some(q)) = (truth, q)
        && needs & (bit(Q::ErrDeg) | bit(Q::ErrX) | bit(Q::ErrY) | bit(Q::ErrZ)) != 0
    {
        // The error rotation in body axes, once: its angle is the total error, its
        // scaled axis the error per axis.
        let err = small_angle_error_body(&t.q_ref_from_body, &q);
        d[Q::ErrDeg as usize] = err.norm().to_degrees();
        d[Q::ErrX as usize] = err.x.to_degrees();
        d[Q::ErrY as usize] = err.y.to_degrees();
        d[Q::ErrZ as usize] = err.z.to_degrees();
    }
    Derived { values: d }
}

/// The tilt errors' bits: they need the vertical of the estimate and of the truth.
const TILT_BITS: u32 =
    (1 << Q::TiltErr as u32) | (1 << Q::PitchErr as u32) | (1 << Q::RollErr as u32);

/// A single-axis source's angle and rate (about its z), with their errors.
fn single_axis_values(d: &mut [f64; N_Q], e: &Estimate, truth: Option<&TruthState>) {
    let deg = f64::to_degrees;
    if let Some(a) = e.angle_rad {
        d[Q::Angle as usize] = deg(a);
        if let Some(ta) = truth.and_then(|t| t.angle_rad) {
            d[Q::AngleErr as usize] = deg(a - ta);
        }
    }
    if let Some(r) = e.rate_body_rad_s {
        d[Q::Rate1 as usize] = deg(r.z);
        if let Some(t) = truth {
            d[Q::RateErr1 as usize] = deg(r.z - t.rate_body_rad_s.z);
        }
    }
}

/// A three-axis source's body rate `r` (if asked for) and its error against the truth.
fn rate_values(d: &mut [f64; N_Q], needs: u32, r: Vector3<f64>, truth: Option<&TruthState>) {
    let deg = f64::to_degrees;
    if needs & (bit(Q::RateX) | bit(Q::RateY) | bit(Q::RateZ)) != 0 {
        d[Q::RateX as usize] = deg(r.x);
        d[Q::RateY as usize] = deg(r.y);
        d[Q::RateZ as usize] = deg(r.z);
    }
    if let Some(t) = truth {
        let err = r - t.rate_body_rad_s;
        d[Q::RateErrX as usize] = deg(err.x);
        d[Q::RateErrY as usize] = deg(err.y);
        d[Q::RateErrZ as usize] = deg(err.z);
    }
}

/// What the vertical `k` in body axes gives: pitch and roll, k itself, w = u + jv away from
/// the pole, and (with the truth's derived values) the tilt errors.
fn vertical_values(d: &mut [f64; N_Q], needs: u32, k: &Vector3<f64>, truth: Option<&Derived>) {
    let has = |q: Q| needs & bit(q) != 0;
    let deg = f64::to_degrees;
    if needs & (bit(Q::Pitch) | bit(Q::Roll) | TILT_BITS) != 0 {
        // Pitch and roll depend on the vertical only (paper 3, eqs. 24–25), so a tilt-only
        // estimate still has them.
        let (pitch, roll) = pitch_roll_of_vertical(k);
        d[Q::Pitch as usize] = deg(pitch);
        d[Q::Roll as usize] = deg(roll);
    }
    d[Q::Kx as usize] = k.x;
    d[Q::Ky as usize] = k.y;
    d[Q::Kz as usize] = k.z;
    if (has(Q::U) || has(Q::V)) && 1.0 + k.z > 0.0 {
        // w = (a′ + jb′)/(1 + c′) (paper 3, eq. 12), recorded only away from the pole.
        let (u, v) = (k.x / (1.0 + k.z), k.y / (1.0 + k.z));
        if u * u + v * v < W_RECORD_LIMIT * W_RECORD_LIMIT {
            d[Q::U as usize] = u;
            d[Q::V as usize] = v;
        }
    }
    if let Some(td) = truth
        && needs & TILT_BITS != 0
    {
        let kt = Vector3::new(
            td.values[Q::Kx as usize],
            td.values[Q::Ky as usize],
            td.values[Q::Kz as usize],
        );
        let (pt, rt) = pitch_roll_of_vertical(&kt);
        if has(Q::TiltErr) {
            d[Q::TiltErr as usize] = deg(kt.cross(k).norm().atan2(kt.dot(k)));
        }
        d[Q::PitchErr as usize] = d[Q::Pitch as usize] - deg(pt);
        d[Q::RollErr as usize] = deg(wrap_pi(d[Q::Roll as usize].to_radians() - rt));
    }
}

/// z (deg), chart dependent: in paper 3's chart where that chart exists.
fn z_deg(e: &Estimate, q: Option<UnitQuaternion<f64>>) -> f64 {
    match (e.attitude, q) {
        (Attitude::Wz(w), _) if w.chart == WzChart::North => w.z_rad.to_degrees(),
        (_, Some(q)) => WzAttitude::from_dcm_in_chart(&dcm_from_quaternion(&q), WzChart::North)
            .map_or(f64::NAN, |w| w.z_rad.to_degrees()),
        _ => f64::NAN,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{Covariance, Measurements, StateInfo};
    use approx::assert_relative_eq;
    use nalgebra::{SMatrix, UnitQuaternion, Vector3};

    const ALL: u32 = u32::MAX;

    fn truth_at(q: UnitQuaternion<f64>) -> TruthState {
        TruthState::new(1.0, q, Vector3::new(0.01, -0.02, 0.03))
    }

    fn estimate(q: UnitQuaternion<f64>, rate: Vector3<f64>) -> Estimate {
        Estimate {
            attitude: Attitude::Quaternion(q),
            angle_rad: None,
            rate_body_rad_s: Some(rate),
        }
    }

    fn of_truth(t: &TruthState) -> Derived {
        derive(
            ALL,
            &estimate(t.q_ref_from_body, t.rate_body_rad_s),
            None,
            false,
        )
    }

    fn v(d: &Derived, q: Q) -> f64 {
        d.values[q as usize]
    }

    #[test]
    fn an_estimate_equal_to_the_truth_has_zero_errors() {
        let t = truth_at(UnitQuaternion::from_euler_angles(0.2, -0.4, 1.1));
        let td = of_truth(&t);
        let d = derive(
            ALL,
            &estimate(t.q_ref_from_body, t.rate_body_rad_s),
            Some((&t, &td)),
            false,
        );
        for q in [
            Q::ErrDeg,
            Q::ErrX,
            Q::ErrY,
            Q::ErrZ,
            Q::TiltErr,
            Q::PitchErr,
            Q::RollErr,
        ] {
            assert!(v(&d, q).abs() < 1e-9, "{q:?} = {}", v(&d, q));
        }
        for q in [Q::RateErrX, Q::RateErrY, Q::RateErrZ] {
            assert_eq!(v(&d, q), 0.0, "{q:?}");
        }
        // The truth has no truth to compare with: its own errors are missing.
        assert!(v(&td, Q::ErrDeg).is_nan());
    }

    #[test]
    fn a_turn_about_body_x_is_an_error_about_x_in_degrees() {
        let t = truth_at(UnitQuaternion::from_euler_angles(0.3, 0.1, -0.5));
        let td = of_truth(&t);
        let turned =
            t.q_ref_from_body * UnitQuaternion::from_scaled_axis(Vector3::x() * 1f64.to_radians());
        let rate = t.rate_body_rad_s + Vector3::new(0.0, 0.5f64.to_radians(), 0.0);
        let d = derive(ALL, &estimate(turned, rate), Some((&t, &td)), false);
        assert_relative_eq!(v(&d, Q::ErrX), 1.0, epsilon = 1e-9);
        assert_relative_eq!(v(&d, Q::ErrDeg), 1.0, epsilon = 1e-9);
        assert!(v(&d, Q::ErrY).abs() < 1e-9 && v(&d, Q::ErrZ).abs() < 1e-9);
        assert_relative_eq!(v(&d, Q::RateErrY), 0.5, epsilon = 1e-9);
        // A turn by θ about the body's x axis moves the vertical k by φ with
        // cos φ = cos θ + (1 − cos θ)(x·k)².
        let k = crate::math::vertical_in_body(&t.q_ref_from_body);
        let c = 1f64.to_radians().cos();
        let tilt_deg = (c + (1.0 - c) * k.x * k.x).acos().to_degrees();
        assert!(tilt_deg < 0.999, "the test's attitude tilts k less than θ");
        assert_relative_eq!(v(&d, Q::TiltErr), tilt_deg, epsilon = 1e-6);
    }

    #[test]
    fn w_is_the_stereographic_projection_of_the_vertical_and_missing_near_the_pole() {
        // Level: the vertical is the body's z, w = 0.
        let level = of_truth(&truth_at(UnitQuaternion::identity()));
        assert_eq!((v(&level, Q::U), v(&level, Q::V)), (0.0, 0.0));
        assert_eq!(v(&level, Q::Kz), 1.0);
        // Pitched by 90°: |w| = 1 (paper 3: the equator of the sphere).
        let side = of_truth(&truth_at(UnitQuaternion::from_scaled_axis(
            Vector3::y() * std::f64::consts::FRAC_PI_2,
        )));
        assert_relative_eq!(v(&side, Q::U).hypot(v(&side, Q::V)), 1.0, epsilon = 1e-12);
        // Within ~11° of upside down |w| > 10: recorded as missing, the vertical still is.
        let near_pole = of_truth(&truth_at(UnitQuaternion::from_scaled_axis(
            Vector3::x() * 175f64.to_radians(),
        )));
        assert!(v(&near_pole, Q::U).is_nan() && v(&near_pole, Q::V).is_nan());
        assert_relative_eq!(
            v(&near_pole, Q::Kz),
            175f64.to_radians().cos(),
            epsilon = 1e-12
        );
    }

    #[test]
    fn only_the_quantities_asked_for_are_computed() {
        let t = truth_at(UnitQuaternion::from_euler_angles(0.2, 0.3, 0.4));
        let d = derive(
            bit(Q::Yaw),
            &estimate(t.q_ref_from_body, t.rate_body_rad_s),
            None,
            false,
        );
        assert!(v(&d, Q::Yaw).is_finite());
        for q in [Q::Pitch, Q::Kx, Q::U, Q::Z, Q::RateX] {
            assert!(v(&d, q).is_nan(), "{q:?} was computed");
        }
    }

    #[test]
    fn a_single_axis_source_has_its_angle_and_rate_errors() {
        let mut t = truth_at(UnitQuaternion::identity());
        t.angle_rad = Some(0.5);
        let e = Estimate {
            attitude: Attitude::None,
            angle_rad: Some(0.5 + 2f64.to_radians()),
            rate_body_rad_s: Some(Vector3::new(0.0, 0.0, 0.03 - 1f64.to_radians())),
        };
        let d = derive(ALL, &e, Some((&t, &NAN_DERIVED)), true);
        assert_relative_eq!(v(&d, Q::AngleErr), 2.0, epsilon = 1e-9);
        assert_relative_eq!(v(&d, Q::RateErr1), -1.0, epsilon = 1e-9);
        assert_relative_eq!(v(&d, Q::Angle), (0.5 + 2f64.to_radians()).to_degrees());
    }

    /// An estimator that only publishes a diagonal attitude covariance.
    #[derive(Clone)]
    struct Diag(SMatrix<f64, 3, 3>);

    const ATT: [StateInfo; 3] = [
        StateInfo::new("att_x", "rad", StateKind::AttitudeAxis(0)),
        StateInfo::new("att_y", "rad", StateKind::AttitudeAxis(1)),
        StateInfo::new("att_z", "rad", StateKind::AttitudeAxis(2)),
    ];

    impl Estimator for Diag {
        fn id(&self) -> &'static str {
            "diag"
        }
        fn label(&self) -> &'static str {
            "diag"
        }
        fn apply_params(&mut self, _params: &crate::model::ParamValues) {}
        fn step(&mut self, _m: &Measurements, _dt_s: f64) {}
        fn estimate(&self) -> Estimate {
            Estimate::default()
        }
        fn covariance(&self) -> Option<Covariance<'_>> {
            Some(Covariance {
                states: &ATT,
                matrix: self.0.as_slice(),
            })
        }
        fn covariance_states(&self) -> &'static [StateInfo] {
            &ATT
        }
    }

    #[test]
    fn the_attitude_nees_is_the_error_weighted_by_the_inverse_covariance() {
        let sigma_rad = 0.5f64.to_radians();
        let e = Diag(SMatrix::identity() * sigma_rad * sigma_rad);
        let mut d = NAN_DERIVED;
        d.values[Q::ErrX as usize] = 1.0;
        d.values[Q::ErrY as usize] = 0.0;
        d.values[Q::ErrZ as usize] = -0.5;
        // (1² + 0.5²)° over (0.5°)²: 5.
        assert_relative_eq!(nees_att(&e, &d), 5.0, epsilon = 1e-9);
    }
}
