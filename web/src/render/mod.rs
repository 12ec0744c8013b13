//! Drawing: the 3D body (wgpu), the Riemann sphere, the single-axis dial and phase
//! portrait, and the plots.

pub mod body3d;
pub mod clip;
pub mod dense;
pub mod fonts;
pub mod legend;
pub mod mesh;
mod orbit_inset;
pub mod outages;
pub mod palette;
pub mod plots;
pub mod riemann_sphere;
mod series_lines;
pub mod single_axis;
pub mod ticks;
pub mod y_range;

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
