//! Tests of [`super::Mekf`]: the Jacobian against finite differences, the degenerate
//! geometry flagged.

use super::*;

fn onboard() -> Onboard {
    Onboard {
        frame_rate_orbit_rad_s: Vector3::new(0.0, 1.08e-3, 0.0),
        gravity_gradient_coeff: 3.0 * 1.17e-6,
        mag_ref_orbit_nt: Vector3::new(2e4, -5e3, 3e4),
        sun_ref_orbit: Vector3::new(0.3, 0.4, 0.866).normalize(),
        wheel_momentum_body: Vector3::new(1e-3, -2e-3, 5e-4),
        wheel_torque_body: Vector3::new(1e-6, 0.0, -2e-6),
    }
}

fn filter() -> Mekf<6> {
    let cfg = MekfConfig {
        id: "t",
        label: "t",
        sensors: SensorSet {
            star: true,
            gyro: true,
            mag: false,
            sun: false,
        },
        states: StateSet::AttRate,
        disturbance: false,
        constant_gain: false,
        // A TabletSat-like, slightly asymmetric inertia with products (kg·m²).
        inertia_kg_m2: Matrix3::new(0.52, 0.002, 0.005, 0.002, 0.58, 0.009, 0.005, 0.009, 0.71),
    };
    let tuning = MekfTuning {
        q_att: 1e-6,
        q_rate: 1e-6,
        q_bias: 0.0,
        star_sigma: 1e-5,
        gyro_sigma_rad_s: 1e-4,
        mag_sigma_nt: 250.0,
        sun_sigma_rad: 1e-3,
        alpha: 1.0,
        rd_scale: 1.0,
        freeze_after_s: 150.0,
    };
    let q = UnitQuaternion::from_euler_angles(0.3, -0.2, 0.5);
    Mekf::new(
        cfg,
        tuning,
        q,
        Vector3::new(0.01, -0.02, 0.015),
        SMatrix::identity() * 1e-6,
    )
}

/// The error state after propagating a perturbed and the nominal estimate for `dt`.
fn error_after(f: &Mekf<6>, dx: &SVector<f64, 6>, dt: f64, ob: &Onboard) -> SVector<f64, 6> {
    let mut a = f.clone();
    let mut b = f.clone();
    b.apply_correction(dx);
    a.predict(ob, dt);
    b.predict(ob, dt);
    let mut dq = (a.q.inverse() * b.q).into_inner();
    if dq.w < 0.0 {
        dq = -dq;
    }
    let dw = b.omega - a.omega;
    SVector::<f64, 6>::from_iterator(dq.imag().iter().chain(dw.iter()).copied())
}

#[test]
fn the_jacobian_matches_finite_differences_of_the_propagation() {
    let f = filter();
    let ob = onboard();
    let dt = 0.1;
    let jac = f.jacobian(&f.omega, &ob);
    for k in 0..6 {
        let mut dx = SVector::<f64, 6>::zeros();
        let h = if k < 3 { 1e-6 } else { 1e-7 };
        dx[k] = h;
        let numeric =
            (error_after(&f, &dx, dt, &ob) - error_after(&f, &(-dx), dt, &ob)) / (2.0 * h);
        // The exact Φ = exp(F dt) to second order; the filter's I + F dt drops the
        // (F dt)²/2 term (≈ 3e-5 here), which this test keeps so it checks F itself.
        let fdt = jac * dt;
        let analytic = (SMatrix::<f64, 6, 6>::identity() + fdt + fdt * fdt / 2.0)
            .column(k)
            .into_owned();
        let diff = (numeric - analytic).amax();
        assert!(
            diff < 2e-6,
            "column {k}: numeric {numeric} vs exp(F dt) {analytic}"
        );
    }
}

#[test]
fn a_degenerate_geometry_is_said_not_hidden() {
    let mut f = filter();
    f.cfg.sensors = SensorSet {
        star: false,
        gyro: false,
        mag: true,
        sun: true,
    };
    let mut ob = onboard();
    ob.sun_ref_orbit = ob.mag_ref_orbit_nt.normalize();
    let m = Measurements {
        mag_body_nt: Some(f.q.inverse_transform_vector(&ob.mag_ref_orbit_nt)),
        sun_body: Some(f.q.inverse_transform_vector(&ob.sun_ref_orbit)),
        lab: crate::model::LabData::new(ob),
        ..Measurements::default()
    };
    f.step(&m, 0.1);
    assert!(
        matches!(f.status(), EstimatorStatus::Unobservable(_)),
        "{:?}",
        f.status()
    );
    assert!(f.estimate().is_finite());
}

#[test]
fn the_flop_count_uses_the_full_filters_real_structure() {
    let cfg = MekfConfig {
        id: "full",
        label: "full",
        sensors: SensorSet::ALL,
        states: StateSet::AttRateGyroBias,
        ..filter().cfg
    };
    let f = Mekf::<9>::new(
        cfg,
        filter().tuning,
        UnitQuaternion::from_euler_angles(0.3, -0.2, 0.5),
        Vector3::new(0.01, -0.02, 0.015),
        SMatrix::identity() * 1e-6,
    );
    let ob = onboard();
    let nonzero = |v: &mut dyn Iterator<Item = &f64>| v.filter(|x| **x != 0.0).count() as u64;
    let jac = f.jacobian(&f.rate(), &ob);
    assert_eq!(nonzero(&mut jac.iter()), FULL_F_NONZEROS);
    let m = Measurements {
        star_q_ref_from_body: Some(f.q),
        gyro_body_rad_s: Some(Vector3::new(0.01, -0.02, 0.015)),
        mag_body_nt: Some(f.q.inverse_transform_vector(&ob.mag_ref_orbit_nt)),
        sun_body: Some(f.q.inverse_transform_vector(&ob.sun_ref_orbit)),
        ..Measurements::default()
    };
    let (rows, present) = f.rows(&m, &ob);
    assert!(present.iter().all(|p| *p), "all twelve rows");
    let h: u64 = rows.iter().map(|(_, h, _)| nonzero(&mut h.iter())).sum();
    assert_eq!(h, FULL_H_NONZEROS);
}

/// A Mag+Gyro (+ Sun, if `sun`) filter whose magnetometer bias is a turn of the field, with
/// P₀ = `p0`·E and no process noise on the bias.
fn turn_filter(sun: bool, p0: f64) -> Mekf<9> {
    let f6 = filter();
    let sensors = SensorSet {
        star: false,
        gyro: true,
        mag: true,
        sun,
    };
    let cfg = MekfConfig {
        sensors,
        states: StateSet::AttRateMagTurn,
        ..f6.cfg
    };
    let tuning = MekfTuning {
        q_bias: 0.0,
        ..f6.tuning
    };
    Mekf::<9>::new(cfg, tuning, f6.q, f6.omega, SMatrix::identity() * p0)
}

/// Fig. 7's bias model: the magnetometer's rows for a turn δ of the field are the exact
/// derivative of the prediction b₀ + δ × b₀ (a sign error here would make the filter push
/// its bias estimate away from the truth).
#[test]
fn the_field_turn_rows_are_the_derivative_of_the_prediction() {
    let mut f = turn_filter(false, 1e-6);
    f.mag_bias = Vector3::new(0.01, -0.02, 0.005);
    let ob = onboard();
    let m = Measurements {
        mag_body_nt: Some(Vector3::new(1e4, 2e4, -3e4)),
        lab: crate::model::LabData::new(ob),
        ..Measurements::default()
    };
    let residuals = |f: &Mekf<9>| {
        let (rows, _) = f.rows(&m, &ob);
        Vector3::new(rows[6].0, rows[7].0, rows[8].0)
    };
    let (rows, present) = f.rows(&m, &ob);
    assert!(present[6] && present[7] && present[8]);
    let eps = 1e-7;
    for k in 0..3 {
        let mut g = f.clone();
        g.mag_bias[k] += eps;
        // residual = z − h(x): its change is −∂h/∂δ_k · ε.
        let d = (residuals(&f) - residuals(&g)) / eps;
        for i in 0..3 {
            let h = rows[6 + i].1[6 + k];
            assert!(
                (d[i] - h).abs() < 1e-6 * h.abs().max(1.0),
                "row {i}, δ_{k}: {} vs {h}",
                d[i]
            );
        }
    }
}

/// Why Fig. 7's bias settles slowly: a turn of the field about the field itself changes no
/// reading, so under a fixed geometry the filter learns nothing along the field direction,
/// while a turn across it is learnt at once (the third only in part: it looks like a turn
/// of the attitude about the sun line). Only the field turning along the orbit helps.
#[test]
fn a_turn_of_the_field_about_itself_is_not_observed() {
    let p0 = 1e-3;
    let mut f = turn_filter(true, p0);
    let ob = onboard();
    for _ in 0..200 {
        let m = Measurements {
            mag_body_nt: Some(f.q.inverse_transform_vector(&ob.mag_ref_orbit_nt)),
            sun_body: Some(f.q.inverse_transform_vector(&ob.sun_ref_orbit)),
            gyro_body_rad_s: Some(f.omega),
            lab: crate::model::LabData::new(ob),
            ..Measurements::default()
        };
        let (rows, present) = f.rows(&m, &ob);
        let mut err = KalmanState::new(SVector::<f64, 9>::zeros(), f.p);
        for ((_, h, var), here) in rows.iter().zip(present) {
            if here {
                err.update_scalar(0.0, h, *var).unwrap();
            }
        }
        f.p = err.p;
    }
    let b =
        f.q.inverse_transform_vector(&ob.mag_ref_orbit_nt)
            .normalize();
    let block = f.p.fixed_view::<3, 3>(6, 6).into_owned();
    let along_var = (b.transpose() * block * b)[0];
    assert!(
        along_var > 0.99 * p0,
        "along the field: {along_var:e} of {p0:e}"
    );
    let least = block.symmetric_eigen().eigenvalues.min();
    assert!(
        least < 0.01 * p0,
        "the best-learnt turn: {least:e} of {p0:e}"
    );
}

/// Every state set's F at a generic point is non-zero only where its pattern says, so the
/// propagation that reads the pattern alone drops no term; and the propagation equals the
/// dense Φ P Φᵀ to rounding.
fn check_pattern<const N: usize>(states: StateSet) {
    let cfg = MekfConfig {
        id: "pattern",
        label: "pattern",
        sensors: SensorSet::ALL,
        states,
        ..filter().cfg
    };
    // A generic P: correlations everywhere, positive definite.
    let a = SMatrix::<f64, N, N>::from_fn(|i, j| ((i * 7 + j * 3) % 11) as f64 * 1e-4 - 4e-4);
    let p = a * a.transpose() + SMatrix::identity() * 1e-6;
    let mut f = Mekf::<N>::new(
        cfg,
        filter().tuning,
        UnitQuaternion::from_euler_angles(0.3, -0.2, 0.5),
        Vector3::new(0.01, -0.02, 0.015),
        p,
    );
    f.last_gyro = Some(Vector3::new(0.011, -0.019, 0.016));
    let ob = onboard();
    let jac = f.jacobian(&f.rate(), &ob);
    let pattern = f.f_nonzeros();
    for (index, value) in jac.iter().enumerate() {
        let (i, k) = (index % N, index / N);
        assert!(
            *value == 0.0 || pattern.contains(&(i, k)),
            "{states:?}: F[{i},{k}] = {value} is outside the pattern"
        );
    }
    assert!(
        pattern.windows(2).all(|w| w[0] < w[1]),
        "row by row, ascending"
    );
    let dt = 0.1;
    let phi = SMatrix::<f64, N, N>::identity() + jac * dt;
    let dense = phi * p * phi.transpose();
    let fast = propagate_first_order(&p, &jac, pattern, dt);
    assert!(
        (fast - dense).amax() <= 1e-15 * p.amax(),
        "{states:?}: {fast} against {dense}"
    );
}

#[test]
fn the_jacobian_is_non_zero_only_in_its_pattern() {
    check_pattern::<6>(StateSet::AttRate);
    check_pattern::<6>(StateSet::AttGyroBias);
    check_pattern::<9>(StateSet::AttRateGyroBias);
    check_pattern::<9>(StateSet::AttRateMagBias);
    check_pattern::<9>(StateSet::AttRateMagTurn);
}

#[test]
fn the_skew_products_equal_the_dense_ones_to_the_last_bit() {
    use super::predict::{mul_skew, skew_mul};
    let mut x = 0.618_033_988_749_895_f64;
    let mut next = || {
        x = (x * 997.0 + 0.123).fract();
        x * 2.0 - 1.0
    };
    for _ in 0..1000 {
        let v = Vector3::new(next(), next() * 1e-3, next() * 1e3);
        let m = Matrix3::from_fn(|_, _| next() * 0.7);
        let (a, b) = (skew_mul(&v, &m), mul_skew(&m, &v));
        let (da, db) = (skew(&v) * m, m * skew(&v));
        // Bit for bit; only the sign of an exact zero may differ.
        let same = |x: f64, y: f64| x.to_bits() == y.to_bits() || (x == 0.0 && y == 0.0);
        for k in 0..9 {
            assert!(same(a[k], da[k]), "[v×]m: {a} against {da}");
            assert!(same(b[k], db[k]), "m[v×]: {b} against {db}");
        }
    }
}
