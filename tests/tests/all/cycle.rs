//! The filter's cycle the page's step-through panel shows is the filter's own: after any
//! step, its x̂ and P after the step are the estimate and covariance the filter reports, and
//! its numbers satisfy the equations they are printed beside (x̂⁻ = Φx̂, P⁻ = ΦPΦᵀ + Q,
//! x̂⁺ = x̂⁻ + K(z − Hx̂⁻), P⁺ in Joseph form).
#![cfg(not(target_arch = "wasm32"))]

use attlab::labs;
use attlab::model::{KalmanCycle, ParamValues};
use attlab::sim::Simulation;

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-9 * (1.0 + a.abs().max(b.abs()))
}

/// Checks one cycle against its filter's outputs and against the equations.
fn check(cycle: &KalmanCycle, x: &[f64], p: &[f64], what: &str) {
    let n = cycle.n();
    for i in 0..n {
        assert!(
            close(cycle.x_after[i], x[i]),
            "{what}: x̂[{i}] {} vs the filter's {}",
            cycle.x_after[i],
            x[i]
        );
        for j in 0..n {
            // The covariance is column-major in `Covariance::matrix` (nalgebra's order).
            let own = p[j * n + i];
            assert!(
                close(cycle.p_after[i][j], own),
                "{what}: P[{i}][{j}] {} vs {own}",
                cycle.p_after[i][j]
            );
        }
    }
    let mul = |a: &dyn Fn(usize, usize) -> f64,
               b: &dyn Fn(usize, usize) -> f64,
               i: usize,
               j: usize,
               k: usize| { (0..k).map(|l| a(i, l) * b(l, j)).sum::<f64>() };
    // P⁻ = Φ P Φᵀ + Q.
    for i in 0..n {
        for j in 0..n {
            let phi_p = |r: usize, c: usize| {
                mul(
                    &|a, b| cycle.phi[a][b],
                    &|a, b| cycle.p_before[a][b],
                    r,
                    c,
                    n,
                )
            };
            let v = mul(&phi_p, &|a, b| cycle.phi[b][a], i, j, n) + cycle.q[i][j];
            assert!(
                close(v, cycle.p_prior[i][j]),
                "{what}: P⁻[{i}][{j}] {} vs ΦPΦᵀ + Q = {v}",
                cycle.p_prior[i][j]
            );
        }
    }
    let Some(u) = &cycle.update else {
        return;
    };
    for i in 0..n {
        let correction: f64 = (0..u.m).map(|r| u.k[i][r] * u.residual[r]).sum();
        let v = cycle.x_prior[i] + correction;
        assert!(
            close(v, u.x_post[i]),
            "{what}: x̂⁺[{i}] {} vs x̂⁻ + K r = {v}",
            u.x_post[i]
        );
    }
    for r in 0..u.m {
        let hx: f64 = (0..n).map(|j| u.h[r][j] * cycle.x_prior[j]).sum();
        assert!(close(u.z[r] - hx, u.residual[r]), "{what}: residual {r}");
    }
    if cycle.note.is_none() {
        for i in 0..n {
            for j in 0..n {
                assert!(
                    close(u.p_post[i][j], cycle.p_after[i][j]),
                    "{what}: P⁺ is the filter's P"
                );
            }
        }
    }
}

#[test]
fn every_cycle_a_filter_shows_is_its_own_state_and_obeys_its_equations() {
    let mut checked = 0;
    for (lab_id, settings) in [
        ("p1", &["kf_window=0"][..]),
        ("p1", &["kf_window=50"][..]),
        ("p4", &[][..]),
        ("p4", &["rig=2"][..]),
    ] {
        let lab = labs::find(lab_id).unwrap();
        let mut params = ParamValues::defaults(lab.params());
        let errors = params.apply_assignments(lab.params(), settings.iter().copied());
        assert!(errors.is_empty(), "{errors:?}");
        let mut sim = Simulation::new(lab, params, 3);
        let mut updates = 0;
        for step in 0..3000 {
            sim.step();
            for e in sim.estimators() {
                let Some(cycle) = e.teaching().map(|t| t.cycle()) else {
                    continue;
                };
                let est = e.estimate();
                let x = [
                    est.angle_rad.unwrap(),
                    est.rate_body_rad_s.unwrap().z,
                    cycle.x_after[2],
                ];
                let cov = e.covariance().unwrap();
                check(
                    cycle,
                    &x,
                    cov.matrix,
                    &format!("{lab_id} {settings:?} {} step {step}", e.id()),
                );
                updates += usize::from(cycle.update.is_some());
                checked += 1;
            }
        }
        assert!(updates > 0, "{lab_id}: no update was seen");
    }
    assert!(checked > 10_000, "{checked}");
}
