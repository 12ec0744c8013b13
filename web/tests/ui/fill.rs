//! How much a frame shades: the frame is cleared to the panels' colour, so panels paint no
//! background of their own and each pixel is shaded about once. A browser drawing WebGL in
//! software (SwiftShader: no GPU, or one on the blocklist) pays per shaded pixel; there the
//! panels' own fill had been a third of a frame's time.

use attlab::labs;
use attlab_web::state::RunCommand;

/// The area of every triangle a frame draws, in screens (1.0: the window once).
fn shaded_screens(h: &egui_kittest::Harness<'static, attlab_web::AttLabApp>) -> f64 {
    let output = h.output().clone();
    let primitives = h.ctx.tessellate(output.shapes, output.pixels_per_point);
    let screen = h.ctx.content_rect().area() as f64;
    let mut area = 0.0;
    for primitive in &primitives {
        let egui::epaint::Primitive::Mesh(mesh) = &primitive.primitive else {
            continue;
        };
        for t in mesh.indices.chunks_exact(3) {
            let [a, b, c] = [t[0], t[1], t[2]].map(|i| mesh.vertices[i as usize].pos);
            area += f64::from(((b - a).x * (c - a).y - (c - a).x * (b - a).y).abs()) / 2.0;
        }
    }
    area / screen
}

#[test]
fn every_lab_shades_its_window_less_than_once_a_frame() {
    for lab in labs::all() {
        let mut h = super::harness(lab.id());
        for _ in 0..300 {
            h.state_mut().apply(RunCommand::StepOnce.into());
        }
        h.run();
        let shaded = shaded_screens(&h);
        assert!(
            shaded < 1.0,
            "{}: a frame shades {shaded:.2} windows (a panel painting its own background?)",
            lab.id()
        );
    }
}
