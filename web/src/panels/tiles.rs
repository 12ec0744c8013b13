//! Big numbers for the back row: in presenter mode, the values a lesson step names (the
//! current error, a covariance element) as large tiles above the views.

use super::{series_legend, tr};
use crate::state::AppState;
use attlab::i18n;
use egui::text::{LayoutJob, TextFormat};
use egui::{Color32, FontId, RichText, Ui};

/// The number's size, and its unit's after it (points).
const NUMBER_PT: f32 = 34.0;
const UNIT_PT: f32 = 22.0;

/// The strip of tiles, when presenter mode is on and the lesson step names values.
pub fn tiles(ui: &mut Ui, app: &AppState) {
    let Some(step) = app.lesson_step().filter(|s| !s.tiles.is_empty()) else {
        return;
    };
    if !app.view().presenter {
        return;
    }
    egui::Panel::top("lesson_tiles").show(ui, |ui| {
        ui.horizontal(|ui| {
            // Each tile's share of what the row has left (a short tile leaves the rest more),
            // less the frame's margins and the gap.
            let frame = egui::Frame::group(ui.style());
            let margins = frame.total_margin().sum().x + ui.spacing().item_spacing.x;
            for (i, key) in step.tiles.iter().enumerate() {
                let left = (step.tiles.len() - i) as f32;
                let width = ui.available_width() / left - margins;
                frame.show(ui, |ui| tile(ui, app, &key.name(), width));
            }
        });
    });
}

/// One tile: what the series measures, without its unit, in the tile's `width` (see
/// [`fit_title`]), and the value in large type with the unit after it.
fn tile(ui: &mut Ui, app: &AppState, name: &str, width: f32) {
    let lang = app.view().lang();
    let lab = app.sim().lab().id();
    let spec = app.sim().specs().iter().find(|s| s.name == name);
    let value = app.sim().value(name).ok().filter(|v| v.is_finite());
    ui.vertical(|ui| {
        ui.set_max_width(width);
        let font = egui::TextStyle::Small.resolve(ui.style());
        let fits = |text: &str| {
            let galley =
                (ui.painter()).layout_no_wrap(text.to_string(), font.clone(), Color32::WHITE);
            galley.size().x <= width
        };
        let (title, legend) = spec.map_or_else(
            || (Title::One(name.to_string()), name.to_string()),
            |s| {
                let parts = i18n::series_legend_without_unit(lang, lab, s);
                (fit_title(&parts, fits), series_legend(app, s))
            },
        );
        let text = match title {
            Title::One(line) => line,
            Title::Two(owner, what) => format!("{owner}\n{what}"),
        };
        ui.label(RichText::new(text).small()).on_hover_text(legend);
        let Some(value) = value else {
            ui.label(RichText::new(tr(app, "tile-none")).size(NUMBER_PT).strong());
            return;
        };
        let unit = spec.map_or(String::new(), |s| i18n::unit(lang, s.unit));
        ui.label(number_with_unit(ui, &super::cycle_num(value), &unit));
    });
}

/// A tile's title: one line, or the owner's line above what it measures (which wraps in
/// the tile, so it is never cut).
#[derive(Debug, PartialEq)]
enum Title {
    One(String),
    Two(String, String),
}

/// "owner: what" as `fits` allows: whole on one line when it fits; else on one line with
/// the owner cut short ("Beyond the paper: re-i…: rate correction p_x"), so that what the
/// tile measures stays whole (three tiles of one estimator's p_x, p_y, p_z had all read
/// "Beyond the paper: re-integrate the last int…"); else the owner, cut to fit, on a line
/// above the measure. `fits` must hold for a text if it holds for a longer one (a width).
fn fit_title(parts: &i18n::LegendParts, fits: impl Fn(&str) -> bool) -> Title {
    let whole = parts.joined();
    let Some(owner) = parts.owner.as_deref().filter(|_| !fits(&whole)) else {
        return Title::One(whole);
    };
    let cut_owner = |keep: usize| format!("{}: {}", super::elide(owner, keep + 1), parts.what);
    if fits(&cut_owner(MIN_OWNER_CHARS)) {
        let keep = longest(MIN_OWNER_CHARS, owner.chars().count(), |k| {
            fits(&cut_owner(k))
        });
        return Title::One(cut_owner(keep));
    }
    let line = |keep: usize| format!("{}:", super::elide(owner, keep + 1));
    let keep = longest(0, owner.chars().count(), |k| fits(&line(k)));
    Title::Two(line(keep), parts.what.clone())
}

/// The greatest `k` in `lo..=hi` for which `fits(k)` holds, given that it holds at `lo`
/// (or `lo` if nothing does) and once it fails it fails for every greater `k`.
fn longest(lo: usize, hi: usize, fits: impl Fn(usize) -> bool) -> usize {
    if fits(hi) {
        return hi;
    }
    let (mut lo, mut hi) = (lo, hi);
    while hi - lo > 1 {
        let mid = (lo + hi) / 2;
        if fits(mid) { lo = mid } else { hi = mid }
    }
    lo
}

/// The fewest characters of an owner worth showing before its "…" on the measure's line.
const MIN_OWNER_CHARS: usize = 8;

/// "3.6916 °": the number strong at [`NUMBER_PT`], the unit at [`UNIT_PT`] on its baseline.
fn number_with_unit(ui: &Ui, number: &str, unit: &str) -> LayoutJob {
    let colour = ui.visuals().strong_text_color();
    let family = egui::TextStyle::Body.resolve(ui.style()).family;
    let mut job = LayoutJob::default();
    let format = |size: f32, color: Color32| TextFormat {
        font_id: FontId::new(size, family.clone()),
        color,
        valign: egui::Align::BOTTOM,
        ..Default::default()
    };
    job.append(number, 0.0, format(NUMBER_PT, colour));
    if !unit.is_empty() {
        let weak = ui.visuals().text_color();
        job.append(&format!(" {unit}"), 0.0, format(UNIT_PT, weak));
    }
    job
}

#[cfg(test)]
mod tests {
    use super::*;
    use attlab::i18n::Lang;
    use attlab::labs;

    /// Characters a projector's row of tiles holds at the tiles' small type (853 points
    /// less a lesson's panel: three tiles of 44 characters fit, as on paper 3's step 3).
    const ROW_CHARS: usize = 132;

    /// Every tile of every lesson step names a series the run records, and with its share
    /// of a projector's row its title keeps what the tile measures whole, in each language:
    /// so no tile hides what it measures behind "…".
    #[test]
    fn every_tile_title_keeps_its_measure_whole_in_each_language() {
        let mut cut = Vec::new();
        for lab in labs::all() {
            let lesson = lab.lesson().expect("every lab has a lesson");
            for (i, step) in lesson.steps.iter().enumerate() {
                let budget = ROW_CHARS / step.tiles.len().max(1);
                for lang in Lang::ALL {
                    let link = format!("lesson={}&step={}&lang={}", lab.id(), i + 1, lang.code());
                    let app = AppState::from_fragment(&link);
                    for key in step.tiles {
                        let name = key.name();
                        let spec = app.sim().specs().iter().find(|s| s.name == name);
                        let spec = spec.unwrap_or_else(|| panic!("{link}: no series {name}"));
                        let parts = i18n::series_legend_without_unit(lang, lab.id(), spec);
                        let title = fit_title(&parts, |t| t.chars().count() <= budget);
                        let (first, whole) = match &title {
                            Title::One(line) => (
                                line,
                                line.ends_with(&format!(": {}", parts.what))
                                    || line == &parts.joined(),
                            ),
                            Title::Two(owner, what) => (owner, what == &parts.what),
                        };
                        if !whole || first.chars().count() > budget {
                            cut.push(format!("{link}: {title:?}"));
                        }
                    }
                }
            }
        }
        assert!(cut.is_empty(), "{cut:#?}");
    }

    #[test]
    fn a_long_owner_is_cut_before_the_measure() {
        let parts = |owner: Option<&str>, what: &str| i18n::LegendParts {
            owner: owner.map(str::to_string),
            what: what.to_string(),
        };
        let within = |n: usize| move |t: &str| t.chars().count() <= n;
        let one = |s: &str| Title::One(s.to_string());
        let short = parts(Some("(u, v, z) RK4 integration"), "attitude error");
        let whole = "(u, v, z) RK4 integration: attitude error";
        assert_eq!(fit_title(&short, within(44)), one(whole));
        let long = parts(
            Some("Beyond the paper: re-integrate the last interval"),
            "rate correction p_x",
        );
        let cut = "Beyond the paper: re-i…: rate correction p_x";
        assert_eq!(fit_title(&long, within(44)), one(cut));
        // No room for an owner worth reading beside the measure: two lines.
        let wide = parts(
            Some("Method (9): Gauss–Newton"),
            "tilt error (angle of the vertical)",
        );
        assert_eq!(
            fit_title(&wide, within(20)),
            Title::Two("Method (9): Gauss–…:".into(), wide.what.clone())
        );
        // No owner: the measure alone, whole (it wraps in the tile).
        assert_eq!(fit_title(&parts(None, "period"), within(4)), one("period"));
        assert_eq!(longest(0, 10, |k| k <= 3), 3);
        assert_eq!(longest(0, 10, |_| true), 10);
    }
}
