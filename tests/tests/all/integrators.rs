//! The two attitude integrators on motions with known truth: paper 3's harmonic motion and
//! a tumble that turns the body upside down (w → ∞, exercising the chart switch).
#![cfg(not(target_arch = "wasm32"))]

use attlab::dynamics::{AngleProfile, EulerMotion};
use attlab::math::{WzAttitude, WzChart, step_quaternion_rk4, step_uvz_rk4};
use attlab_tests::{max_keep_nan, min_keep_nan};

struct Outcome {
    quat_vs_uvz_rad: f64,
    quat_vs_truth_rad: f64,
    uvz_vs_truth_rad: f64,
    switches: u32,
    min_kz: f64,
}

fn integrate(motion: &EulerMotion, duration_s: f64, dt_s: f64) -> Outcome {
    let mut q = motion.attitude(0.0);
    let mut wz = WzAttitude::from_quaternion(&q);
    let (mut worst_pair, mut worst_q, mut worst_w, mut switches, mut min_kz) =
        (0.0_f64, 0.0_f64, 0.0_f64, 0, 1.0_f64);
    let steps = (duration_s / dt_s).round() as usize;
    for k in 0..steps {
        let t0 = k as f64 * dt_s;
        let rate_at = |f: f64| motion.body_rate_rad_s(t0 + f * dt_s);
        q = step_quaternion_rk4(&q, rate_at, dt_s);
        let next = step_uvz_rk4(&wz, rate_at, dt_s);
        switches += u32::from(next.chart != wz.chart);
        wz = next;
        let truth = motion.attitude(t0 + dt_s);
        let q_w = wz.to_quaternion();
        worst_pair = max_keep_nan(worst_pair, q.angle_to(&q_w));
        worst_q = max_keep_nan(worst_q, q.angle_to(&truth));
        worst_w = max_keep_nan(worst_w, q_w.angle_to(&truth));
        min_kz = min_keep_nan(min_kz, wz.vertical_in_body().z);
    }
    Outcome {
        quat_vs_uvz_rad: worst_pair,
        quat_vs_truth_rad: worst_q,
        uvz_vs_truth_rad: worst_w,
        switches,
        min_kz,
    }
}

#[test]
fn paper3_motion_both_integrators_agree_with_each_other_and_the_truth() {
    let o = integrate(&EulerMotion::paper3(), 100.0, 0.01);
    assert!(
        o.quat_vs_uvz_rad <= 1e-9,
        "quaternion vs (u,v,z): {:e} rad",
        o.quat_vs_uvz_rad
    );
    assert!(
        o.quat_vs_truth_rad <= 1e-9,
        "quaternion vs truth: {:e} rad",
        o.quat_vs_truth_rad
    );
    assert!(
        o.uvz_vs_truth_rad <= 1e-9,
        "(u,v,z) vs truth: {:e} rad",
        o.uvz_vs_truth_rad
    );
    assert_eq!(o.switches, 0, "paper 3's motion stays within |w| < 2");
}

#[test]
fn upside_down_tumble_switches_chart_and_stays_accurate() {
    // Roll turns through full circles (0.5 rad/s) while yaw and pitch wobble: the vertical
    // passes through the body's −ζ′ axis, where w = ∞.
    let motion = EulerMotion {
        yaw: AngleProfile {
            rate_rad_s: 0.1,
            amplitude_rad: 0.2,
            frequency_rad_s: 0.3,
            phase_rad: 0.0,
        },
        pitch: AngleProfile {
            amplitude_rad: 0.3,
            frequency_rad_s: 0.2,
            phase_rad: 0.5,
            ..AngleProfile::default()
        },
        roll: AngleProfile {
            rate_rad_s: 0.5,
            ..AngleProfile::default()
        },
    };
    let o = integrate(&motion, 60.0, 0.01);
    assert!(
        o.min_kz < -0.9,
        "the body did turn upside down (k_z = {})",
        o.min_kz
    );
    assert!(o.switches >= 4, "chart switched {} times", o.switches);
    assert!(
        o.quat_vs_uvz_rad <= 1e-9,
        "quaternion vs (u,v,z): {:e} rad",
        o.quat_vs_uvz_rad
    );
    assert!(
        o.uvz_vs_truth_rad <= 1e-9,
        "(u,v,z) vs truth: {:e} rad",
        o.uvz_vs_truth_rad
    );
}

#[test]
fn without_the_chart_switch_the_north_chart_blows_up() {
    // The same tumble integrated in the north chart only: near w = ∞ RK4 loses accuracy —
    // the reason the switch exists.
    let motion = EulerMotion {
        roll: AngleProfile {
            rate_rad_s: 0.5,
            ..AngleProfile::default()
        },
        ..EulerMotion::default()
    };
    let dt = 0.01;
    let mut wz = WzAttitude::from_quaternion(&motion.attitude(0.0));
    let mut worst = 0.0_f64;
    for k in 0..1200 {
        let t0 = k as f64 * dt;
        let x = nalgebra::Vector3::new(wz.u, wz.v, wz.z_rad);
        let x = attlab::math::rk4_step(0.0, &x, dt, |t, x| {
            attlab::math::uvz_derivative(x, &motion.body_rate_rad_s(t0 + t))
        });
        wz = WzAttitude {
            u: x[0],
            v: x[1],
            z_rad: x[2],
            chart: WzChart::North,
        };
        if x.iter().all(|c| c.is_finite()) {
            worst = max_keep_nan(
                worst,
                wz.to_quaternion().angle_to(&motion.attitude(t0 + dt)),
            );
        } else {
            worst = f64::INFINITY;
            break;
        }
    }
    assert!(worst > 1e-3, "north-chart-only error {worst:e} rad");
}
