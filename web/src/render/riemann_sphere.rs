//! The Riemann-sphere view (paper 3, Figs. 3 and 6): the reference vertical seen from the
//! body, k = (a′, b′, c′), on the unit sphere; the projection ray from the pole
//! S = (0, 0, −1) through k to the body's ξ′η′ plane, where it lands at w = u + jv; and the
//! complex plane with the w trajectories beside it.

use attlab::i18n::Lang;
use egui::{Align2, Color32, FontId, Painter, Pos2, Rect, Sense, Stroke, Ui, Vec2};
use egui_plot::{Legend, Line, Plot, PlotPoints, Points};
use nalgebra::{Rotation3, Vector3};

/// One trajectory: recent vertical directions in body axes and the matching w, oldest first.
pub struct SphereTrack {
    /// Legend name.
    pub name: String,
    /// Colour.
    pub color: Color32,
    /// Line pattern (the source's everywhere).
    pub pattern: egui_plot::LineStyle,
    /// k in body axes (unit vectors).
    pub k_body: Vec<Vector3<f64>>,
    /// (u, v) points for the complex plane (non-finite where w is at infinity).
    pub w: Vec<[f64; 2]>,
    /// A 3σ covariance ellipse around the current point.
    pub ellipse: Option<Ellipse>,
}

/// A closed ring of points, on the w plane and on the sphere.
pub type Ellipse = (Vec<[f64; 2]>, Vec<Vector3<f64>>);

/// Orientation of the sphere drawing (drag to turn).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SphereView {
    /// Turn about the vertical axis (rad).
    pub yaw_rad: f64,
    /// Tilt towards the viewer (rad).
    pub pitch_rad: f64,
}

impl Default for SphereView {
    fn default() -> Self {
        Self {
            yaw_rad: 0.6,
            pitch_rad: 0.35,
        }
    }
}

struct Projector {
    rot: Rotation3<f64>,
    center: Pos2,
    radius: f32,
}

impl Projector {
    /// Screen position and whether the point is on the viewer's side.
    fn project(&self, p: &Vector3<f64>) -> (Pos2, bool) {
        let q = self.rot * p;
        (
            self.center + Vec2::new(q.x as f32, -q.z as f32) * self.radius,
            q.y <= 0.0,
        )
    }

    /// Draws the points as lines, in `front` where both ends of a segment face the reader and
    /// in `back` elsewhere: one path per run of one kind (not a shape per segment), thinned
    /// to half a pixel ([`super::clip::thin_to_pixels`]'s rule), the last point always kept.
    fn polyline(
        &self,
        painter: &Painter,
        pts: impl Iterator<Item = Vector3<f64>>,
        front: Stroke,
        back: Stroke,
    ) {
        let close = |a: Pos2, b: Pos2| {
            super::clip::within_half_pixel(
                [a.x, a.y].map(f64::from),
                [b.x, b.y].map(f64::from),
                [1.0; 2],
            )
        };
        let draw = |run: &mut Vec<Pos2>, in_front: bool| {
            if run.len() >= 2 {
                let stroke = if in_front { front } else { back };
                painter.add(egui::Shape::line(std::mem::take(run), stroke));
            }
            run.clear();
        };
        let (mut run, mut run_front) = (Vec::new(), true);
        let (mut prev_front, mut skipped) = (None, None);
        for p in pts {
            let (q, q_front) = self.project(&p);
            if let Some(was_front) = prev_front {
                let segment_front = was_front && q_front;
                if run.len() >= 2 && segment_front != run_front {
                    // The run ends, and the next begins, at the previous point exactly.
                    run.extend(skipped.take());
                    let start = run.last().copied();
                    draw(&mut run, run_front);
                    run.extend(start);
                }
                run_front = segment_front;
            }
            match run.last() {
                Some(&last) if close(last, q) => skipped = Some(q),
                _ => {
                    run.push(q);
                    skipped = None;
                }
            }
            prev_front = Some(q_front);
        }
        run.extend(skipped);
        draw(&mut run, run_front);
    }
}

fn circle_points(f: impl Fn(f64) -> Vector3<f64>) -> impl Iterator<Item = Vector3<f64>> {
    (0..=72).map(move |i| f(f64::from(i) * 5f64.to_radians()))
}

fn draw_grid(pr: &Projector, painter: &Painter, pole: &str) {
    let colours = super::palette::of_ctx(painter.ctx());
    let front = Stroke::new(0.8, colours.grid_front);
    let back = Stroke::new(0.6, colours.grid_back);
    for lat_deg in [-60.0f64, -30.0, 30.0, 60.0] {
        let (s, c) = lat_deg.to_radians().sin_cos();
        pr.polyline(
            painter,
            circle_points(|a| Vector3::new(c * a.cos(), c * a.sin(), s)),
            front,
            back,
        );
    }
    for lon_deg in [0.0f64, 30.0, 60.0, 90.0, 120.0, 150.0] {
        let (s, c) = lon_deg.to_radians().sin_cos();
        pr.polyline(
            painter,
            circle_points(|a| Vector3::new(c * a.cos(), s * a.cos(), a.sin())),
            front,
            back,
        );
    }
    // The complex plane ζ′ = 0 cuts the sphere in |w| = 1 (pitch ±90° in paper 3).
    let eq_front = Stroke::new(1.8, colours.equator[0]);
    let eq_back = Stroke::new(1.0, colours.equator[1]);
    pr.polyline(
        painter,
        circle_points(|a| Vector3::new(a.cos(), a.sin(), 0.0)),
        eq_front,
        eq_back,
    );
    let axis = Stroke::new(1.0, colours.ink_dim);
    for (dir, label) in [
        (Vector3::x(), "ξ′ → u"),
        (Vector3::y(), "η′ → v"),
        (Vector3::z(), "ζ′"),
    ] {
        let (a, _) = pr.project(&(-dir * 1.45));
        let (b, _) = pr.project(&(dir * 1.45));
        painter.line_segment([a, b], axis);
        painter.text(
            b,
            Align2::LEFT_CENTER,
            label,
            FontId::proportional(12.0),
            colours.ink,
        );
    }
    let (s, _) = pr.project(&Vector3::new(0.0, 0.0, -1.0));
    painter.circle_filled(s, 4.0, colours.highlight);
    painter.text(
        s + Vec2::new(6.0, 2.0),
        Align2::LEFT_TOP,
        pole,
        FontId::proportional(12.0),
        colours.highlight,
    );
}

fn draw_track(pr: &Projector, painter: &Painter, track: &SphereTrack) {
    let faint = track.color.gamma_multiply(0.35);
    pr.polyline(
        painter,
        track.k_body.iter().copied(),
        Stroke::new(1.6, track.color),
        Stroke::new(1.0, faint),
    );
    let Some(k) = track.k_body.last() else { return };
    if let Some((_, ring)) = &track.ellipse {
        let closed = ring.iter().chain(ring.first()).copied();
        pr.polyline(
            painter,
            closed,
            Stroke::new(1.5, track.color),
            Stroke::new(1.0, faint),
        );
    }
    let (p, front) = pr.project(k);
    painter.circle_filled(p, if front { 5.0 } else { 3.5 }, track.color);
    // Projection ray from S through k to the plane ζ′ = 0, where it meets w = u + jv.
    let south = Vector3::new(0.0, 0.0, -1.0);
    if 1.0 + k.z > 0.2 {
        let w = Vector3::new(k.x / (1.0 + k.z), k.y / (1.0 + k.z), 0.0);
        let end = if w.norm() > 2.5 {
            w * (2.5 / w.norm())
        } else {
            w
        };
        let (a, _) = pr.project(&south);
        let (b, _) = pr.project(&end);
        painter.line_segment([a, b], Stroke::new(1.0, track.color.gamma_multiply(0.8)));
        painter.circle_stroke(b, 4.0, Stroke::new(1.5, track.color));
    }
}

/// The least height the sphere keeps between its view's title and caption (points): a
/// radius of 32 with room for its axis labels.
const MIN_SPHERE_BAND_PT: f32 = 80.0;

/// Draws the sphere in `rect`; drag turns it.
pub fn show_sphere(
    ui: &mut Ui,
    rect: Rect,
    view: &mut SphereView,
    tracks: &[SphereTrack],
    (title, caption, pole): (&str, &str, &str),
) {
    let response = ui.allocate_rect(rect, Sense::click_and_drag());
    if response.double_clicked() {
        *view = SphereView::default();
    }
    if response.dragged() {
        let d = response.drag_delta();
        view.yaw_rad += f64::from(d.x) * 0.01;
        view.pitch_rad = (view.pitch_rad + f64::from(d.y) * 0.01).clamp(-1.5, 1.5);
    }
    let painter = ui.painter_at(rect);
    let colours = super::palette::of(ui.visuals());
    painter.rect_filled(rect, 4.0, colours.view_bg);
    // Title on top and caption at the bottom, each wrapped inside the view; the sphere takes
    // the band between them, so none runs into another on a small view.
    let wrap = (rect.width() - 16.0).max(40.0);
    let title = painter.layout(
        title.to_string(),
        FontId::proportional(13.0),
        colours.ink,
        wrap,
    );
    // The sphere keeps a band of its own: a caption taller than the rest (a chart per
    // filter) is cut to the rows that fit.
    let room = rect.height() - 12.0 - title.size().y - MIN_SPHERE_BAND_PT;
    let caption = super::rows_within(
        &painter,
        caption,
        (FontId::proportional(12.0), colours.highlight),
        (wrap, room),
    );
    let top = rect.top() + 6.0 + title.size().y;
    let bottom = rect.bottom() - 6.0 - caption.size().y;
    let band = egui::Rect::from_x_y_ranges(rect.x_range(), top..=bottom.max(top + 40.0));
    // Room for the axis labels (ζ′ above, S and its label below) around the sphere.
    let radius = (0.36 * band.width()).min(0.40 * band.height()).max(12.0);
    let rot = Rotation3::from_axis_angle(&Vector3::x_axis(), view.pitch_rad)
        * Rotation3::from_axis_angle(&Vector3::z_axis(), view.yaw_rad);
    let pr = Projector {
        rot,
        center: band.center(),
        radius,
    };
    painter.circle(
        pr.center,
        radius,
        Color32::from_rgba_unmultiplied(60, 80, 120, 40),
        Stroke::new(1.2, colours.ink_dim),
    );
    draw_grid(&pr, &painter, pole);
    for t in tracks {
        draw_track(&pr, &painter, t);
    }
    painter.galley(rect.left_top() + Vec2::new(8.0, 6.0), title, colours.ink);
    let at = rect.left_bottom() + Vec2::new(8.0, -6.0 - caption.size().y);
    painter.galley(at, caption, colours.highlight);
}

/// Largest |w| drawn on the complex plane: beyond it the point is near the pole S and the
/// trajectory is broken rather than stretching the view.
const PLANE_LIMIT: f64 = 4.0;

/// Splits a w trajectory into pieces that stay within [`PLANE_LIMIT`].
fn plane_segments(w: &[[f64; 2]]) -> Vec<Vec<[f64; 2]>> {
    let mut out = vec![Vec::new()];
    for p in w {
        let inside = p[0].is_finite() && p[1].is_finite() && p[0].hypot(p[1]) <= PLANE_LIMIT;
        match (inside, out.last_mut()) {
            (true, Some(seg)) => seg.push(*p),
            (false, Some(seg)) if !seg.is_empty() => out.push(Vec::new()),
            _ => {}
        }
    }
    out.retain(|s| !s.is_empty());
    out
}

/// A small view draws its legend for at most this many sources, and only when it is at
/// least this tall (points).
pub const ROOM_FOR_LEGEND: (usize, f32) = (5, 280.0);

/// The complex plane with the w trajectories and the unit circle |w| = 1.
pub fn show_plane(ui: &mut Ui, tracks: &[SphereTrack], lang: Lang) {
    let colours = super::palette::of(ui.visuals());
    let circle: PlotPoints<'_> = (0..=96)
        .map(|i| {
            let a = f64::from(i) * std::f64::consts::TAU / 96.0;
            [a.cos(), a.sin()]
        })
        .collect();
    let mut plane = Plot::new("w_plane").data_aspect(1.0);
    // A legend of many sources would hide the plane: the estimator chips give the colours.
    if tracks.len() <= ROOM_FOR_LEGEND.0 && ui.available_height() >= ROOM_FOR_LEGEND.1 {
        let corner = super::emptiest_corner(tracks.iter().flat_map(|t| t.w.iter()));
        plane = plane.legend(
            Legend::default()
                .text_style(egui::TextStyle::Small)
                .background_alpha(0.6)
                .position(corner),
        );
    }
    super::ticks::in_language(plane, lang)
        .include_x(-2.0)
        .include_x(2.0)
        .include_y(-2.0)
        .include_y(2.0)
        .x_axis_label("u = Re w")
        .y_axis_label("v = Im w")
        .show(ui, |plot| {
            plot.line(
                Line::new("|w| = 1", circle)
                    .color(colours.equator[0])
                    .width(1.0),
            );
            for t in tracks {
                if let Some(last) =
                    t.w.last()
                        .copied()
                        .filter(|p| p[0].hypot(p[1]) <= PLANE_LIMIT)
                {
                    plot.points(
                        Points::new(t.name.clone(), vec![last])
                            .radius(4.0)
                            .color(t.color),
                    );
                }
                // Dashed lines cut to the view, so a deep zoom draws no endless dashes.
                let cut = |plot: &egui_plot::PlotUi<'_>, seg: &[[f64; 2]], style| {
                    super::plots::pieces(plot, seg, style)
                };
                for seg in plane_segments(&t.w) {
                    for piece in cut(plot, &seg, t.pattern) {
                        plot.line(
                            Line::new(t.name.clone(), piece)
                                .color(t.color)
                                .style(t.pattern),
                        );
                    }
                }
                if let Some((ring, _)) = &t.ellipse {
                    let closed: Vec<[f64; 2]> = ring.iter().chain(ring.first()).copied().collect();
                    let dense = egui_plot::LineStyle::dashed_dense();
                    for seg in plane_segments(&closed) {
                        for piece in cut(plot, &seg, dense) {
                            plot.line(
                                Line::new(format!("{} 3σ", t.name), piece)
                                    .color(t.color)
                                    .style(dense),
                            );
                        }
                    }
                }
            }
        });
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn trajectories_break_where_w_leaves_the_plane() {
        let w = [
            [0.0, 0.0],
            [1.0, 0.0],
            [10.0, 0.0],
            [f64::NAN, 0.0],
            [1.0, 1.0],
            [0.5, 0.5],
        ];
        let segs = plane_segments(&w);
        assert_eq!(
            segs,
            vec![vec![[0.0, 0.0], [1.0, 0.0]], vec![[1.0, 1.0], [0.5, 0.5]]]
        );
    }
}
