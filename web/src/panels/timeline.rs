//! The timeline under the plots: a bar over the whole run with a cursor that can be
//! dragged, clicked or moved by the keyboard (←/→ a step, Shift a second, Home/End), "Live"
//! back to now, "What if…" at the cursor, and a chip per branch with its one-line summary.

use crate::state::{AppState, Command, TravelCommand, branch_words};
use attlab::i18n::{FluentValue, t, t_with};
use egui::{Color32, Key, Sense, Stroke, Ui, vec2};

/// The bar's height (points): a thumb's width on a touch screen, a row of text elsewhere
/// (a projector's plot keeps its room).
fn bar_height(ctx: &egui::Context) -> f32 {
    if super::narrow::is_phone(ctx) || ctx.input(|i| i.has_touch_screen()) {
        30.0
    } else {
        18.0
    }
}

/// How tall the timeline is with its rows (points), for the plots to leave it room.
pub fn height(ctx: &egui::Context, app: &AppState) -> f32 {
    // A what-if's row wraps to three lines on a phone: its changes, its summary, its buttons.
    let per_branch = if super::narrow::is_phone(ctx) { 3 } else { 1 };
    let rows =
        usize::from(app.travel().cursor.is_some()) + per_branch * app.travel().branches.len();
    bar_height(ctx) + 2.0 + 22.0 * rows as f32
}

/// The timeline and its rows.
pub fn show(ui: &mut Ui, app: &AppState, commands: &mut Vec<Command>) {
    let lang = app.view().lang();
    ui.horizontal(|ui| {
        let cursor = app.travel().cursor.as_ref();
        let what_if = cursor.map(|_| t(lang, "timeline-what-if"));
        let label = match cursor {
            Some(c) if !c.ready() => {
                t_with(lang, "timeline-seeking", &[("t", seconds(app, c.t_s()))])
            }
            Some(c) => t_with(lang, "timeline-at", &[("t", seconds(app, c.sim().t_s()))]),
            None => t_with(
                lang,
                "timeline-now",
                &[("t", seconds(app, app.sim().t_s()))],
            ),
        };
        let reserved = 150.0 + if what_if.is_some() { 170.0 } else { 0.0 };
        let width = (ui.available_width() - reserved).max(80.0);
        bar(ui, app, width, &label, commands);
        ui.label(label);
        // After the bar, so that the bar keeps its place (and the keyboard) when it appears.
        if cursor.is_some()
            && ui
                .button(t(lang, "timeline-live"))
                .on_hover_text(t(lang, "timeline-live-hint"))
                .clicked()
        {
            commands.push(Command::from(TravelCommand::Live));
        }
        if let Some(text) = what_if
            && ui
                .button(text)
                .on_hover_text(t(lang, "timeline-what-if-hint"))
                .clicked()
        {
            commands.push(Command::from(TravelCommand::WhatIf));
        }
    });
    if let Some(c) = &app.travel().cursor {
        let line = if c.changes.is_empty() {
            t(lang, "timeline-no-changes")
        } else {
            let lab = app.sim().lab();
            let changes: Vec<String> = (c.changes.iter())
                .map(|(k, v)| attlab::i18n::errors::param_at(lang, lab, k, *v))
                .collect();
            t_with(
                lang,
                "timeline-changes",
                &[("changes", changes.join(", ").into())],
            )
        };
        ui.small(line);
    }
    for (i, branch) in app.travel().branches.iter().enumerate() {
        ui.horizontal_wrapped(|ui| branch_row(ui, app, i, branch, commands));
    }
}

/// Seconds with the reader's decimal sign, to two decimals.
fn seconds(app: &AppState, t_s: f64) -> FluentValue<'static> {
    attlab::i18n::fixed(app.view().lang(), t_s, 2).into()
}

/// The bar itself: the run from its first snapshot to now, each branch's start marked.
fn bar(ui: &mut Ui, app: &AppState, width: f32, label: &str, commands: &mut Vec<Command>) {
    let sim = app.sim();
    let (start, now) = (sim.history_start_s().unwrap_or(0.0), sim.t_s());
    let size = vec2(width, bar_height(ui.ctx()));
    let (rect, _) = ui.allocate_exact_size(size, Sense::hover());
    // A stable id: the bar keeps the keyboard whatever appears beside it.
    let response = ui.interact(
        rect,
        egui::Id::unique("timeline-bar"),
        Sense::click_and_drag(),
    );
    let name = t(app.view().lang(), "timeline-label");
    let t_shown = app.cursor_t();
    // The screen reader hears the bar's name with the moment it shows.
    response.widget_info(|| egui::WidgetInfo::slider(true, t_shown, format!("{name}: {label}")));
    let span = (now - start).max(1e-9);
    let x_of = |t: f64| rect.left() + ((t - start) / span).clamp(0.0, 1.0) as f32 * rect.width();
    let visuals = ui.visuals();
    let painter = ui.painter_at(rect.expand(2.0));
    let mid = rect.center().y;
    let track = visuals.widgets.inactive.bg_stroke.color;
    painter.line_segment(
        [rect.left_center(), rect.right_center()],
        Stroke::new(4.0, track),
    );
    let accent = visuals.selection.bg_fill;
    painter.line_segment(
        [rect.left_center(), egui::pos2(x_of(t_shown), mid)],
        Stroke::new(4.0, accent),
    );
    for b in &app.travel().branches {
        let x = x_of(b.from_s());
        painter.line_segment(
            [
                egui::pos2(x, rect.top() + 4.0),
                egui::pos2(x, rect.bottom() - 4.0),
            ],
            Stroke::new(2.0, visuals.strong_text_color()),
        );
    }
    let handle = rect.height() * if response.has_focus() { 0.36 } else { 0.3 };
    painter.circle(
        egui::pos2(x_of(t_shown), mid),
        handle,
        accent,
        Stroke::new(2.0, Color32::WHITE),
    );
    if response.has_focus() {
        painter.rect_stroke(
            rect,
            4.0,
            visuals.selection.stroke,
            egui::StrokeKind::Outside,
        );
    }
    if let Some(p) = response.interact_pointer_pos()
        && (response.clicked() || response.dragged())
    {
        response.request_focus();
        let t = start + f64::from((p.x - rect.left()) / rect.width()).clamp(0.0, 1.0) * span;
        commands.push(Command::from(TravelCommand::Seek(t)));
    }
    keys(ui, &response, (start, now), commands);
}

/// The keyboard while the bar has it: ←/→ a step, Shift+←/→ a second, Home/End.
fn keys(ui: &Ui, response: &egui::Response, (start, now): (f64, f64), commands: &mut Vec<Command>) {
    if !response.has_focus() {
        return;
    }
    ui.memory_mut(|m| {
        m.set_focus_lock_filter(
            response.id,
            egui::EventFilter {
                horizontal_arrows: true,
                ..Default::default()
            },
        );
    });
    // Every press of the frame counts (a held key repeats faster than a slow frame).
    let (mut seconds, mut frames, mut jump) = (0.0, 0i64, None);
    ui.input(|i| {
        for (key, modifiers) in super::slider_keys::presses(i) {
            let sign = match key {
                Key::ArrowLeft => -1,
                Key::ArrowRight => 1,
                Key::Home => {
                    jump = Some(start);
                    continue;
                }
                Key::End => {
                    jump = Some(now);
                    continue;
                }
                _ => continue,
            };
            if modifiers.shift {
                seconds += f64::from(sign);
            } else {
                frames += i64::from(sign);
            }
        }
    });
    if let Some(t) = jump {
        commands.push(Command::from(TravelCommand::Seek(t)));
    }
    if seconds != 0.0 {
        commands.push(Command::from(TravelCommand::Nudge(seconds)));
    }
    if frames != 0 {
        commands.push(Command::from(TravelCommand::StepFrames(frames)));
    }
}

/// One branch: its changes, its summary (or how far it has caught up), Remove and Make main.
fn branch_row(
    ui: &mut Ui,
    app: &AppState,
    i: usize,
    branch: &attlab::sim::Branch,
    commands: &mut Vec<Command>,
) {
    let lang = app.view().lang();
    let chip = t_with(
        lang,
        "branch-chip",
        &[
            ("n", (i as i64 + 1).into()),
            ("changes", branch_words(app, branch).into()),
            ("t", seconds(app, branch.from_s())),
        ],
    );
    ui.label(egui::RichText::new(chip).strong());
    ui.add(egui::Label::new(summary(app, branch)).wrap());
    if ui
        .small_button(t(lang, "branch-drop"))
        .on_hover_text(t(lang, "branch-drop-hint"))
        .clicked()
    {
        commands.push(Command::from(TravelCommand::Drop(i)));
    }
    if ui
        .small_button(t(lang, "branch-promote"))
        .on_hover_text(t(lang, "branch-promote-hint"))
        .clicked()
    {
        commands.push(Command::from(TravelCommand::Promote(i)));
    }
}

/// The branch's one line: the estimator whose error changed the most, before → after.
pub fn summary(app: &AppState, branch: &attlab::sim::Branch) -> String {
    let lang = app.view().lang();
    let Some(differences) = branch.differences(app.sim()) else {
        let t_s = seconds(app, branch.sim().t_s());
        return t_with(lang, "branch-catching-up", &[("t", t_s)]);
    };
    let ratio = |d: &attlab::sim::Difference| (d.branch.rms_deg / d.original.rms_deg).ln().abs();
    let best = (differences.iter())
        .filter(|d| d.original.rms_deg > 0.0 && d.branch.rms_deg > 0.0 && ratio(d).is_finite())
        .max_by(|a, b| ratio(a).total_cmp(&ratio(b)))
        .or_else(|| differences.first());
    let Some(d) = best else {
        return String::new();
    };
    let name = super::estimator_name(app, d.estimator);
    if !(d.original.rms_deg.is_finite() && d.branch.rms_deg.is_finite()) {
        return t_with(lang, "branch-summary-none", &[("estimator", name.into())]);
    }
    let number = |v: f64| attlab::i18n::number(lang, &significant(v, 3)).into();
    t_with(
        lang,
        "branch-summary",
        &[
            ("estimator", name.into()),
            ("over", attlab::i18n::fixed(lang, d.over_s, 0).into()),
            ("before", number(d.original.rms_deg)),
            ("after", number(d.branch.rms_deg)),
        ],
    )
}

/// `v` with `digits` significant digits, in plain decimals.
fn significant(v: f64, digits: i32) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let decimals = (digits - 1 - v.abs().log10().floor() as i32).max(0) as usize;
    format!("{v:.decimals$}")
}
