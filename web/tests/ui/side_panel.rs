//! The side panel on a projector (presenter mode, 1280 pixels wide at its zoom) and on a
//! laptop (1366 wide), and the controls' sheet on a phone (390 wide): nothing in them is
//! cut at their right edge, in English and in Russian, with every parameter shown.

use super::legend::{PRESENTER_ZOOM, window};
use attlab::i18n::Lang;
use attlab::labs;
use attlab_web::state::ViewCommand;
use egui::epaint::Shape;
use egui_kittest::kittest::Queryable;

/// Texts painted across the right edge of the panel (the clip the catalogue's text
/// `anchor` is painted in: the lab picker's label "Lab" in a side panel, "Parameters" in
/// the phone's sheet), and the lab's parameters not painted in it; fails when that text,
/// or the panel's other texts, are not found, so the check cannot pass on nothing.
fn cut_at_the_panels_edge(
    h: &egui_kittest::Harness<'_, attlab_web::AttLabApp>,
    case: &str,
    anchor: &str,
) -> Vec<String> {
    let texts: Vec<_> = (h.output().shapes.iter())
        .filter_map(|c| match &c.shape {
            Shape::Text(t) => Some((c.clip_rect, t)),
            _ => None,
        })
        .collect();
    let lab = attlab::i18n::t(h.state().state.view().lang(), anchor);
    let panel = texts.iter().find(|(_, t)| t.galley.text() == lab);
    let panel = panel
        .unwrap_or_else(|| panic!("{case}: no “{lab}” label"))
        .0;
    let in_panel: Vec<_> = (texts.into_iter())
        .filter(|(clip, _)| clip.left() == panel.left() && clip.right() == panel.right())
        .collect();
    assert!(
        in_panel.len() >= 10,
        "{case}: {} texts in the panel",
        in_panel.len()
    );
    let missing = parameter_labels(h)
        .into_iter()
        .filter(|label| !in_panel.iter().any(|(_, t)| t.galley.text() == label))
        .map(|label| format!("not painted: {label}"))
        .collect::<Vec<_>>();
    (in_panel.into_iter())
        .filter_map(|(clip, t)| {
            let r = t.visual_bounding_rect();
            (r.right() > clip.right() + 0.5 && r.left() < clip.right())
                .then(|| format!("{r:?} in {clip:?}: {}", t.galley.text()))
        })
        .chain(missing)
        .collect()
}

/// The labels of the lab's parameters in the page's language (every one is in the panel),
/// and outside presenter mode those of its log's units (in its laboratory mode).
fn parameter_labels(h: &egui_kittest::Harness<'_, attlab_web::AttLabApp>) -> Vec<String> {
    let state = &h.state().state;
    let (lang, lab) = (state.view().lang(), state.sim().lab());
    let units = (lab.page().log_format)
        .filter(|_| !state.view().presenter)
        .map_or(&[][..], |f| f.units);
    (lab.params().iter().chain(units))
        .map(|spec| {
            let id = attlab::i18n::param_label_id(lab.id(), spec.key);
            attlab::i18n::lab_text(lang, &id, spec.label)
        })
        .collect()
}

/// The page `pixels` wide at `zoom`, tall enough that the whole panel is painted (egui
/// paints no widget outside the scrolled view), with the phone's controls' sheet open
/// where `sheet`, and the sections that start closed opened: "All parameters" (presenter
/// mode) and the laboratory mode of a lab that reads logs. The value boxes take their
/// width from the frames before, so a box wider than its first guess settles in two.
fn whole_panel(
    fragment: &str,
    (pixels, zoom): (f32, f32),
    sheet: bool,
) -> egui_kittest::Harness<'static, attlab_web::AttLabApp> {
    // The phone's sheet stands at the least of its sizes here, a fifth of the window.
    let height = if sheet { 30_000.0 } else { 6000.0 };
    let mut h = window(fragment, 5, (egui::vec2(pixels, height), zoom));
    if sheet {
        h.state_mut().apply(ViewCommand::SetSheet(true).into());
        h.run_steps(2);
    }
    let (lang, lab) = (h.state().state.view().lang(), h.state().state.sim().lab());
    let mut closed = vec![attlab::i18n::t(lang, "all-parameters")];
    if let Some(format) = lab.page().log_format {
        let id = attlab::i18n::log_format_id(lab.id(), "title");
        closed.push(attlab::i18n::lab_text(lang, &id, format.title));
    }
    for title in closed {
        if h.query_by_label(&title).is_some() {
            h.get_by_label(&title).click();
            h.run_steps(3);
        }
    }
    h
}

/// Each lab in both languages, with every parameter shown: the projector's narrow
/// presenter panel (where the lab picker's label once wrapped letter by letter past the
/// edge and widened every line below it; every slider's label ran past it too), a
/// laptop's panel, and a phone's sheet.
#[test]
fn nothing_in_the_side_panel_is_cut_at_its_edge() {
    let mut wrong = Vec::new();
    for lab in labs::all() {
        for lang in Lang::ALL {
            let presenter = format!("lab={}&presenter=1&lang={}", lab.id(), lang.code());
            let laptop = format!("lab={}&lang={}", lab.id(), lang.code());
            for (fragment, h, anchor) in [
                (
                    &presenter,
                    whole_panel(&presenter, (1280.0, PRESENTER_ZOOM), false),
                    "lab",
                ),
                (&laptop, whole_panel(&laptop, (1366.0, 1.0), false), "lab"),
                (
                    &format!("{laptop} (phone)"),
                    whole_panel(&laptop, (390.0, 1.0), true),
                    "parameters",
                ),
            ] {
                let cut = cut_at_the_panels_edge(&h, fragment, anchor).into_iter();
                wrong.extend(cut.map(|t| format!("{fragment}: {t}")));
            }
        }
    }
    assert!(
        wrong.is_empty(),
        "cut at the panel's edge:\n{}",
        wrong.join("\n")
    );
}

/// Presets stand in rows with the panel's usual spacing between them: in presenter mode
/// one under another, and on a laptop in English and in Russian. In rows wrapped across
/// the panel, a preset whose name took two lines had left a gap as tall as itself under
/// the next row.
#[test]
fn presets_stand_without_gaps_between_their_rows() {
    for lab in labs::all() {
        for (fragment, size, presenter) in [
            (
                format!("lab={}&presenter=1", lab.id()),
                (1280.0, PRESENTER_ZOOM),
                true,
            ),
            (format!("lab={}", lab.id()), (1366.0, 1.0), false),
            (format!("lab={}&lang=ru", lab.id()), (1366.0, 1.0), false),
        ] {
            let h = whole_panel(&fragment, size, false);
            let lang = h.state().state.view().lang();
            let spacing = h.ctx.global_style().spacing.item_spacing.y;
            let mut rects: Vec<egui::Rect> = (lab.presets().iter())
                .map(|p| {
                    let id = attlab::i18n::preset_id(lab.id(), p.id);
                    let name = attlab::i18n::lab_text(lang, &id, p.name);
                    h.get_by_label(&name).rect()
                })
                .collect();
            rects.sort_by(|a, b| a.top().total_cmp(&b.top()));
            for pair in rects.windows(2) {
                let gap = pair[1].top() - pair[0].bottom();
                // Two presets side by side in one row overlap in height.
                let same_row = !presenter && pair[1].top() < pair[0].bottom();
                assert!(
                    same_row || (0.0..=spacing + 0.5).contains(&gap),
                    "{fragment}: {gap} points between {:?} and {:?}",
                    pair[0],
                    pair[1]
                );
            }
        }
    }
}
