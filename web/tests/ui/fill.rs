//! How much a frame draws. A browser drawing WebGL in software (SwiftShader: no GPU, or one
//! on the blocklist) pays per shaded pixel and per triangle. The frame is cleared to the
//! panels' colour, so panels paint no background of their own and each pixel is shaded
//! about once (the panels' own fill had been a third of a frame's time); lines are thinned
//! to the pixels they cross, so a triangle covers ten pixels or more on average (p2's
//! sixteen trails on the sphere had been 194 000 triangles, its whole frame 405 000).

use attlab::labs;
use attlab_web::state::RunCommand;

/// The area of every triangle a frame draws, in screens (1.0: the window once), and the
/// number of triangles.
fn shaded_screens(h: &egui_kittest::Harness<'static, attlab_web::AttLabApp>) -> (f64, usize) {
    let output = h.output().clone();
    let primitives = h.ctx.tessellate(output.shapes, output.pixels_per_point);
    let screen = h.ctx.content_rect().area() as f64;
    let (mut area, mut triangles) = (0.0, 0);
    for primitive in &primitives {
        let egui::epaint::Primitive::Mesh(mesh) = &primitive.primitive else {
            continue;
        };
        triangles += mesh.indices.len() / 3;
        for t in mesh.indices.chunks_exact(3) {
            let [a, b, c] = [t[0], t[1], t[2]].map(|i| mesh.vertices[i as usize].pos);
            area += f64::from(((b - a).x * (c - a).y - (c - a).x * (b - a).y).abs()) / 2.0;
        }
    }
    (area / screen, triangles)
}

/// Steps run first: the views' trails full (3 000 rows) and the plots' lines long.
const STEPS: usize = 3000;

#[test]
fn every_lab_shades_its_window_less_than_once_a_frame_in_big_triangles() {
    for lab in labs::all() {
        let mut h = super::harness(lab.id());
        for _ in 0..STEPS {
            h.state_mut().apply(RunCommand::StepOnce.into());
        }
        h.run();
        let (shaded, triangles) = shaded_screens(&h);
        let pixels = h.ctx.content_rect().area() as usize;
        assert!(
            triangles * 10 < pixels,
            "{}: {triangles} triangles for {pixels} pixels (a line not thinned to its pixels?)",
            lab.id()
        );
        assert!(
            shaded < 1.0,
            "{}: a frame shades {shaded:.2} windows (a panel painting its own background?)",
            lab.id()
        );
    }
}
