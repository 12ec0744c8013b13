//! Lines cut to what a plot shows. egui_plot hands a dashed or dotted line to epaint whole,
//! in screen space: zoomed in far, a line of a few points is kilometres of dashes, and the
//! dash list overflows. Cutting each line to the visible bounds with a wide margin keeps a
//! line's drawn length within some twenty plot widths whatever the zoom, and lets a plot
//! whose bounds follow its data grow to it within a few frames.

use egui_plot::PlotBounds;

/// How many times its size the box is grown by on each side.
const MARGIN: f64 = 10.0;

/// `points` cut to `bounds` grown by `MARGIN` times its size on each side: the pieces
/// inside, broken where the line leaves and enters (a NaN point breaks it too).
pub fn clip_to_bounds(points: &[[f64; 2]], bounds: &PlotBounds) -> Vec<Vec<[f64; 2]>> {
    let (min, max) = (bounds.min(), bounds.max());
    let grow = |k: usize| MARGIN * (max[k] - min[k]).abs().max(f64::MIN_POSITIVE);
    let lo = [min[0] - grow(0), min[1] - grow(1)];
    let hi = [max[0] + grow(0), max[1] + grow(1)];
    let mut pieces: Vec<Vec<[f64; 2]>> = Vec::new();
    let mut current: Vec<[f64; 2]> = Vec::new();
    for pair in points.windows(2) {
        let Some((a, b)) = clip_segment(pair[0], pair[1], lo, hi) else {
            if !current.is_empty() {
                pieces.push(std::mem::take(&mut current));
            }
            continue;
        };
        if current.last() != Some(&a) {
            if !current.is_empty() {
                pieces.push(std::mem::take(&mut current));
            }
            current.push(a);
        }
        current.push(b);
    }
    if points.len() == 1 && inside(points[0], lo, hi) {
        current.push(points[0]);
    }
    if !current.is_empty() {
        pieces.push(current);
    }
    pieces
}

fn inside(p: [f64; 2], lo: [f64; 2], hi: [f64; 2]) -> bool {
    (0..2).all(|k| p[k] >= lo[k] && p[k] <= hi[k])
}

/// The part of the segment a–b inside the box (Liang and Barsky), if any.
fn clip_segment(
    a: [f64; 2],
    b: [f64; 2],
    lo: [f64; 2],
    hi: [f64; 2],
) -> Option<([f64; 2], [f64; 2])> {
    if !(a.iter().chain(&b).all(|v| v.is_finite())) {
        return None;
    }
    let d = [b[0] - a[0], b[1] - a[1]];
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for k in 0..2 {
        for (p, q) in [(-d[k], a[k] - lo[k]), (d[k], hi[k] - a[k])] {
            if p == 0.0 {
                if q < 0.0 {
                    return None;
                }
            } else {
                let t = q / p;
                if p < 0.0 {
                    t0 = t0.max(t);
                } else {
                    t1 = t1.min(t);
                }
            }
        }
    }
    if t0 > t1 {
        return None;
    }
    let at = |t: f64| [a[0] + t * d[0], a[1] + t * d[1]];
    // The ends themselves when not cut, so consecutive segments join exactly.
    let start = if t0 == 0.0 { a } else { at(t0) };
    let end = if t1 == 1.0 { b } else { at(t1) };
    Some((start, end))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn bounds(x0: f64, x1: f64, y0: f64, y1: f64) -> PlotBounds {
        PlotBounds::from_min_max([x0, y0], [x1, y1])
    }

    #[test]
    fn a_line_inside_stays_whole() {
        let line = [[0.0, 0.0], [1.0, 1.0], [2.0, 0.5]];
        assert_eq!(
            clip_to_bounds(&line, &bounds(0.0, 2.0, 0.0, 1.0)),
            vec![line.to_vec()]
        );
    }

    #[test]
    fn zoomed_far_in_a_long_segment_is_cut_to_the_view() {
        // A view a millionth of the line's length: what is drawn spans 21 views.
        let line = [[-1e6, 0.0], [1e6, 0.0]];
        let pieces = clip_to_bounds(&line, &bounds(0.0, 1.0, -1.0, 1.0));
        assert_eq!(pieces, vec![vec![[-10.0, 0.0], [11.0, 0.0]]]);
    }

    #[test]
    fn a_line_that_leaves_and_comes_back_is_broken() {
        let line = [[0.0, 0.0], [1.0, 100.0], [2.0, 0.0]];
        let pieces = clip_to_bounds(&line, &bounds(0.0, 2.0, -1.0, 1.0));
        assert_eq!(pieces.len(), 2, "{pieces:?}");
        for piece in &pieces {
            assert!(piece.iter().all(|p| p[1] <= 21.0 + 1e-12), "{piece:?}");
        }
        // NaN breaks too; nothing outside is drawn.
        let gap = [[0.0, 0.0], [f64::NAN, 0.0], [1.0, 0.0]];
        assert!(clip_to_bounds(&gap, &bounds(0.0, 1.0, -1.0, 1.0)).is_empty());
        let away = [[30.0, 30.0], [31.0, 30.0]];
        assert!(clip_to_bounds(&away, &bounds(0.0, 1.0, 0.0, 1.0)).is_empty());
    }
}
