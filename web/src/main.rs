//! Attitude Lab as a desktop window. An optional first argument is a URL-style state,
//! e.g. `lab=free-rotation&seed=3&gyro_bias_deg_s=0.5`.

// A panic in the product is a bug to report, not an answer: fallible paths return typed
// errors. Tests may unwrap (clippy.toml allows it in tests).
#![deny(clippy::unwrap_used, clippy::expect_used)]

#[cfg(not(target_arch = "wasm32"))]
fn main() -> eframe::Result {
    let options = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_inner_size([1400.0, 900.0])
            .with_title("Attitude Lab"),
        ..Default::default()
    };
    eframe::run_native(
        "Attitude Lab",
        options,
        Box::new(|cc| Ok(Box::new(attlab_web::AttLabApp::new(cc)))),
    )
}

#[cfg(target_arch = "wasm32")]
fn main() {}
