//! Registry conformance: every lab in `labs::all()` obeys the lab contract.
#![cfg(not(target_arch = "wasm32"))]

use attlab::labs;
use attlab::params::{ParamKind, ParamValues};
use attlab::sim::Simulation;
use std::collections::HashSet;

#[test]
fn ids_are_unique_and_params_are_well_formed() {
    let mut ids = HashSet::new();
    for lab in labs::all() {
        assert!(ids.insert(lab.id()), "duplicate lab id {}", lab.id());
        assert!(!lab.summary().is_empty() && !lab.title().is_empty());
        let mut keys = HashSet::new();
        for p in lab.params() {
            assert!(keys.insert(p.key), "{}: duplicate key {}", lab.id(), p.key);
            assert!(
                p.min <= p.default && p.default <= p.max,
                "{}: {} default out of range",
                lab.id(),
                p.key
            );
            assert!(
                p.validate(p.default).is_ok(),
                "{}: {} default invalid",
                lab.id(),
                p.key
            );
            if let ParamKind::Choice(options) = p.kind {
                assert_eq!(p.max as usize + 1, options.len());
            }
        }
    }
}

fn run(lab: &'static dyn labs::Lab, params: ParamValues, seed: u64, steps: usize) -> Simulation {
    let mut sim = Simulation::with_history(lab, params, seed, steps + 1);
    for _ in 0..steps {
        sim.step();
    }
    sim
}

fn rows(sim: &Simulation) -> Vec<Vec<f64>> {
    let r = sim.recorder();
    (0..r.specs().len())
        .map(|i| r.column(i).unwrap().iter().copied().collect())
        .collect()
}

fn same_bits(a: &[Vec<f64>], b: &[Vec<f64>]) -> bool {
    a.len() == b.len()
        && a.iter().zip(b).all(|(x, y)| {
            x.len() == y.len() && x.iter().zip(y).all(|(p, q)| p.to_bits() == q.to_bits())
        })
}

#[test]
fn same_lab_params_and_seed_give_the_identical_run() {
    for lab in labs::all() {
        let p = ParamValues::defaults(lab.params());
        let a = run(*lab, p.clone(), 5, 300);
        let b = run(*lab, p.clone(), 5, 300);
        assert!(
            same_bits(&rows(&a), &rows(&b)),
            "{} is not deterministic",
            lab.id()
        );
        let mut c = Simulation::with_history(*lab, p, 99, 301);
        for _ in 0..123 {
            c.step();
        }
        c.reset(5);
        for _ in 0..300 {
            c.step();
        }
        assert!(
            same_bits(&rows(&a), &rows(&c)),
            "{}: reset does not reproduce a fresh run",
            lab.id()
        );
    }
}

/// Runs `lab` 50 steps, changes `key` to `value` live, runs 2000 more steps (some
/// parameters act only after a while, e.g. an adaptation window) and tells whether the last
/// row differs from an unchanged run.
fn live_change_shows(lab: &'static dyn labs::Lab, p: &ParamValues, key: &str, value: f64) -> bool {
    let mut a = run(lab, p.clone(), 3, 50);
    let mut b = run(lab, p.clone(), 3, 50);
    b.set_param(key, value).unwrap();
    assert_eq!(
        b.t_s(),
        a.t_s(),
        "{}: set_param restarted the run",
        lab.id()
    );
    for _ in 0..2000 {
        a.step();
        b.step();
    }
    a.last_row() != b.last_row()
}

#[test]
fn a_live_parameter_change_acts_on_the_next_step_without_restart() {
    for lab in labs::all() {
        for spec in lab.params().iter().filter(|s| !s.needs_reset) {
            let mut p = ParamValues::defaults(lab.params());
            if let Some(dep) = spec.requires {
                let dep_spec = lab
                    .params()
                    .iter()
                    .find(|s| s.key == dep)
                    .expect("required parameter exists");
                p.set(lab.params(), dep, dep_spec.max).unwrap();
            }
            // A live change must show at one end of the range at least (an impulse moved
            // from 300 s to 600 s does nothing in the first seconds, moved to 0 s it does).
            let shows = [spec.min, spec.max]
                .iter()
                .filter(|v| **v != spec.default)
                .any(|v| live_change_shows(*lab, &p, spec.key, *v));
            assert!(shows, "{}: changing {} had no effect", lab.id(), spec.key);
        }
    }
}

#[test]
fn every_parameter_at_its_extremes_runs_without_panic_or_silent_nan() {
    for lab in labs::all() {
        for spec in lab.params() {
            for value in [spec.min, spec.max] {
                let mut p = ParamValues::defaults(lab.params());
                p.set(lab.params(), spec.key, value).unwrap();
                let sim = run(*lab, p, 1, 400);
                for ((id, _, est), status) in sim.estimates().iter().zip(sim.statuses()) {
                    let finite = est
                        .q_ref_from_body
                        .is_none_or(|q| q.coords.iter().all(|c| c.is_finite()));
                    assert!(
                        finite || *status != attlab::estimators::EstimatorStatus::Ok,
                        "{}: {id} non-finite but not flagged ({}={value})",
                        lab.id(),
                        spec.key
                    );
                }
            }
        }
    }
}

#[test]
fn estimators_publish_as_many_elements_as_they_name() {
    for lab in labs::all() {
        let mut rng = <rand_chacha::ChaCha8Rng as rand::SeedableRng>::seed_from_u64(1);
        let run = lab.build(&ParamValues::defaults(lab.params()), &mut rng);
        for e in &run.estimators {
            let est = e.estimate();
            assert_eq!(
                est.covariance.len(),
                e.covariance_names().len(),
                "{}",
                e.id()
            );
            assert_eq!(
                est.innovation.len(),
                e.innovation_names().len(),
                "{}",
                e.id()
            );
        }
    }
}

#[test]
fn every_row_has_one_value_per_series() {
    for lab in labs::all() {
        let mut sim = Simulation::new(*lab, ParamValues::defaults(lab.params()), 1);
        assert_eq!(
            sim.last_row().len(),
            sim.recorder().specs().len(),
            "{} at t = 0",
            lab.id()
        );
        sim.step();
        assert_eq!(
            sim.last_row().len(),
            sim.recorder().specs().len(),
            "{} after a step",
            lab.id()
        );
    }
}

#[test]
fn recorder_memory_stays_flat() {
    let lab = labs::all()[0];
    let mut sim = Simulation::with_history(lab, ParamValues::defaults(lab.params()), 1, 500);
    for _ in 0..5000 {
        sim.step();
    }
    assert_eq!(sim.recorder().len(), 500);
    assert_eq!(sim.recorder().total_rows(), 5001);
}

#[test]
fn every_lab_reproduces_its_anchors() {
    for lab in labs::all() {
        let rep = lab.reproduce();
        assert!(!rep.rows.is_empty(), "{} has no anchors", lab.id());
        assert!(rep.all_pass(), "{}\n{}", lab.id(), rep.to_table());
    }
}
