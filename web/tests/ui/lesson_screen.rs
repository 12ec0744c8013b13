//! What a lesson step says is on the screen: on a laptop's 1366×768 (not only in presenter
//! mode), every tile a step names is drawn inside the window with what it measures and its
//! number; a step opened from its link starts its sweep and puts its filter in the 3D ghost,
//! as walking to it does. (The numbers the steps' words quote are checked against their runs
//! by the core's `lessons` tests.)

use super::*;
use attlab::i18n::{self, Lang};
use attlab_web::state::AppState;

/// Every text of the last frame with where it was painted.
fn painted_at(h: &Harness<'_, AttLabApp>) -> Vec<(String, egui::Rect)> {
    (h.output().shapes.iter())
        .filter_map(|c| match &c.shape {
            egui::Shape::Text(t) => Some((t.galley.text().to_owned(), t.visual_bounding_rect())),
            _ => None,
        })
        .collect()
}

/// A laptop's screen (1366×768 points: a laptop's CSS pixels at zoom 1).
const LAPTOP: egui::Vec2 = egui::vec2(1366.0, 768.0);

#[test]
fn every_tile_a_step_names_is_on_the_laptop_screen_with_its_number() {
    let screen = egui::Rect::from_min_size(egui::Pos2::ZERO, LAPTOP);
    let mut problems = Vec::new();
    for lab in labs::all() {
        let lesson = lab.lesson().expect("every lab has a lesson");
        for (i, step) in lesson
            .steps
            .iter()
            .enumerate()
            .filter(|(_, s)| !s.tiles.is_empty())
        {
            let link = format!("lesson={}&step={}", lab.id(), i + 1);
            let mut app = AttLabApp::headless(AppState::from_fragment(&link));
            app.apply(RunCommand::SetPlaying(false).into());
            // A few samples in, so every tile has a number (an estimator's first sample
            // may come after t = 0).
            for _ in 0..10 {
                app.apply(RunCommand::StepOnce.into());
            }
            let mut h = Harness::builder()
                .with_size(LAPTOP)
                .with_context_setup(attlab_web::render::fonts::install)
                .build_ui_state(|ui, app: &mut AttLabApp| app.frame(ui), app);
            h.run_steps(4);
            let texts = painted_at(&h);
            let state = &h.state().state;
            for key in step.tiles {
                let name = key.name();
                let Some(spec) = state.sim().specs().iter().find(|s| s.name == name) else {
                    problems.push(format!("{link}: tile {name} is not recorded"));
                    continue;
                };
                let what = i18n::series_legend_without_unit(Lang::En, lab.id(), spec).what;
                let value = state.sim().value(&name).unwrap_or(f64::NAN);
                let number = attlab_web::panels::cycle_num(Lang::En, value);
                for shown in [&what, &number] {
                    let on_screen = texts
                        .iter()
                        .any(|(t, r)| t.contains(shown.as_str()) && screen.contains_rect(*r));
                    if !on_screen {
                        problems.push(format!("{link}: tile {name}: “{shown}” is not on screen"));
                    }
                }
            }
        }
    }
    assert!(problems.is_empty(), "{problems:#?}");
}

#[test]
fn a_step_opened_from_its_link_starts_its_sweep_and_ghosts_its_filter() {
    for lab in labs::all() {
        let lesson = lab.lesson().expect("every lab has a lesson");
        for (i, step) in lesson.steps.iter().enumerate() {
            let link = format!("lesson={}&step={}", lab.id(), i + 1);
            let state = AppState::from_fragment(&link);
            let sweep = state.run().sweep.as_ref().map(|(k, _)| *k);
            assert_eq!(sweep, step.sweep, "{link}: the step's sweep");
            let ghost = state.sim().estimators()[state.view().ghost_index].id();
            let with_attitude: Vec<&str> = (step.show.iter().copied())
                .filter(|id| {
                    let k = state.sim().estimators().iter().position(|e| e.id() == *id);
                    k.is_some_and(|k| state.sim().estimates()[k].quaternion().is_some())
                })
                .collect();
            if let Some(first) = with_attitude.first() {
                assert_eq!(ghost, *first, "{link}: the ghost");
            }
        }
    }
}
