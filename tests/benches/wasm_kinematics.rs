//! The labs' cost items measured in WebAssembly, in headless Chromium — paper 3's one RK4
//! step of (u, v), of (u, v, z) and of the quaternion, paper 2's full MEKF step — one
//! simulation step of every lab as the page runs it (paper 2's orbit of 5 800 s is 58 000 of
//! its steps), and every lab's estimators alone on recorded measurements: the floor under
//! that step, which nothing outside the filters can lower (`cargo xtask bench`, or
//! `CHROMEDRIVER=/usr/bin/chromedriver cargo bench --target wasm32-unknown-unknown -p attlab-tests --bench wasm_kinematics`).
//! Natively the same items are timed by `attlab reproduce p3` and `cargo bench -p attlab`.

#[cfg(target_arch = "wasm32")]
mod wasm {
    use attlab::labs;
    use attlab::model::ParamValues;
    use attlab::model::{Estimator, Measurements};
    use attlab::sim::Simulation;
    use rand::SeedableRng;
    use rand_chacha::ChaCha8Rng;
    use wasm_bindgen_test::{Criterion, wasm_bindgen_bench, wasm_bindgen_test_configure};

    wasm_bindgen_test_configure!(run_in_browser);

    #[wasm_bindgen_bench]
    fn kinematics(c: &mut Criterion) {
        for lab in labs::all() {
            for mut item in lab.timing_items() {
                c.bench_function(&format!("{}/{}", lab.id(), item.name), |b| {
                    b.iter(|| (item.run)())
                });
            }
        }
    }

    #[wasm_bindgen_bench]
    fn simulation_steps(c: &mut Criterion) {
        for lab in labs::all() {
            let mut sim = Simulation::new(*lab, ParamValues::defaults(lab.params()), 1);
            c.bench_function(&format!("{}/simulation-step", lab.id()), |b| {
                b.iter(|| sim.step())
            });
        }
    }

    /// Steps of recorded measurements the estimators run through before they start again
    /// from their first step (a tenth of paper 2's orbit).
    const TRACE_STEPS: usize = 5_800;

    /// A lab's estimators as built with seed 1, and the measurements of its first
    /// [`TRACE_STEPS`] steps (truth and sensors only, as `attlab bench` times them: where a
    /// lab's truth is steered by an estimate, paper 4's controller, the trace is of the
    /// motion without that feedback, so its filters see another motion than the page's; they
    /// do the same arithmetic on it).
    fn estimators_and_trace(
        lab: &'static dyn attlab::page::Lab,
        params: &ParamValues,
    ) -> (Vec<Box<dyn Estimator>>, Vec<Measurements>) {
        let mut rng = ChaCha8Rng::seed_from_u64(1);
        let mut run = lab.build(params, &mut rng);
        let trace = run.measurement_trace(lab.dt_s(params), TRACE_STEPS, &mut rng);
        (run.estimators, trace)
    }

    /// The same estimators again, as they were before their first step.
    fn estimators_afresh(
        lab: &'static dyn attlab::page::Lab,
        params: &ParamValues,
    ) -> Vec<Box<dyn Estimator>> {
        lab.build(params, &mut ChaCha8Rng::seed_from_u64(1))
            .estimators
    }

    /// One step of every estimator of a lab on the next recorded measurements, with no
    /// truth, sensors or recorder: what a simulation step costs at least. The estimators are
    /// built again when the trace ends (once in 5 800 steps), so they never run on a
    /// measurement from the past; building paper 2's takes ~17 µs natively, under 0.01 µs a
    /// step spread over the trace.
    #[wasm_bindgen_bench]
    fn estimators_alone(c: &mut Criterion) {
        for lab in labs::all() {
            let params = ParamValues::defaults(lab.params());
            let dt_s = lab.dt_s(&params);
            let (mut estimators, trace) = estimators_and_trace(*lab, &params);
            let mut next = 0;
            c.bench_function(&format!("{}/estimators-alone", lab.id()), |b| {
                b.iter(|| {
                    if next == trace.len() {
                        estimators = estimators_afresh(*lab, &params);
                        next = 0;
                    }
                    for e in &mut estimators {
                        e.step(&trace[next], dt_s);
                        std::hint::black_box(e.status());
                    }
                    next += 1;
                })
            });
        }
    }
}
