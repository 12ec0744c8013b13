//! Noise building blocks: white noise, random-walk bias, quantisation and averaging.

use rand::Rng;
use rand_distr::{Distribution, StandardNormal};

/// Zero-mean Gaussian white noise with standard deviation `sigma`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WhiteNoise {
    /// Standard deviation of one sample (same unit as the signal).
    pub sigma: f64,
}

impl WhiteNoise {
    /// One sample. σ = 0 gives exactly 0 and draws nothing, so noise-free runs are exact.
    pub fn sample(&self, rng: &mut impl Rng) -> f64 {
        if self.sigma == 0.0 {
            return 0.0;
        }
        let n: f64 = StandardNormal.sample(rng);
        self.sigma * n
    }
}

/// A random walk `b ← b + σ √dt · n`: a slowly drifting sensor bias.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RandomWalk {
    /// Current value.
    pub value: f64,
    /// Growth of the standard deviation per √second.
    pub sigma_per_sqrt_s: f64,
}

impl RandomWalk {
    /// Advance by `dt_s` and return the new value.
    pub fn step(&mut self, dt_s: f64, rng: &mut impl Rng) -> f64 {
        let noise = WhiteNoise {
            sigma: self.sigma_per_sqrt_s * dt_s.max(0.0).sqrt(),
        };
        self.value += noise.sample(rng);
        self.value
    }
}

/// Round to the nearest multiple of `lsb` (an `lsb` ≤ 0 means no quantisation), after
/// clipping to ±`range`.
///
/// ```
/// # use attlab::sensors::quantize;
/// assert_eq!(quantize(0.26, 0.1, 10.0), 0.30000000000000004);
/// assert_eq!(quantize(25.0, 0.1, 10.0), 10.0);
/// ```
pub fn quantize(x: f64, lsb: f64, range: f64) -> f64 {
    let clipped = if range > 0.0 {
        x.clamp(-range, range)
    } else {
        x
    };
    if lsb > 0.0 {
        (clipped / lsb).round() * lsb
    } else {
        clipped
    }
}

/// Averages every `n` consecutive samples into one (a sensor decimating from its internal
/// rate to the output rate).
#[derive(Clone, Debug, PartialEq)]
pub struct Averager {
    n: usize,
    sum: f64,
    count: usize,
}

impl Averager {
    /// Average blocks of `n` samples (`n` is at least 1).
    pub fn new(n: usize) -> Self {
        Self {
            n: n.max(1),
            sum: 0.0,
            count: 0,
        }
    }

    /// Push a sample; returns the block mean when a block completes.
    ///
    /// ```
    /// # use attlab::sensors::Averager;
    /// let mut a = Averager::new(2);
    /// assert_eq!(a.push(1.0), None);
    /// assert_eq!(a.push(3.0), Some(2.0));
    /// ```
    pub fn push(&mut self, x: f64) -> Option<f64> {
        self.sum += x;
        self.count += 1;
        (self.count >= self.n).then(|| {
            let mean = self.sum / self.count as f64;
            self.sum = 0.0;
            self.count = 0;
            mean
        })
    }

    /// Block length.
    pub fn len(&self) -> usize {
        self.n
    }

    /// Never empty: a block has at least one sample.
    pub fn is_empty(&self) -> bool {
        false
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;
    use rand_chacha::ChaCha8Rng;

    #[test]
    fn white_noise_has_requested_sigma() {
        let mut rng = ChaCha8Rng::seed_from_u64(7);
        let w = WhiteNoise { sigma: 0.5 };
        let n = 200_000;
        let xs: Vec<f64> = (0..n).map(|_| w.sample(&mut rng)).collect();
        let mean = xs.iter().sum::<f64>() / n as f64;
        let var = xs.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / n as f64;
        // σ̂ of 2e5 samples has a relative standard error of 1/√(2n) ≈ 0.16 %.
        assert!(
            (var.sqrt() - 0.5).abs() < 0.5 * 0.01,
            "sigma {}",
            var.sqrt()
        );
        assert!(mean.abs() < 5.0 * 0.5 / (n as f64).sqrt(), "mean {mean}");
    }

    #[test]
    fn random_walk_variance_grows_linearly() {
        let runs = 4000;
        let mut rng = ChaCha8Rng::seed_from_u64(11);
        let mut finals = Vec::new();
        for _ in 0..runs {
            let mut rw = RandomWalk {
                value: 0.0,
                sigma_per_sqrt_s: 0.2,
            };
            for _ in 0..100 {
                rw.step(0.1, &mut rng);
            }
            finals.push(rw.value);
        }
        let var = finals.iter().map(|x| x * x).sum::<f64>() / runs as f64;
        // expected σ² t = 0.04 · 10 = 0.4; 4000 runs → relative s.e. ≈ 2.2 %.
        assert!((var - 0.4).abs() < 0.4 * 0.1, "var {var}");
    }

    #[test]
    fn averaging_reduces_white_noise_by_sqrt_n() {
        let mut rng = ChaCha8Rng::seed_from_u64(3);
        let w = WhiteNoise { sigma: 1.0 };
        let mut avg = Averager::new(16);
        let means: Vec<f64> = (0..16 * 20_000)
            .filter_map(|_| avg.push(w.sample(&mut rng)))
            .collect();
        let sd = (means.iter().map(|x| x * x).sum::<f64>() / means.len() as f64).sqrt();
        assert!((sd - 0.25).abs() < 0.25 * 0.03, "sd {sd}");
    }
}
