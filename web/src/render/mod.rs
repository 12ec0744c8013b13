//! Drawing: the 3D body (wgpu), the Riemann sphere and the plots.

pub mod body3d;
pub mod fonts;
pub mod mesh;
pub mod plots;
pub mod riemann_sphere;
