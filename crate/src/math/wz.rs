//! Paper 3's (w, z) kinematic parameters on the whole rotation group.
//!
//! `w = u + jv = (a′ + j b′)/(1 + c′)` is the stereographic projection, from the south pole
//! S = (0, 0, −1), of the reference vertical expressed in body axes (a′, b′, c′); `z` is the
//! rotation about the vertical applied first: `A = A(w)·A(z)` (eqs. 11–15).
//!
//! The chart is singular at c′ = −1 (body upside down, w → ∞). There we switch to the
//! *flipped* chart of the digest's §3: the body frame turned 180° about ξ′,
//! `F = diag(1, −1, −1)`, whose parameter is `s = 1/w` and whose attitude is
//! `A = F·A(s)·A(z′)`. The same kinematics (eq. 21) hold for `s` with the rates
//! (ω_ξ, −ω_η, −ω_ζ).

use super::EulerYpr;
use super::rotation::{dcm_from_quaternion, quaternion_from_dcm, rot_z};
use nalgebra::{Matrix3, UnitQuaternion, Vector3};
use serde::{Deserialize, Serialize};

/// |w| (or |s|) beyond which an integrator switches to the other chart. Both charts cover
/// the whole sphere with modulus ≤ 1, so a switch at 2 leaves a hysteresis band 1/2…2 in
/// which neither chart flips back and forth.
pub const CHART_SWITCH_MODULUS: f64 = 2.0;

/// Which stereographic chart (u, v) are coordinates in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum WzChart {
    /// Paper 3's chart: w = u + jv, projection from the south pole.
    North,
    /// Flipped body frame F = diag(1, −1, −1)·body: s = u + jv = 1/w, projection from the
    /// north pole.
    Flipped,
}

/// Attitude as (u, v, z) in a given chart.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct WzAttitude {
    /// Real part of w (or of s in the flipped chart).
    pub u: f64,
    /// Imaginary part of w (or of s).
    pub v: f64,
    /// Rotation about the vertical applied first (rad): z, or z′ in the flipped chart.
    pub z_rad: f64,
    /// The chart (u, v, z) belong to.
    pub chart: WzChart,
}

fn flip() -> Matrix3<f64> {
    Matrix3::from_diagonal(&Vector3::new(1.0, -1.0, -1.0))
}

/// Paper 3's eq. (14): the matrix A(w).
pub fn a_of_w(u: f64, v: f64) -> Matrix3<f64> {
    let n = 1.0 + u * u + v * v;
    Matrix3::new(
        1.0 - u * u + v * v,
        -2.0 * u * v,
        2.0 * u,
        -2.0 * u * v,
        1.0 + u * u - v * v,
        2.0 * v,
        -2.0 * u,
        -2.0 * v,
        1.0 - u * u - v * v,
    ) / n
}

/// Chart coordinates (u, v) of a vertical `k_body` (any length > 0, e.g. an accelerometer
/// reading): eq. (28) in the north chart, its flipped twin otherwise. `None` at the chart's
/// own pole.
///
/// ```
/// # use attlab::math::{chart_coords_of_vertical, WzChart};
/// # use nalgebra::Vector3;
/// let (u, v) = chart_coords_of_vertical(&Vector3::new(0.0, 0.5, 0.75f64.sqrt()), WzChart::North).unwrap();
/// assert!((v - 0.5 / (1.0 + 0.75f64.sqrt())).abs() < 1e-15 && u == 0.0);
/// ```
pub fn chart_coords_of_vertical(k_body: &Vector3<f64>, chart: WzChart) -> Option<(f64, f64)> {
    let n = k_body.norm();
    if !(n > 0.0 && n.is_finite()) {
        return None;
    }
    let k = k_body / n;
    let (x, y, z) = match chart {
        WzChart::North => (k.x, k.y, k.z),
        WzChart::Flipped => (k.x, -k.y, -k.z),
    };
    (1.0 + z > 1e-9).then(|| (x / (1.0 + z), y / (1.0 + z)))
}

/// The better-conditioned chart for a vertical `k_body`.
pub fn better_chart(k_body: &Vector3<f64>) -> WzChart {
    if k_body.z >= 0.0 {
        WzChart::North
    } else {
        WzChart::Flipped
    }
}

/// The other chart.
pub fn other_chart(chart: WzChart) -> WzChart {
    match chart {
        WzChart::North => WzChart::Flipped,
        WzChart::Flipped => WzChart::North,
    }
}

impl WzAttitude {
    /// (u, v, z) in the north chart.
    pub fn north(u: f64, v: f64, z_rad: f64) -> Self {
        Self {
            u,
            v,
            z_rad,
            chart: WzChart::North,
        }
    }

    /// Paper 3's eq. (15) (north chart) or `F·A(s)·A(z′)` (flipped chart).
    ///
    /// ```
    /// # use attlab::math::WzAttitude;
    /// # use approx::assert_relative_eq;
    /// let a = WzAttitude::north(0.1, 0.2, 0.3).to_dcm();
    /// assert_relative_eq!(a[(0, 2)], 2.0 * 0.1 / (1.0 + 0.01 + 0.04), epsilon = 1e-15);
    /// ```
    pub fn to_dcm(&self) -> Matrix3<f64> {
        let a = a_of_w(self.u, self.v) * rot_z(self.z_rad);
        match self.chart {
            WzChart::North => a,
            WzChart::Flipped => flip() * a,
        }
    }

    /// Parameters of *A* in the requested chart. Returns `None` at that chart's own pole
    /// (c′ = −1 for North, c′ = +1 for Flipped), where the chart does not exist.
    pub fn from_dcm_in_chart(a: &Matrix3<f64>, chart: WzChart) -> Option<Self> {
        let a_chart = match chart {
            WzChart::North => *a,
            WzChart::Flipped => flip() * a,
        };
        let (ap, bp, cp) = (a_chart[(0, 2)], a_chart[(1, 2)], a_chart[(2, 2)]);
        let denom = 1.0 + cp;
        if denom < 1e-12 {
            return None;
        }
        let (u, v) = (ap / denom, bp / denom);
        // A(z) = A(w)ᵀ A_chart (eq. 15 solved for the first rotation).
        let a_z = a_of_w(u, v).transpose() * a_chart;
        let z_rad = a_z[(0, 1)].atan2(a_z[(0, 0)]);
        Some(Self { u, v, z_rad, chart })
    }

    /// Parameters of *A* in the better-conditioned chart (|w| ≤ 1 or |s| < 1).
    ///
    /// ```
    /// # use attlab::math::{WzAttitude, WzChart, EulerYpr};
    /// // roll 180°: the body is upside down, w = ∞, so the flipped chart is chosen.
    /// let a = EulerYpr::new(0.0, 0.0, std::f64::consts::PI).to_dcm();
    /// assert_eq!(WzAttitude::from_dcm(&a).chart, WzChart::Flipped);
    /// ```
    pub fn from_dcm(a: &Matrix3<f64>) -> Self {
        let chart = if a[(2, 2)] >= 0.0 {
            WzChart::North
        } else {
            WzChart::Flipped
        };
        // c′ ≥ 0 (north) or c′ < 0 (flipped) keeps the denominator ≥ 1.
        Self::from_dcm_in_chart(a, chart).unwrap_or(Self::north(0.0, 0.0, 0.0))
    }

    /// Same attitude expressed in `chart`; `None` only exactly at that chart's pole.
    pub fn to_chart(&self, chart: WzChart) -> Option<Self> {
        if chart == self.chart {
            return Some(*self);
        }
        Self::from_dcm_in_chart(&self.to_dcm(), chart)
    }

    /// Modulus of the chart coordinate, |w| or |s|.
    pub fn modulus(&self) -> f64 {
        self.u.hypot(self.v)
    }

    /// w = u + jv in paper 3's chart, as (Re, Im); `None` at w = ∞.
    pub fn w(&self) -> Option<(f64, f64)> {
        match self.chart {
            WzChart::North => Some((self.u, self.v)),
            WzChart::Flipped => {
                let m2 = self.u * self.u + self.v * self.v;
                // w = 1/s = s̄/|s|²; and s = u_s + j v_s here.
                (m2 > 1e-300).then(|| (self.u / m2, -self.v / m2))
            }
        }
    }

    /// The reference vertical in body axes (a′, b′, c′), eq. (13) — chart independent.
    pub fn vertical_in_body(&self) -> Vector3<f64> {
        let n = 1.0 + self.u * self.u + self.v * self.v;
        let k = Vector3::new(
            2.0 * self.u,
            2.0 * self.v,
            1.0 - self.u * self.u - self.v * self.v,
        ) / n;
        match self.chart {
            WzChart::North => k,
            WzChart::Flipped => flip() * k,
        }
    }

    /// `q_ref_from_body`.
    pub fn to_quaternion(&self) -> UnitQuaternion<f64> {
        quaternion_from_dcm(&self.to_dcm())
    }

    /// Parameters of `q_ref_from_body` in the better chart.
    pub fn from_quaternion(q_ref_from_body: &UnitQuaternion<f64>) -> Self {
        Self::from_dcm(&dcm_from_quaternion(q_ref_from_body))
    }

    /// Euler angles (paper 3 eqs. 23–25, via the DCM so the flipped chart works too).
    pub fn to_euler(&self) -> EulerYpr {
        EulerYpr::from_dcm(&self.to_dcm())
    }

    /// Paper 3's eq. (26) plus z: parameters of Euler angles in the better chart.
    pub fn from_euler(e: &EulerYpr) -> Self {
        Self::from_dcm(&e.to_dcm())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn paper3_initial_condition_is_tan15() {
        // ψ = 0, ϑ = 30°, γ = 0 at t = 0 (paper 3 §5): u₀ = 0, v₀ = tan 15°.
        let e = EulerYpr::new(0.0, 30f64.to_radians(), 0.0);
        let wz = WzAttitude::from_euler(&e);
        assert_eq!(wz.chart, WzChart::North);
        assert_relative_eq!(wz.u, 0.0, epsilon = 1e-15);
        assert_relative_eq!(wz.v, 15f64.to_radians().tan(), epsilon = 1e-15);
        assert_relative_eq!(wz.z_rad, 0.0, epsilon = 1e-15);
    }

    #[test]
    fn euler_extraction_matches_paper_eqs_23_to_25() {
        let (u, v, z) = (0.3, -0.2, 0.7);
        let e = WzAttitude::north(u, v, z).to_euler();
        let yaw = z + (2.0 * u * v).atan2(1.0 + u * u - v * v);
        assert_relative_eq!(e.yaw_rad, yaw, epsilon = 1e-14);
        assert_relative_eq!(
            e.pitch_rad,
            (2.0 * v / (1.0 + u * u + v * v)).asin(),
            epsilon = 1e-14
        );
        assert_relative_eq!(
            e.roll_rad,
            (-2.0 * u).atan2(1.0 - u * u - v * v),
            epsilon = 1e-14
        );
    }

    #[test]
    fn quaternion_matches_digest_closed_form() {
        // q = q_z(z) ⊗ (1, v, −u, 0)/N, Hamilton, body → fixed (digest §1).
        let (u, v, z) = (0.4_f64, 0.25_f64, -1.1_f64);
        let n = (1.0 + u * u + v * v).sqrt();
        let (s2, c2) = (z / 2.0).sin_cos();
        let closed = nalgebra::Quaternion::new(c2, v * c2 + u * s2, -u * c2 + v * s2, s2) / n;
        let q = WzAttitude::north(u, v, z).to_quaternion();
        let d = q.quaternion().coords - closed.coords;
        let s = q.quaternion().coords + closed.coords;
        assert!(d.norm().min(s.norm()) < 1e-14, "{q:?} vs {closed:?}");
    }

    #[test]
    fn flipped_chart_is_inverse_of_w() {
        let a = EulerYpr::new(0.3, 0.2, 2.5).to_dcm();
        let n = WzAttitude::from_dcm_in_chart(&a, WzChart::North).unwrap();
        let f = WzAttitude::from_dcm_in_chart(&a, WzChart::Flipped).unwrap();
        let (wr, wi) = f.w().unwrap();
        assert_relative_eq!(wr, n.u, epsilon = 1e-12);
        assert_relative_eq!(wi, n.v, epsilon = 1e-12);
        assert_relative_eq!(f.to_dcm(), a, epsilon = 1e-12);
        assert_relative_eq!(f.vertical_in_body(), n.vertical_in_body(), epsilon = 1e-12);
    }
}
