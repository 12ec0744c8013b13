//! # Attitude Lab app
//!
//! The eframe front end (wgpu renderer) of Attitude Lab. The same code runs in the browser
//! (see `start`, built for wasm32 only) and as a desktop window (`cargo run -p attlab-web --release`).
//!
//! Dependencies point one way: `app` (the frame loop) → `panels` (read the state, emit
//! commands) → `export` (PNG capture over frames) → `state` (the state and the one place
//! that applies commands) → `render` (drawing) and `platform` (browser/desktop differences);
//! `a11y` (the accessibility mirror, an egui plugin) depends on egui alone.

// A panic in the product is a bug to report, not an answer: fallible paths return typed
// errors. Tests may unwrap (clippy.toml allows it in tests).
#![deny(clippy::unwrap_used, clippy::expect_used)]

pub mod a11y;
pub mod app;
pub mod export;
pub mod host;
pub mod live_io;
pub mod panels;
pub mod pick;
pub mod platform;
pub mod python;
pub mod render;
pub mod state;
pub mod sweep_workers;

pub use app::AttLabApp;

/// Runs one point of a sweep in a Web Worker (`sweep-worker.js`): a
/// [`attlab::analysis::sweep::PointJob`] as JSON in, `{"ok": PointDone}` or `{"err": why}`
/// as JSON out ([`sweep_workers::answer`]).
#[cfg(target_arch = "wasm32")]
#[wasm_bindgen::prelude::wasm_bindgen]
pub fn sweep_point(job: &str) -> String {
    sweep_workers::answer(job)
}

/// Starts the app on the canvas with id `canvas_id` with the page's three fonts (sans,
/// mono, symbols: `render::fonts::FILES`) and its Russian catalogue (`assets/locales/ru.ftl`),
/// all fetched by `index.html` beside the wasm. Without the catalogue (an empty string: the
/// fetch failed) the page still runs, in English.
#[cfg(target_arch = "wasm32")]
#[wasm_bindgen::prelude::wasm_bindgen]
pub async fn start(
    canvas_id: String,
    sans: Vec<u8>,
    mono: Vec<u8>,
    symbols: Vec<u8>,
    russian: String,
) -> Result<(), wasm_bindgen::JsValue> {
    use wasm_bindgen::JsCast as _;
    let _ = eframe::WebLogger::init(log::LevelFilter::Info);
    if [&sans, &mono, &symbols].iter().any(|f| f.is_empty()) {
        return Err("a font file of assets/fonts/ arrived empty".into());
    }
    render::fonts::provide(sans, mono, symbols);
    if russian.is_empty() {
        log::warn!("the Russian catalogue (assets/locales/ru.ftl) did not arrive: English only");
    } else {
        attlab::i18n::provide_russian(russian);
    }
    let document = web_sys::window()
        .and_then(|w| w.document())
        .ok_or("no document")?;
    let canvas = document
        .get_element_by_id(&canvas_id)
        .ok_or_else(|| format!("no element with id `{canvas_id}`"))?
        .dyn_into::<web_sys::HtmlCanvasElement>()
        .map_err(|_| format!("`{canvas_id}` is not a canvas"))?;
    eframe::WebRunner::new()
        .start(
            canvas,
            eframe::WebOptions::default(),
            Box::new(|cc| Ok(Box::new(AttLabApp::new(cc)))),
        )
        .await
}
