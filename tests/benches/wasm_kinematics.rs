//! The labs' cost items measured in WebAssembly, in headless Chromium — paper 3's one RK4
//! step of (u, v), of (u, v, z) and of the quaternion, paper 2's full MEKF step — and one
//! simulation step of every lab as the page runs it (paper 2's orbit of 5 800 s is 58 000 of
//! its steps) (`cargo xtask bench`, or
//! `CHROMEDRIVER=/usr/bin/chromedriver cargo bench --target wasm32-unknown-unknown -p attlab-tests --bench wasm_kinematics`).
//! Natively the same items are timed by `attlab reproduce p3` and `cargo bench -p attlab`.

#[cfg(target_arch = "wasm32")]
mod wasm {
    use attlab::labs;
    use attlab::model::ParamValues;
    use attlab::sim::Simulation;
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
}
