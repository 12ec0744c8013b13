//! The cost claim of paper 3 measured in WebAssembly, in headless Chromium: one RK4 step of
//! (u, v), of (u, v, z) and of the quaternion (`cargo xtask bench`, or
//! `CHROMEDRIVER=/usr/bin/chromedriver cargo bench --target wasm32-unknown-unknown -p attlab-tests --bench wasm_kinematics`).
//! Natively the same items are timed by `attlab reproduce p3` and `cargo bench -p attlab`.

#[cfg(target_arch = "wasm32")]
mod wasm {
    use attlab::labs;
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
}
