//! Round trips between every pair of attitude representations over the whole rotation
//! group: quaternion, DCM, paper 3's Euler angles, Krylov angles and (w, z) in both charts.
//! 10 000 cases per pair, each pair in both directions.
#![cfg(not(target_arch = "wasm32"))]

use attlab::math::{
    EulerYpr, KrylovAngles, WzAttitude, WzChart, dcm_from_quaternion, quaternion_from_dcm,
};
use attlab_tests::{angle_diff, max_keep_nan};
use nalgebra::{Matrix3, Quaternion, UnitQuaternion};
use proptest::prelude::*;
use std::f64::consts::{FRAC_PI_2, PI};

const TOL: f64 = 1e-9;

fn cfg() -> ProptestConfig {
    ProptestConfig {
        cases: 10_000,
        ..ProptestConfig::default()
    }
}

/// Uniform over SO(3): a uniformly random point in the 4-ball, normalised.
fn any_q() -> impl Strategy<Value = UnitQuaternion<f64>> {
    (-1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64)
        .prop_filter("inside the unit ball, away from 0", |(a, b, c, d)| {
            let n = a * a + b * b + c * c + d * d;
            n > 1e-4 && n <= 1.0
        })
        .prop_map(|(a, b, c, d)| UnitQuaternion::from_quaternion(Quaternion::new(a, b, c, d)))
}

/// Three angles with the middle one away from the gimbal lock (where the angles are not unique).
fn angles() -> impl Strategy<Value = (f64, f64, f64)> {
    (
        -PI + 1e-9..PI,
        -FRAC_PI_2 + 1e-4..FRAC_PI_2 - 1e-4,
        -PI + 1e-9..PI,
    )
}

fn any_euler() -> impl Strategy<Value = EulerYpr> {
    angles().prop_map(|(a, b, c)| EulerYpr::new(a, b, c))
}

fn any_krylov() -> impl Strategy<Value = KrylovAngles> {
    angles().prop_map(|(a, b, c)| KrylovAngles::new(a, b, c))
}

/// (u, v, z) with |w| < 1 in either chart: the region each chart is chosen for.
fn any_wz() -> impl Strategy<Value = WzAttitude> {
    (0.0..0.999f64, -PI..PI, -PI + 1e-9..PI, any::<bool>()).prop_map(|(r, arg, z, flipped)| {
        WzAttitude {
            u: r * arg.cos(),
            v: r * arg.sin(),
            z_rad: z,
            chart: if flipped {
                WzChart::Flipped
            } else {
                WzChart::North
            },
        }
    })
}

fn q_dist(a: &UnitQuaternion<f64>, b: &UnitQuaternion<f64>) -> f64 {
    a.angle_to(b)
}
fn m_dist(a: &Matrix3<f64>, b: &Matrix3<f64>) -> f64 {
    (a - b).amax()
}
/// The largest of three differences, NaN if any is (so a NaN fails the test's bound).
fn worst3(a: f64, b: f64, c: f64) -> f64 {
    max_keep_nan(max_keep_nan(a.abs(), b.abs()), c.abs())
}
fn e_dist(a: &EulerYpr, b: &EulerYpr) -> f64 {
    worst3(
        angle_diff(a.yaw_rad, b.yaw_rad),
        a.pitch_rad - b.pitch_rad,
        angle_diff(a.roll_rad, b.roll_rad),
    )
}
fn k_dist(a: &KrylovAngles, b: &KrylovAngles) -> f64 {
    let (x, y) = (a.to_array(), b.to_array());
    worst3(angle_diff(x[0], y[0]), x[1] - y[1], angle_diff(x[2], y[2]))
}
fn w_dist(a: &WzAttitude, b: &WzAttitude) -> f64 {
    if a.chart != b.chart {
        return f64::INFINITY;
    }
    worst3(a.u - b.u, a.v - b.v, angle_diff(a.z_rad, b.z_rad))
}

proptest! {
    #![proptest_config(cfg())]

    #[test]
    fn quaternion_dcm(q in any_q()) {
        prop_assert!(q_dist(&q, &quaternion_from_dcm(&dcm_from_quaternion(&q))) < TOL);
        let a = dcm_from_quaternion(&q);
        prop_assert!(m_dist(&a, &dcm_from_quaternion(&quaternion_from_dcm(&a))) < TOL);
    }

    #[test]
    fn quaternion_euler(q in any_q(), e in any_euler()) {
        prop_assert!(q_dist(&q, &EulerYpr::from_quaternion(&q).to_quaternion()) < TOL);
        prop_assert!(e_dist(&e, &EulerYpr::from_quaternion(&e.to_quaternion())) < TOL);
    }

    #[test]
    fn dcm_euler(q in any_q(), e in any_euler()) {
        let a = dcm_from_quaternion(&q);
        prop_assert!(m_dist(&a, &EulerYpr::from_dcm(&a).to_dcm()) < TOL);
        prop_assert!(e_dist(&e, &EulerYpr::from_dcm(&e.to_dcm())) < TOL);
    }

    #[test]
    fn quaternion_krylov(q in any_q(), k in any_krylov()) {
        prop_assert!(q_dist(&q, &KrylovAngles::from_quaternion(&q).to_quaternion()) < TOL);
        prop_assert!(k_dist(&k, &KrylovAngles::from_quaternion(&k.to_quaternion())) < TOL);
    }

    #[test]
    fn dcm_krylov(q in any_q(), k in any_krylov()) {
        let a = dcm_from_quaternion(&q);
        prop_assert!(m_dist(&a, &KrylovAngles::from_dcm(&a).to_dcm()) < TOL);
        prop_assert!(k_dist(&k, &KrylovAngles::from_dcm(&k.to_dcm())) < TOL);
    }

    #[test]
    fn euler_krylov(e in any_euler(), k in any_krylov()) {
        let k_of_e = KrylovAngles::from_dcm(&e.to_dcm());
        prop_assert!(e_dist(&e, &EulerYpr::from_dcm(&k_of_e.to_dcm())) < TOL);
        let e_of_k = EulerYpr::from_dcm(&k.to_dcm());
        prop_assert!(k_dist(&k, &KrylovAngles::from_dcm(&e_of_k.to_dcm())) < TOL);
    }

    #[test]
    fn quaternion_wz(q in any_q(), w in any_wz()) {
        prop_assert!(q_dist(&q, &WzAttitude::from_quaternion(&q).to_quaternion()) < TOL);
        prop_assert!(w_dist(&w, &WzAttitude::from_quaternion(&w.to_quaternion())) < TOL);
    }

    #[test]
    fn dcm_wz(q in any_q(), w in any_wz()) {
        let a = dcm_from_quaternion(&q);
        let wz = WzAttitude::from_dcm(&a);
        prop_assert!(wz.modulus() <= 1.0 + 1e-12, "the better chart has |w| ≤ 1");
        prop_assert!(m_dist(&a, &wz.to_dcm()) < TOL);
        prop_assert!(w_dist(&w, &WzAttitude::from_dcm(&w.to_dcm())) < TOL);
    }

    #[test]
    fn euler_wz(e in any_euler(), w in any_wz()) {
        prop_assert!(e_dist(&e, &WzAttitude::from_euler(&e).to_euler()) < TOL);
        prop_assert!(w_dist(&w, &WzAttitude::from_euler(&w.to_euler())) < TOL);
    }

    #[test]
    fn krylov_wz(k in any_krylov(), w in any_wz()) {
        let wz = WzAttitude::from_dcm(&k.to_dcm());
        prop_assert!(k_dist(&k, &KrylovAngles::from_dcm(&wz.to_dcm())) < TOL);
        let kw = KrylovAngles::from_dcm(&w.to_dcm());
        prop_assert!(w_dist(&w, &WzAttitude::from_dcm(&kw.to_dcm())) < TOL);
    }

    #[test]
    fn chart_change_keeps_the_attitude(q in any_q()) {
        let a = dcm_from_quaternion(&q);
        for chart in [WzChart::North, WzChart::Flipped] {
            if let Some(wz) = WzAttitude::from_dcm_in_chart(&a, chart) {
                // Far from a chart's own pole its parameters are well conditioned.
                if wz.modulus() < 100.0 {
                    prop_assert!(m_dist(&a, &wz.to_dcm()) < 1e-8 * (1.0 + wz.modulus().powi(2)));
                }
            }
        }
    }
}

#[test]
fn gimbal_lock_and_poles_convert_without_nan() {
    let specials = [
        EulerYpr::new(0.3, FRAC_PI_2, 0.2),
        EulerYpr::new(-1.0, -FRAC_PI_2, 0.7),
        EulerYpr::new(0.0, 0.0, PI),
        EulerYpr::new(0.5, 0.0, PI),
        EulerYpr::new(0.0, 0.0, 0.0),
    ];
    for e in specials {
        let a = e.to_dcm();
        assert!(
            m_dist(&a, &EulerYpr::from_dcm(&a).to_dcm()) < 1e-12,
            "{e:?}"
        );
        assert!(
            m_dist(&a, &KrylovAngles::from_dcm(&a).to_dcm()) < 1e-12,
            "{e:?}"
        );
        let wz = WzAttitude::from_dcm(&a);
        assert!(m_dist(&a, &wz.to_dcm()) < 1e-12, "{e:?} → {wz:?}");
    }
}
