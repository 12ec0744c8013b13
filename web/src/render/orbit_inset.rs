//! The orbit inset of the 3D view: the Earth seen from the orbit normal, the orbit, the
//! satellite, the sun's direction and the Earth's shadow.

use attlab::model::OrbitPicture;
use egui::{Color32, Rect, Stroke};
use nalgebra::Vector3;

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
    let center = area.center() + egui::vec2(0.0, 6.0);
    let scale = area.width() * 0.40 / r as f32;
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
    let beta = 90.0 - orbit.sun_eci.angle(&n).to_degrees();
    let caption = if orbit.eclipse {
        format!("{word} · β {beta:.0}° · {shadow_word}")
    } else {
        format!("{word} · β {beta:.0}°")
    };
    painter.text(
        area.left_top() + egui::vec2(4.0, 3.0),
        egui::Align2::LEFT_TOP,
        caption,
        egui::FontId::proportional(10.0),
        Color32::from_gray(200),
    );
}
