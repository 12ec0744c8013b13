//! What time travel adds to a plot: a vertical line at the timeline's cursor, and each
//! "what if" branch's series drawn dashed in the colour of the same series of the main run.

use attlab::record::Recorder;
use egui::Color32;
use egui_plot::{Line, LineStyle, PlotPoints, VLine};

/// The cursor and the branches' recorders.
pub struct TravelMarks<'a> {
    /// The moment the cursor shows (s), when it is off now.
    pub cursor_s: Option<f64>,
    /// Each branch's recorder, in the order of the branch chips.
    pub branches: Vec<&'a Recorder>,
    /// The cursor line's colour (the theme's strong text).
    pub line: Color32,
}

/// Points a branch's line keeps at most.
const BRANCH_POINTS: usize = 1500;

/// Draws `marks` on `plot`: for each of `shown` (index into `rec`, colour), the series of
/// the same name in every branch.
pub fn draw(
    plot: &mut egui_plot::PlotUi<'_>,
    rec: &Recorder,
    shown: &[(usize, Color32)],
    marks: &TravelMarks<'_>,
    (width, log): (f32, bool),
) {
    for branch in &marks.branches {
        for (i, color) in shown {
            let Some(j) = rec.specs().get(*i).and_then(|s| branch.index_of(&s.name)) else {
                continue;
            };
            let mut points = branch.plot_points(j, BRANCH_POINTS);
            if log {
                for p in &mut points {
                    p[1] = if p[1] > 0.0 { p[1].log10() } else { f64::NAN };
                }
            }
            for piece in Recorder::split_at_gaps(&points) {
                plot.line(
                    Line::new("", PlotPoints::from(piece))
                        .color(*color)
                        .width(width)
                        .style(LineStyle::Dashed { length: 9.0 })
                        .allow_hover(false),
                );
            }
        }
    }
    if let Some(t) = marks.cursor_s {
        plot.vline(VLine::new("", t).color(marks.line).width(1.5));
    }
}
