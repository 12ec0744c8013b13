//! The central view: the lab's declared views on top (3D body, Riemann sphere and complex
//! plane or the lab's diagram; for a single-axis lab a dial and the phase portrait), the plot
//! tabs and plots below. Reads the state, emits commands (tab choices); the widgets own their view.

use super::trails::{Trails, trails_of};
use super::{arg, tabs, tr, tr_with};
use crate::export::Regions;
use crate::render::palette::{self, Palette};
use crate::render::travel_lines::TravelMarks;
use crate::render::{body3d, plots, riemann_sphere, scene, single_axis};
use crate::state::{AppState, Command, Focus, IoCommand, PngTarget, View};
use attlab::math::WzChart;
use attlab::page::ViewKind;
use egui::{Pos2, Rect, Ui, Vec2};
use std::cell::OnceCell;

/// Draws the central panel and notes in `regions` where each part went (for PNG export).
pub fn central(
    ui: &mut Ui,
    app: &AppState,
    view: &mut View,
    regions: &mut Regions,
    gpu_ready: bool,
    commands: &mut Vec<Command>,
) {
    egui::CentralPanel::default().show(ui, |ui| {
        let full = ui.available_rect_before_wrap();
        let kinds = app.sim().lab().page().views;
        match app.view().focus {
            Focus::View(k) if k < kinds.len() => {
                let trails = OnceCell::new();
                draw_view(ui, app, view, kinds[k], full, &trails, gpu_ready);
                png_button(ui, app, k, full, commands);
                reset_button(ui, app, view, kinds[k], full);
                regions.views.push((k, full));
                return;
            }
            Focus::Plots => {
                ui.scope_builder(egui::UiBuilder::new().max_rect(full), |ui| {
                    draw_plots(ui, app, regions, commands);
                });
                return;
            }
            _ => {}
        }
        // A phone held sideways: one view on the left, the plots beside it.
        if super::narrow::is_short(ui.ctx()) {
            beside(ui, app, (view, regions, gpu_ready), full, commands);
            return;
        }
        // The plots carry each paper's result: the views take what leaves the plot itself
        // (below the chips and the tab rows) at least 40 % of the window's height.
        let window_h = ui.ctx().content_rect().height();
        let chrome = ui
            .ctx()
            .data(|d| d.get_temp::<f32>(chrome_id()))
            .unwrap_or(PLOT_CHROME_PT);
        let below_views = PLOT_SHARE * window_h + chrome + 6.0;
        // Never more than 55 % of the area (a short window, or a phone with its sheet open,
        // can make that less than the views' least height: then that wins).
        let top_h = (full.height() - below_views)
            .max(MIN_VIEW_PT)
            .min(full.height() * 0.55);
        let top = Rect::from_min_size(full.min, Vec2::new(full.width(), top_h));
        // A narrow screen shows one view at a time (the bar's switcher picks it).
        let shown: Vec<(usize, &ViewKind)> = if super::narrow::is_narrow(ui.ctx()) {
            let k = app.view().narrow_view.min(kinds.len().saturating_sub(1));
            kinds.get(k).map(|kind| (k, kind)).into_iter().collect()
        } else {
            kinds.iter().enumerate().collect()
        };
        let total: f32 = shown.iter().map(|(_, k)| weight(**k)).sum();
        let mut x = top.min.x;
        // The sphere and the w plane draw the same trails: gathered once a frame.
        let trails = OnceCell::new();
        for (k, kind) in shown {
            let w = top.width() * weight(*kind) / total.max(1.0);
            let rect = Rect::from_min_size(Pos2::new(x, top.min.y), Vec2::new(w - 4.0, top_h));
            x += w;
            draw_view(ui, app, view, *kind, rect, &trails, gpu_ready);
            png_button(ui, app, k, rect, commands);
            reset_button(ui, app, view, *kind, rect);
            regions.views.push((k, rect));
        }
        let bottom = Rect::from_min_max(full.min + Vec2::new(0.0, top_h + 6.0), full.max);
        ui.scope_builder(egui::UiBuilder::new().max_rect(bottom), |ui| {
            draw_plots(ui, app, regions, commands);
        });
    });
}

/// A short, wide screen (a phone held sideways): the view the bar's switcher picks on the
/// left, [`SIDE_VIEW_SHARE`] of the width, and the plots on the right at full height.
fn beside(
    ui: &mut Ui,
    app: &AppState,
    (view, regions, gpu_ready): (&mut View, &mut Regions, bool),
    full: Rect,
    commands: &mut Vec<Command>,
) {
    let kinds = app.sim().lab().page().views;
    let k = app.view().narrow_view.min(kinds.len().saturating_sub(1));
    // With the controls' sheet open beside them, the plots alone: the sheet is what the
    // reader is working with, the plot what it changes.
    let share = if app.view().sheet_open {
        0.0
    } else {
        SIDE_VIEW_SHARE
    };
    let w = (full.width() * share).round();
    if let Some(kind) = kinds.get(k).filter(|_| w > 0.0) {
        let rect = Rect::from_min_size(full.min, Vec2::new(w - 4.0, full.height()));
        let trails = OnceCell::new();
        draw_view(ui, app, view, *kind, rect, &trails, gpu_ready);
        png_button(ui, app, k, rect, commands);
        reset_button(ui, app, view, *kind, rect);
        regions.views.push((k, rect));
    }
    let right = Rect::from_min_max(full.min + Vec2::new(w, 0.0), full.max);
    ui.scope_builder(egui::UiBuilder::new().max_rect(right), |ui| {
        draw_plots(ui, app, regions, commands);
    });
}

/// The share of a sideways phone's width its one view takes.
const SIDE_VIEW_SHARE: f32 = 0.38;

/// The share of the window's height the plot itself gets at least.
const PLOT_SHARE: f32 = 0.42;
/// What of the plots' area is not the plot itself (the estimator chips, the tab rows, the
/// axes), before a frame has measured it (points).
const PLOT_CHROME_PT: f32 = 120.0;

/// Where the height of the chips and tab rows, as last drawn, is kept between frames.
fn chrome_id() -> egui::Id {
    egui::Id::unique("attlab_plot_chrome_height")
}
/// The views' height below which they are no use (points).
const MIN_VIEW_PT: f32 = 120.0;

/// A visible "⟲" in the top-right corner of the 3D view or the sphere once the reader has
/// turned or zoomed it (a double click does the same, but nothing says so on a touch screen).
fn reset_button(ui: &mut Ui, app: &AppState, view: &mut View, kind: ViewKind, rect: Rect) {
    let moved = match kind {
        ViewKind::Body3d => view.camera != body3d::OrbitCamera::default(),
        ViewKind::Sphere => view.sphere != riemann_sphere::SphereView::default(),
        _ => false,
    };
    if !moved || app.view().capturing {
        return;
    }
    let size = Vec2::new(26.0, 22.0);
    let at = Rect::from_min_size(Pos2::new(rect.max.x - size.x - 4.0, rect.min.y + 4.0), size);
    if ui
        .put(at, egui::Button::new("⟲"))
        .on_hover_text(tr(app, "view-reset-hint"))
        .clicked()
    {
        match kind {
            ViewKind::Body3d => view.camera = body3d::OrbitCamera::default(),
            _ => view.sphere = riemann_sphere::SphereView::default(),
        }
    }
}

/// A phone or a tablet: the narrow layout, or a screen a finger has touched (since, not
/// only while: the hint must not change under a dragging finger).
fn touch_screen(ui: &Ui) -> bool {
    super::narrow::is_phone(ui.ctx()) || ui.ctx().input(|i| i.has_touch_screen())
}

/// A small "PNG" button in the bottom-right corner of view `k` while the pointer is over
/// the view (so it hides no caption otherwise; never while a capture runs, so it is not in
/// the picture).
fn png_button(ui: &mut Ui, app: &AppState, k: usize, rect: Rect, commands: &mut Vec<Command>) {
    // On a touch screen there is no hover: the button stays.
    let touch = touch_screen(ui);
    if app.view().capturing || !(touch || ui.rect_contains_pointer(rect)) {
        return;
    }
    let at = scene::png_button_rect(rect);
    let button = egui::Button::new(egui::RichText::new(tr(app, "png")).small());
    if ui
        .put(at, button)
        .on_hover_text(tr(app, "png-view-hint"))
        .clicked()
    {
        commands.push(Command::from(IoCommand::ExportPng(PngTarget::View(k))));
    }
}

/// The plot tabs and the selected plot; the tab row and the plot are the PNG export's area.
fn draw_plots(ui: &mut Ui, app: &AppState, regions: &mut Regions, commands: &mut Vec<Command>) {
    let area = ui.available_rect_before_wrap();
    // A phone held sideways has them in a menu on the tab row.
    if !super::narrow::is_short(ui.ctx()) {
        tabs::estimator_legend(ui, app, commands);
    }
    // The timeline under the plots keeps its rows; the plots take the rest.
    let rest = ui.available_rect_before_wrap();
    let below = super::timeline::height(ui.ctx(), app).min(rest.height() * 0.5);
    let (above, timeline) = rest.split_top_bottom_at_y(rest.bottom() - below);
    ui.scope_builder(egui::UiBuilder::new().max_rect(timeline), |ui| {
        super::timeline::show(ui, app, commands);
    });
    ui.scope_builder(egui::UiBuilder::new().max_rect(above), |ui| {
        plots_above(ui, app, regions, commands);
    });
    ui.advance_cursor_after_rect(rest);
    // Everything of this area that is not the plot itself: chips, tabs, axes, timeline.
    if let Some(plot) = regions.plot_area {
        let chrome = area.height() - plot.height();
        ui.ctx().data_mut(|d| d.insert_temp(chrome_id(), chrome));
    }
}

/// The tabs and the plot, above the timeline.
fn plots_above(ui: &mut Ui, app: &AppState, regions: &mut Regions, commands: &mut Vec<Command>) {
    regions.plots = Some(ui.available_rect_before_wrap());
    tabs::plot_tabs(ui, app, commands);
    regions.plot_area = Some(plots::show(
        ui,
        app.sim().recorder(),
        app.sim().lab().page().figures,
        &super::outages(app),
        &app.view().plots,
        if app.view().presenter { 3.0 } else { 1.4 },
        &app.view().hidden,
        &super::plot_words(app),
        &travel_marks(app, ui.visuals().strong_text_color()),
    ));
}

/// What time travel adds to the plot: the cursor's line and the branches' series.
fn travel_marks(app: &AppState, line: egui::Color32) -> TravelMarks<'_> {
    TravelMarks {
        line,
        cursor_s: app.travel().cursor.as_ref().map(|c| c.sim().t_s()),
        branches: (app.travel().branches.iter())
            .map(|b| b.sim().recorder())
            .collect(),
    }
}

/// Share of the top row a view takes.
fn weight(kind: ViewKind) -> f32 {
    match kind {
        ViewKind::Body3d => 42.0,
        ViewKind::Sphere => 30.0,
        ViewKind::WPlane => 28.0,
        ViewKind::Dial => 24.0,
        ViewKind::PhasePortrait => 34.0,
    }
}

/// Draws one of the lab's views, `kind`, into `rect`.
fn draw_view(
    ui: &mut Ui,
    app: &AppState,
    view: &mut View,
    kind: ViewKind,
    rect: Rect,
    trails: &Trails,
    gpu_ready: bool,
) {
    match kind {
        ViewKind::Body3d => draw_body(ui, app, &mut view.camera, rect, gpu_ready),
        ViewKind::Sphere => {
            let tracks = trails_of(trails, app, ui);
            let caption = chart_caption(app);
            let title = tr(app, "sphere-title");
            let pole = tr(app, "sphere-pole");
            let words = (title.as_str(), caption.as_str(), pole.as_str());
            riemann_sphere::show_sphere(ui, rect, &mut view.sphere, tracks, words);
        }
        ViewKind::WPlane => {
            // A lab with a diagram of its own (paper 5's eigenvalues) shows it here instead.
            let diagrams = app.shown().lab().page().diagrams(app.shown().params());
            ui.scope_builder(egui::UiBuilder::new().max_rect(rect), |ui| {
                match diagrams.first() {
                    Some(d) => super::lab_tools::diagram(ui, app, d),
                    None => riemann_sphere::show_plane(
                        ui,
                        trails_of(trails, app, ui),
                        app.view().lang(),
                    ),
                }
            });
        }
        ViewKind::Dial => {
            let (sources, shown) = axis_sources(app, palette::of(ui.visuals()));
            let visible: Vec<_> = sources
                .into_iter()
                .zip(shown)
                .filter(|(_, v)| *v)
                .map(|(s, _)| s)
                .collect();
            let title = tr(app, "dial-title");
            single_axis::dial(ui, rect, &visible, (&title, app.view().lang()));
        }
        ViewKind::PhasePortrait => {
            // Trails are kept for hidden sources too, so showing one again loses nothing.
            let (sources, shown) = axis_sources(app, palette::of(ui.visuals()));
            view.trails.push(app.shown().t_s(), &sources);
            let words = [
                tr(app, "phase-title"),
                tr(app, "phase-angle"),
                tr(app, "phase-rate"),
            ];
            let words = (
                words[0].as_str(),
                words[1].as_str(),
                words[2].as_str(),
                app.view().lang(),
            );
            single_axis::phase_portrait(ui, rect, &view.trails, &sources, &shown, words);
        }
    }
}

/// Truth and every single-axis estimator: angle and rate about the axis, in source colours,
/// and whether each is shown. A replayed or live log has no truth: the dial and the phase
/// portrait leave it out (the dial had read "— truth").
fn axis_sources(app: &AppState, colours: &Palette) -> (Vec<single_axis::AxisSource>, Vec<bool>) {
    let mut shown = vec![app.shown().has_truth()];
    let truth = app.shown().truth();
    let mut out = vec![single_axis::AxisSource {
        name: tr(app, "truth"),
        color: colours.source(0),
        pattern: palette::pattern(0),
        angle_rad: truth.angle_rad.unwrap_or(f64::NAN),
        rate_rad_s: truth.rate_body_rad_s.z,
        is_truth: true,
    }];
    for (i, est) in app.shown().estimates().iter().enumerate() {
        if let Some(angle) = est.angle_rad {
            shown.push(!app.view().hidden.contains(&(i + 1)));
            out.push(single_axis::AxisSource {
                name: super::estimator_cut(app, i, single_axis::DIAL_NAME),
                color: colours.source(i + 1),
                pattern: palette::pattern(i + 1),
                angle_rad: angle,
                rate_rad_s: est.rate_body_rad_s.map_or(f64::NAN, |w| w.z),
                is_truth: false,
            });
        }
    }
    (out, shown)
}

fn draw_body(
    ui: &mut Ui,
    app: &AppState,
    camera: &mut body3d::OrbitCamera,
    rect: Rect,
    gpu_ready: bool,
) {
    // A replayed or live log has no truth: the estimate is drawn alone, solid.
    let truth = app
        .sim()
        .has_truth()
        .then(|| app.shown().truth().q_ref_from_body);
    let ghost_name = super::estimator_name(app, app.view().ghost_index);
    let ghost = app
        .sim()
        .estimates()
        .get(app.view().ghost_index)
        .and_then(|e| e.quaternion())
        .map(|q| (q, ghost_name.as_str()));
    let extras = app.shown().scene();
    let top = super::body_captions(app, ghost.map(|(_, label)| label));
    let scene = scene::Scene {
        truth,
        ghost,
        suspended: app.shown().lab().page().suspended,
        shape: app.shown().lab().page().body,
        vectors: &extras.vectors,
        ghost_axis: app
            .sim()
            .estimators()
            .get(app.view().ghost_index)
            .and_then(|e| e.unobservable_axis_body()),
        orbit: extras.orbit,
        // No wheel or double click on a touch screen (the ⟲ button resets a turned view):
        // a hint of one line leaves the body more of a phone's short view.
        // In presenter mode the room is the body's: the lecturer knows how to turn it, and
        // the hint had been printed over a body 60 px tall on a projector.
        captions: (
            top,
            if app.view().presenter {
                String::new()
            } else if touch_screen(ui) {
                tr(app, "body-hint-touch")
            } else {
                tr(app, "body-hint")
            },
        ),
        words: scene::SceneWords {
            vectors: extras
                .vectors
                .iter()
                .map(|v| {
                    let id = attlab::i18n::scene_id(app.shown().lab().id(), v.label);
                    super::lab_word(app, &id, v.label)
                })
                .collect(),
            unobservable: tr(app, "body-unobservable"),
            orbit: (tr(app, "body-orbit"), tr(app, "body-shadow")),
            no_gpu: tr(app, "body-no-gpu"),
        },
    };
    body3d::show(ui, rect, camera, &scene, gpu_ready);
}

/// Which chart of w the estimators integrate in, short enough for a small view: "all in
/// chart w" while none is upside down; else the ones in the flipped chart s = 1/w by name,
/// and how many stay in chart w.
fn chart_caption(app: &AppState) -> String {
    let mut north = 0;
    let mut flipped = Vec::new();
    for (i, est) in app.shown().estimates().iter().enumerate() {
        match est.attitude.wz().map(|wz| wz.chart) {
            Some(WzChart::North) => north += 1,
            Some(WzChart::Flipped) => flipped.push(super::estimator_short(app, i)),
            None => {}
        }
    }
    if flipped.is_empty() {
        return if north > 0 {
            tr(app, "chart-all-w")
        } else {
            String::new()
        };
    }
    let mut lines = vec![tr_with(app, "chart-s", &[("ids", arg(flipped.join(", ")))])];
    if north > 0 {
        lines.push(tr_with(app, "chart-w-rest", &[("n", north.into())]));
    }
    lines.join("\n")
}
