//! The side panel on a projector (presenter mode, 1280×720) and on a laptop (1366×768):
//! nothing in it is cut at its right edge, in English and in Russian.

use super::legend::{projector, window};
use attlab::i18n::Lang;
use attlab::labs;
use egui::epaint::Shape;

/// Texts painted across the right edge of the side panel (the clip the lab picker's label
/// "Lab" is painted in); fails when that label, or the panel's other texts, are not
/// found, so the check cannot pass on nothing.
fn cut_at_the_panels_edge(
    h: &egui_kittest::Harness<'_, attlab_web::AttLabApp>,
    case: &str,
) -> Vec<String> {
    let texts: Vec<_> = (h.output().shapes.iter())
        .filter_map(|c| match &c.shape {
            Shape::Text(t) => Some((c.clip_rect, t)),
            _ => None,
        })
        .collect();
    let lab = attlab::i18n::t(h.state().state.view().lang(), "lab");
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
    (in_panel.into_iter())
        .filter_map(|(clip, t)| {
            let r = t.visual_bounding_rect();
            (r.right() > clip.right() + 0.5 && r.left() < clip.right())
                .then(|| format!("{r:?} in {clip:?}: {}", t.galley.text()))
        })
        .collect()
}

/// Each lab in both languages: the projector's narrow presenter panel (where the lab
/// picker's label once wrapped letter by letter past the edge and widened every line below
/// it), and a laptop's panel.
#[test]
fn nothing_in_the_side_panel_is_cut_at_its_edge() {
    let mut wrong = Vec::new();
    for lab in labs::all() {
        for lang in Lang::ALL {
            let presenter = format!("lab={}&presenter=1&lang={}", lab.id(), lang.code());
            let laptop = format!("lab={}&lang={}", lab.id(), lang.code());
            for (fragment, h) in [
                (&presenter, projector(&presenter, 5)),
                (
                    &laptop,
                    window(&laptop, 5, (egui::vec2(1366.0, 768.0), 1.0)),
                ),
            ] {
                let cut = cut_at_the_panels_edge(&h, fragment).into_iter();
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
