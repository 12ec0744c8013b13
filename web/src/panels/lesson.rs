//! The lesson card: the step's title and text beside the model, its question (predict, then
//! see), and the way on (back, next, end). It sits at the top of the controls, so the sliders
//! the step points at are just below it; "Start the lesson" opens it.

use super::{arg, lab_word, num_arg, tr, tr_with};
use crate::state::{AppState, Command, LessonCommand, ShareCommand, ViewCommand};
use attlab::i18n::lesson_id;
use attlab::page::{Lesson, Question};
use egui::{RichText, Ui};

/// The lesson's word `part` of step number `n` (or of the lesson, `n` = `None`), by the
/// step's id.
fn word(app: &AppState, n: Option<usize>, part: &str, english: &str) -> String {
    let lab = app.sim().lab();
    let step = n.and_then(|n| lab.lesson()?.step(n)).map(|s| s.id);
    lab_word(app, &lesson_id(lab.id(), step, part), english)
}

/// "Start the lesson" when the lab has one and none is open; the card when one is.
pub(super) fn card(ui: &mut Ui, app: &AppState, commands: &mut Vec<Command>) {
    let Some(lesson) = app.sim().lab().lesson() else {
        return;
    };
    let Some(state) = app.lesson() else {
        let title = word(app, None, "title", lesson.title);
        if ui
            .button(RichText::new(tr(app, "lesson-start")).strong())
            .on_hover_text(title)
            .clicked()
        {
            commands.push(LessonCommand::Start.into());
        }
        return;
    };
    let Some(step) = lesson.step(state.step) else {
        return;
    };
    egui::Frame::group(ui.style())
        .fill(ui.visuals().faint_bg_color)
        .show(ui, |ui| {
            heading(ui, app, lesson, state.step);
            let n = Some(state.step);
            ui.label(
                RichText::new(word(app, n, "title", step.title))
                    .strong()
                    .size(ui.style().text_styles[&egui::TextStyle::Heading].size * 0.85),
            );
            ui.label(word(app, n, "text", step.text));
            if let Some(q) = &step.question {
                question(ui, app, q, state.step, state.answer(state.step), commands);
            }
            if let Some(i) = step.sweep.and_then(|id| app.sim().lab().sweep_index(id)) {
                ui.add_space(4.0);
                super::sweeps::in_lesson(ui, app, i, commands);
            }
            // Embedded, the host page is the way out and the way on.
            if !app.view().embed {
                tools(ui, app, commands);
            }
        });
}

/// Back, Next and Again, where the lesson card's panel keeps them in view (pinned under
/// the card, however long its text and answer): nothing when no lesson is open.
pub(super) fn navigation_bar(ui: &mut Ui, app: &AppState, commands: &mut Vec<Command>) {
    let (Some(lesson), Some(state)) = (app.sim().lab().lesson(), app.lesson()) else {
        return;
    };
    navigation(ui, app, lesson, state.step, commands);
}

/// "Lesson: title · step k of n".
fn heading(ui: &mut Ui, app: &AppState, lesson: &Lesson, n: usize) {
    let title = word(app, None, "title", lesson.title);
    let of = tr_with(
        app,
        "lesson-step",
        &[("n", arg(n)), ("count", arg(lesson.steps.len()))],
    );
    ui.label(RichText::new(format!("{title} · {of}")).small().weak());
}

/// The question, its answers as buttons, and, once the run has shown it, the answer.
fn question(
    ui: &mut Ui,
    app: &AppState,
    q: &Question,
    n: usize,
    chosen: Option<usize>,
    commands: &mut Vec<Command>,
) {
    ui.add_space(4.0);
    ui.label(RichText::new(word(app, Some(n), "ask", q.ask)).strong());
    if chosen.is_none() {
        ui.label(RichText::new(tr(app, "lesson-predict")).small().weak());
    }
    for (k, english) in q.answers.iter().enumerate() {
        let text = word(app, Some(n), &format!("answer-{}", k + 1), english);
        let letter = char::from(b'a' + k as u8);
        let mut label = RichText::new(format!("{letter}) {text}"));
        if app.lesson_revealed() && k == q.answer {
            label = label.strong().color(ui.visuals().selection.stroke.color);
        }
        if ui.selectable_label(chosen == Some(k + 1), label).clicked() {
            commands.push(LessonCommand::Answer(k + 1).into());
        }
    }
    // Per zoom: the first frame after presenter mode is chosen is laid out at the old one.
    let zoom = ui.ctx().zoom_factor().to_bits();
    let seen = egui::Id::unique(("lesson why shown", app.sim().lab().id(), n, zoom));
    if chosen.is_none() || !app.lesson_revealed() {
        ui.data_mut(|d| d.remove::<bool>(seen));
    }
    let Some(_) = chosen else {
        return;
    };
    if app.lesson_revealed() {
        let answer = word(
            app,
            Some(n),
            &format!("answer-{}", q.answer + 1),
            q.answers[q.answer],
        );
        let shows = tr_with(app, "lesson-shows", &[("answer", arg(answer))]);
        ui.label(RichText::new(shows).strong());
        let why = ui.label(word(app, Some(n), "why", q.why));
        // Brought into view when the run first shows it (after an answer the why had stayed
        // below the card's fold on a projector), frame after frame until it is seen; then
        // the reader scrolls as they like.
        if !ui.data(|d| d.get_temp::<bool>(seen).unwrap_or(false)) {
            if ui.clip_rect().contains_rect(why.rect) {
                ui.data_mut(|d| d.insert_temp(seen, true));
            } else {
                why.scroll_to_me_animation(
                    Some(egui::Align::BOTTOM),
                    egui::style::ScrollAnimation::none(),
                );
                ui.ctx().request_repaint();
            }
        }
    } else if let Some(t) = app.run().pause_at_s {
        let running = tr_with(app, "lesson-running", &[("t", num_arg(app, t))]);
        ui.label(RichText::new(running).weak());
    }
}

/// Back, next and again (PageUp and PageDown, or ← and →, do the same).
fn navigation(ui: &mut Ui, app: &AppState, lesson: &Lesson, n: usize, commands: &mut Vec<Command>) {
    ui.horizontal_wrapped(|ui| {
        if ui
            .add_enabled(n > 1, egui::Button::new(tr(app, "lesson-back")))
            .clicked()
        {
            commands.push(LessonCommand::Go(n - 1).into());
        }
        if ui
            .add_enabled(
                n < lesson.steps.len(),
                egui::Button::new(tr(app, "lesson-next")),
            )
            .clicked()
        {
            commands.push(LessonCommand::Go(n + 1).into());
        }
        if ui.button(tr(app, "lesson-again")).clicked() {
            commands.push(LessonCommand::Go(n).into());
        }
    });
}

/// The tools a lesson uses (share, the filter's cycle) and the way out.
fn tools(ui: &mut Ui, app: &AppState, commands: &mut Vec<Command>) {
    ui.horizontal_wrapped(|ui| {
        if ui.small_button(tr(app, "share")).clicked() {
            commands.push(ShareCommand::Open.into());
        }
        // The step that talks about the filter's terms points at its cycle.
        let talks = app.lesson_step().is_some_and(|s| !s.terms.is_empty());
        let label = if talks {
            RichText::new(tr(app, "cycle-open"))
                .strong()
                .color(ui.visuals().selection.stroke.color)
        } else {
            RichText::new(tr(app, "cycle-open"))
        };
        if app
            .sim()
            .estimators()
            .iter()
            .any(|e| e.teaching().is_some())
            && ui.small_button(label).clicked()
        {
            commands.push(ViewCommand::SetCycle(!app.view().cycle_open).into());
        }
        if ui.small_button(tr(app, "lesson-end")).clicked() {
            commands.push(LessonCommand::Close.into());
        }
    });
}
