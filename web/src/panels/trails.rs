//! The trails the Riemann sphere and the w plane draw: the recent vertical of the truth and
//! of every estimator that has one, with each filter's 3σ ellipse, computed in its own
//! chart, gathered once a frame for both views.

use super::tr;
use crate::render::palette::{self, Palette};
use crate::render::riemann_sphere;
use crate::state::AppState;
use attlab::math::WzAttitude;
use attlab::model::{Quantity, SeriesKey, StateKind, TRUTH, q};
use egui::Ui;
use nalgebra::Vector3;
use std::cell::OnceCell;

/// The sphere's and the w plane's trails with their ellipses, gathered on first use.
pub(super) type Trails = OnceCell<Vec<riemann_sphere::SphereTrack>>;

/// The trails of `trails`, gathered if this is the frame's first view to need them.
pub(super) fn trails_of<'a>(
    trails: &'a Trails,
    app: &AppState,
    ui: &Ui,
) -> &'a [riemann_sphere::SphereTrack] {
    trails.get_or_init(|| {
        let mut tracks = tracks(app, palette::of(ui.visuals()));
        attach_ellipses(app, &mut tracks);
        tracks
    })
}

/// The recent trail of every source with a vertical: truth, then each estimator.
fn tracks(app: &AppState, colours: &Palette) -> Vec<riemann_sphere::SphereTrack> {
    let rec = app.sim().recorder();
    // Up to the timeline's cursor: the rows recorded after it are left out.
    let skipped = app.sim().steps().saturating_sub(app.shown().steps()) as usize;
    let truth = tr(app, "truth");
    let mut names = vec![(TRUTH, truth)];
    names.extend(
        app.sim()
            .estimators()
            .iter()
            .enumerate()
            .map(|(i, e)| (e.id(), super::estimator_name(app, i))),
    );
    let mut out = Vec::new();
    for (i, (src, label)) in names.iter().enumerate() {
        if app.view().hidden.contains(&i) {
            continue;
        }
        let col = |quantity: &'static Quantity| {
            rec.index_of(&SeriesKey::new(src, quantity).name())
                .map(|j| rec.recent_tail_before(j, skipped, TRAIL_ROWS, TRAIL_POINTS))
        };
        let (Some(kx), Some(ky), Some(kz), Some(u), Some(v)) = (
            col(&q::K_X),
            col(&q::K_Y),
            col(&q::K_Z),
            col(&q::U),
            col(&q::V),
        ) else {
            continue;
        };
        let mut k_body = Vec::new();
        let mut w = Vec::new();
        for j in 0..kx.len() {
            if kx[j].is_finite() {
                k_body.push(Vector3::new(kx[j], ky[j], kz[j]));
                w.push([u[j], v[j]]);
            }
        }
        if k_body.is_empty() {
            continue;
        }
        out.push(riemann_sphere::SphereTrack {
            name: label.to_string(),
            color: colours.source(i),
            pattern: palette::pattern(i),
            k_body,
            w,
            ellipse: None,
        });
    }
    out
}

/// Rows of history drawn as trails on the sphere and the plane.
const TRAIL_ROWS: usize = 3000;
/// Points per trail after thinning.
const TRAIL_POINTS: usize = 600;

/// 3σ ellipses of every estimator whose covariance holds (u, v), in its own chart, mapped
/// point by point to the w plane and to the sphere (so it stays right in the flipped chart).
/// The states are found by what the covariance says they are, not by names.
fn attach_ellipses(app: &AppState, tracks: &mut [riemann_sphere::SphereTrack]) {
    for (e, est) in app.shown().estimators().iter().zip(app.shown().estimates()) {
        let (Some(wz), Some(cov)) = (est.attitude.wz(), e.covariance()) else {
            continue;
        };
        let (Some(iu), Some(iv)) = (cov.index_of(StateKind::WzU), cov.index_of(StateKind::WzV))
        else {
            continue;
        };
        let p = nalgebra::Matrix2::new(
            cov.get(iu, iu),
            cov.get(iu, iv),
            cov.get(iv, iu),
            cov.get(iv, iv),
        );
        let Some(chol) = p.cholesky() else { continue };
        let l = chol.l();
        let ring: Vec<WzAttitude> = (0..64)
            .map(|j| {
                let a = f64::from(j) * std::f64::consts::TAU / 64.0;
                let d = l * nalgebra::Vector2::new(a.cos(), a.sin()) * 3.0;
                WzAttitude {
                    u: wz.u + d.x,
                    v: wz.v + d.y,
                    ..wz
                }
            })
            .collect();
        let plane = ring
            .iter()
            .map(|p| p.w().map_or([f64::NAN, f64::NAN], |(u, v)| [u, v]))
            .collect();
        let sphere = ring.iter().map(WzAttitude::vertical_in_body).collect();
        if let Some(t) = tracks.iter_mut().find(|t| t.name == e.label()) {
            t.ellipse = Some((plane, sphere));
        }
    }
}
