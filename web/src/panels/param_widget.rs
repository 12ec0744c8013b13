//! One parameter's widget — a checkbox, a choice or a slider in the reader's language, with
//! its help, its keys and its screen-reader value — used by the controls, the slider rows
//! and the laboratory mode's unit choices.

use super::slider_keys::{self, Rail};
use super::{arg, tr_with};
use crate::state::AppState;
use attlab::i18n::{self, Lang};
use attlab::model::{ParamKind, ParamSpec, Scale};
use egui::Ui;

/// One widget for one parameter; returns the new value if the user changed it.
pub(super) fn param_widget(
    ui: &mut Ui,
    app: &AppState,
    spec: &ParamSpec,
    value: f64,
) -> Option<f64> {
    let mut v = value;
    let (lang, lab) = (app.view().lang(), app.sim().lab().id());
    let label = i18n::lab_text(lang, &i18n::param_label_id(lab, spec.key), spec.label);
    let option = |i: usize| {
        let english = spec_option(spec, i);
        i18n::lab_text(lang, &i18n::param_option_id(lab, spec.key, i), english)
    };
    let help = i18n::lab_text(lang, &i18n::param_help_id(lab, spec.key), spec.help);
    let hint = if spec.needs_reset {
        tr_with(app, "applies-at-reset", &[("help", arg(help))])
    } else {
        help
    };
    let response = match spec.kind {
        ParamKind::Toggle => {
            let mut on = v >= 0.5;
            let r = ui.checkbox(&mut on, label);
            v = if on { 1.0 } else { 0.0 };
            r
        }
        ParamKind::Choice(options) => {
            let mut index = v.max(0.0) as usize;
            let selected = if index < options.len() {
                option(index)
            } else {
                "?".into()
            };
            let combo = egui::ComboBox::from_id_salt(("param", spec.key)).selected_text(selected);
            let (r, label) = super::fit::labelled(ui, (spec.key, label), combo, |combo, ui| {
                combo.show_index(ui, &mut index, options.len(), option)
            });
            if !hint.is_empty() {
                label.on_hover_text(hint.clone());
            }
            v = index as f64;
            r
        }
        ParamKind::Real | ParamKind::Integer => {
            let mut slider = in_language(egui::Slider::new(&mut v, spec.min..=spec.max), lang)
                .logarithmic(spec.scale == Scale::Log && spec.min > 0.0);
            if spec.scale == Scale::Log && spec.min == 0.0 {
                slider = slider.logarithmic(true).smallest_positive(1e-4);
            }
            let unit = i18n::unit(lang, spec.unit);
            if !unit.is_empty() {
                slider = slider.suffix(format!(" {unit}"));
            }
            if spec.kind == ParamKind::Integer {
                slider = slider.integer();
            }
            let (r, label) = super::fit::slider(ui, slider, (spec.key, label), &unit);
            if !hint.is_empty() {
                label.on_hover_text(hint.clone());
            }
            // A screen reader reads the value with its unit ("0.02 °/s").
            let text = format!("{} {unit}", i18n::number(lang, &crate::a11y::tidy(v)));
            ui.ctx()
                .accesskit_node_builder(r.id, |node| node.set_value(text.trim_end()));
            if let Some(keyed) = slider_keys::handle(ui, &r, Rail::of(spec), value) {
                v = keyed;
                return Some(v);
            }
            r
        }
    };
    let response = if hint.is_empty() {
        response
    } else {
        response.on_hover_text(hint)
    };
    (response.changed() && v != value).then_some(v)
}

/// Option `i` of a choice parameter in English ("" for any other kind).
fn spec_option(spec: &ParamSpec, i: usize) -> &'static str {
    match spec.kind {
        ParamKind::Choice(options) => options.get(i).copied().unwrap_or(""),
        _ => "",
    }
}

/// `slider` writing its value as the reader's language does ("0,050" in Russian), with the
/// decimals egui would choose, and reading a typed value as egui does, in Russian with a
/// point or a comma.
pub(super) fn in_language(slider: egui::Slider<'_>, lang: Lang) -> egui::Slider<'_> {
    slider
        .custom_formatter(move |v, decimals| {
            i18n::number(
                lang,
                &egui::emath::format_with_decimals_in_range(v, decimals),
            )
        })
        .custom_parser(move |text| i18n::parse_number(lang, text))
}
