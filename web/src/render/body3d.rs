//! The 3D body view: a wgpu paint callback drawing the truth body and the estimate as a
//! translucent ghost beside it (a log, which has no truth: the estimate alone, solid),
//! with a mouse-orbit camera.

use super::mesh::{
    Triangle, Vertex, body_mesh, hex_prism_mesh, place, rod, sorted_vertices, string_mesh,
};
use super::scene::Scene;
use attlab::model::Direction;
use attlab::page::BodyShape;
use eframe::egui_wgpu::{self, wgpu};
use egui::{Color32, Pos2, Rect, Sense, Ui};
use nalgebra::{Matrix4, Point3, UnitQuaternion, Vector3};
use std::sync::OnceLock;

/// Orbit camera around the scene centre (world z up).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OrbitCamera {
    /// Azimuth (rad).
    pub yaw_rad: f64,
    /// Elevation (rad).
    pub pitch_rad: f64,
    /// Distance from the centre.
    pub distance: f64,
}

impl Default for OrbitCamera {
    fn default() -> Self {
        Self {
            yaw_rad: -1.2,
            pitch_rad: 0.45,
            distance: 7.5,
        }
    }
}

impl OrbitCamera {
    /// Eye position.
    pub fn eye(&self) -> Point3<f64> {
        let (sy, cy) = self.yaw_rad.sin_cos();
        let (sp, cp) = self.pitch_rad.sin_cos();
        Point3::new(cp * cy, cp * sy, sp) * self.distance
    }

    /// View-projection matrix for wgpu's clip space (z in 0…1).
    pub fn view_proj(&self, aspect: f64) -> Matrix4<f64> {
        let view = Matrix4::look_at_rh(&self.eye(), &Point3::origin(), &Vector3::z());
        let proj = Matrix4::new_perspective(aspect.max(1e-3), 40f64.to_radians(), 0.1, 100.0);
        // OpenGL clip z (−1…1) → wgpu (0…1).
        let gl_to_wgpu = Matrix4::new(
            1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.5, 0.5, 0.0, 0.0, 0.0, 1.0,
        );
        gl_to_wgpu * proj * view
    }

    /// Drag to orbit, scroll to zoom.
    pub fn handle_input(&mut self, response: &egui::Response, ui: &Ui) {
        if response.dragged() {
            let d = response.drag_delta();
            self.yaw_rad -= f64::from(d.x) * 0.01;
            self.pitch_rad = (self.pitch_rad + f64::from(d.y) * 0.01).clamp(-1.5, 1.5);
        }
        // The wheel, and two fingers pinching (egui's zoom delta: > 1 spreads them).
        let (scroll, pinch) = ui.input(|i| (i.smooth_scroll_delta.y, i.zoom_delta()));
        let factor = (1.0 - f64::from(scroll) * 0.002) / f64::from(pinch);
        if response.hovered() {
            self.distance = (self.distance * factor).clamp(3.0, 30.0);
        }
        if response.double_clicked() {
            *self = Self::default();
        }
    }
}

fn mesh(shape: BodyShape) -> &'static [Triangle] {
    static BOX: OnceLock<Vec<Triangle>> = OnceLock::new();
    static HEX: OnceLock<Vec<Triangle>> = OnceLock::new();
    match shape {
        BodyShape::Box => BOX.get_or_init(body_mesh),
        BodyShape::HexPrism => HEX.get_or_init(hex_prism_mesh),
    }
}

#[repr(C)]
#[derive(Clone, Copy, Debug, bytemuck::Pod, bytemuck::Zeroable)]
struct Uniforms {
    view_proj: [[f32; 4]; 4],
    light_dir: [f32; 4],
    flags: [f32; 4],
}

/// GPU objects kept in egui-wgpu's callback resources.
struct Body3dResources {
    pipeline: wgpu::RenderPipeline,
    bind_group: wgpu::BindGroup,
    uniform_buffer: wgpu::Buffer,
    vertex_buffer: wgpu::Buffer,
    vertex_capacity: usize,
    vertex_count: u32,
}

/// Creates the pipeline once; call from the app's creation context.
pub fn init(render_state: &egui_wgpu::RenderState) {
    let device = &render_state.device;
    let uniform_buffer = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("attlab_body3d_uniforms"),
        size: std::mem::size_of::<Uniforms>() as u64,
        usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("attlab_body3d_layout"),
        entries: &[wgpu::BindGroupLayoutEntry {
            binding: 0,
            visibility: wgpu::ShaderStages::VERTEX | wgpu::ShaderStages::FRAGMENT,
            ty: wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Uniform,
                has_dynamic_offset: false,
                min_binding_size: None,
            },
            count: None,
        }],
    });
    let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some("attlab_body3d_bind_group"),
        layout: &layout,
        entries: &[wgpu::BindGroupEntry {
            binding: 0,
            resource: uniform_buffer.as_entire_binding(),
        }],
    });
    let pipeline = pipeline(device, &layout, render_state.target_format);
    let vertex_capacity = 4096;
    let vertex_buffer = new_vertex_buffer(device, vertex_capacity);
    let srgb = render_state.target_format.is_srgb();
    log::info!(
        "body3d pipeline ready (target {:?}, sRGB {srgb})",
        render_state.target_format
    );
    render_state
        .renderer
        .write()
        .callback_resources
        .insert(Body3dResources {
            pipeline,
            bind_group,
            uniform_buffer,
            vertex_buffer,
            vertex_capacity,
            vertex_count: 0,
        });
    SRGB_TARGET.get_or_init(|| srgb);
}

/// The render pipeline: body3d.wgsl over triangles of [`Vertex`], blended with
/// premultiplied alpha into `format`.
fn pipeline(
    device: &wgpu::Device,
    layout: &wgpu::BindGroupLayout,
    format: wgpu::TextureFormat,
) -> wgpu::RenderPipeline {
    let shader = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("attlab_body3d"),
        source: wgpu::ShaderSource::Wgsl(include_str!("body3d.wgsl").into()),
    });
    let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
        label: Some("attlab_body3d_pipeline_layout"),
        bind_group_layouts: &[Some(layout)],
        immediate_size: 0,
    });
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some("attlab_body3d_pipeline"),
        layout: Some(&pipeline_layout),
        vertex: wgpu::VertexState {
            module: &shader,
            entry_point: Some("vs_main"),
            buffers: &[Some(wgpu::VertexBufferLayout {
                array_stride: std::mem::size_of::<Vertex>() as u64,
                step_mode: wgpu::VertexStepMode::Vertex,
                attributes: &wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3, 2 => Float32x4],
            })],
            compilation_options: wgpu::PipelineCompilationOptions::default(),
        },
        primitive: wgpu::PrimitiveState { cull_mode: None, ..wgpu::PrimitiveState::default() },
        depth_stencil: None,
        multisample: wgpu::MultisampleState::default(),
        fragment: Some(wgpu::FragmentState {
            module: &shader,
            entry_point: Some("fs_main"),
            targets: &[Some(wgpu::ColorTargetState {
                format,
                blend: Some(wgpu::BlendState::PREMULTIPLIED_ALPHA_BLENDING),
                write_mask: wgpu::ColorWrites::ALL,
            })],
            compilation_options: wgpu::PipelineCompilationOptions::default(),
        }),
        multiview_mask: None,
        cache: None,
    })
}

static SRGB_TARGET: OnceLock<bool> = OnceLock::new();

fn new_vertex_buffer(device: &wgpu::Device, capacity: usize) -> wgpu::Buffer {
    device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("attlab_body3d_vertices"),
        size: (capacity * std::mem::size_of::<Vertex>()) as u64,
        usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    })
}

struct Body3dCallback {
    uniforms: Uniforms,
    vertices: Vec<Vertex>,
}

impl egui_wgpu::CallbackTrait for Body3dCallback {
    fn prepare(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        _screen: &egui_wgpu::ScreenDescriptor,
        _encoder: &mut wgpu::CommandEncoder,
        resources: &mut egui_wgpu::CallbackResources,
    ) -> Vec<wgpu::CommandBuffer> {
        let Some(res) = resources.get_mut::<Body3dResources>() else {
            return Vec::new();
        };
        if self.vertices.len() > res.vertex_capacity {
            res.vertex_capacity = self.vertices.len().next_power_of_two();
            res.vertex_buffer = new_vertex_buffer(device, res.vertex_capacity);
        }
        queue.write_buffer(&res.uniform_buffer, 0, bytemuck::bytes_of(&self.uniforms));
        if !self.vertices.is_empty() {
            queue.write_buffer(&res.vertex_buffer, 0, bytemuck::cast_slice(&self.vertices));
        }
        res.vertex_count = self.vertices.len() as u32;
        Vec::new()
    }

    fn paint(
        &self,
        _info: egui::PaintCallbackInfo,
        pass: &mut wgpu::RenderPass<'static>,
        resources: &egui_wgpu::CallbackResources,
    ) {
        let Some(res) = resources.get::<Body3dResources>() else {
            return;
        };
        if res.vertex_count == 0 {
            return;
        }
        pass.set_pipeline(&res.pipeline);
        pass.set_bind_group(0, &res.bind_group, &[]);
        pass.set_vertex_buffer(0, res.vertex_buffer.slice(..));
        pass.draw(0..res.vertex_count, 0..1);
    }
}

/// Shows the 3D view filling `rect`.
pub fn show(ui: &mut Ui, rect: Rect, camera: &mut OrbitCamera, scene: &Scene<'_>, gpu_ready: bool) {
    let response = ui.allocate_rect(rect, Sense::click_and_drag());
    camera.handle_input(&response, ui);
    let painter = ui.painter_at(rect);
    let colours = super::palette::of(ui.visuals());
    painter.rect_filled(rect, 4.0, colours.view_bg);
    if !gpu_ready {
        painter.text(
            rect.center(),
            egui::Align2::CENTER_CENTER,
            &scene.words.no_gpu,
            egui::FontId::proportional(14.0),
            colours.error,
        );
        return;
    }
    let (tris, labels) = scene_triangles(scene, &camera.eye());
    let vp = camera.view_proj(f64::from(rect.width() / rect.height().max(1.0)));
    painter.add(egui_wgpu::Callback::new_paint_callback(
        rect,
        Body3dCallback {
            uniforms: uniforms(&vp),
            vertices: sorted_vertices(tris),
        },
    ));
    for (p, text, color) in labels {
        if let Some(at) = to_screen(&vp, rect, &p) {
            painter.text(
                at,
                egui::Align2::LEFT_BOTTOM,
                text,
                egui::FontId::proportional(12.0),
                color,
            );
        }
    }
    let (caption_rects, below) = super::body_captions::captions(&painter, rect, scene);
    if let Some(orbit) = &scene.orbit
        && let Some(area) = super::orbit_inset::area(rect, &caption_rects, below)
    {
        super::orbit_inset::orbit_picture(&painter, area, orbit, &scene.words.orbit);
    }
}

/// A label at a world point: (point, text, colour).
type Label<'a> = (Vector3<f64>, &'a str, Color32);

/// A triangle ready to sort back to front: (distance from the eye, vertices).
type Placed = (f64, [Vertex; 3]);

/// The scene's triangles seen from `eye` — the body, its ghost, the reference vectors, the
/// unobservable axis, the string — and the labels at the tips of the vectors.
fn scene_triangles<'a>(scene: &'a Scene<'a>, eye: &Point3<f64>) -> (Vec<Placed>, Vec<Label<'a>>) {
    let body = mesh(scene.shape);
    let mut tris = Vec::with_capacity(body.len() * 2 + 64);
    // Side by side when both are drawn; the estimate solid when there is no truth.
    let spacing = if scene.truth.is_some() && scene.ghost.is_some() {
        1.6
    } else {
        0.0
    };
    let ghost_alpha = if scene.truth.is_some() { 0.35 } else { 1.0 };
    let truth_at = Vector3::new(0.0, -spacing, 0.0);
    let ghost_at = Vector3::new(0.0, spacing, 0.0);
    if let Some(q) = scene.truth {
        place(body, &q, truth_at, 1.0, eye, &mut tris);
    }
    if let Some((q, _)) = scene.ghost {
        place(body, &q, ghost_at, ghost_alpha, eye, &mut tris);
    }
    let mut labels: Vec<Label<'a>> = Vec::new();
    let mut rods = Vec::new();
    for (k, v) in scene.vectors.iter().enumerate() {
        let tip = truth_at + v.dir_ref * 1.5;
        let [r, g, b] = direction_rgb(v.kind);
        let color = [
            f32::from(r) / 255.0,
            f32::from(g) / 255.0,
            f32::from(b) / 255.0,
        ];
        rod(truth_at, tip, 0.018, color, &mut rods);
        let label = scene.words.vectors.get(k).map_or(v.label, String::as_str);
        labels.push((tip, label, Color32::from_rgb(r, g, b)));
    }
    if let (Some(axis), Some((q, _))) = (scene.ghost_axis, scene.ghost) {
        let d = q * axis;
        rod(
            ghost_at - d * 1.1,
            ghost_at + d * 1.1,
            0.022,
            [0.95, 0.3, 0.85],
            &mut rods,
        );
        labels.push((
            ghost_at + d * 1.15,
            &scene.words.unobservable,
            Color32::from_rgb(242, 77, 217),
        ));
    }
    let world = UnitQuaternion::identity();
    place(&rods, &world, Vector3::zeros(), 1.0, eye, &mut tris);
    if scene.suspended {
        let top = Vector3::new(0.0, 0.0, 0.3);
        let mut bodies: Vec<_> = scene
            .truth
            .map(|q| (q, -spacing, 1.0))
            .into_iter()
            .collect();
        bodies.extend(scene.ghost.map(|(q, _)| (q, spacing, ghost_alpha)));
        for (q, y, alpha) in bodies {
            let attach = q * top + Vector3::new(0.0, y, 0.0);
            let string = string_mesh(attach, 4.0);
            place(&string, &world, Vector3::zeros(), alpha, eye, &mut tris);
        }
    }
    (tris, labels)
}

/// The shader's uniforms for the view-projection `vp`.
fn uniforms(vp: &Matrix4<f64>) -> Uniforms {
    let mut view_proj = [[0.0f32; 4]; 4];
    for (c, col) in view_proj.iter_mut().enumerate() {
        for (r, v) in col.iter_mut().enumerate() {
            *v = vp[(r, c)] as f32;
        }
    }
    let srgb = SRGB_TARGET.get().copied().unwrap_or(false);
    Uniforms {
        view_proj,
        light_dir: [0.4, -0.6, 0.8, 0.28],
        flags: [if srgb { 1.0 } else { 0.0 }, 0.0, 0.0, 0.0],
    }
}

/// `p` (world) on the screen, if it is in front of the camera.
fn to_screen(vp: &Matrix4<f64>, rect: Rect, p: &Vector3<f64>) -> Option<Pos2> {
    let clip = vp * p.push(1.0);
    if clip.w <= 1e-9 {
        return None;
    }
    let (x, y) = (clip.x / clip.w, clip.y / clip.w);
    Some(Pos2::new(
        rect.left() + ((x + 1.0) / 2.0) as f32 * rect.width(),
        rect.top() + ((1.0 - y) / 2.0) as f32 * rect.height(),
    ))
}

/// A reference direction's colour (sRGB): the Sun yellow, the field blue, the nadir green.
fn direction_rgb(kind: Direction) -> [u8; 3] {
    match kind {
        Direction::Sun => [255, 210, 60],
        Direction::MagneticField => [90, 200, 255],
        Direction::Nadir => [120, 220, 120],
    }
}
