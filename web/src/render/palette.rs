//! The page's colours and line patterns, for a dark and a light (projector) theme: every
//! source has one colour and one line pattern in every view, chosen so that a reader with
//! deuteranopia, protanopia or tritanopia can still tell them apart (checked by the tests
//! below with simulated colour vision), and every colour stands out from its background.

use egui::{Color32, Visuals};
use egui_plot::LineStyle;

/// One theme's colours.
#[derive(Debug)]
pub struct Palette {
    /// Truth, then the estimators' colours (cycled).
    pub sources: [Color32; 8],
    /// Colours for what is neither truth nor an estimator (a second truth series, sensors).
    pub others: [Color32; 5],
    /// The background of the views (3D, sphere, plane, dial).
    pub view_bg: Color32,
    /// What the background of the plots is (egui's panel colour), for the contrast test.
    pub plot_bg: Color32,
    /// Text and marks drawn on a view.
    pub ink: Color32,
    /// Secondary text and marks on a view.
    pub ink_dim: Color32,
    /// Grid lines on the front and the back of the sphere.
    pub grid_front: Color32,
    /// Grid lines on the back of the sphere.
    pub grid_back: Color32,
    /// The sphere's equator (|w| = 1), front and back.
    pub equator: [Color32; 2],
    /// A highlighted point (the pole S, the optimum of a sweep).
    pub highlight: Color32,
    /// Errors (a diverged filter, a failed step).
    pub error: Color32,
    /// Warnings (behind real time, unobservable).
    pub warn: Color32,
    /// Good news (a message that something worked).
    pub good: Color32,
    /// The shading of outages, by position.
    pub outages: [Color32; 3],
    /// The ring around the control that has the keyboard.
    pub focus: Color32,
}

/// The dark theme: Okabe and Ito's colour-blind-safe palette (their blue lightened so it
/// reads on a dark panel), truth near-white.
pub const DARK: Palette = Palette {
    sources: [
        Color32::from_rgb(0xEB, 0xEB, 0xEB),
        Color32::from_rgb(0xE6, 0x9F, 0x00),
        Color32::from_rgb(0x56, 0xB4, 0xE9),
        Color32::from_rgb(0x00, 0x9E, 0x73),
        Color32::from_rgb(0xF0, 0xE4, 0x42),
        Color32::from_rgb(0x3D, 0x8B, 0xD9),
        Color32::from_rgb(0xD5, 0x5E, 0x00),
        Color32::from_rgb(0xCC, 0x79, 0xA7),
    ],
    others: [
        Color32::from_rgb(150, 150, 150),
        Color32::from_rgb(90, 140, 160),
        Color32::from_rgb(200, 170, 130),
        Color32::from_rgb(130, 170, 120),
        Color32::from_rgb(170, 130, 170),
    ],
    view_bg: Color32::from_rgb(16, 20, 30),
    plot_bg: Color32::from_rgb(27, 27, 27),
    ink: Color32::from_gray(210),
    ink_dim: Color32::from_gray(150),
    grid_front: Color32::from_gray(95),
    grid_back: Color32::from_gray(50),
    equator: [
        Color32::from_rgb(120, 160, 230),
        Color32::from_rgb(60, 80, 120),
    ],
    highlight: Color32::from_rgb(230, 200, 80),
    error: Color32::from_rgb(255, 128, 128),
    warn: Color32::from_rgb(240, 220, 90),
    good: Color32::from_rgb(140, 220, 140),
    outages: [
        Color32::from_rgba_premultiplied(60, 50, 0, 40),
        Color32::from_rgba_premultiplied(60, 0, 30, 40),
        Color32::from_rgba_premultiplied(0, 40, 60, 40),
    ],
    focus: Color32::from_rgb(0xFF, 0xD3, 0x3D),
};

/// The light theme for projectors: truth black; vermillion, blue and bluish green from
/// Okabe and Ito, the rest found by a search that kept every pair apart under simulated
/// colour-blindness and every colour at 3:1 or more against white.
pub const LIGHT: Palette = Palette {
    sources: [
        Color32::from_rgb(0x00, 0x00, 0x00),
        Color32::from_rgb(0xD5, 0x5E, 0x00),
        Color32::from_rgb(0x00, 0x72, 0xB2),
        Color32::from_rgb(0x00, 0x9E, 0x73),
        Color32::from_rgb(0x99, 0x00, 0xFF),
        Color32::from_rgb(0x77, 0x44, 0x66),
        Color32::from_rgb(0xDD, 0x00, 0x44),
        Color32::from_rgb(0x99, 0x66, 0xEE),
    ],
    others: [
        Color32::from_rgb(120, 120, 120),
        Color32::from_rgb(60, 110, 130),
        Color32::from_rgb(150, 110, 60),
        Color32::from_rgb(80, 120, 70),
        Color32::from_rgb(140, 90, 140),
    ],
    view_bg: Color32::from_rgb(244, 246, 250),
    plot_bg: Color32::from_rgb(248, 248, 248),
    ink: Color32::from_gray(25),
    ink_dim: Color32::from_gray(90),
    grid_front: Color32::from_gray(170),
    grid_back: Color32::from_gray(220),
    equator: [
        Color32::from_rgb(30, 80, 180),
        Color32::from_rgb(150, 170, 215),
    ],
    highlight: Color32::from_rgb(170, 120, 0),
    error: Color32::from_rgb(190, 0, 0),
    warn: Color32::from_rgb(140, 90, 0),
    good: Color32::from_rgb(0, 120, 40),
    outages: [
        Color32::from_rgba_premultiplied(60, 50, 0, 40),
        Color32::from_rgba_premultiplied(60, 0, 30, 40),
        Color32::from_rgba_premultiplied(0, 40, 60, 40),
    ],
    focus: Color32::from_rgb(0x00, 0x50, 0xB3),
};

/// The palette of the theme `visuals` belong to.
pub fn of(visuals: &Visuals) -> &'static Palette {
    if visuals.dark_mode { &DARK } else { &LIGHT }
}

/// The panels' background of the theme `visuals` belong to (egui's own), which the frame is
/// cleared to: see [`panels_on_the_clear`].
pub fn clear_colour(visuals: &Visuals) -> Color32 {
    if visuals.dark_mode {
        Visuals::dark().panel_fill
    } else {
        Visuals::light().panel_fill
    }
}

/// Panels paint no background of their own: the frame is cleared to it already
/// ([`clear_colour`]). Each panel's fill was a rectangle over the whole panel, so the whole
/// screen was shaded twice per frame, once by the clear and once by the panels; in a browser
/// drawing WebGL in software (SwiftShader: a GPU on the blocklist, or none) that fill was a
/// third of a frame's cost.
pub fn panels_on_the_clear(ctx: &egui::Context) {
    ctx.all_styles_mut(|style| style.visuals.panel_fill = Color32::TRANSPARENT);
}

/// The palette of the theme a context shows (for painters, which have no `Ui`).
pub fn of_ctx(ctx: &egui::Context) -> &'static Palette {
    if ctx.theme() == egui::Theme::Dark {
        &DARK
    } else {
        &LIGHT
    }
}

/// Estimators' colours cycle through the seven after the truth's.
const ESTIMATOR_COLOURS: usize = 7;

/// The line patterns, cycled by estimator: with seven colours and four patterns, no two of
/// the first 28 estimators share both.
const PATTERNS: usize = 4;

impl Palette {
    /// Colour of a source: truth, then estimators by position — the same colour in the 3D
    /// ghost, the sphere, the dial, every plot and the tables.
    pub fn source(&self, source_index: usize) -> Color32 {
        match source_index {
            0 => self.sources[0],
            s => self.sources[1 + (s - 1) % ESTIMATOR_COLOURS],
        }
    }
}

/// The line pattern of a source (the second channel besides colour): the truth solid, the
/// estimators solid, long dashes, dots, short dashes in turn.
pub fn pattern(source_index: usize) -> LineStyle {
    match source_index {
        0 => LineStyle::Solid,
        s => match (s - 1) % PATTERNS {
            0 => LineStyle::Solid,
            1 => LineStyle::Dashed { length: 14.0 },
            2 => LineStyle::Dotted { spacing: 6.0 },
            _ => LineStyle::Dashed { length: 5.0 },
        },
    }
}

/// The line pattern of each of a plot's `shown` series (index into `specs`, colour): its
/// source's, except where one source draws several series in one colour (a group tab's x,
/// y and z of the truth, which had been three identical white lines), which then take the
/// patterns in turn by their order, so the legend tells them apart; and an estimator's
/// series that a figure colours by position (its x, y, z, in colours that differ) are
/// solid, their colours telling them apart (dashed, paper 2's noisy errors at the scale of their steady part had drawn a
/// dash every few pixels, 221 000 triangles a frame).
pub fn patterns(specs: &[attlab::model::SeriesSpec], shown: &[(usize, Color32)]) -> Vec<LineStyle> {
    let source = |k: usize| specs[shown[k].0].source;
    let same = |a: usize, b: usize| source(a) == source(b) && shown[a].1 == shown[b].1;
    (0..shown.len())
        .map(|k| {
            // Told apart by colour: the source's series in this plot differ in colour.
            let by_colour =
                (0..shown.len()).any(|j| source(j) == source(k) && shown[j].1 != shown[k].1);
            if source(k) > 0 && by_colour {
                return LineStyle::Solid;
            }
            let alike = (0..shown.len()).filter(|j| same(*j, k)).count();
            if alike < 2 {
                return pattern(source(k));
            }
            let rank = (0..k).filter(|j| same(*j, k)).count();
            // The patterns of sources 1, 2, 3, 4: solid, long dashes, dots, short dashes.
            pattern(1 + rank % PATTERNS)
        })
        .collect()
}

/// The marker a plot puts along the line of a source past the palette's first round of
/// colours (the eighth estimator on), by round: a third channel besides colour and
/// pattern, which a noisy line on a log plot hides (paper 2's sixteen filters of "every
/// filter" had shown in about five colours with dashes no one could see).
pub fn marker(source_index: usize) -> Option<egui_plot::MarkerShape> {
    use egui_plot::MarkerShape;
    let round = source_index.checked_sub(1)? / ESTIMATOR_COLOURS;
    const ROUNDS: [MarkerShape; 4] = [
        MarkerShape::Circle,
        MarkerShape::Square,
        MarkerShape::Diamond,
        MarkerShape::Up,
    ];
    round.checked_sub(1).map(|r| ROUNDS[r % ROUNDS.len()])
}

/// The marker of each of a plot's `shown` series (index into `specs`, colour): its
/// source's [`marker`] where another source in the plot draws in the same colour, none
/// where colour already tells it apart (a figure's x, y and z of the eighth filter, in
/// three colours of their own, had carried the markers meant for the sixteen-filter plot).
pub fn markers(
    specs: &[attlab::model::SeriesSpec],
    shown: &[(usize, Color32)],
) -> Vec<Option<egui_plot::MarkerShape>> {
    let source = |k: usize| specs[shown[k].0].source;
    (0..shown.len())
        .map(|k| {
            let shared =
                (0..shown.len()).any(|j| source(j) != source(k) && shown[j].1 == shown[k].1);
            marker(source(k)).filter(|_| shared)
        })
        .collect()
}

/// Paints `shape` `radius` points about `center` in `colour` (a legend's swatch).
pub fn paint_marker(
    painter: &egui::Painter,
    center: egui::Pos2,
    radius: f32,
    (shape, colour): (egui_plot::MarkerShape, Color32),
) {
    use egui_plot::MarkerShape;
    let r = radius;
    let at = |dx: f32, dy: f32| center + egui::vec2(dx, dy);
    let polygon =
        |points: Vec<egui::Pos2>| egui::Shape::convex_polygon(points, colour, egui::Stroke::NONE);
    match shape {
        MarkerShape::Square => {
            painter.rect_filled(
                egui::Rect::from_center_size(center, egui::vec2(1.8 * r, 1.8 * r)),
                0.0,
                colour,
            );
        }
        MarkerShape::Diamond => {
            painter.add(polygon(vec![
                at(0.0, -r),
                at(r, 0.0),
                at(0.0, r),
                at(-r, 0.0),
            ]));
        }
        MarkerShape::Up => {
            painter.add(polygon(vec![at(0.0, -r), at(r, 0.8 * r), at(-r, 0.8 * r)]));
        }
        _ => {
            painter.circle_filled(center, r, colour);
        }
    }
}

/// Draws `points` as one polyline in `style` with `stroke` (the views' trails use the
/// plots' patterns).
pub fn styled_polyline(
    painter: &egui::Painter,
    points: Vec<egui::Pos2>,
    stroke: egui::Stroke,
    style: LineStyle,
) {
    match style {
        LineStyle::Solid => {
            painter.add(egui::Shape::line(points, stroke));
        }
        LineStyle::Dashed { length } => {
            painter.extend(egui::Shape::dashed_line(
                &points,
                stroke,
                length,
                0.6 * length,
            ));
        }
        LineStyle::Dotted { spacing } => {
            painter.extend(egui::Shape::dotted_line(
                &points,
                stroke.color,
                spacing,
                stroke.width,
            ));
        }
    }
}

/// Colours of a figure's series: an estimator's series in its source colour when it is that
/// source's only series in the figure; several series of one estimator (its x, y, z) in the
/// palette by position, skipping the colours the figure's other series take (free
/// rotation's "error about y" had taken the blue of the (u, v, z) integration's whole angle
/// beside it) and the dark theme's second blue until last; the truth's first series in the
/// truth's colour; a second truth series and sensor readings in muted colours no estimator
/// uses.
pub fn figure_colors(palette: &Palette, specs: &[&attlab::model::SeriesSpec]) -> Vec<Color32> {
    let count = |src: usize| specs.iter().filter(|s| s.source == src).count();
    let taken: Vec<Color32> = (specs.iter())
        .filter(|s| s.source > 0 && !s.name.starts_with("truth.") && count(s.source) == 1)
        .map(|s| palette.source(s.source))
        .collect();
    let mut by_position = BY_POSITION
        .iter()
        .map(|k| palette.sources[*k])
        .filter(|c| !taken.contains(c))
        .cycle();
    let mut other = 0;
    let mut truth_seen = false;
    specs
        .iter()
        .map(|s| {
            let is_truth = s.name.starts_with("truth.");
            if is_truth && !truth_seen {
                truth_seen = true;
                return palette.source(0);
            }
            if !is_truth && s.source > 0 {
                if count(s.source) == 1 {
                    return palette.source(s.source);
                }
                return by_position.next().unwrap_or(palette.source(s.source));
            }
            other += 1;
            palette.others[(other - 1) % palette.others.len()]
        })
        .collect()
}

/// The estimators' colours (indices into a palette's sources) in the order a figure gives
/// one filter's several series: the dark theme's two blues (2 and 5) and its orange and
/// vermillion (1 and 6) as far apart as the seven allow.
const BY_POSITION: [usize; 7] = [1, 2, 3, 4, 7, 6, 5];

#[cfg(test)]
#[path = "palette_tests.rs"]
mod tests;
