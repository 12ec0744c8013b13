//! Fixed-step RK4 and the two attitude kinematics it integrates: the quaternion
//! (`q̇ = ½ q ⊗ (0, ω)`) and paper 3's (u, v, z) system (eq. 21).

use super::wz::{CHART_SWITCH_MODULUS, WzAttitude, WzChart};
use nalgebra::{Quaternion, SVector, UnitQuaternion, Vector3};

/// One classical Runge–Kutta step of `ẋ = f(t, x)` from `t_s` over `dt_s`.
///
/// ```
/// # use attlab::math::rk4_step;
/// # use nalgebra::Vector1;
/// # use approx::assert_relative_eq;
/// // ẋ = x from x = 1 over 1 s in 100 steps ≈ e.
/// let mut x = Vector1::new(1.0);
/// for k in 0..100 { x = rk4_step(k as f64 * 0.01, &x, 0.01, |_, x| *x); }
/// assert_relative_eq!(x[0], std::f64::consts::E, epsilon = 1e-9);
/// ```
pub fn rk4_step<const N: usize>(
    t_s: f64,
    x: &SVector<f64, N>,
    dt_s: f64,
    f: impl Fn(f64, &SVector<f64, N>) -> SVector<f64, N>,
) -> SVector<f64, N> {
    let h = dt_s;
    let k1 = f(t_s, x);
    let k2 = f(t_s + 0.5 * h, &(x + k1 * (0.5 * h)));
    let k3 = f(t_s + 0.5 * h, &(x + k2 * (0.5 * h)));
    let k4 = f(t_s + h, &(x + k3 * h));
    x + (k1 + k2 * 2.0 + k3 * 2.0 + k4) * (h / 6.0)
}

/// Body rates over one step, linear between the samples at its start and end — how RK4 uses
/// sampled gyro data (the mid-step rate is the mean of the two samples).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RateSegment {
    /// Body rate at the start of the step (rad/s).
    pub start_rad_s: Vector3<f64>,
    /// Body rate at the end of the step (rad/s).
    pub end_rad_s: Vector3<f64>,
}

impl RateSegment {
    /// A constant rate over the step.
    pub fn constant(rate_rad_s: Vector3<f64>) -> Self {
        Self {
            start_rad_s: rate_rad_s,
            end_rad_s: rate_rad_s,
        }
    }

    /// The rate at `fraction` ∈ [0, 1] of the step.
    pub fn at(&self, fraction: f64) -> Vector3<f64> {
        self.start_rad_s + (self.end_rad_s - self.start_rad_s) * fraction
    }
}

/// `q̇ = ½ q ⊗ (0, ω_body)` for `q_ref_from_body`, as a 4-vector (w, i, j, k).
pub fn quaternion_derivative(
    q: &SVector<f64, 4>,
    rate_body_rad_s: &Vector3<f64>,
) -> SVector<f64, 4> {
    let q = Quaternion::new(q[0], q[1], q[2], q[3]);
    let omega = Quaternion::from_imag(*rate_body_rad_s);
    let d = q * omega * 0.5;
    SVector::<f64, 4>::new(d.w, d.i, d.j, d.k)
}

/// One RK4 step of the quaternion kinematics, renormalised. `rate_at(f)` is the body rate
/// (rad/s) at fraction `f` ∈ [0, 1] of the step, e.g. `|f| segment.at(f)`.
pub fn step_quaternion_rk4(
    q_ref_from_body: &UnitQuaternion<f64>,
    rate_at: impl Fn(f64) -> Vector3<f64>,
    dt_s: f64,
) -> UnitQuaternion<f64> {
    let q = q_ref_from_body.quaternion();
    let x = SVector::<f64, 4>::new(q.w, q.i, q.j, q.k);
    let x = rk4_step(0.0, &x, dt_s, |t, x| {
        quaternion_derivative(x, &rate_at(t / dt_s))
    });
    UnitQuaternion::from_quaternion(Quaternion::new(x[0], x[1], x[2], x[3]))
}

/// Paper 3's eq. (21) in a chart whose body rates are `rate_rad_s` = (ω_ξ, ω_η, ω_ζ).
///
/// ```
/// # use attlab::math::uvz_derivative;
/// # use nalgebra::Vector3;
/// // Level body (w = 0) turning about its own vertical only changes z.
/// let d = uvz_derivative(&Vector3::new(0.0, 0.0, 0.0), &Vector3::new(0.0, 0.0, 0.2));
/// assert_eq!(d, Vector3::new(0.0, 0.0, 0.2));
/// ```
pub fn uvz_derivative(uvz: &Vector3<f64>, rate_rad_s: &Vector3<f64>) -> Vector3<f64> {
    let (u, v) = (uvz[0], uvz[1]);
    let (wx, wy, wz) = (rate_rad_s[0], rate_rad_s[1], rate_rad_s[2]);
    Vector3::new(
        v * wz + u * v * wx - 0.5 * wy * (1.0 + u * u - v * v),
        -u * wz - u * v * wy + 0.5 * wx * (1.0 - u * u + v * v),
        wz + u * wx + v * wy,
    )
}

/// Paper 3's eqs. (18–19) alone: the (u, v) subsystem, which needs no z.
pub fn uv_derivative(
    uv: &nalgebra::Vector2<f64>,
    rate_rad_s: &Vector3<f64>,
) -> nalgebra::Vector2<f64> {
    let (u, v) = (uv[0], uv[1]);
    let (wx, wy, wz) = (rate_rad_s[0], rate_rad_s[1], rate_rad_s[2]);
    nalgebra::Vector2::new(
        v * wz + u * v * wx - 0.5 * wy * (1.0 + u * u - v * v),
        -u * wz - u * v * wy + 0.5 * wx * (1.0 - u * u + v * v),
    )
}

/// Body rates as seen by the flipped frame F = diag(1, −1, −1)·body.
fn chart_rates(chart: WzChart, rate_body_rad_s: Vector3<f64>) -> Vector3<f64> {
    match chart {
        WzChart::North => rate_body_rad_s,
        WzChart::Flipped => Vector3::new(rate_body_rad_s.x, -rate_body_rad_s.y, -rate_body_rad_s.z),
    }
}

/// One RK4 step of (u, v, z) in the attitude's chart, then a chart switch if |w| (or |s|)
/// has passed [`CHART_SWITCH_MODULUS`]. `rate_at(f)` is the body rate at fraction `f` of
/// the step.
pub fn step_uvz_rk4(
    att: &WzAttitude,
    rate_at: impl Fn(f64) -> Vector3<f64>,
    dt_s: f64,
) -> WzAttitude {
    let x = Vector3::new(att.u, att.v, att.z_rad);
    let chart = att.chart;
    let x = rk4_step(0.0, &x, dt_s, |t, x| {
        uvz_derivative(x, &chart_rates(chart, rate_at(t / dt_s)))
    });
    let next = WzAttitude {
        u: x[0],
        v: x[1],
        z_rad: x[2],
        chart,
    };
    if next.modulus() > CHART_SWITCH_MODULUS {
        let other = match chart {
            WzChart::North => WzChart::Flipped,
            WzChart::Flipped => WzChart::North,
        };
        next.to_chart(other).unwrap_or(next)
    } else {
        next
    }
}
