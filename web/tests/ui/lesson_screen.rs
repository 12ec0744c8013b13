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
                .with_context_setup(attlab_web::app::setup_context)
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
            let sweep_id = sweep.map(|k| lab.sweeps()[k].id);
            assert_eq!(sweep_id, step.sweep, "{link}: the step's sweep");
            let ghost = state.sim().estimators()[state.view().ghost_index].id();
            let about = (step.tiles.iter().map(|t| t.source)).chain(step.show.iter().copied());
            let with_attitude: Vec<&str> = about
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

/// A state run, as the page's frames run it, until the step's pause (at most `frames` frames
/// of a quarter second each).
fn run_to_pause(state: &mut AppState, frames: u64) {
    let t0 = web_time::Instant::now();
    for k in 0..frames {
        if state.lesson_revealed() && !state.run().playing {
            return;
        }
        let at = t0 + web_time::Duration::from_millis(250 * k);
        state.apply(RunCommand::Advance(at).into());
    }
}

#[test]
fn on_a_projector_an_answered_step_keeps_its_why_and_next_in_view() {
    // A projector's 1280×720 in presenter mode: the panel is 230 points at 1.5 times.
    let screen = egui::vec2(1280.0, 720.0);
    let mut problems = Vec::new();
    for lab in labs::all() {
        let lesson = lab.lesson().expect("every lab has a lesson");
        for (i, step) in lesson.steps.iter().enumerate() {
            let Some(q) = step.question else { continue };
            let n = i + 1;
            let letter = char::from(b'a' + q.answer as u8);
            let link = format!(
                "lesson={}&step={n}&answers={n}{letter}&presenter=1",
                lab.id()
            );
            let mut state = AppState::from_fragment(&link);
            run_to_pause(&mut state, 4000);
            assert!(state.lesson_revealed(), "{link}: never reached its pause");
            let mut h = Harness::builder()
                .with_size(screen)
                .with_context_setup(attlab_web::app::setup_context)
                .build_ui_state(
                    |ui, app: &mut AttLabApp| app.frame(ui),
                    AttLabApp::headless(state),
                );
            h.run_steps(6);
            let window = h.ctx.content_rect();
            let next = h.get_by_label(if n < lesson.steps.len() {
                "Next ▶"
            } else {
                "◀ Back"
            });
            let rect = next.rect();
            if !window.contains_rect(rect) {
                problems.push(format!("{link}: Next at {rect:?}, the window {window:?}"));
            }
            // The why's first words are painted where its panel shows them.
            let start: String = q.why.chars().take(24).collect();
            let shown = (h.output().shapes.iter()).any(|c| match &c.shape {
                egui::Shape::Text(t) if t.galley.text().starts_with(&start) => {
                    let r = t.visual_bounding_rect();
                    c.clip_rect.contains_rect(r) && window.contains_rect(r)
                }
                _ => false,
            });
            if !shown {
                problems.push(format!("{link}: the why “{start}…” is out of view"));
            }
        }
    }
    assert!(problems.is_empty(), "{problems:#?}");
}
