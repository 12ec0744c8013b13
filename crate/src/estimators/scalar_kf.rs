//! The two-state (angle, rate) Kalman filter of paper 1, shared by its two models, with the
//! paper's covariance matching ("covariance refinement", §2.6, Table 2.3).
//!
//! State x = (φ, φ̇), measurement z = φ̇ + v (H = (0 1), R = σ²). Prediction P⁻ = Φ P Φᵀ
//! (+ Q); gain K = P⁻Hᵀ/(HP⁻Hᵀ + R) (eq. 4.3); update (4.4) and, in Joseph form, (4.5).
//!
//! Adaptation: over a window of N measurements the filter accumulates q_j q_jᵀ/N with
//! q_j = x̂_j − Φ x̂_{j−1} (the correction each update made) and, if asked, r_j²/N with
//! r_j = z_j − H x̂_j⁻ (the innovation); at j = N the estimate Q_N (and R_N) is put into the
//! filter and a new window starts (Table 2.3). The paper is ambiguous about *how* Q_N is put
//! in, so both readings are offered:
//! * [`QUse::ProcessNoise`]: the rate element of Q_N becomes the process noise of the next
//!   window, added to P before every update (classic covariance matching). Only the φ̇φ̇
//!   element is used: feeding the whole 2×2 Q_N back lets every rate innovation move the angle
//!   and, measured here, makes the torsional filter diverge (angle error 3e14° at N = 1);
//!   the paper does not say which elements it substitutes;
//! * [`QUse::ResetP`]: P := Q_N at the end of each window, Q = 0 in between (the digest's
//!   reading of "P is computed from the Riccati solution with substituted initial
//!   conditions"; it gives the paper's saw-tooth P).
//!
//! Without adaptation (N = 0) Q = 0: P decays to 0, the gain with it, and the filter stops
//! listening to the gyro.

use crate::math::{joseph_update, symmetrize};
use nalgebra::{Matrix1, Matrix1x2, Matrix2, Vector2};

/// How the windowed estimate Q_N enters the filter.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum QUse {
    /// Q := Q_N, added to P before each update of the next window.
    ProcessNoise,
    /// P := Q_N at each window end, Q = 0 otherwise.
    ResetP,
}

/// How a filter adapts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Adaptation {
    /// Window N in measurements; 0 = no adaptation (Q = 0 throughout).
    pub window: usize,
    /// Also replace R by the windowed innovation variance.
    pub adapt_r: bool,
    /// How Q_N is used.
    pub q_use: QUse,
}

/// State, covariance and adaptation bookkeeping of one two-state filter.
#[derive(Clone, Debug)]
pub struct ScalarKf {
    /// Estimate (φ rad, φ̇ rad/s).
    pub x: Vector2<f64>,
    /// Covariance (rad², rad²/s, rad²/s²).
    pub p: Matrix2<f64>,
    /// Measurement variance (rad²/s²).
    pub r: f64,
    /// Adaptation settings.
    pub adaptation: Adaptation,
    /// Last innovation z − φ̇⁻ (rad/s).
    pub innovation: f64,
    /// Process noise added before each update (rad², …), from the last window.
    pub q: Matrix2<f64>,
    q_sum: Matrix2<f64>,
    r_sum: f64,
    count: usize,
    x_predicted: Vector2<f64>,
    /// Windows completed (each one reset P).
    pub resets: u64,
}

impl ScalarKf {
    /// A filter at `x0` with covariance `p0` and measurement variance `r`.
    pub fn new(x0: Vector2<f64>, p0: Matrix2<f64>, r: f64, adaptation: Adaptation) -> Self {
        Self {
            x: x0,
            p: p0,
            r,
            adaptation,
            innovation: 0.0,
            q: Matrix2::zeros(),
            q_sum: Matrix2::zeros(),
            r_sum: 0.0,
            count: 0,
            x_predicted: x0,
            resets: 0,
        }
    }

    /// Prediction over one interval with transition matrix `phi` (Q = 0, as in the paper).
    pub fn predict(&mut self, phi: &Matrix2<f64>) {
        self.x = phi * self.x;
        self.p = symmetrize(&(phi * self.p * phi.transpose()));
        self.x_predicted = self.x;
    }

    /// Measurement update with a rate reading `z` (rad/s), then the adaptation bookkeeping.
    pub fn update(&mut self, z: f64) {
        if self.adaptation.window > 0 && self.adaptation.q_use == QUse::ProcessNoise {
            self.p += self.q;
        }
        let h = Matrix1x2::new(0.0, 1.0);
        let r = Matrix1::new(self.r.max(f64::MIN_POSITIVE));
        let s = self.p[(1, 1)] + r[(0, 0)];
        let k = self.p.column(1) / s;
        self.innovation = z - self.x[1];
        self.x += k * self.innovation;
        self.p = joseph_update(&self.p, &k.into_owned(), &h, &r);
        self.adapt();
    }

    fn adapt(&mut self) {
        let n = self.adaptation.window;
        if n == 0 {
            return;
        }
        let q = self.x - self.x_predicted;
        self.q_sum += q * q.transpose() / n as f64;
        self.r_sum += self.innovation * self.innovation / n as f64;
        self.count += 1;
        if self.count >= n {
            match self.adaptation.q_use {
                QUse::ResetP => self.p = symmetrize(&self.q_sum),
                QUse::ProcessNoise => {
                    self.q = Matrix2::new(0.0, 0.0, 0.0, self.q_sum[(1, 1)].max(0.0))
                }
            }
            if self.adaptation.adapt_r && self.r_sum > 0.0 {
                self.r = self.r_sum;
            }
            self.q_sum = Matrix2::zeros();
            self.r_sum = 0.0;
            self.count = 0;
            self.resets += 1;
        }
    }

    /// The published covariance elements a, b, c.
    pub fn abc(&self) -> [f64; 3] {
        [self.p[(0, 0)], self.p[(0, 1)], self.p[(1, 1)]]
    }
}

/// Transition matrix of the permanent-rotation model φ̈ = 0 (eq. 4.1) over `dt_s`.
pub fn rotation_transition(dt_s: f64) -> Matrix2<f64> {
    Matrix2::new(1.0, dt_s, 0.0, 1.0)
}

/// Transition matrix of the torsional model Iφ̈ = −fφ, Ω = 2π/T (eq. 4.6) over `dt_s`.
pub fn torsion_transition(omega_rad_s: f64, dt_s: f64) -> Matrix2<f64> {
    let (s, c) = (omega_rad_s * dt_s).sin_cos();
    if omega_rad_s.abs() < 1e-12 {
        return rotation_transition(dt_s);
    }
    Matrix2::new(c, s / omega_rad_s, -omega_rad_s * s, c)
}

/// Paper 1's closed form (4.2) of P(t) for the permanent-rotation model with Q = 0, from
/// P(t₀) = (a₀, b₀, c₀).
pub fn rotation_covariance_closed_form(abc0: [f64; 3], t0: f64, t: f64) -> [f64; 3] {
    let [a0, b0, c0] = abc0;
    let (c1, c2, c3) = (c0, b0 - c0 * t0, a0 - 2.0 * b0 * t0 + c0 * t0 * t0);
    [c1 * t * t + 2.0 * c2 * t + c3, c1 * t + c2, c1]
}

/// Paper 1's closed form (4.7) of P(t) for the torsional model with Q = 0.
pub fn torsion_covariance_closed_form(abc0: [f64; 3], omega: f64, t0: f64, t: f64) -> [f64; 3] {
    let [a0, b0, c0] = abc0;
    let (s0, k0) = (2.0 * omega * t0).sin_cos();
    let c1 = a0 * omega / 2.0 * s0 + b0 * k0 - c0 / (2.0 * omega) * s0;
    let c2 = -a0 * omega / 2.0 * k0 + b0 * s0 + c0 / (2.0 * omega) * k0;
    let c3 = c0 + omega * omega * a0;
    let (s, k) = (2.0 * omega * t).sin_cos();
    [
        c1 / omega * s - c2 / omega * k + c3 / (2.0 * omega * omega),
        c1 * k + c2 * s,
        -c1 * omega * s + c2 * omega * k + c3 / 2.0,
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn propagate(phi: &Matrix2<f64>, p0: Matrix2<f64>, steps: usize) -> Matrix2<f64> {
        (0..steps).fold(p0, |p, _| phi * p * phi.transpose())
    }

    #[test]
    fn closed_forms_agree_with_transition_matrix_propagation() {
        let p0 = Matrix2::new(2e-4, 1e-4, 1e-4, 3e-4);
        let abc0 = [p0[(0, 0)], p0[(0, 1)], p0[(1, 1)]];
        let (t0, dt, steps) = (3.0, 0.01, 12_345);
        let t = t0 + dt * steps as f64;
        let rot = propagate(&rotation_transition(dt), p0, steps);
        let cf = rotation_covariance_closed_form(abc0, t0, t);
        for (x, y) in [rot[(0, 0)], rot[(0, 1)], rot[(1, 1)]].iter().zip(cf) {
            assert!(
                (x - y).abs() <= 1e-9 * x.abs().max(1e-12),
                "rotation: {x} vs {y}"
            );
        }
        let omega = 2.0 * std::f64::consts::PI / 37.0;
        let tor = propagate(&torsion_transition(omega, dt), p0, steps);
        let cf = torsion_covariance_closed_form(abc0, omega, t0, t);
        for (x, y) in [tor[(0, 0)], tor[(0, 1)], tor[(1, 1)]].iter().zip(cf) {
            assert!(
                (x - y).abs() <= 1e-9 * x.abs().max(1e-6),
                "torsion: {x} vs {y}"
            );
        }
    }

    #[test]
    fn without_adaptation_the_covariance_collapses_and_with_it_resets() {
        let phi = rotation_transition(0.01);
        let p0 = Matrix2::identity() * 1e-4;
        let adapt = |window| Adaptation {
            window,
            adapt_r: false,
            q_use: QUse::ProcessNoise,
        };
        let mut off = ScalarKf::new(Vector2::zeros(), p0, 1e-6, adapt(0));
        let mut on = ScalarKf::new(Vector2::zeros(), p0, 1e-6, adapt(100));
        // The measured rate ramps up (an acceleration the model φ̈ = 0 does not know).
        for k in 0..5000 {
            let z = 1e-4 * k as f64 + 0.001 * (((k * 7919) % 13) as f64 - 6.0);
            for f in [&mut off, &mut on] {
                f.predict(&phi);
                f.update(z);
            }
        }
        assert!(off.p[(1, 1)] < 1e-9, "P collapses: {}", off.p);
        assert_eq!(on.resets, 50);
        assert!(
            on.p[(1, 1)] > off.p[(1, 1)] * 10.0,
            "adapted P {} vs {}",
            on.p,
            off.p
        );
        let truth = 1e-4 * 4999.0;
        assert!(
            (on.x[1] - truth).abs() < (off.x[1] - truth).abs() / 10.0,
            "adapted {} vs collapsed {} (truth {truth})",
            on.x[1],
            off.x[1]
        );
    }
}
