//! Drawing: the 3D body (wgpu), the Riemann sphere, the single-axis dial and phase
//! portrait, and the plots.

pub mod body3d;
pub mod clip;
pub mod fonts;
pub mod legend;
pub mod mesh;
mod orbit_inset;
pub mod outages;
pub mod palette;
pub mod plots;
pub mod riemann_sphere;
pub mod single_axis;
pub mod ticks;

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
