//! The values a lesson step names (the current error, a covariance element) as tiles above
//! the views, on every screen: large for the back row in presenter mode, smaller on a
//! laptop and a phone (a step's text points at them, so every reader must have them).

use super::{series_legend, tr};
use crate::state::AppState;
use attlab::i18n;
use egui::text::{LayoutJob, TextFormat};
use egui::{Color32, FontId, RichText, Ui};

/// The number's size (points) in presenter mode, for the back row.
const NUMBER_PT: f32 = 34.0;
/// The number's size elsewhere: a laptop's or a phone's reader sits at the screen.
const NUMBER_NEAR_PT: f32 = 20.0;
/// The unit's size after the number, as a share of the number's, on its baseline.
const UNIT_SHARE: f32 = 0.65;

/// The strip of tiles, when a lesson step names values.
pub fn tiles(ui: &mut Ui, app: &AppState) {
    let Some(step) = app.lesson_step().filter(|s| !s.tiles.is_empty()) else {
        return;
    };
    let size = if app.view().presenter {
        NUMBER_PT
    } else {
        NUMBER_NEAR_PT
    };
    egui::Panel::top("lesson_tiles").show(ui, |ui| {
        ui.horizontal(|ui| {
            // Each tile's share of what the row has left (a short tile leaves the rest more),
            // less the frame's margins and the gap.
            let frame = egui::Frame::group(ui.style());
            let margins = frame.total_margin().sum().x + ui.spacing().item_spacing.x;
            for (i, key) in step.tiles.iter().enumerate() {
                let left = (step.tiles.len() - i) as f32;
                // Never negative: a number wider than its share leaves the rest nothing.
                let width = (ui.available_width() / left - margins).max(0.0);
                frame.show(ui, |ui| tile(ui, app, &key.name(), (width, size)));
            }
        });
    });
}

/// One tile: what the series measures, without its unit, in the tile's `width` (see
/// [`fit_title`]), and the value in large type with the unit after it.
fn tile(ui: &mut Ui, app: &AppState, name: &str, (width, size): (f32, f32)) {
    let lang = app.view().lang();
    let lab = app.shown().lab().id();
    let spec = app.shown().specs().iter().find(|s| s.name == name);
    let value = app.shown().value(name).ok().filter(|v| v.is_finite());
    ui.vertical(|ui| {
        ui.set_max_width(width);
        // The width the label wraps at, as the layout rounded it.
        let width = ui.available_width();
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
            ui.label(RichText::new(tr(app, "tile-none")).size(size).strong());
            return;
        };
        let unit = spec.map_or(String::new(), |s| i18n::unit(lang, s.unit));
        ui.label(number_with_unit(
            ui,
            &super::cycle_num(lang, value),
            &unit,
            size,
        ));
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
/// the owner cut a little ("Quaternion RK4 integr…: attitude error (whole angle)"), keeping
/// at least [`MIN_OWNER_SHARE`] of it; else the owner, cut to fit, on a line above the
/// measure. So what the tile measures stays whole, and tiles of owners that share their
/// first words still differ (cut at 44 characters, paper 5's three tiles had all read
/// "Beyond the paper: re-integrate the last int…", and in Russian paper 3's two
/// integrations would have read "Интегриров…"). `fits` must hold for a text if it holds for
/// a longer one (a width).
fn fit_title(parts: &i18n::LegendParts, fits: impl Fn(&str) -> bool) -> Title {
    let whole = parts.joined();
    let Some(owner) = parts.owner.as_deref().filter(|_| !fits(&whole)) else {
        return Title::One(whole);
    };
    let n = owner.chars().count();
    let least = (n * MIN_OWNER_SHARE.0).div_ceil(MIN_OWNER_SHARE.1);
    let cut_owner = |keep: usize| format!("{}: {}", super::elide(owner, keep + 1), parts.what);
    if least < n && fits(&cut_owner(least)) {
        let keep = longest(least, n, |k| fits(&cut_owner(k)));
        return Title::One(cut_owner(keep));
    }
    let line = |keep: usize| format!("{}:", super::elide(owner, keep + 1));
    let keep = longest(0, n, |k| fits(&line(k)));
    Title::Two(line(keep), parts.what.clone())
}

/// The share of an owner's characters (numerator, denominator) a title keeps on the
/// measure's line; a shorter cut goes on a line of its own.
const MIN_OWNER_SHARE: (usize, usize) = (2, 3);

/// The greatest `k` in `lo..=hi` for which `fits(k)` holds, given that it holds at `lo`
/// (or `lo` if nothing does) and once it fails it fails for every greater `k`.
fn longest(lo: usize, hi: usize, fits: impl Fn(usize) -> bool) -> usize {
    if hi <= lo || fits(hi) {
        return hi.max(lo);
    }
    let (mut lo, mut hi) = (lo, hi);
    while hi - lo > 1 {
        let mid = (lo + hi) / 2;
        if fits(mid) { lo = mid } else { hi = mid }
    }
    lo
}

/// "3.6916 °": the number strong at `size`, the unit at [`UNIT_SHARE`] of it on its
/// baseline; a degree alone at the number's size, so its ring stands at the digits' top as
/// in print (smaller, on the baseline, it sat at a lowercase letter's height).
fn number_with_unit(ui: &Ui, number: &str, unit: &str, size: f32) -> LayoutJob {
    let colour = ui.visuals().strong_text_color();
    let family = egui::TextStyle::Body.resolve(ui.style()).family;
    let mut job = LayoutJob::default();
    let format = |size: f32, color: Color32| TextFormat {
        font_id: FontId::new(size, family.clone()),
        color,
        valign: egui::Align::BOTTOM,
        ..Default::default()
    };
    job.append(number, 0.0, format(size, colour));
    if !unit.is_empty() {
        let weak = ui.visuals().text_color();
        let unit_size = if unit == "°" {
            size
        } else {
            UNIT_SHARE * size
        };
        job.append(&format!(" {unit}"), 0.0, format(unit_size, weak));
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

    /// Every tile of every lesson step names a series the run records; with its share of a
    /// projector's row, each title's lines fit (the measure on a line of its own included)
    /// and no two tiles of a step read alike, in each language. Cut at 44 characters, paper
    /// 5's step 7 had shown three tiles all reading "Beyond the paper: re-integrate the last
    /// int…", and paper 1's two filters had lost "less the integrated φ_int".
    #[test]
    fn every_tiles_title_fits_its_share_and_tells_the_tiles_apart() {
        let mut problems = Vec::new();
        for lab in labs::all() {
            let lesson = lab.lesson().expect("every lab has a lesson");
            for (i, step) in lesson.steps.iter().enumerate() {
                let budget = ROW_CHARS / step.tiles.len().max(1);
                let fits = |t: &str| t.chars().count() <= budget;
                for lang in Lang::ALL {
                    let link = format!("lesson={}&step={}&lang={}", lab.id(), i + 1, lang.code());
                    let app = AppState::from_fragment(&link);
                    let mut titles = Vec::new();
                    for key in step.tiles {
                        let name = key.name();
                        let spec = app.shown().specs().iter().find(|s| s.name == name);
                        let spec = spec.unwrap_or_else(|| panic!("{link}: no series {name}"));
                        let parts = i18n::series_legend_without_unit(lang, lab.id(), spec);
                        let title = fit_title(&parts, fits);
                        let lines_fit = match &title {
                            Title::One(line) => fits(line),
                            Title::Two(owner, what) => fits(owner) && fits(what),
                        };
                        if !lines_fit || titles.contains(&title) {
                            problems.push(format!("{link}: {title:?}"));
                        }
                        titles.push(title);
                    }
                }
            }
        }
        assert!(problems.is_empty(), "{problems:#?}");
    }

    #[test]
    fn a_long_owner_is_cut_before_the_measure() {
        let one = |s: &str| Title::One(s.to_string());
        let two = |owner: &str, what: &str| Title::Two(owner.to_string(), what.to_string());
        // (owner, measure, characters that fit, the title).
        let cases = [
            // Whole when it fits.
            (
                Some("(u, v, z) RK4 integration"),
                "attitude error",
                44,
                one("(u, v, z) RK4 integration: attitude error"),
            ),
            // Cut a little, the owner keeps two thirds or more on the measure's line.
            (
                Some("Quaternion RK4 integration"),
                "attitude error (whole angle)",
                52,
                one("Quaternion RK4 integr…: attitude error (whole angle)"),
            ),
            // Cut to under two thirds, the owner goes on a line of its own.
            (
                Some("Beyond the paper: re-integrate the last interval"),
                "rate correction p_x",
                44,
                two(
                    "Beyond the paper: re-integrate the last in…:",
                    "rate correction p_x",
                ),
            ),
            (
                Some("Method (9): Gauss–Newton"),
                "tilt error (angle of the vertical)",
                20,
                two("Method (9): Gauss–…:", "tilt error (angle of the vertical)"),
            ),
            // No owner: the measure alone, whole (it wraps in the tile).
            (None, "period", 4, one("period")),
        ];
        for (owner, what, n, title) in cases {
            let parts = i18n::LegendParts {
                owner: owner.map(str::to_string),
                what: what.to_string(),
            };
            let fits = |t: &str| t.chars().count() <= n;
            assert_eq!(fit_title(&parts, fits), title, "{owner:?} {what} in {n}");
        }
        assert_eq!(longest(0, 10, |k| k <= 3), 3);
        assert_eq!(longest(0, 10, |_| true), 10);
        assert_eq!(longest(8, 5, |_| false), 8);
    }
}
