//! Tests of [`super::SensitivityCorrection`]: U against finite differences, the step search,
//! and the re-integration history held to its reserved size.

use super::*;

#[test]
fn the_sensitivity_matches_finite_differences_of_the_integrated_quaternion() {
    let d = sensitivity_finite_difference_check();
    assert!(d <= 1e-6, "U vs finite differences {d:e}");
}

#[test]
fn golden_section_finds_a_parabola_minimum() {
    let s = golden_section(|s| (s - 0.73).powi(2), 0.0, 2.0);
    assert!((s - 0.73).abs() < 1e-6, "{s}");
}

/// A long gap without references restarts the interval once the reserved history is full,
/// so the history never grows past what was reserved when the run started.
#[test]
fn a_gap_longer_than_the_reserved_history_does_not_grow_it() {
    let settings = SensitivitySettings {
        eps: 1e-3,
        weights: [1.0; 4],
        renormalise: true,
        axes: [0, 1, 2],
        tolerance_rad: 1e-3,
        integrator: &crate::math::RK4,
        history_steps: 16,
    };
    let mut f = SensitivityCorrection::new(
        "t",
        "t",
        Method::Plain,
        UnitQuaternion::identity(),
        Vector3::zeros(),
        settings,
    );
    let capacity = f.history.capacity();
    let m = Measurements {
        gyro_body_rad_s: Some(Vector3::new(0.01, 0.02, -0.01)),
        ..Measurements::default()
    };
    for _ in 0..100 {
        f.step(&m, 0.01);
        assert!(f.history.len() <= 16, "{}", f.history.len());
    }
    assert_eq!(f.history.capacity(), capacity);
    assert!(f.estimate().is_finite());
}
