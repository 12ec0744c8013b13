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

/// Whether `b` is within half a pixel of `a` in both axes, a pixel being `px` (units per
/// pixel in x and y): such a point adds nothing a reader can see to a line through `a`.
pub fn within_half_pixel(a: [f64; 2], b: [f64; 2], px: [f64; 2]) -> bool {
    (0..2).all(|k| (b[k] - a[k]).abs() < 0.5 * px[k])
}

/// `points` without those within half a pixel of the last one kept (first and last always
/// kept, a NaN kept as the break it is): the line drawn is the same to within half a pixel,
/// with as many vertices as the pixels it crosses rather than the samples it has. A plot of
/// 3 000 samples 500 pixels wide, or a trail creeping a pixel a second, otherwise hands the
/// tessellator, and a software-rendering browser, many times the triangles it shows.
pub fn thin_to_pixels(points: Vec<[f64; 2]>, px: [f64; 2]) -> Vec<[f64; 2]> {
    let usable = px.iter().all(|p| p.is_finite() && *p > 0.0);
    let Some((&last, body)) = points.split_last().filter(|_| usable && points.len() > 2) else {
        return points;
    };
    let mut kept: Vec<[f64; 2]> = Vec::with_capacity(points.len());
    for &p in body {
        if kept.last().is_none_or(|&k| !within_half_pixel(k, p, px)) {
            kept.push(p);
        }
    }
    if kept.len() > 1 && kept.last().is_some_and(|&k| within_half_pixel(k, last, px)) {
        kept.pop();
    }
    kept.push(last);
    kept
}

/// The greatest value of `points` in each column `px` wide (at the column's greatest
/// point), in order; a NaN point is kept as the break it is. A line that rises and falls
/// within a pixel (a covariance between updates) becomes the line over its peaks.
pub fn upper_envelope(points: &[[f64; 2]], px: f64) -> Vec<[f64; 2]> {
    if !(px.is_finite() && px > 0.0) {
        return points.to_vec();
    }
    let mut out: Vec<[f64; 2]> = Vec::with_capacity(points.len());
    let mut column: Option<(f64, [f64; 2])> = None;
    for &p in points {
        if !p[1].is_finite() || !p[0].is_finite() {
            out.extend(column.take().map(|(_, top)| top));
            out.push(p);
            continue;
        }
        let k = (p[0] / px).floor();
        match &mut column {
            Some((c, top)) if *c == k => {
                if p[1] > top[1] {
                    *top = p;
                }
            }
            _ => {
                out.extend(column.replace((k, p)).map(|(_, top)| top));
            }
        }
    }
    out.extend(column.map(|(_, top)| top));
    out
}

/// `points` of an angle in degrees broken where it wraps: between two points more than
/// [`WRAP_DEG`] apart goes a NaN, so the line does not cross the plot from +180° to −180°
/// (a roll through ±180° had been drawn as vertical lines).
pub fn break_at_wraps(points: Vec<[f64; 2]>) -> Vec<[f64; 2]> {
    let mut out: Vec<[f64; 2]> = Vec::with_capacity(points.len());
    for p in points {
        if let Some(last) = out.last()
            && (p[1] - last[1]).abs() > WRAP_DEG
        {
            out.push([0.5 * (p[0] + last[0]), f64::NAN]);
        }
        out.push(p);
    }
    out
}

/// A jump of an angle between two points that can only be its wrap (degrees).
pub const WRAP_DEG: f64 = 270.0;

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
    fn thinning_keeps_the_ends_and_every_point_half_a_pixel_away() {
        // A pixel is 0.1 units wide and 2 units high.
        let px = [0.1, 2.0];
        let line = vec![
            [0.0, 0.0],
            [0.01, 0.5],     // within half a pixel of the first: dropped
            [0.02, 1.2],     // a pixel up less a bit: kept (|Δy| ≥ 1)
            [0.03, 1.3],     // dropped
            [0.2, 1.3],      // kept (|Δx| ≥ 0.05)
            [f64::NAN, 0.0], // a break: kept
            [0.21, 1.31],    // the last: kept
        ];
        let thin = thin_to_pixels(line, px);
        let bits: Vec<[u64; 2]> = thin.iter().map(|p| p.map(f64::to_bits)).collect();
        let want: Vec<[u64; 2]> = [
            [0.0, 0.0],
            [0.02, 1.2],
            [0.2, 1.3],
            [f64::NAN, 0.0],
            [0.21, 1.31],
        ]
        .iter()
        .map(|p| p.map(f64::to_bits))
        .collect();
        assert_eq!(bits, want);
        // The last point replaces a kept one within half a pixel of it.
        let end = thin_to_pixels(vec![[0.0, 0.0], [1.0, 0.0], [1.01, 0.1]], px);
        assert_eq!(end, vec![[0.0, 0.0], [1.01, 0.1]]);
        // No usable pixel size: left alone.
        let line = vec![[0.0, 0.0], [0.0, 0.0], [0.0, 0.0]];
        assert_eq!(thin_to_pixels(line.clone(), [0.0, 1.0]), line);
    }

    #[test]
    fn the_upper_envelope_keeps_each_columns_peak_and_the_breaks() {
        // Columns 1 wide: a sawtooth rising within each and dropping at its edge.
        let saw = [
            [0.1, 1.0],
            [0.5, 2.0],
            [0.9, 3.0],
            [1.1, 1.0],
            [1.9, 3.5],
            [f64::NAN, 0.0],
            [2.2, 1.0],
        ];
        let top = upper_envelope(&saw, 1.0);
        assert_eq!(top.len(), 4, "{top:?}");
        assert_eq!((top[0], top[1]), ([0.9, 3.0], [1.9, 3.5]));
        assert!(top[2][0].is_nan());
        assert_eq!(top[3], [2.2, 1.0]);
        assert_eq!(upper_envelope(&saw, 0.0).len(), saw.len());
    }

    #[test]
    fn an_angle_is_broken_where_it_wraps_and_nowhere_else() {
        let roll = vec![
            [0.0, 170.0],
            [1.0, 179.0],
            [2.0, -179.0],
            [3.0, -170.0],
            [4.0, 100.0],
        ];
        let broken = break_at_wraps(roll);
        assert_eq!(broken.len(), 6, "{broken:?}");
        assert!(broken[2][1].is_nan() && broken[2][0] == 1.5);
        // A twist of 360° that does not wrap (paper 1's angle) is left whole.
        let twist: Vec<[f64; 2]> = (0..10)
            .map(|k| [f64::from(k), 360.0 - 40.0 * f64::from(k)])
            .collect();
        assert_eq!(break_at_wraps(twist.clone()), twist);
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
