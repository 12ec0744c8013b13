//! Criterion benchmark of one UI pass of every lab at 1280×800, its plots and trails full of
//! 3 000 steps, paused: the app's own work per frame before any drawing (layout, plots,
//! trails, AccessKit), which the page pays on every frame and on every input event.
#![cfg(not(target_arch = "wasm32"))]
#![allow(missing_docs)] // criterion's macros generate undocumented public functions

use attlab::labs;
use attlab::model::ParamValues;
use attlab_web::AttLabApp;
use attlab_web::state::RunCommand;
use criterion::{Criterion, criterion_group, criterion_main};
use egui_kittest::Harness;

/// Steps run before the passes are timed.
const STEPS: usize = 3000;

fn ui_pass(c: &mut Criterion) {
    for lab in labs::all() {
        let mut app = AttLabApp::with_state(*lab, ParamValues::defaults(lab.params()), 1, 1.0);
        app.apply(RunCommand::SetPlaying(false).into());
        for _ in 0..STEPS {
            app.apply(RunCommand::StepOnce.into());
        }
        let mut h = Harness::builder()
            .with_size(egui::vec2(1280.0, 800.0))
            .with_context_setup(attlab_web::app::setup_context)
            .build_ui_state(|ui, app: &mut AttLabApp| app.frame(ui), app);
        h.run();
        c.bench_function(&format!("{}/ui-pass", lab.id()), |b| b.iter(|| h.step()));
    }
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(20);
    targets = ui_pass
}
criterion_main!(benches);
