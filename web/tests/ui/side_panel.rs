//! The side panel on a projector (presenter mode, 1280×720) and on a laptop (1366×768):
//! nothing in it is cut at its right edge, in English and in Russian.

use super::legend::{projector, window};
use attlab::i18n::Lang;
use attlab::labs;
use egui::epaint::Shape;

/// Texts painted across the right edge of the clip they are painted in, when that clip
/// ends at the side panel (the left third of the window).
fn cut_at_the_panels_edge(h: &egui_kittest::Harness<'_, attlab_web::AttLabApp>) -> Vec<String> {
    let window = h.ctx.content_rect();
    (h.output().shapes.iter())
        .filter_map(|c| match &c.shape {
            Shape::Text(t) if c.clip_rect.right() < window.width() / 3.0 => {
                let r = t.visual_bounding_rect();
                (r.right() > c.clip_rect.right() + 0.5 && r.left() < c.clip_rect.right())
                    .then(|| format!("{:?} in {:?}: {}", r, c.clip_rect, t.galley.text()))
            }
            _ => None,
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
                let cut = cut_at_the_panels_edge(&h).into_iter();
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
