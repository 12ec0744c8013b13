//! The central view: 3D body, Riemann sphere and complex plane on top, plots below.

use crate::app::AttLabApp;
use crate::render::{body3d, plots, riemann_sphere};
use attlab::math::{WzAttitude, WzChart};
use attlab::record::Recorder;
use egui::{Rect, Ui, Vec2};
use nalgebra::Vector3;

/// Rows of history drawn as trails on the sphere and the plane.
const TRAIL_ROWS: usize = 3000;
/// Points per trail after thinning.
const TRAIL_POINTS: usize = 600;

/// Draws the central panel.
pub fn central(ui: &mut Ui, app: &mut AttLabApp) {
    egui::CentralPanel::default().show(ui, |ui| {
        let full = ui.available_rect_before_wrap();
        let top_h = (full.height() * 0.55).max(220.0);
        let top = Rect::from_min_size(full.min, Vec2::new(full.width(), top_h));
        let w3d = top.width() * 0.42;
        let wsphere = top.width() * 0.30;
        let r3d = Rect::from_min_size(top.min, Vec2::new(w3d - 4.0, top_h));
        let rsphere = Rect::from_min_size(
            top.min + Vec2::new(w3d, 0.0),
            Vec2::new(wsphere - 4.0, top_h),
        );
        let rplane = Rect::from_min_max(top.min + Vec2::new(w3d + wsphere, 0.0), top.max);
        let sources = sources(app);
        let source_refs: Vec<&str> = sources.iter().map(String::as_str).collect();
        let mut tracks = tracks(
            app.sim.recorder(),
            &source_refs,
            app.sim.estimates().iter().map(|e| e.1).collect(),
        );
        attach_ellipses(app, &mut tracks);
        draw_body(ui, app, r3d);
        let caption = chart_caption(app);
        riemann_sphere::show_sphere(ui, rsphere, &mut app.sphere, &tracks, &caption);
        ui.scope_builder(egui::UiBuilder::new().max_rect(rplane), |ui| {
            riemann_sphere::show_plane(ui, &tracks)
        });
        let bottom = Rect::from_min_max(full.min + Vec2::new(0.0, top_h + 6.0), full.max);
        ui.scope_builder(egui::UiBuilder::new().max_rect(bottom), |ui| {
            plots::show(
                ui,
                app.sim.recorder(),
                &source_refs,
                app.sim.lab().figures(),
                &mut app.plots,
            );
        });
    });
}

fn sources(app: &AttLabApp) -> Vec<String> {
    std::iter::once("truth".to_string())
        .chain(app.sim.estimates().iter().map(|e| e.0.to_string()))
        .collect()
}

fn draw_body(ui: &mut Ui, app: &mut AttLabApp, rect: Rect) {
    let truth = app.sim.truth().q_ref_from_body;
    let estimates = app.sim.estimates();
    let ghost = estimates
        .get(app.ghost_index)
        .and_then(|e| e.2.q_ref_from_body.map(|q| (q, e.1)));
    let scene = body3d::Scene {
        truth,
        ghost,
        suspended: app.sim.lab().suspended(),
    };
    let ready = app.gpu_ready();
    body3d::show(ui, rect, &mut app.camera, &scene, ready);
}

fn chart_caption(app: &AttLabApp) -> String {
    let charts: Vec<String> = app
        .sim
        .estimates()
        .iter()
        .filter_map(|(id, _, e)| {
            e.wz.map(|wz| match wz.chart {
                WzChart::North => format!("{id}: chart w (projection from S)"),
                WzChart::Flipped => format!("{id}: chart s = 1/w (body upside down)"),
            })
        })
        .collect();
    charts.join("\n")
}

fn tracks(rec: &Recorder, sources: &[&str], labels: Vec<&str>) -> Vec<riemann_sphere::SphereTrack> {
    let mut out = Vec::new();
    for (i, src) in sources.iter().enumerate() {
        let col = |q: &str| {
            rec.index_of(&format!("{src}.{q}"))
                .and_then(|j| rec.column(j))
        };
        let (Some(kx), Some(ky), Some(kz), Some(u), Some(v)) =
            (col("k_x"), col("k_y"), col("k_z"), col("u"), col("v"))
        else {
            continue;
        };
        let n = kx.len();
        let start = n.saturating_sub(TRAIL_ROWS);
        let stride = ((n - start) / TRAIL_POINTS).max(1);
        let mut k_body = Vec::new();
        let mut w = Vec::new();
        let mut j = start;
        while j < n {
            if kx[j].is_finite() {
                k_body.push(Vector3::new(kx[j], ky[j], kz[j]));
                w.push([u[j], v[j]]);
            }
            j = if j + stride >= n && j != n - 1 {
                n - 1
            } else {
                j + stride
            };
        }
        if k_body.is_empty() {
            continue;
        }
        let name = if i == 0 {
            "truth".to_string()
        } else {
            labels.get(i - 1).copied().unwrap_or(src).to_string()
        };
        out.push(riemann_sphere::SphereTrack {
            name,
            color: plots::source_color(i),
            k_body,
            w,
            ellipse: None,
        });
    }
    out
}

/// Covariance names of an estimator that publishes a (u, v) covariance.
const UV_COVARIANCE: [&str; 3] = ["P_uu", "P_uv", "P_vv"];

/// 3σ ellipses of every estimator publishing a (u, v) covariance, in its own chart, mapped
/// point by point to the w plane and to the sphere (so it stays right in the flipped chart).
fn attach_ellipses(app: &AttLabApp, tracks: &mut [riemann_sphere::SphereTrack]) {
    for (i, e) in app.sim.estimates().into_iter().enumerate() {
        let names_match = app
            .sim
            .covariance_names(i)
            .is_some_and(|n| n == UV_COVARIANCE);
        let (Some(wz), true) = (e.2.wz, names_match) else {
            continue;
        };
        let [puu, puv, pvv] = [e.2.covariance[0], e.2.covariance[1], e.2.covariance[2]];
        let Some(chol) = nalgebra::Matrix2::new(puu, puv, puv, pvv).cholesky() else {
            continue;
        };
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
        if let Some(t) = tracks.iter_mut().find(|t| t.name == e.1) {
            t.ellipse = Some((plane, sphere));
        }
    }
}
