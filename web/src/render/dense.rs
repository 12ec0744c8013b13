//! A solid line that zigzags within each pixel column (a noisy error at the scale of its
//! steady part, min/max buckets of a long run) is drawn as what it looks like: in each
//! column a bar from its least to its greatest value, joined to the column before, one mesh
//! of two triangles a column. Stroked, each zigzag had been shaded by a feathered line two
//! and a half pixels wide over and over: paper 2's three errors at their steady scale had
//! shaded their plot three times a frame, which a browser drawing in software pays for.

use egui::{Color32, Pos2, Rect};
use egui_plot::PlotTransform;

/// A line is dense when its path on screen is this many times its width.
const ZIGZAG: f64 = 6.0;

/// Whether `points` (plot coordinates), at `px` plot units per pixel in x and y, zigzag:
/// their path on screen is more than `ZIGZAG` (six) times as long as it is wide.
pub fn is_dense(points: &[[f64; 2]], px: [f64; 2]) -> bool {
    if !px.iter().all(|p| p.is_finite() && *p > 0.0) || points.len() < 3 {
        return false;
    }
    let (mut path, mut first, mut last) = (0.0, f64::INFINITY, f64::NEG_INFINITY);
    for w in points.windows(2) {
        let (dx, dy) = ((w[1][0] - w[0][0]) / px[0], (w[1][1] - w[0][1]) / px[1]);
        if dx.is_finite() && dy.is_finite() {
            path += dx.hypot(dy);
            first = first.min(w[0][0]);
            last = last.max(w[1][0]);
        }
    }
    path > ZIGZAG * ((last - first) / px[0]).max(1.0)
}

/// Paints `pieces` (plot coordinates) through `transform` in `colour`, each column a pixel
/// wide from its least to its greatest value (and the last of the column before, so the
/// line stays joined), at least `width` points tall; clipped to the plot's frame.
pub fn paint(
    painter: &egui::Painter,
    transform: &PlotTransform,
    pieces: &[Vec<[f64; 2]>],
    (colour, width): (Color32, f32),
) {
    let frame = *transform.frame();
    let painter = painter.with_clip_rect(frame);
    let mut mesh = egui::Mesh::default();
    for piece in pieces {
        for bar in columns(piece, transform, width) {
            if bar.intersects(frame) {
                mesh.add_colored_rect(bar, colour);
            }
        }
    }
    painter.add(egui::Shape::mesh(mesh));
}

/// The bars of one piece: a column a pixel wide per pixel it crosses.
fn columns(piece: &[[f64; 2]], transform: &PlotTransform, width: f32) -> Vec<Rect> {
    let screen: Vec<Pos2> = (piece.iter())
        .filter(|p| p[0].is_finite() && p[1].is_finite())
        .map(|p| transform.position_from_point(&egui_plot::PlotPoint::new(p[0], p[1])))
        .collect();
    let mut bars = Vec::new();
    let mut k = 0;
    let mut joined: Option<f32> = None;
    while k < screen.len() {
        let x0 = screen[k].x.floor();
        let (mut lo, mut hi) = (screen[k].y, screen[k].y);
        if let Some(y) = joined {
            (lo, hi) = (lo.min(y), hi.max(y));
        }
        let mut j = k;
        while j < screen.len() && screen[j].x.floor() == x0 {
            (lo, hi) = (lo.min(screen[j].y), hi.max(screen[j].y));
            j += 1;
        }
        let grow = (0.5 * (width - (hi - lo))).max(0.0);
        bars.push(Rect::from_min_max(
            Pos2::new(x0, lo - grow),
            Pos2::new(x0 + 1.0, hi + grow),
        ));
        joined = Some(screen[j - 1].y);
        k = j;
    }
    bars
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_zigzag_is_dense_and_a_smooth_line_is_not() {
        let px = [1.0, 1.0];
        let zigzag: Vec<[f64; 2]> = (0..100)
            .map(|k| [f64::from(k), f64::from(k % 2) * 50.0])
            .collect();
        assert!(is_dense(&zigzag, px));
        let ramp: Vec<[f64; 2]> = (0..100)
            .map(|k| [f64::from(k), f64::from(k) * 2.0])
            .collect();
        assert!(!is_dense(&ramp, px));
        assert!(!is_dense(&zigzag, [0.0, 1.0]));
    }

    #[test]
    fn each_pixel_column_is_one_bar_from_its_least_to_its_greatest_value_joined() {
        let frame = Rect::from_min_size(Pos2::ZERO, egui::vec2(100.0, 100.0));
        let bounds = egui_plot::PlotBounds::from_min_max([0.0, 0.0], [100.0, 100.0]);
        let transform = PlotTransform::new(frame, bounds, egui::Vec2b::FALSE);
        // Two points in the first column, one far up in the next.
        let piece = vec![[0.2, 10.0], [0.6, 20.0], [1.5, 60.0]];
        let bars = columns(&piece, &transform, 2.0);
        assert_eq!(bars.len(), 2, "{bars:?}");
        // y grows downwards on screen: value 10 is at 90, 20 at 80.
        assert_eq!((bars[0].min.y, bars[0].max.y), (80.0, 90.0));
        // The second column reaches back to where the first ended (value 20).
        assert_eq!((bars[1].min.y, bars[1].max.y), (40.0, 80.0));
        // A flat run is still a line `width` tall.
        let flat = columns(&[[5.2, 50.0], [5.7, 50.0]], &transform, 2.0);
        assert_eq!(flat[0].height(), 2.0);
    }
}
