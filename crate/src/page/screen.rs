//! What a lab shows, as data: the views of the page's top row, the body the 3D view draws,
//! what the sensors add to it, the paper's figures as plot tabs, the outages the plots shade
//! and the diagrams beside them. The page (web/) draws from these; the core never reads them
//! to simulate.

use crate::model::{ExampleLog, LogFormat, ParamValues, Quantity, SeriesKey};

/// The body the 3D view draws.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum BodyShape {
    /// A box with two panels.
    #[default]
    Box,
    /// A hexagonal prism (TabletSat).
    HexPrism,
}

/// A named set of series plotted together, e.g. a figure of the paper.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Figure {
    /// Stable id within the lab (`fig8-v`): its messages, a lesson's tab and the page's
    /// tab name it, never its position.
    pub id: &'static str,
    /// Tab title, e.g. "Fig. 8: v and vᵃ".
    pub title: &'static str,
    /// The series drawn in it.
    pub series: &'static [SeriesKey],
    /// Draw log10 of the values (covariance elements spanning decades).
    pub log: bool,
    /// The run's start is a transient that would set the scale (s): the value axis fits
    /// what comes after it, the result the figure shows; zooming out shows the rest.
    pub steady_after_s: Option<f64>,
}

impl Figure {
    /// A figure on a linear axis.
    pub const fn new(id: &'static str, title: &'static str, series: &'static [SeriesKey]) -> Self {
        Self {
            id,
            title,
            series,
            log: false,
            steady_after_s: None,
        }
    }

    /// The same on a log10 axis.
    pub const fn log(self) -> Self {
        Self { log: true, ..self }
    }

    /// The same, its value axis fitted to what comes after the first `t_s` seconds (a
    /// filter that starts degrees off and settles at its first measurement).
    pub const fn steady_after(self, t_s: f64) -> Self {
        Self {
            steady_after_s: Some(t_s),
            ..self
        }
    }
}

/// A sensor outage a lab's plots shade: the intervals where a recorded 0/1 series equals
/// `out_when` (e.g. paper 2's eclipse, or the star tracker unavailable).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Outage {
    /// Stable id within the lab (`star-tracker-out`): its label's message names it.
    pub id: &'static str,
    /// The 0/1 series.
    pub series: SeriesKey,
    /// Its value during the outage.
    pub out_when: f64,
    /// What the shading is called in the legend.
    pub label: &'static str,
}

/// A view the page's top row shows, left to right, as the lab declares (each lab shows what
/// explains it: a body turning about one axis has no use for the Riemann sphere).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ViewKind {
    /// The body in 3D with the estimate as a ghost.
    Body3d,
    /// The Riemann sphere: the vertical in body axes.
    Sphere,
    /// The complex plane of w (or the lab's diagram, when it has one).
    WPlane,
    /// A single-axis angle on a dial, a needle per source.
    Dial,
    /// Rate against angle, a trail per source.
    PhasePortrait,
}

impl ViewKind {
    /// A short lower-case name (file names, test output).
    pub fn slug(self) -> &'static str {
        match self {
            Self::Body3d => "body3d",
            Self::Sphere => "sphere",
            Self::WPlane => "wplane",
            Self::Dial => "dial",
            Self::PhasePortrait => "phase-portrait",
        }
    }

    /// The id of the view's name in the page's message catalogue (`view-body3d`…).
    pub fn message(self) -> &'static str {
        match self {
            Self::Body3d => "view-body3d",
            Self::Sphere => "view-sphere",
            Self::WPlane => "view-wplane",
            Self::Dial => "view-dial",
            Self::PhasePortrait => "view-phase",
        }
    }
}

/// The views of a lab that does not say otherwise.
pub const DEFAULT_VIEWS: &[ViewKind] = &[ViewKind::Body3d, ViewKind::Sphere, ViewKind::WPlane];

/// The views of a lab whose body turns about one axis.
pub const SINGLE_AXIS_VIEWS: &[ViewKind] =
    &[ViewKind::Body3d, ViewKind::Dial, ViewKind::PhasePortrait];

/// A small x–y diagram a lab draws beside its plots (e.g. eigenvalues on the unit circle).
#[derive(Clone, Debug, PartialEq)]
pub struct Diagram {
    /// Stable id within the lab (`eigenvalues`): its title's message names it.
    pub id: &'static str,
    /// Title in words (a catalogue translates it: `lab-<id>-diagram-<index>`).
    pub title: &'static str,
    /// What the title adds in the paper's notation: each setting's symbol, value and unit
    /// as the code writes it, e.g. `("Δt", 1.0, "s")` and `("ε", 0.1, "")` for "Δt = 1 s,
    /// ε = 0.1" (`i18n::diagram_detail` writes it in the reader's language).
    pub detail: Vec<DiagramSetting>,
    /// Draw the unit circle.
    pub unit_circle: bool,
    /// Labelled points.
    pub points: Vec<DiagramPoint>,
}

/// One setting a diagram's title names: its symbol, its value and its unit as the code
/// writes it ("" for none).
pub type DiagramSetting = (&'static str, f64, &'static str);

/// One labelled point of a [`Diagram`].
#[derive(Clone, Debug, PartialEq)]
pub struct DiagramPoint {
    /// Legend text.
    pub label: String,
    /// Position (x, y).
    pub xy: [f64; 2],
    /// Id of the estimator the point belongs to (it takes that estimator's colour and hides
    /// with it), if any.
    pub source: Option<&'static str>,
}

/// What the page shows of a lab, as data: the views of the top row, the body the 3D view
/// draws, the paper's figures as plot tabs, the outages they shade, the diagrams beside
/// them, and the recorded logs its estimators can replay. Nothing in it changes the
/// simulation: the loop reads only the figures (their series are recorded by default) and
/// whether the body hangs on a string (then it has no sphere to record).
#[derive(Clone, Copy, Debug)]
pub struct Page {
    /// The views of the top row, left to right.
    pub views: &'static [ViewKind],
    /// The body the 3D view draws.
    pub body: BodyShape,
    /// True when the body hangs on a string (the 3D view draws it).
    pub suspended: bool,
    /// The paper's figures as plot tabs.
    pub figures: &'static [Figure],
    /// Outages the plots shade (every plot, every tab).
    pub outages: &'static [Outage],
    /// Diagrams that explain the current parameters, if the lab draws any.
    pub diagrams: Option<fn(&ParamValues) -> Vec<Diagram>>,
    /// The kind of recorded log the lab's estimators can run on instead of simulated
    /// sensors (its laboratory mode), if any.
    pub log_format: Option<&'static LogFormat>,
    /// A log the lab ships for its laboratory mode, if it has one.
    pub example_log: Option<ExampleLog>,
}

impl Page {
    /// A three-axis body in a box with the default views and nothing else.
    pub const DEFAULT: Page = Page {
        views: DEFAULT_VIEWS,
        body: BodyShape::Box,
        suspended: false,
        figures: &[],
        outages: &[],
        diagrams: None,
        log_format: None,
        example_log: None,
    };

    /// The figure with id `id`.
    pub fn figure(&self, id: &str) -> Option<&'static Figure> {
        self.figures.iter().find(|f| f.id == id)
    }

    /// The diagrams for `params` (none if the lab draws none).
    pub fn diagrams(&self, params: &ParamValues) -> Vec<Diagram> {
        self.diagrams.map_or_else(Vec::new, |d| d(params))
    }
}

/// 1 at a replay's step that delivered a logged sample, 0 at one that did not (a dropped
/// sample, or the join of a gap or a restart).
pub const LOGGED_SAMPLE: Quantity = Quantity::new("log_sample", "logged sample at this step", "");

/// What a replay's plots shade: the steps without a logged sample.
pub const REPLAY_GAPS: Outage = Outage {
    id: "replay-gaps",
    series: SeriesKey::sensors(&LOGGED_SAMPLE),
    out_when: 0.0,
    label: "no logged sample (a gap or a restart of the log's clock)",
};
