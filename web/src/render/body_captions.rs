//! The 3D view's words: what is solid and what is the ghost on top, how to move the camera
//! at the bottom, fitted around the orbit inset and, in a short view, a line each.

use super::scene::{Scene, png_button_rect};
use egui::Rect;

/// What is solid and what is the ghost (on top), and how to move the camera (at the
/// bottom); returns where the top lines were drawn and what the orbit inset must stay
/// above (the hint, and the view's PNG button in the same corner).
pub(super) fn captions(
    painter: &egui::Painter,
    rect: Rect,
    scene: &Scene<'_>,
) -> (Vec<Rect>, Rect) {
    let font = egui::FontId::proportional(13.0);
    let colours = super::palette::of_ctx(painter.ctx());
    // Each wrapped inside the view, so a long estimator label shows whole on a narrow view;
    // each on its own line, so it cannot run into the truth's. They take the whole width
    // where the orbit inset below them keeps its full size, else they wrap left of its
    // column. The hint at the bottom takes the whole width, under the inset.
    let wrap = (rect.width() - 16.0).max(40.0);
    let lay = |width: f32| -> (Vec<_>, Vec<Rect>) {
        let mut y = rect.top() + 6.0;
        (scene.captions.0.iter())
            .map(|text| {
                let galley = painter.layout(text.clone(), font.clone(), colours.ink, width);
                let at = egui::pos2(rect.left() + 8.0, y);
                y += galley.size().y;
                let laid = Rect::from_min_size(at, galley.size());
                (galley, laid)
            })
            .unzip()
    };
    let hint = painter.layout(
        scene.captions.1.clone(),
        egui::FontId::proportional(12.0),
        colours.ink_dim,
        wrap,
    );
    let at = rect.left_bottom() + egui::vec2(8.0, -6.0 - hint.size().y);
    let below = Rect::from_min_size(at, hint.size()).union(png_button_rect(rect));
    painter.galley(at, hint, colours.ink_dim);
    let (mut galleys, mut top) = lay(wrap);
    let mut width = wrap;
    if scene.orbit.is_some() && !super::orbit_inset::keeps_its_size(rect, &top, below) {
        width = wrap - super::orbit_inset::column(rect);
        (galleys, top) = lay(width);
    }
    // Wrapped, they would take more than a third of a short view (a projector's top row in
    // presenter mode, where the body was left 60 points): a line each, cut with "…".
    let taken: f32 = top.iter().map(Rect::height).sum();
    if taken > rect.height() / 3.0 {
        let mut y = rect.top() + 6.0;
        (galleys, top) = (scene.captions.0.iter())
            .map(|text| {
                let galley = super::one_line(painter, text, font.clone(), colours.ink, width);
                let laid = Rect::from_min_size(egui::pos2(rect.left() + 8.0, y), galley.size());
                y += galley.size().y;
                (galley, laid)
            })
            .unzip();
    }
    for (galley, laid) in galleys.into_iter().zip(&top) {
        painter.galley(laid.min, galley, colours.ink);
    }
    (top, below)
}
