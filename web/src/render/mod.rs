//! Drawing: the 3D body (wgpu), the Riemann sphere, the single-axis dial and phase
//! portrait, and the plots.

pub mod body3d;
mod body_captions;
pub mod clip;
pub mod dense;
pub mod fonts;
pub mod legend;
pub mod mesh;
mod orbit_inset;
pub mod outages;
pub mod palette;
pub mod plot_state;
pub mod plots;
pub mod riemann_sphere;
pub mod scene;
mod series_lines;
pub mod single_axis;
pub mod ticks;
pub mod travel_lines;
pub mod y_range;

/// The corner of a small plot's legend: the one whose quarter of the data's extent holds
/// the fewest of `points` (the phase portrait's and the w plane's legends had sat on their
/// trails in the default top-right corner, which it stays on a tie).
pub(crate) fn emptiest_corner<'a>(
    points: impl Iterator<Item = &'a [f64; 2]> + Clone,
) -> egui_plot::Corner {
    use egui_plot::Corner;
    let finite = points.filter(|p| p[0].is_finite() && p[1].is_finite());
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in finite.clone() {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    let mid = [0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])];
    let mut count = [0usize; 4];
    for p in finite {
        let (right, top) = (p[0] > mid[0], p[1] > mid[1]);
        count[usize::from(right) + 2 * usize::from(!top)] += 1;
    }
    // Top right first: egui_plot's own corner, kept on a tie.
    [
        (1, Corner::RightTop),
        (0, Corner::LeftTop),
        (3, Corner::RightBottom),
        (2, Corner::LeftBottom),
    ]
    .into_iter()
    .min_by_key(|(k, _)| count[*k])
    .map_or(Corner::RightTop, |(_, c)| c)
}

/// `text` laid out on one line, cut with "…" to `max_width` where it is wider (a view's
/// title, an outage's label): the one way the renderer fits a label into its room.
pub(crate) fn one_line(
    painter: &egui::Painter,
    text: &str,
    font: egui::FontId,
    colour: egui::Color32,
    max_width: f32,
) -> std::sync::Arc<egui::Galley> {
    let mut job = egui::text::LayoutJob::simple_singleline(text.to_owned(), font, colour);
    job.wrap = egui::text::TextWrapping::truncate_at_width(max_width);
    painter.layout_job(job)
}

/// `text` wrapped at `max_width` and cut with "…" after the rows that fit in `max_height`
/// (at least one): a caption that must leave its view room for the drawing (the sphere's
/// chart caption, a row per filter, ran over the sphere on a projector's lesson layout).
pub(crate) fn rows_within(
    painter: &egui::Painter,
    text: &str,
    (font, colour): (egui::FontId, egui::Color32),
    (max_width, max_height): (f32, f32),
) -> std::sync::Arc<egui::Galley> {
    let full = painter.layout(text.to_owned(), font.clone(), colour, max_width);
    let rows = full.rows.len();
    if rows <= 1 || full.size().y <= max_height {
        return full;
    }
    let row_height = full.size().y / rows as f32;
    let mut job = egui::text::LayoutJob::simple(text.to_owned(), font, colour, max_width);
    job.wrap.max_rows = ((max_height / row_height).floor() as usize).max(1);
    painter.layout_job(job)
}

#[cfg(test)]
mod tests {
    #[test]
    fn a_legend_goes_to_the_corner_the_data_leaves_empty() {
        use egui_plot::Corner;
        // A trail along the top and down the right: the bottom left is empty.
        let trail = [
            [0.0, 1.0],
            [1.0, 1.0],
            [1.0, 0.0],
            [0.9, 0.9],
            [0.6, 0.95],
            [1.0, 0.4],
        ];
        assert_eq!(super::emptiest_corner(trail.iter()), Corner::LeftBottom);
        assert_eq!(super::emptiest_corner([].iter()), Corner::RightTop);
    }

    /// The last character of a laid-out text.
    fn last_char(galley: &egui::Galley) -> Option<char> {
        galley
            .rows
            .last()
            .and_then(|r| r.glyphs.last())
            .map(|g| g.chr)
    }

    #[test]
    fn a_caption_keeps_the_rows_that_fit_and_says_it_was_cut() {
        let ctx = egui::Context::default();
        super::fonts::install(&ctx);
        let text = "chart s = 1/w (upside down): (u, v, z) RK4 integration, Accelerometer \
                    only (uᵃ, vᵃ), Blend HPF(u) + LPF(uᵃ), Kalman filter in (u, v)";
        let mut seen = Vec::new();
        // The fonts are installed by the first frame; the second lays out with them.
        for _ in 0..2 {
            let mut output = ctx.run_pass(egui::RawInput::default(), |ctx| {
                let painter = ctx.layer_painter(egui::LayerId::background());
                let style = (egui::FontId::proportional(12.0), egui::Color32::WHITE);
                let fit = |h: f32| super::rows_within(&painter, text, style.clone(), (150.0, h));
                let full = fit(1000.0);
                let row = full.size().y / full.rows.len() as f32;
                let two = fit(2.5 * row);
                let one = fit(0.0);
                let short = super::rows_within(&painter, "chart w", style.clone(), (150.0, 0.0));
                seen = vec![
                    (full.rows.len(), last_char(&full)),
                    (two.rows.len(), last_char(&two)),
                    (one.rows.len(), last_char(&one)),
                    (short.rows.len(), last_char(&short)),
                ];
            });
            // No renderer takes the font atlas's texture here.
            output.textures_delta.clear();
        }
        let (full_rows, full_end) = seen[0];
        assert!(full_rows >= 4, "the whole caption wraps: {seen:?}");
        assert_eq!(full_end, Some(')'), "whole, not cut: {seen:?}");
        assert_eq!(seen[1], (2, Some('…')), "two rows fit: {seen:?}");
        assert_eq!(seen[2], (1, Some('…')), "at least one row: {seen:?}");
        assert_eq!(
            seen[3],
            (1, Some('w')),
            "a short caption is left whole: {seen:?}"
        );
    }
}
