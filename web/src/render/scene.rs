//! What the 3D view is asked to draw — the truth, the ghost, the reference directions, the
//! orbit, its words — and where the page puts a view's PNG button, which the view's
//! captions and the orbit inset keep clear of.

use attlab::model::{OrbitPicture, SceneVector};
use attlab::page::BodyShape;
use egui::Rect;
use nalgebra::{UnitQuaternion, Vector3};

/// What the 3D view draws: the truth and, beside it, an estimate as a ghost; a replayed or
/// live log, which has no truth, the estimate alone, solid.
pub struct Scene<'a> {
    /// True attitude, where the run has one (not a log's).
    pub truth: Option<UnitQuaternion<f64>>,
    /// Estimated attitude and its label, if the lab's estimator has one: a ghost beside
    /// the truth, or solid where there is no truth.
    pub ghost: Option<(UnitQuaternion<f64>, &'a str)>,
    /// The body hangs on a string from above (paper 1).
    pub suspended: bool,
    /// The body's shape.
    pub shape: BodyShape,
    /// Reference directions drawn from the truth (sun, field, nadir).
    pub vectors: &'a [SceneVector],
    /// The axis (ghost's body axes) about which the ghost's sensors say nothing now.
    pub ghost_axis: Option<Vector3<f64>>,
    /// The orbit, drawn small in a corner.
    pub orbit: Option<OrbitPicture>,
    /// The captions in the reader's language: the lines on top (what is solid, what is the
    /// ghost), and how to move the camera at the bottom.
    pub captions: (Vec<String>, String),
    /// The words drawn in the view, in the reader's language.
    pub words: SceneWords,
}

/// The words the 3D view draws, in the reader's language.
#[derive(Clone, Debug, Default)]
pub struct SceneWords {
    /// Each reference direction's label, in the order of [`Scene::vectors`].
    pub vectors: Vec<String>,
    /// The ghost's unobservable axis.
    pub unobservable: String,
    /// The orbit inset's caption ("orbit") and the word for the Earth's shadow.
    pub orbit: (String, String),
    /// What the view says without a GPU renderer.
    pub no_gpu: String,
}

/// Where a view's small "PNG" button goes: the bottom-right corner of `view` (the page
/// draws it there over every view; the orbit inset keeps clear of it).
pub fn png_button_rect(view: Rect) -> Rect {
    let size = egui::vec2(38.0, 18.0);
    Rect::from_min_size(view.max - size - egui::Vec2::splat(4.0), size)
}
