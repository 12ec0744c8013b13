//! Panels: they read [`AppState`] and emit [`Command`]s, never changing the state
//! themselves. The generic lab panel serves every lab from its parameter specs and recorded
//! series; a lab that needs its own controls gets its own file here.

mod about;
mod central;
mod controls;
mod cycle;
mod embed;
mod fit;
mod keys;
mod lab_picker;
mod lab_tools;
mod lesson;
mod live;
mod narration;
mod narrow;
mod param_widget;
mod share;
mod slider_keys;
mod sliders;
mod sweeps;
mod tabs;
mod tiles;
mod timeline;
mod trails;

pub use central::central;
pub use controls::controls;
pub use cycle::{
    cycle_panel, matrix as cycle_matrix, num as cycle_num, shown_filter, vector as cycle_vector,
};
pub use embed::{embed_bar, open_url};
pub use keys::{focus_ring, help_dialog, shortcuts, tabs};
pub use narration::{Narration, describe as describe_run};
pub use narrow::{controls_for_the_screen, is_narrow, is_phone, is_short, touch_style};
pub use share::share_dialog;
pub use slider_keys::rail_position;
pub use tiles::tiles;

use crate::state::{AppState, Command, RunCommand};
use attlab::i18n::{self, FluentValue};
use attlab::model::EstimatorStatus;

/// The page's message `id` (crate/locales/*/page.ftl) in the reader's language.
pub(crate) fn tr(app: &AppState, id: &str) -> String {
    i18n::t(app.view().lang(), id)
}

/// The page's message `id` in the reader's language, for the frame loop outside the panels.
pub fn tr_page(app: &AppState, id: &str) -> String {
    tr(app, id)
}

/// The same with arguments (`$name` in the message).
pub(crate) fn tr_with(app: &AppState, id: &str, args: &[(&str, FluentValue<'_>)]) -> String {
    i18n::t_with(app.view().lang(), id, args)
}

/// An argument for [`tr_with`] from anything that prints.
pub(crate) fn arg(value: impl std::fmt::Display) -> FluentValue<'static> {
    FluentValue::from(value.to_string())
}

/// An argument for [`tr_with`] that is a number as the code formats it ("0.05"), written as
/// the reader's language writes it ("0,05" in Russian).
pub(crate) fn num_arg(app: &AppState, value: impl std::fmt::Display) -> FluentValue<'static> {
    FluentValue::from(i18n::number(app.view().lang(), &value.to_string()))
}

/// The name of estimator `i` a student reads (its label, in the reader's language).
pub(crate) fn estimator_name(app: &AppState, i: usize) -> String {
    let lab = app.sim().lab().id();
    app.sim()
        .estimators()
        .get(i)
        .map(|e| i18n::estimator_name(app.view().lang(), lab, e.id(), e.label()))
        .unwrap_or_default()
}

/// The same, cut to [`SHORT_NAME`] characters with "…" where a view has little room (a
/// chip, a dial's readout, a caption); the whole name is in the legend and on hover.
pub(crate) fn estimator_short(app: &AppState, i: usize) -> String {
    estimator_cut(app, i, SHORT_NAME)
}

/// Estimator `i`'s name cut to `max` characters so that no two of the lab's read alike.
pub(crate) fn estimator_cut(app: &AppState, i: usize, max: usize) -> String {
    let names: Vec<String> = (0..app.sim().estimators().len())
        .map(|k| estimator_name(app, k))
        .collect();
    distinct_cuts(&names, max).swap_remove(i)
}

/// `names` cut to `max` characters (see [`elide`]), except that names whose cuts would read
/// alike drop the words they share at their start ("…[θ, ω, b]", "…fed u_v + u₀"): paper
/// 4's two "Beyond the paper: KF …" filters had read the same on their chips and on the
/// dial.
pub(crate) fn distinct_cuts(names: &[String], max: usize) -> Vec<String> {
    let cut: Vec<String> = names.iter().map(|n| elide(n, max)).collect();
    (0..names.len())
        .map(|i| {
            let alike: Vec<&String> = (0..names.len())
                .filter(|j| *j != i && cut[*j] == cut[i])
                .map(|j| &names[j])
                .collect();
            if alike.is_empty() {
                return cut[i].clone();
            }
            // The characters every alike name shares at its start, back to a word's start
            // where there is one ("Beyond the paper: KF " of both KF filters).
            let chars: Vec<char> = names[i].chars().collect();
            let common = (0..chars.len())
                .take_while(|k| alike.iter().all(|o| o.chars().nth(*k) == Some(chars[*k])))
                .count();
            let word = chars[..common]
                .iter()
                .rposition(|c| *c == ' ')
                .map_or(0, |k| k + 1);
            let from = if word > 0 { word } else { common };
            let rest: String = chars[from.min(chars.len())..].iter().collect();
            let rest = rest.trim_start();
            elide(&format!("…{rest}"), max)
        })
        .collect()
}

/// The longest name a chip or a dial shows whole.
pub(crate) const SHORT_NAME: usize = 24;

/// `text` cut to `max` characters, the last one "…" when cut.
pub(crate) fn elide(text: &str, max: usize) -> String {
    if text.chars().count() <= max {
        return text.to_string();
    }
    let kept: String = text.chars().take(max.saturating_sub(1)).collect();
    format!("{}…", kept.trim_end())
}

/// A lab's own word `english` in the reader's language (the catalogue's message `id`).
pub(crate) fn lab_word(app: &AppState, id: &str, english: &str) -> String {
    i18n::lab_text(app.view().lang(), id, english)
}

/// A series' legend (label and unit) in the reader's language.
pub(crate) fn series_legend(app: &AppState, spec: &attlab::model::SeriesSpec) -> String {
    i18n::series_legend(app.view().lang(), app.sim().lab().id(), spec)
}

/// The words the plot draws, in the reader's language.
pub fn plot_words(app: &AppState) -> crate::render::plots::PlotWords<'_> {
    let lab = app.sim().lab();
    let mut outage_words: Vec<String> = lab
        .page()
        .outages
        .iter()
        .map(|o| lab_word(app, &i18n::outage_id(lab.id(), o.id), o.label))
        .collect();
    if app.sim().replay_log().is_some() {
        outage_words.push(tr(app, "replay-gaps"));
    }
    crate::render::plots::PlotWords {
        legend: Box::new(move |spec| {
            i18n::series_legend_parts(app.view().lang(), app.sim().lab().id(), spec)
        }),
        time_axis: tr(app, "axis-time"),
        mixed_units: tr(app, "axis-mixed-units"),
        group_axis: Box::new(move |group| group.axis_message().map(|id| tr(app, id))),
        unit: Box::new(move |unit| i18n::unit(app.view().lang(), unit)),
        bands: tr(app, "bands-legend"),
        no_data: tr(app, "legend-no-data"),
        no_positive: tr(app, "legend-no-positive"),
        reset: tr(app, "plot-reset-hint"),
        outages: outage_words,
        lang: app.view().lang(),
        steady_note: Box::new(move |s| tr_with(app, "plot-steady-note", &[("s", num_arg(app, s))])),
        unit_noun: Box::new(move |unit| {
            // A unit's word: `axis-of-deg`, `axis-of-deg-s` (its letters and digits, dashed).
            let key: String = unit
                .chars()
                .map(|c| match c {
                    '²' => '2',
                    c if c.is_ascii_alphanumeric() => c,
                    _ => '-',
                })
                .collect();
            let id = format!("axis-of-{key}");
            tr(
                app,
                if i18n::has(app.view().lang(), &id) {
                    &id
                } else {
                    "axis-value"
                },
            )
        }),
    }
}

/// The 3D view's lines on top: what is solid and what is the ghost (labelled `ghost`), or,
/// for a log, that there is no truth and the estimate is the solid body.
pub fn body_captions(app: &AppState, ghost: Option<&str>) -> Vec<String> {
    let (first, ghost_words) = if app.sim().has_truth() {
        ("body-truth", "body-ghost")
    } else {
        ("body-no-truth", "body-estimate")
    };
    let mut top = vec![tr(app, first)];
    top.extend(ghost.map(|label| tr_with(app, ghost_words, &[("label", arg(label))])));
    top
}

/// The outages the plots shade: the lab's, and a replay's steps without a logged sample.
pub fn outages(app: &AppState) -> Vec<attlab::page::Outage> {
    let mut all = app.sim().lab().page().outages.to_vec();
    if app.sim().replay_log().is_some() {
        all.push(attlab::page::REPLAY_GAPS);
    }
    all
}

/// The bad items of the link the page opened with, at the top of the page in the warning
/// colour, until dismissed (the rest of the link is applied).
pub fn link_problems(ui: &mut egui::Ui, app: &AppState, commands: &mut Vec<Command>) {
    if app.link_problems().is_empty() {
        return;
    }
    egui::Panel::top("link_problems").show(ui, |ui| {
        let warn = crate::render::palette::of(ui.visuals()).warn;
        ui.horizontal_wrapped(|ui| {
            ui.colored_label(warn, egui::RichText::new(tr(app, "link-problems")).strong());
            if ui.small_button(tr(app, "link-dismiss")).clicked() {
                commands.push(Command::from(crate::state::UrlCommand::DismissProblems));
            }
        });
        for p in app.link_problems() {
            ui.colored_label(warn, p);
        }
    });
}

/// The status line at the bottom: a re-run or export under way (with its progress and a
/// button that stops it), time, rates, frame time, recorder memory and estimator health.
pub fn status_line(ui: &mut egui::Ui, app: &AppState, commands: &mut Vec<Command>) {
    egui::Panel::bottom("status").show(ui, |ui| {
        // A line of text, not a finger's row, unless it holds a button (a job's Stop, a
        // trouble's menu): on a phone held sideways it had taken 53 of 390 points.
        let buttons = app.run().job().is_some()
            || (app.sim().statuses().iter()).any(|s| !matches!(s, EstimatorStatus::Ok));
        if !buttons {
            ui.spacing_mut().interact_size.y = ui.text_style_height(&egui::TextStyle::Monospace);
        }
        if let Some(job) = app.run().job() {
            ui.horizontal(|ui| {
                let done = job.progress();
                let percent = format!("{:.0}", 100.0 * done);
                let text = tr_with(
                    app,
                    "job-progress",
                    &[
                        ("what", arg(tr(app, job.title_id()))),
                        ("percent", arg(percent)),
                    ],
                );
                ui.add(
                    egui::ProgressBar::new(done as f32)
                        .desired_width(220.0)
                        .text(text),
                );
                ui.label(tr(app, "job-holds"));
                if ui.small_button(tr(app, "stop")).clicked() {
                    commands.push(Command::from(RunCommand::CancelJob));
                }
            });
        }
        let colours = crate::render::palette::of(ui.visuals());
        ui.horizontal_wrapped(|ui| {
            ui.monospace(stats_text(app, is_phone(ui.ctx())));
            if app.run().stats.behind {
                ui.colored_label(colours.warn, tr(app, "behind"));
            }
            health(ui, app);
        });
    });
}

/// The filters' health in the status line: one filter's trouble in full; two or more of a
/// kind as one line whose menu lists each with its reason. Six filters that lost the star
/// tracker had taken six lines, which left a projector's plot a strip ~100 px high.
fn health(ui: &mut egui::Ui, app: &AppState) {
    let mut diverged = Vec::new();
    let mut unobservable = Vec::new();
    for (k, status) in app.sim().statuses().iter().enumerate() {
        let (list, id, why) = match status {
            EstimatorStatus::Ok => continue,
            EstimatorStatus::Diverged(why) => (&mut diverged, "diverged", why),
            EstimatorStatus::Unobservable(why) => (&mut unobservable, "unobservable", why),
        };
        let name = estimator_name(app, k);
        let why = attlab::i18n::trouble(app.view().lang(), why);
        list.push(tr_with(app, id, &[("id", arg(&name)), ("why", arg(why))]));
    }
    let colours = crate::render::palette::of(ui.visuals());
    health_group(ui, app, colours.error, "diverged-many", &diverged);
    health_group(ui, app, colours.warn, "unobservable-many", &unobservable);
}

/// One kind of trouble: nothing, its one line, or a menu of its `lines` titled by the
/// catalogue's `many` message with their count.
fn health_group(
    ui: &mut egui::Ui,
    app: &AppState,
    colour: egui::Color32,
    many: &str,
    lines: &[String],
) {
    match lines {
        [] => {}
        [one] => {
            ui.colored_label(colour, one);
        }
        _ => {
            let title = tr_with(app, many, &[("n", lines.len().into())]);
            ui.menu_button(egui::RichText::new(title).color(colour), |ui| {
                for line in lines {
                    ui.colored_label(colour, line);
                }
            });
        }
    }
}

/// The status line's numbers: for a room or a phone the time and the pace; for the
/// engineer the step, the rates, the frame and the recorder too.
fn stats_text(app: &AppState, narrow: bool) -> String {
    let s = &app.run().stats;
    let rec = app.sim().recorder();
    if app.view().presenter || narrow {
        // A room (or a phone) reads the time and the pace; the rest is for the engineer.
        tr_with(
            app,
            "status-short",
            &[
                ("t", num_arg(app, format!("{:7.2}", app.sim().t_s()))),
                ("realtime", num_arg(app, format!("{:.2}", s.realtime))),
                ("asked", num_arg(app, app.run().speed)),
            ],
        )
    } else {
        tr_with(
            app,
            "status-long",
            &[
                ("t", num_arg(app, format!("{:8.2}", app.sim().t_s()))),
                (
                    "step",
                    num_arg(app, format!("{:.1}", app.sim().dt_s() * 1e3)),
                ),
                ("rate", num_arg(app, format!("{:6.0}", s.steps_per_s))),
                (
                    "realtime",
                    num_arg(app, format!("{:>9}", format!("×{:.2}", s.realtime))),
                ),
                ("asked", num_arg(app, app.run().speed)),
                ("frame", num_arg(app, format!("{:5.1}", s.frame_ms))),
                ("sim", num_arg(app, format!("{:4.1}", s.step_ms))),
                (
                    "mib",
                    num_arg(
                        app,
                        format!("{:.1}", rec.memory_bytes() as f64 / f64::from(1 << 20)),
                    ),
                ),
                // A number, so that Russian picks its plural ("194 ряда").
                ("series", rec.specs().len().into()),
            ],
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// At a chip's and at the dial's width, no two of a lab's estimators read alike, in
    /// either language.
    #[test]
    fn every_labs_estimators_read_apart_on_their_chips_and_the_dial() {
        for lab in attlab::labs::all() {
            for lang in attlab::i18n::Lang::ALL {
                let link = format!("lab={}&lang={}", lab.id(), lang.code());
                let app = AppState::from_fragment(&link);
                let names: Vec<String> = (0..app.sim().estimators().len())
                    .map(|i| estimator_name(&app, i))
                    .collect();
                let dial = lab.page().views.contains(&attlab::page::ViewKind::Dial);
                let dial = dial.then_some(crate::render::single_axis::DIAL_NAME);
                for max in std::iter::once(SHORT_NAME).chain(dial) {
                    let cuts = distinct_cuts(&names, max);
                    for (a, x) in cuts.iter().enumerate() {
                        for (b, y) in cuts.iter().enumerate().skip(a + 1) {
                            assert!(
                                x != y || names[a] == names[b],
                                "{link}: “{}” and “{}” both read “{x}” at {max}",
                                names[a],
                                names[b]
                            );
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn names_that_would_read_alike_lose_the_words_they_share() {
        let names = [
            "Beyond the paper: KF [θ, ω, b]".to_string(),
            "Beyond the paper: KF fed u_v + u₀".to_string(),
            "Complementary filter".to_string(),
        ];
        let cuts = distinct_cuts(&names, 14);
        assert_eq!(cuts, ["…[θ, ω, b]", "…fed u_v + u₀", "Complementary…"]);
    }
}
