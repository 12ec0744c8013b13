//! Criterion benchmarks: one simulation step of every lab (recording what the page shows),
//! one step of every estimator, and the ratio the loop is held to: a step should cost at
//! most twice its estimators plus 0.5 µs (`attlab bench` prints the ratio).
#![allow(missing_docs)] // criterion's macros generate undocumented public functions

use attlab::labs;
use attlab::model::ParamValues;
use attlab::sim::Simulation;
use criterion::{Criterion, criterion_group, criterion_main};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use std::hint::black_box;

fn steps(c: &mut Criterion) {
    for lab in labs::all() {
        let params = ParamValues::defaults(lab.params());
        let mut sim = Simulation::new(*lab, params.clone(), 1);
        c.bench_function(&format!("{}/simulation-step", lab.id()), |b| {
            b.iter(|| sim.step())
        });
        let mut rng = ChaCha8Rng::seed_from_u64(1);
        let mut run = lab.build(&params, &mut rng);
        let dt = lab.dt_s(&params);
        let trace = run.measurement_trace(dt, 4096, &mut rng);
        for est in &mut run.estimators {
            let mut i = 0;
            c.bench_function(&format!("{}/estimator/{}", lab.id(), est.id()), |b| {
                b.iter(|| {
                    est.step(black_box(&trace[i % trace.len()]), dt);
                    i += 1;
                })
            });
        }
    }
}

/// The labs' own cost comparisons (e.g. paper 3's (u, v) vs (u, v, z) vs quaternion).
fn timing_items(c: &mut Criterion) {
    for lab in labs::all() {
        for mut item in lab.timing_items() {
            c.bench_function(&format!("{}/{}", lab.id(), item.name), |b| {
                b.iter(|| (item.run)())
            });
        }
    }
}

criterion_group! {
    name = benches;
    config = Criterion::default();
    targets = steps, timing_items
}
criterion_main!(benches);
