//! The orbit inset of the 3D view: the Earth seen from the orbit normal, the orbit, the
//! satellite, the sun's direction and the Earth's shadow.

use attlab::model::OrbitPicture;
use egui::{Color32, Rect, Stroke};
use nalgebra::Vector3;

/// The inset's smallest side (points): below it the picture says nothing and is left out.
const MIN_SIDE: f32 = 48.0;

/// The inset's distance from the view's edges (points).
const MARGIN: f32 = 6.0;

/// The width the inset takes from a 3D view `view`, its margin included: the view's words
/// on top wrap to the rest, so they leave its column free.
pub(super) fn column(view: Rect) -> f32 {
    side(view) + MARGIN
}

/// The inset's side in `view` before it is fitted between the words: a third of the view's
/// short side, at least 84 points (readable on a projector's small 3D view), at most 45 %.
fn side(view: Rect) -> f32 {
    let short = view.width().min(view.height());
    (short * 0.34).max(84.0).min(short * 0.45)
}

/// Whether the inset, placed below `captions` and above `hint`, has its full size.
pub(super) fn keeps_its_size(view: Rect, captions: &[Rect], hint: Rect) -> bool {
    area(view, captions, hint).is_some_and(|a| a.width() >= side(view) - 0.5)
}

/// Where the inset goes in a 3D view `view` whose caption lines take `captions` (on top)
/// and whose hint takes `hint` (at the bottom): bottom right, [`side`] large, above the
/// hint and below any caption line that reaches into its column, shrunk to fit between
/// them; `None` when less than [`MIN_SIDE`] is left. So it never hides a word of the view.
pub(super) fn area(view: Rect, captions: &[Rect], hint: Rect) -> Option<Rect> {
    const GAP: f32 = 4.0;
    let side = side(view);
    let left = view.right() - MARGIN - side;
    let bottom = if hint.right() > left && hint.height() > 0.0 {
        hint.top() - GAP
    } else {
        view.bottom() - MARGIN
    };
    let top = captions
        .iter()
        .filter(|c| c.right() > left)
        .map(|c| c.bottom() + GAP)
        .fold(view.top() + MARGIN, f32::max);
    let side = side.min(bottom - top);
    (side >= MIN_SIDE).then(|| {
        Rect::from_min_size(
            egui::pos2(view.right() - MARGIN - side, bottom - side),
            egui::vec2(side, side),
        )
    })
}

/// The Earth seen from the orbit normal: the orbit, the satellite, the sun to the right and
/// the shadow cylinder behind the Earth (the satellite turns red inside it).
pub(super) fn orbit_picture(
    painter: &egui::Painter,
    area: Rect,
    orbit: &OrbitPicture,
    (word, shadow_word): &(String, String),
) {
    painter.rect_filled(area, 4.0, Color32::from_rgba_unmultiplied(8, 10, 18, 220));
    let n = orbit.normal_eci;
    let sun_in_plane = orbit.sun_eci - n * orbit.sun_eci.dot(&n);
    let ea = sun_in_plane.try_normalize(1e-9).unwrap_or_else(|| {
        n.cross(&Vector3::x())
            .try_normalize(1e-9)
            .unwrap_or_else(Vector3::y)
    });
    let eb = n.cross(&ea);
    let r = orbit.position_eci_m.norm().max(orbit.earth_radius_m);
    // The caption on top, wrapped inside the inset (a small view's inset is narrower than
    // "orbit · β -24° · shadow"); the picture takes the square band below it.
    let beta = 90.0 - orbit.sun_eci.angle(&n).to_degrees();
    let caption = if orbit.eclipse {
        format!("{word} · β {beta:.0}° · {shadow_word}")
    } else {
        format!("{word} · β {beta:.0}°")
    };
    let caption = painter.layout(
        caption,
        egui::FontId::proportional(10.0),
        Color32::from_gray(200),
        (area.width() - 8.0).max(20.0),
    );
    let band = Rect::from_min_max(
        area.left_top() + egui::vec2(0.0, 3.0 + caption.size().y),
        area.right_bottom(),
    );
    let center = band.center();
    let scale = band.width().min(band.height()).max(1.0) * 0.40 / r as f32;
    let at = |x: f64, y: f64| center + egui::vec2(x as f32 * scale, -(y as f32) * scale);
    let re = orbit.earth_radius_m;
    // The shadow: the cylinder of the Earth's radius away from the sun.
    let far = r * 1.25;
    let shadow = vec![at(0.0, re), at(-far, re), at(-far, -re), at(0.0, -re)];
    painter.add(egui::Shape::convex_polygon(
        shadow,
        Color32::from_rgba_unmultiplied(0, 0, 0, 170),
        Stroke::NONE,
    ));
    painter.circle_filled(center, re as f32 * scale, Color32::from_rgb(40, 90, 170));
    painter.circle_stroke(
        center,
        r as f32 * scale,
        Stroke::new(1.0, Color32::from_gray(150)),
    );
    let p = orbit.position_eci_m;
    let sat = at(p.dot(&ea), p.dot(&eb));
    let sat_color = if orbit.eclipse {
        Color32::from_rgb(230, 70, 70)
    } else {
        Color32::from_rgb(255, 230, 120)
    };
    painter.circle_filled(sat, 4.0, sat_color);
    let tip = at(far, 0.0);
    painter.arrow(
        at(r * 1.02, 0.0),
        tip - at(r * 1.02, 0.0),
        Stroke::new(1.5, Color32::from_rgb(255, 210, 60)),
    );
    painter.galley(
        area.left_top() + egui::vec2(4.0, 3.0),
        caption,
        Color32::from_gray(200),
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rect(x0: f32, y0: f32, x1: f32, y1: f32) -> Rect {
        Rect::from_min_max(egui::pos2(x0, y0), egui::pos2(x1, y1))
    }

    /// The projector's 3D view (375 × 195): a long ghost caption over the whole width and a
    /// two-line hint; the inset sits between them, at its least size of 84 px.
    #[test]
    fn the_inset_sits_between_the_captions_and_the_hint() {
        let view = rect(0.0, 0.0, 375.0, 195.0);
        let captions = [rect(8.0, 6.0, 90.0, 24.0), rect(8.0, 24.0, 340.0, 60.0)];
        let hint = rect(8.0, 155.0, 330.0, 189.0);
        let area = area(view, &captions, hint).expect("room for the inset");
        assert!((area.width() - 84.0).abs() < 1e-3, "{area:?}");
        assert!(area.bottom() <= hint.top() && area.top() >= captions[1].bottom());
        assert!(area.right() <= view.right() && area.left() >= view.left());
    }

    /// A caption line that stops short of the inset's column does not push it down, and a
    /// hint that stops short of it lets it go down to the bottom margin.
    #[test]
    fn text_outside_its_column_does_not_move_it() {
        let view = rect(0.0, 0.0, 600.0, 400.0);
        let captions = [rect(8.0, 6.0, 200.0, 300.0)];
        let hint = rect(8.0, 370.0, 200.0, 394.0);
        let area = area(view, &captions, hint).expect("room for the inset");
        assert_eq!(area.bottom(), 394.0);
        assert!(
            (area.width() - 136.0).abs() < 1e-3,
            "a third of 400: {area:?}"
        );
    }

    /// A phone's short 3D view with a three-line caption: what is left between the texts
    /// is less than the least side, so no inset.
    #[test]
    fn no_inset_where_the_words_leave_no_room() {
        let view = rect(0.0, 0.0, 370.0, 120.0);
        let captions = [rect(8.0, 6.0, 360.0, 60.0)];
        let hint = rect(8.0, 84.0, 360.0, 114.0);
        assert_eq!(area(view, &captions, hint), None);
        let shrunk = area(view, &captions[..0], hint).expect("room without captions");
        assert!(
            shrunk.width() < 84.0 && shrunk.width() >= MIN_SIDE,
            "{shrunk:?}"
        );
    }
}
