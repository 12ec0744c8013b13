// Attitude Lab — shaded body mesh. Vertices arrive in world space (reference frame, ζ up),
// already sorted back to front on the CPU, so translucent ghosts blend correctly without a
// depth buffer.

struct Uniforms {
    view_proj: mat4x4<f32>,
    light_dir: vec4<f32>,   // xyz: direction towards the light (world), w: ambient
    flags: vec4<f32>,       // x: 1 when the target is sRGB (convert gamma colours to linear)
};

@group(0) @binding(0) var<uniform> u: Uniforms;

struct VertexIn {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) color: vec4<f32>,
};

struct VertexOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) normal: vec3<f32>,
    @location(1) color: vec4<f32>,
};

@vertex
fn vs_main(v: VertexIn) -> VertexOut {
    var out: VertexOut;
    out.clip = u.view_proj * vec4<f32>(v.position, 1.0);
    out.normal = v.normal;
    out.color = v.color;
    return out;
}

fn to_linear(c: vec3<f32>) -> vec3<f32> {
    return pow(c, vec3<f32>(2.2));
}

@fragment
fn fs_main(v: VertexOut) -> @location(0) vec4<f32> {
    let n = normalize(v.normal);
    let diffuse = max(dot(n, normalize(u.light_dir.xyz)), 0.0);
    let shade = u.light_dir.w + (1.0 - u.light_dir.w) * diffuse;
    var rgb = v.color.rgb * shade;
    if (u.flags.x > 0.5) {
        rgb = to_linear(rgb);
    }
    // Premultiplied alpha, as egui's own pipeline blends.
    return vec4<f32>(rgb * v.color.a, v.color.a);
}
