//! The 3D view's words and its orbit inset, painted at the sizes the view has on a
//! projector (1280×720) and on a phone (390×844), in English and in Russian: no word is cut
//! at the view's edge and none hides another or is hidden by the inset.

use attlab::i18n::{self, FluentValue, Lang};
use attlab::model::OrbitPicture;
use attlab::page::BodyShape;
use attlab_web::render::body3d::{self, OrbitCamera};
use attlab_web::render::scene::{self, Scene, SceneWords};
use egui::epaint::Shape;
use egui::{Rect, Vec2};
use egui_kittest::Harness;
use nalgebra::{UnitQuaternion, Vector3};

/// The sizes of the 3D view in the page tests' screenshots, in points, with the hint each
/// shows: the projector's presenter mode (378 × 193 px at 1.5 px a point), the phone's
/// (a touch screen: no wheel, no double click) and a laptop's (1366×768).
const VIEWS: [(f32, f32, &str); 3] = [
    (252.0, 129.0, "body-hint"),
    (374.0, 120.0, "body-hint-touch"),
    (360.0, 293.0, "body-hint"),
];

/// Paper 2's ghost label, the longest the view shows by default.
const GHOST: &str = "1 ST+Gyro+Mag+Sun [λ,ω]";

/// The scene with its captions: the truth and the ghost, or, for a log (`truth` false),
/// the estimate alone.
fn scene(lang: Lang, (eclipse, truth): (bool, bool), hint: &str) -> Scene<'static> {
    let label = FluentValue::from(GHOST);
    let (first, ghost) = if truth {
        ("body-truth", "body-ghost")
    } else {
        ("body-no-truth", "body-estimate")
    };
    Scene {
        truth: truth.then(UnitQuaternion::identity),
        ghost: Some((UnitQuaternion::identity(), GHOST)),
        suspended: false,
        shape: BodyShape::HexPrism,
        vectors: &[],
        ghost_axis: None,
        orbit: Some(OrbitPicture {
            position_eci_m: Vector3::new(6.978e6, 0.0, 0.0),
            normal_eci: Vector3::z(),
            sun_eci: Vector3::new(0.9, 0.0, -0.436).normalize(),
            eclipse,
            earth_radius_m: 6.378e6,
        }),
        captions: (
            vec![
                i18n::t(lang, first),
                i18n::t_with(lang, ghost, &[("label", label)]),
            ],
            i18n::t(lang, hint),
        ),
        words: SceneWords {
            orbit: (i18n::t(lang, "body-orbit"), i18n::t(lang, "body-shadow")),
            ..SceneWords::default()
        },
    }
}

/// Where each text of the painted view went, and the text itself.
fn texts(h: &Harness<'_>) -> Vec<(Rect, String)> {
    h.output()
        .shapes
        .iter()
        .filter_map(|c| match &c.shape {
            Shape::Text(t) => Some((t.visual_bounding_rect(), t.galley.text().to_owned())),
            _ => None,
        })
        .collect()
}

/// The smallest filled rectangle that holds the inset's caption (the one with "β").
fn inset(h: &Harness<'_>, caption: Rect) -> Option<Rect> {
    h.output()
        .shapes
        .iter()
        .filter_map(|c| match &c.shape {
            Shape::Rect(r) if r.rect.contains_rect(caption) => Some(r.rect),
            _ => None,
        })
        .min_by(|a, b| a.area().total_cmp(&b.area()))
}

#[test]
fn the_views_words_and_orbit_inset_do_not_cover_one_another() {
    for lang in Lang::ALL {
        for (w, h, hint) in VIEWS {
            for (eclipse, truth) in [(false, true), (true, true), (false, false)] {
                let scene = scene(lang, (eclipse, truth), hint);
                let ghost_caption = scene.captions.0[1].clone();
                let mut harness = Harness::builder()
                    .with_size(Vec2::new(w, h))
                    .with_context_setup(attlab_web::app::setup_context)
                    .build_ui(move |ui| {
                        let rect = ui.ctx().content_rect();
                        body3d::show(ui, rect, &mut OrbitCamera::default(), &scene, true);
                    });
                harness.run();
                let case = format!("{lang:?} {w}×{h} eclipse {eclipse} truth {truth}");
                check(&harness, &case);
                let one_line = |said: &str| {
                    let (r, _) = (texts(&harness).into_iter())
                        .find(|(_, t)| t == said)
                        .unwrap_or_else(|| panic!("{case}: “{said}” not drawn"));
                    assert!(r.height() < 20.0, "{case}: “{said}” is {r:?}");
                };
                // The phone's view is short: its English hint takes one line of it.
                if hint == "body-hint-touch" && lang == Lang::En {
                    one_line(&i18n::t(lang, hint));
                }
                // A laptop's view is wide enough for the ghost's caption on one line, the
                // inset below it.
                if w > 355.0 && h > 200.0 && lang == Lang::En && truth {
                    one_line(&ghost_caption);
                }
            }
        }
    }
}

fn check(h: &Harness<'_>, case: &str) {
    let view = h.ctx.content_rect();
    let texts = texts(h);
    assert_eq!(
        texts.len(),
        4,
        "{case}: two captions, the hint, the inset's: {texts:?}"
    );
    for (r, text) in &texts {
        assert!(
            r.left() >= view.left() && r.right() <= view.right() + 0.5,
            "{case}: “{text}” {r:?} is cut at the view's edge {view:?}"
        );
        assert!(
            r.top() >= view.top() && r.bottom() <= view.bottom() + 0.5,
            "{case}: “{text}” {r:?} is outside the view {view:?}"
        );
    }
    for (i, (a, ta)) in texts.iter().enumerate() {
        for (b, tb) in &texts[i + 1..] {
            assert!(
                !a.intersects(*b),
                "{case}: “{ta}” {a:?} runs into “{tb}” {b:?}"
            );
        }
    }
    let Some((caption, _)) = texts.iter().find(|(_, t)| t.contains('β')) else {
        panic!("{case}: no inset caption in {texts:?}");
    };
    let inset = inset(h, *caption).expect("the inset's background");
    assert!(
        inset.width() >= 48.0,
        "{case}: inset {inset:?} too small to read"
    );
    let png = scene::png_button_rect(view);
    assert!(
        !inset.intersects(png),
        "{case}: the inset {inset:?} is under the PNG button {png:?}"
    );
    for (r, text) in texts.iter().filter(|(_, t)| !t.contains('β')) {
        assert!(
            !r.intersects(inset),
            "{case}: the inset {inset:?} hides “{text}” {r:?}"
        );
    }
}
