//! The body meshes (a box bus with two solar panels, TabletSat's hexagonal prism, body axes)
//! and rods for drawn vectors, built in body axes and
//! transformed and depth-sorted on the CPU each frame.

use nalgebra::{Point3, UnitQuaternion, Vector3};

/// One vertex as the shader reads it.
#[repr(C)]
#[derive(Clone, Copy, Debug, bytemuck::Pod, bytemuck::Zeroable)]
pub struct Vertex {
    /// World position.
    pub position: [f32; 3],
    /// World normal.
    pub normal: [f32; 3],
    /// Gamma-space RGBA.
    pub color: [f32; 4],
}

/// A triangle in body axes with a flat normal and colour.
#[derive(Clone, Copy, Debug)]
pub struct Triangle {
    corners: [Vector3<f64>; 3],
    normal: Vector3<f64>,
    color: [f32; 3],
}

fn cuboid(center: Vector3<f64>, half: Vector3<f64>, color: [f32; 3], out: &mut Vec<Triangle>) {
    // Each face: outward normal along ±axis; corners ordered counter-clockwise seen from outside.
    for axis in 0..3 {
        for sign in [-1.0, 1.0] {
            let mut n = Vector3::zeros();
            n[axis] = sign;
            let (a, b) = ((axis + 1) % 3, (axis + 2) % 3);
            let corner = |sa: f64, sb: f64| {
                let mut p = center;
                p[axis] += sign * half[axis];
                p[a] += sa * half[a];
                p[b] += sb * half[b];
                p
            };
            let quad = if sign > 0.0 {
                [
                    corner(-1.0, -1.0),
                    corner(1.0, -1.0),
                    corner(1.0, 1.0),
                    corner(-1.0, 1.0),
                ]
            } else {
                [
                    corner(-1.0, -1.0),
                    corner(-1.0, 1.0),
                    corner(1.0, 1.0),
                    corner(1.0, -1.0),
                ]
            };
            out.push(Triangle {
                corners: [quad[0], quad[1], quad[2]],
                normal: n,
                color,
            });
            out.push(Triangle {
                corners: [quad[0], quad[2], quad[3]],
                normal: n,
                color,
            });
        }
    }
}

/// The spacecraft-like body in body axes: bus, panels along ±x, an antenna along +y (the
/// forward axis of paper 3) and the three body axes (x red, y green, z blue).
pub fn body_mesh() -> Vec<Triangle> {
    let mut t = Vec::new();
    cuboid(
        Vector3::zeros(),
        Vector3::new(0.35, 0.5, 0.3),
        [0.78, 0.74, 0.62],
        &mut t,
    );
    for s in [-1.0, 1.0] {
        cuboid(
            Vector3::new(s * 0.85, 0.0, 0.0),
            Vector3::new(0.45, 0.28, 0.02),
            [0.20, 0.32, 0.72],
            &mut t,
        );
    }
    cuboid(
        Vector3::new(0.0, 0.62, 0.0),
        Vector3::new(0.08, 0.12, 0.08),
        [0.85, 0.55, 0.2],
        &mut t,
    );
    body_axes(&mut t);
    t
}

/// The three body axes (x red, y green, z blue).
fn body_axes(t: &mut Vec<Triangle>) {
    let axes = [
        (0, [0.9, 0.2, 0.2]),
        (1, [0.2, 0.8, 0.25]),
        (2, [0.25, 0.45, 1.0]),
    ];
    for (axis, color) in axes {
        let mut c = Vector3::zeros();
        c[axis] = 0.75;
        let mut h = Vector3::repeat(0.025);
        h[axis] = 0.75;
        cuboid(c, h, color, t);
    }
}

/// TabletSat: a hexagonal prism about body z (the zenith in nominal attitude) with a star
/// tracker 45° off +z toward +y, and the body axes.
pub fn hex_prism_mesh() -> Vec<Triangle> {
    let mut t = Vec::new();
    let (r, h) = (0.5, 0.3);
    let color = [0.78, 0.74, 0.62];
    let corner = |k: usize, z: f64| {
        let a = std::f64::consts::TAU * k as f64 / 6.0;
        Vector3::new(r * a.cos(), r * a.sin(), z)
    };
    for k in 0..6 {
        let (a0, a1) = (corner(k, -h), corner(k + 1, -h));
        let (b0, b1) = (corner(k, h), corner(k + 1, h));
        let mid = (a0 + a1) / 2.0;
        let normal = Vector3::new(mid.x, mid.y, 0.0).normalize();
        t.push(Triangle {
            corners: [a0, a1, b1],
            normal,
            color,
        });
        t.push(Triangle {
            corners: [a0, b1, b0],
            normal,
            color,
        });
        // End caps as fans about the axis (solar cells on +z).
        t.push(Triangle {
            corners: [Vector3::new(0.0, 0.0, h), b0, b1],
            normal: Vector3::z(),
            color: [0.22, 0.32, 0.62],
        });
        t.push(Triangle {
            corners: [Vector3::new(0.0, 0.0, -h), a1, a0],
            normal: -Vector3::z(),
            color,
        });
    }
    let boresight = Vector3::new(0.0, 1.0, 1.0).normalize();
    rod(
        boresight * 0.3,
        boresight * 0.55,
        0.07,
        [0.35, 0.35, 0.4],
        &mut t,
    );
    body_axes(&mut t);
    t
}

/// A square rod from `from` to `to` (same axes as the mesh it joins), half-width `half`.
pub fn rod(
    from: Vector3<f64>,
    to: Vector3<f64>,
    half: f64,
    color: [f32; 3],
    out: &mut Vec<Triangle>,
) {
    let d = to - from;
    let len = d.norm();
    if len < 1e-9 {
        return;
    }
    let turn = UnitQuaternion::rotation_between(&Vector3::z(), &d).unwrap_or_else(|| {
        UnitQuaternion::from_axis_angle(&Vector3::x_axis(), std::f64::consts::PI)
    });
    let mut local = Vec::new();
    cuboid(
        Vector3::new(0.0, 0.0, len / 2.0),
        Vector3::new(half, half, len / 2.0),
        color,
        &mut local,
    );
    out.extend(local.into_iter().map(|tri| Triangle {
        corners: tri.corners.map(|c| turn * c + from),
        normal: turn * tri.normal,
        color: tri.color,
    }));
}

/// A thin vertical string from `bottom` (world) up to height `top_z`.
pub fn string_mesh(bottom: Vector3<f64>, top_z: f64) -> Vec<Triangle> {
    let mut t = Vec::new();
    let half_len = ((top_z - bottom.z) / 2.0).max(0.0);
    cuboid(
        Vector3::new(bottom.x, bottom.y, bottom.z + half_len),
        Vector3::new(0.012, 0.012, half_len),
        [0.85, 0.85, 0.8],
        &mut t,
    );
    t
}

/// Places `mesh` at `offset` with attitude `q_ref_from_body`, tinted with `alpha`, into
/// `out` together with each triangle's view depth (for sorting).
pub fn place(
    mesh: &[Triangle],
    q_ref_from_body: &UnitQuaternion<f64>,
    offset: Vector3<f64>,
    alpha: f32,
    eye: &Point3<f64>,
    out: &mut Vec<(f64, [Vertex; 3])>,
) {
    for tri in mesh {
        let world = tri.corners.map(|c| q_ref_from_body * c + offset);
        let n = q_ref_from_body * tri.normal;
        let centroid = (world[0] + world[1] + world[2]) / 3.0;
        let to_eye = eye.coords - centroid;
        // Opaque back faces are hidden by the front faces; translucent ones show through.
        if alpha >= 0.999 && n.dot(&to_eye) < 0.0 {
            continue;
        }
        let depth = to_eye.norm();
        let color = [tri.color[0], tri.color[1], tri.color[2], alpha];
        let normal = [n.x as f32, n.y as f32, n.z as f32];
        let v = world.map(|p| Vertex {
            position: [p.x as f32, p.y as f32, p.z as f32],
            normal,
            color,
        });
        out.push((depth, v));
    }
}

/// Sorts back to front (painter's algorithm) and flattens to a vertex list.
pub fn sorted_vertices(mut tris: Vec<(f64, [Vertex; 3])>) -> Vec<Vertex> {
    tris.sort_by(|a, b| b.0.total_cmp(&a.0));
    tris.into_iter().flat_map(|(_, v)| v).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cuboid_normals_point_outwards_and_winding_is_ccw() {
        let mesh = body_mesh();
        assert!(!mesh.is_empty());
        for t in &mesh {
            let e1 = t.corners[1] - t.corners[0];
            let e2 = t.corners[2] - t.corners[0];
            let geometric = e1.cross(&e2);
            assert!(
                geometric.dot(&t.normal) > 0.0,
                "winding disagrees with normal"
            );
        }
    }

    #[test]
    fn the_prism_and_rods_face_outwards() {
        let mut mesh = hex_prism_mesh();
        rod(
            Vector3::new(0.1, 0.2, 0.3),
            Vector3::new(-1.0, 2.0, 0.5),
            0.02,
            [1.0; 3],
            &mut mesh,
        );
        for t in &mesh {
            let geometric = (t.corners[1] - t.corners[0]).cross(&(t.corners[2] - t.corners[0]));
            assert!(
                geometric.dot(&t.normal) > 0.0,
                "winding disagrees with normal"
            );
        }
    }

    #[test]
    fn sorting_puts_far_triangles_first() {
        let eye = Point3::new(0.0, -5.0, 0.0);
        let mut tris = Vec::new();
        place(
            &body_mesh(),
            &UnitQuaternion::identity(),
            Vector3::zeros(),
            0.4,
            &eye,
            &mut tris,
        );
        let depths: Vec<f64> = {
            let mut t = tris.clone();
            t.sort_by(|a, b| b.0.total_cmp(&a.0));
            t.iter().map(|x| x.0).collect()
        };
        assert!(depths.windows(2).all(|w| w[0] >= w[1]));
        assert_eq!(sorted_vertices(tris).len() % 3, 0);
    }
}
