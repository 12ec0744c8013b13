//! Drawing: the 3D body (wgpu), the Riemann sphere, the single-axis dial and phase
//! portrait, and the plots.

pub mod body3d;
pub mod clip;
pub mod fonts;
pub mod legend;
pub mod mesh;
mod orbit_inset;
pub mod outages;
pub mod palette;
pub mod plots;
pub mod riemann_sphere;
pub mod single_axis;
pub mod ticks;
