//! The two-state (angle, rate) Kalman filter of paper 1 with its covariance matching
//! ("covariance refinement", §2.6, Table 2.3), built on the shared [`super::kf`] update.
//!
//! State x = (φ, φ̇), measurement z = φ̇ + v (H = (0 1), R = σ²). Prediction P⁻ = Φ P Φᵀ;
//! gain K = P⁻Hᵀ/(HP⁻Hᵀ + R) (eq. 4.3); update (4.4) and, in Joseph form, (4.5).
//!
//! Over a window of N measurements the filter accumulates q qᵀ/N; at the window's end the
//! sum is put into the filter and a new window starts (Table 2.3). The paper is ambiguous
//! about what q is and how the sum is put in, so three readings are offered:
//!
//! * [`AdaptMode::SawTooth`] — this project's reading, the default: q = (φ_int − φ̂⁺,
//!   z − φ̇̂⁺), the spread of the filter about the kinematically integrated angle and the
//!   measured rate; every N samples P := (1/N) Σ q qᵀ, then the Riccati solution with Q = 0
//!   until the next window — the saw-tooth P of Fig. 5.6 and the text's "the next 10 s, P is
//!   computed from the Riccati solution with the substituted initial conditions".
//!   Measured here: it reproduces the paper's N = 100 and N = 1000 panels, but the feedback
//!   through the cross term b makes it unstable for N ≈ 3–10 and under a swing leaking into
//!   the gyro (the estimate runs away; [`super::OneAxisKf`] then reports "diverged").
//! * [`AdaptMode::SawToothDiagonal`] — the same with only the diagonal of the sum
//!   (b := 0 at each reset): as good at N = 100 and 1000, and stable for small N.
//! * [`AdaptMode::LiteralReset`] — Table 2.3 read literally: q = x̂⁺ − Φx̂⁻ = K r (the
//!   correction of each update) and P := Q_N. It collapses: with Q = 0 between updates the
//!   rate variance obeys c⁺ = c⁻ − c⁻²/S and E[(K r)²_φ̇] = c⁻²/S = c⁻ − c⁺, so the sum over a
//!   window telescopes, E\[Q_N,cc\] = (c₀ − c_N)/N < c₀/N: every window shrinks P at least N-fold.
//! * [`AdaptMode::RateProcessNoise`] — the φ̇φ̇ element of the K r sample covariance as
//!   process noise for the next window, added to P before every update (classic covariance
//!   matching; this project's earlier default). Feeding the whole 2×2 matrix back lets rate
//!   innovations move the angle and makes the torsional filter diverge.
//!
//! Without adaptation (N = 0) Q = 0: P decays to 0, the gain with it, and the filter stops
//! listening to the gyro (Figs. 5.3–5.4).

use super::kf::{KalmanState, KfError};
use nalgebra::{Matrix2, Vector2};

/// What the window's sum is built from and how it enters the filter.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AdaptMode {
    /// q = (φ_int − φ̂⁺, z − φ̇̂⁺); P := mean q qᵀ every N samples (this project's reading).
    SawTooth,
    /// The same, keeping only the diagonal of mean q qᵀ.
    SawToothDiagonal,
    /// q = K r; P := mean q qᵀ every N samples (Table 2.3 literally; collapses).
    LiteralReset,
    /// Q := the φ̇φ̇ element of mean (K r)(K r)ᵀ, added before each update of the next window.
    RateProcessNoise,
}

impl AdaptMode {
    /// The modes in menu order (the parameter's choice index).
    pub const ALL: [AdaptMode; 4] = [
        Self::SawTooth,
        Self::SawToothDiagonal,
        Self::LiteralReset,
        Self::RateProcessNoise,
    ];
}

/// How a filter adapts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Adaptation {
    /// Window N in measurements; 0 = no adaptation (Q = 0 throughout).
    pub window: usize,
    /// Also replace R by the windowed innovation variance.
    pub adapt_r: bool,
    /// What is summed and how it is used.
    pub mode: AdaptMode,
}

/// State, covariance and adaptation bookkeeping of one two-state filter.
#[derive(Clone, Debug)]
pub struct AdaptiveKf {
    /// Estimate (φ rad, φ̇ rad/s) and covariance (rad², rad²/s, rad²/s²).
    pub kf: KalmanState<2>,
    /// Measurement variance (rad²/s²).
    pub r: f64,
    /// Adaptation settings.
    pub adaptation: Adaptation,
    /// Last innovation z − φ̇⁻ (rad/s).
    pub innovation: f64,
    /// Process noise added before each update (rad²/s²), from the last window
    /// ([`AdaptMode::RateProcessNoise`] only).
    pub q_rate: f64,
    sum: Matrix2<f64>,
    r_sum: f64,
    count: usize,
    /// Windows completed.
    pub resets: u64,
    /// The last update's prior (after the process noise it adds) and its Joseph result
    /// (before any adaptation), for the step-through panel.
    pub last_update: Option<(KalmanState<2>, KalmanState<2>)>,
}

impl AdaptiveKf {
    /// A filter at `x0` with covariance `p0` and measurement variance `r`.
    pub fn new(x0: Vector2<f64>, p0: Matrix2<f64>, r: f64, adaptation: Adaptation) -> Self {
        Self {
            kf: KalmanState::new(x0, p0),
            r,
            adaptation,
            innovation: 0.0,
            q_rate: 0.0,
            sum: Matrix2::zeros(),
            r_sum: 0.0,
            count: 0,
            resets: 0,
            last_update: None,
        }
    }

    /// Estimate (φ, φ̇).
    pub fn x(&self) -> &Vector2<f64> {
        &self.kf.x
    }

    /// Covariance.
    pub fn p(&self) -> &Matrix2<f64> {
        &self.kf.p
    }

    /// Prediction over one interval with transition matrix `phi` (Q = 0, as in the paper).
    pub fn predict(&mut self, phi: &Matrix2<f64>) {
        let x = phi * self.kf.x;
        self.kf.predict_with(x, phi, &Matrix2::zeros());
    }

    /// Measurement update with a rate reading `z` (rad/s), then the adaptation bookkeeping;
    /// `phi_int_rad` is the kinematically integrated angle now (the saw-tooth's reference).
    pub fn update(&mut self, z: f64, phi_int_rad: f64) -> Result<(), KfError> {
        if self.adaptation.window > 0 && self.adaptation.mode == AdaptMode::RateProcessNoise {
            self.kf.p[(1, 1)] += self.q_rate;
        }
        self.innovation = z - self.kf.x[1];
        let prior = self.kf;
        let before = self.kf.x;
        self.kf
            .update_scalar(self.innovation, &Vector2::new(0.0, 1.0), self.r.max(1e-16))?;
        self.last_update = Some((prior, self.kf));
        let q = match self.adaptation.mode {
            AdaptMode::SawTooth | AdaptMode::SawToothDiagonal => {
                Vector2::new(phi_int_rad - self.kf.x[0], z - self.kf.x[1])
            }
            AdaptMode::LiteralReset | AdaptMode::RateProcessNoise => self.kf.x - before,
        };
        self.adapt(&q);
        Ok(())
    }

    fn adapt(&mut self, q: &Vector2<f64>) {
        let n = self.adaptation.window;
        if n == 0 {
            return;
        }
        self.sum += q * q.transpose() / n as f64;
        self.r_sum += self.innovation * self.innovation / n as f64;
        self.count += 1;
        if self.count >= n {
            match self.adaptation.mode {
                AdaptMode::SawTooth | AdaptMode::LiteralReset => self.kf.p = self.sum,
                AdaptMode::SawToothDiagonal => {
                    self.kf.p = Matrix2::from_diagonal(&self.sum.diagonal());
                }
                AdaptMode::RateProcessNoise => self.q_rate = self.sum[(1, 1)].max(0.0),
            }
            if self.adaptation.adapt_r && self.r_sum > 0.0 {
                self.r = self.r_sum;
            }
            self.sum = Matrix2::zeros();
            self.r_sum = 0.0;
            self.count = 0;
            self.resets += 1;
        }
    }
}

/// Transition matrix of the permanent-rotation model φ̈ = 0 (eq. 4.1) over `dt_s`.
pub fn rotation_transition(dt_s: f64) -> Matrix2<f64> {
    Matrix2::new(1.0, dt_s, 0.0, 1.0)
}

/// Transition matrix of the torsional model Iφ̈ = −fφ, Ω = 2π/T (eq. 4.6) over `dt_s`.
pub fn torsion_transition(omega_rad_s: f64, dt_s: f64) -> Matrix2<f64> {
    if omega_rad_s.abs() < 1e-12 {
        return rotation_transition(dt_s);
    }
    let (s, c) = (omega_rad_s * dt_s).sin_cos();
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

    fn filter(mode: AdaptMode, window: usize, r: f64) -> AdaptiveKf {
        let adaptation = Adaptation {
            window,
            adapt_r: false,
            mode,
        };
        AdaptiveKf::new(Vector2::zeros(), Matrix2::identity() * 1e-4, r, adaptation)
    }

    /// Runs `f` on 5000 samples of the rate `rate(k)` plus white noise of variance `r`
    /// (seeded), at 100 Hz.
    fn feed(mut f: AdaptiveKf, rate: impl Fn(usize) -> f64, r: f64) -> AdaptiveKf {
        use rand::SeedableRng;
        use rand_distr::{Distribution, Normal};
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(7);
        let noise = Normal::new(0.0, r.sqrt()).unwrap();
        let phi = rotation_transition(0.01);
        let mut phi_int = 0.0;
        for k in 0..5000 {
            let z = rate(k) + noise.sample(&mut rng);
            phi_int += z * 0.01;
            f.predict(&phi);
            f.update(z, phi_int).unwrap();
        }
        f
    }

    #[test]
    fn with_a_consistent_model_the_literal_reset_collapses_and_the_saw_tooth_does_not() {
        // Constant rate, noise exactly R: the innovations match the filter's own S, so the
        // sum of (K r)² over a window telescopes to c₀ − c_N and P shrinks N-fold per window.
        let r = 1e-6;
        let literal = feed(filter(AdaptMode::LiteralReset, 100, r), |_| 0.3, r);
        let saw = feed(filter(AdaptMode::SawTooth, 100, r), |_| 0.3, r);
        assert_eq!(literal.resets, 50);
        assert!(
            literal.p()[(1, 1)] < saw.p()[(1, 1)] * 1e-6,
            "literal {} vs saw-tooth {}",
            literal.p(),
            saw.p()
        );
        // The saw-tooth's rate variance is the sample variance of z − φ̇̂⁺ ≈ R/4 … R.
        assert!((0.1 * r..2.0 * r).contains(&saw.p()[(1, 1)]), "{}", saw.p());
    }

    #[test]
    fn under_an_unmodelled_acceleration_q_zero_collapses_and_adaptation_tracks() {
        let r = 1e-6;
        let ramp = |k: usize| 1e-4 * k as f64;
        let off = feed(filter(AdaptMode::SawTooth, 0, r), ramp, r);
        assert!(off.p()[(1, 1)] < 1e-9, "Q = 0 collapses: {}", off.p());
        let truth = ramp(4999);
        // The literal reset collapses here too (its sum shrinks with the gain).
        for mode in [
            AdaptMode::SawTooth,
            AdaptMode::SawToothDiagonal,
            AdaptMode::RateProcessNoise,
        ] {
            let f = feed(filter(mode, 100, r), ramp, r);
            assert_eq!(f.resets, 50);
            assert!(
                (f.x()[1] - truth).abs() < (off.x()[1] - truth).abs() / 10.0,
                "{mode:?}: adapted {} vs collapsed {} (truth {truth})",
                f.x()[1],
                off.x()[1]
            );
        }
    }
}
