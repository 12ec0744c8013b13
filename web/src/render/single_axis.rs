//! Views for labs that turn about one axis (papers 1 and 4), where the Riemann sphere and the
//! w plane explain nothing: the angle on a dial (truth and every estimator as needles) and
//! the phase portrait angle–rate, a trail per source. A replayed or live log has no truth:
//! the caller leaves it out of both.

use attlab::i18n::Lang;
use egui::{Color32, Painter, Pos2, Rect, Stroke, Ui, Vec2};
use egui_plot::{Legend, Line, Plot, Points};
use std::collections::VecDeque;

/// One source's current angle and rate.
#[derive(Clone, Debug, PartialEq)]
pub struct AxisSource {
    /// Legend name.
    pub name: String,
    /// Colour (the source's everywhere).
    pub color: Color32,
    /// Line pattern (the source's everywhere).
    pub pattern: egui_plot::LineStyle,
    /// Angle (rad).
    pub angle_rad: f64,
    /// Rate about the axis (rad/s).
    pub rate_rad_s: f64,
    /// The simulated truth: its needle is drawn widest.
    pub is_truth: bool,
}

/// Points kept per trail.
const TRAIL: usize = 900;

/// The phase-portrait trails, one per source, kept by the view between frames.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PhaseTrails {
    t_s: f64,
    trails: Vec<(String, VecDeque<[f64; 2]>)>,
}

impl PhaseTrails {
    /// Adds the sources' current (angle °, rate °/s) at time `t_s`; a time that went back
    /// (a reset, another lab) starts the trails afresh.
    pub fn push(&mut self, t_s: f64, sources: &[AxisSource]) {
        if t_s < self.t_s || self.trails.len() != sources.len() {
            self.trails = sources
                .iter()
                .map(|s| (s.name.clone(), VecDeque::new()))
                .collect();
        }
        if t_s == self.t_s && self.trails.iter().any(|(_, t)| !t.is_empty()) {
            return; // paused: nothing new
        }
        self.t_s = t_s;
        for ((_, trail), s) in self.trails.iter_mut().zip(sources) {
            let p = [s.angle_rad.to_degrees(), s.rate_rad_s.to_degrees()];
            if p.iter().all(|v| v.is_finite()) {
                if trail.len() == TRAIL {
                    trail.pop_front();
                }
                trail.push_back(p);
            }
        }
    }
}

/// A view's title in its top-left corner on one line, cut with "…" where the view is
/// narrower (Russian on a projector's presenter layout ran past the view's edge and was
/// clipped mid-word).
fn view_title(painter: &egui::Painter, rect: Rect, title: &str, ink: egui::Color32) {
    let font = egui::FontId::proportional(13.0);
    let galley = super::one_line(painter, title, font, ink, rect.width() - 16.0);
    painter.galley(rect.left_top() + Vec2::new(8.0, 6.0), galley, ink);
}

/// The angle on a dial: a needle per source, truth drawn widest; 0° up, positive clockwise
/// as on an instrument.
pub fn dial(ui: &mut Ui, rect: Rect, sources: &[AxisSource], (title, lang): (&str, Lang)) {
    let painter = ui.painter_at(rect);
    let colours = super::palette::of(ui.visuals());
    painter.rect_filled(rect, 4.0, colours.view_bg);
    view_title(&painter, rect, title, colours.ink);
    let (center, radius, readouts, row, read) = dial_or_readouts(rect, sources.len());
    painter.circle_stroke(center, radius, Stroke::new(1.5, colours.ink_dim));
    for k in 0..36 {
        let a = f64::from(k) * 10f64.to_radians();
        let len = if k % 9 == 0 {
            0.14
        } else if k % 3 == 0 {
            0.08
        } else {
            0.04
        };
        let dir = direction(a);
        painter.line_segment(
            [center + dir * radius, center + dir * radius * (1.0 - len)],
            Stroke::new(1.0, colours.ink_dim),
        );
    }
    // On a small dial the ticks say enough; the labels would run into each other.
    let labels: &[(&str, f64)] = if radius >= 40.0 {
        &[
            ("0°", 0.0),
            ("90°", 90.0),
            ("±180°", 180.0),
            ("−90°", -90.0),
        ]
    } else {
        &[]
    };
    for &(label, a) in labels {
        let pos = center + direction(f64::to_radians(a)) * (radius * 0.74);
        painter.text(
            pos,
            egui::Align2::CENTER_CENTER,
            label,
            egui::FontId::proportional(11.0),
            colours.ink_dim,
        );
    }
    for s in sources.iter().rev() {
        if !s.angle_rad.is_finite() {
            continue;
        }
        let width = if s.is_truth { 4.0 } else { 2.0 };
        needle(
            &painter,
            center,
            radius * 0.92,
            s.angle_rad,
            Stroke::new(width, s.color),
        );
    }
    painter.circle_filled(center, 4.0, colours.ink);
    for (k, s) in sources.iter().enumerate().filter(|_| read) {
        let at = readouts + Vec2::new(0.0, row * k as f32);
        // The number first, so a long name is what a narrow view cuts, never the angle.
        let text = if s.angle_rad.is_finite() {
            format!(
                "{}°  {}",
                attlab::i18n::number(lang, &format!("{:+8.2}", s.angle_rad.to_degrees())),
                s.name
            )
        } else {
            format!("{:>9}  {}", "—", s.name)
        };
        painter.text(
            at,
            egui::Align2::LEFT_TOP,
            text,
            egui::FontId::monospace(11.0),
            s.color,
        );
    }
}

/// Height of one readout line under or beside the dial (points).
const READOUT_ROW_PT: f32 = 16.0;
/// Width a readout line needs (" +123.45°  " and a name cut to [`DIAL_NAME`] characters, in
/// 11-pt monospace), in points.
const READOUT_W_PT: f32 = 125.0;

/// The longest source name a dial's readout shows whole (the legend and the chips show the
/// whole name in the same colour).
pub const DIAL_NAME: usize = 8;
/// Height of the dial's title (points).
const DIAL_TITLE_PT: f32 = 24.0;

/// The dial's layout with its `n` readouts, or without them where they would leave it a
/// radius under [`SMALL_DIAL_PT`] (a projector's short top row had drawn a dial 30 points
/// across over five lines of numbers): the needles then speak alone, the numbers being the
/// lesson's tiles. The last value says whether the readouts are drawn.
fn dial_or_readouts(rect: Rect, n: usize) -> (Pos2, f32, Pos2, f32, bool) {
    let (center, radius, at, row) = dial_layout(rect, n);
    if radius >= SMALL_DIAL_PT {
        return (center, radius, at, row, true);
    }
    let (c, r, at0, row0) = dial_layout(rect, 0);
    if r > radius {
        (c, r, at0, row0, false)
    } else {
        (center, radius, at, row, true)
    }
}

/// A dial smaller than this (radius, points) gives its readouts' room to the needles.
const SMALL_DIAL_PT: f32 = 36.0;

/// Where the dial goes in `rect` with `n` readouts: its centre and radius, the top left of
/// the readouts and their line height. A wide, low rect (a projector's short top row) puts
/// the readouts beside the dial; otherwise they go below it, closer together where the
/// view is short. Neither overlaps the title, and both stay inside `rect`.
fn dial_layout(rect: Rect, n: usize) -> (Pos2, f32, Pos2, f32) {
    const MIN_RADIUS: f32 = 12.0;
    let body = Rect::from_min_max(rect.min + Vec2::new(0.0, DIAL_TITLE_PT), rect.max);
    let rows = n.max(1) as f32;
    // Beside the dial only where a dial of radius 24 still fits next to the readouts.
    if body.width() > 1.3 * body.height() && body.width() >= 26.0 + READOUT_W_PT + 48.0 {
        let row = READOUT_ROW_PT.min((body.height() - 4.0) / rows);
        let radius = ((body.height() - 8.0) / 2.0)
            .min((body.width() - 26.0 - READOUT_W_PT) / 2.0)
            .max(MIN_RADIUS);
        let center = Pos2::new(body.left() + 12.0 + radius, body.center().y);
        let readouts = Pos2::new(center.x + radius + 14.0, body.center().y - row * rows / 2.0);
        (center, radius, readouts, row)
    } else {
        // 4 above the dial, 8 between it and the readouts, 8 below them.
        let row = READOUT_ROW_PT
            .min((body.height() - 2.0 * MIN_RADIUS - 20.0) / rows)
            .max(10.0);
        let radius = (body.width().min(body.height() - row * rows - 20.0) / 2.0).max(MIN_RADIUS);
        let center = Pos2::new(body.center().x, body.top() + 4.0 + radius);
        let readouts = Pos2::new(rect.left() + 10.0, center.y + radius + 8.0);
        (center, radius, readouts, row)
    }
}

/// Unit screen vector of the angle `a` (0 up, positive clockwise).
fn direction(a: f64) -> Vec2 {
    Vec2::new(a.sin() as f32, -a.cos() as f32)
}

fn needle(painter: &Painter, center: Pos2, length: f32, a: f64, stroke: Stroke) {
    painter.line_segment([center, center + direction(a) * length], stroke);
}

/// The phase portrait: rate against angle, a trail per source (those `shown`), the newest
/// point dotted.
pub fn phase_portrait(
    ui: &mut Ui,
    rect: Rect,
    trails: &PhaseTrails,
    sources: &[AxisSource],
    shown: &[bool],
    (title, angle_axis, rate_axis, lang): (&str, &str, &str, Lang),
) {
    ui.scope_builder(egui::UiBuilder::new().max_rect(rect), |ui| {
        // One line, as the plot's height below assumes; cut with "…" where it does not fit
        // (the Russian title wrapped onto the plot), whole on hover.
        ui.add(egui::Label::new(egui::RichText::new(title).small()).truncate());
        let mut portrait = Plot::new("phase_portrait").height((rect.height() - 24.0).max(60.0));
        let (most, tall) = super::riemann_sphere::ROOM_FOR_LEGEND;
        if sources.len() <= most && rect.height() >= tall {
            let shown_trails = (trails.trails.iter().zip(shown)).filter(|(_, v)| **v);
            let corner = super::emptiest_corner(shown_trails.flat_map(|((_, t), _)| t.iter()));
            let legend = Legend::default().text_style(egui::TextStyle::Small);
            portrait = portrait.legend(legend.position(corner));
        }
        super::ticks::in_language(portrait, lang)
            .x_axis_label(angle_axis)
            .y_axis_label(rate_axis)
            .show(ui, |plot| {
                for (((name, trail), s), _) in trails
                    .trails
                    .iter()
                    .zip(sources)
                    .zip(shown)
                    .filter(|(_, v)| **v)
                {
                    let pts: Vec<[f64; 2]> = trail.iter().copied().collect();
                    if let Some(last) = pts.last().copied() {
                        for piece in super::plots::pieces(plot, &pts, s.pattern) {
                            plot.line(
                                Line::new(name.clone(), piece)
                                    .color(s.color)
                                    .width(1.2)
                                    .style(s.pattern),
                            );
                        }
                        plot.points(
                            Points::new(name.clone(), vec![last])
                                .radius(3.5)
                                .color(s.color),
                        );
                    }
                }
            });
    });
}

#[cfg(test)]
mod tests {
    use super::*;

    fn source(angle: f64) -> AxisSource {
        AxisSource {
            name: "truth".into(),
            color: Color32::WHITE,
            pattern: egui_plot::LineStyle::Solid,
            angle_rad: angle,
            rate_rad_s: 0.5,
            is_truth: true,
        }
    }

    #[test]
    fn trails_grow_while_time_runs_and_restart_when_it_goes_back() {
        let mut t = PhaseTrails::default();
        t.push(0.1, &[source(0.1)]);
        t.push(0.2, &[source(0.2)]);
        t.push(0.2, &[source(0.2)]); // paused
        assert_eq!(t.trails[0].1.len(), 2);
        t.push(0.0, &[source(0.0)]); // reset
        assert_eq!(t.trails[0].1.len(), 1);
        for k in 0..2000 {
            t.push(1.0 + f64::from(k), &[source(f64::NAN)]);
        }
        assert_eq!(t.trails[0].1.len(), 1, "a NaN angle adds no point");
    }

    #[test]
    fn the_dial_never_overlaps_its_title_or_its_readouts() {
        let views = [
            (260.0, 130.0),
            (300.0, 420.0),
            (180.0, 180.0),
            (520.0, 150.0),
            (140.0, 129.0),
        ];
        for (w, h) in views {
            let rect = Rect::from_min_size(Pos2::new(10.0, 20.0), Vec2::new(w, h));
            // The truth and p4's four filters.
            let n = 5;
            let (c, r, at, row) = dial_layout(rect, n);
            let dial = Rect::from_center_size(c, Vec2::splat(2.0 * r));
            let readouts = Rect::from_min_size(at, Vec2::new(READOUT_W_PT, row * n as f32));
            let tag = format!("{w}×{h}: dial {dial:?}, readouts {readouts:?}");
            assert!(
                dial.top() >= rect.top() + DIAL_TITLE_PT,
                "{tag}: under the title"
            );
            assert!(!dial.intersects(readouts), "{tag}: they overlap");
            assert!(rect.contains_rect(dial), "{tag}: the dial is cut off");
            assert!(
                rect.contains_rect(readouts),
                "{tag}: the readouts are cut off"
            );
            assert!(row >= 10.0, "{tag}: lines {row} pt apart");
        }
    }

    #[test]
    fn a_short_dial_gives_its_readouts_room_to_the_needles() {
        // A projector's top row in presenter mode: about 190 × 170 points.
        let rect = Rect::from_min_size(Pos2::new(10.0, 20.0), Vec2::new(190.0, 170.0));
        let (_, with, ..) = dial_layout(rect, 5);
        let (_, radius, _, _, read) = dial_or_readouts(rect, 5);
        assert!(
            with < SMALL_DIAL_PT && !read && radius > 2.0 * with,
            "{with} → {radius}"
        );
        // A laptop's: the readouts stay.
        let rect = Rect::from_min_size(Pos2::new(10.0, 20.0), Vec2::new(300.0, 420.0));
        assert!(dial_or_readouts(rect, 5).4);
    }

    #[test]
    fn zero_is_up_and_a_quarter_turn_is_right() {
        let up = direction(0.0);
        assert!(up.x.abs() < 1e-6 && (up.y + 1.0).abs() < 1e-6);
        let right = direction(std::f64::consts::FRAC_PI_2);
        assert!((right.x - 1.0).abs() < 1e-6 && right.y.abs() < 1e-6);
    }
}
