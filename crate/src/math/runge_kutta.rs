//! Explicit Runge–Kutta methods as data (Butcher tableaux), for integrators a lab lets the
//! student choose — paper 5 makes the integration method a setting. Each method is one
//! entry of [`RK_METHODS`]; [`ExplicitRk::step`] runs any of them on a fixed-size matrix
//! state of an autonomous system `ẋ = f(x)` (the rate is held over the step).

use nalgebra::SMatrix;

/// Most stages a tableau here has.
const MAX_STAGES: usize = 4;

/// One explicit Runge–Kutta method: `kᵢ = f(x + h Σⱼ aᵢⱼ kⱼ)`, `x⁺ = x + h Σᵢ bᵢ kᵢ`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ExplicitRk {
    /// What a student reads, e.g. "Runge–Kutta 4".
    pub name: &'static str,
    /// Order of accuracy: the global error goes as hᵒʳᵈᵉʳ.
    pub order: u32,
    /// Stages used (derivative evaluations per step).
    pub stages: usize,
    /// The strictly lower-triangular a of the tableau.
    pub a: [[f64; MAX_STAGES]; MAX_STAGES],
    /// The weights b.
    pub b: [f64; MAX_STAGES],
}

/// Forward Euler: one evaluation, first order.
pub const EULER: ExplicitRk = ExplicitRk {
    name: "Euler",
    order: 1,
    stages: 1,
    a: [[0.0; MAX_STAGES]; MAX_STAGES],
    b: [1.0, 0.0, 0.0, 0.0],
};

/// The explicit midpoint rule: two evaluations, second order.
pub const MIDPOINT: ExplicitRk = ExplicitRk {
    name: "midpoint (Runge–Kutta 2)",
    order: 2,
    stages: 2,
    a: [
        [0.0; MAX_STAGES],
        [0.5, 0.0, 0.0, 0.0],
        [0.0; MAX_STAGES],
        [0.0; MAX_STAGES],
    ],
    b: [0.0, 1.0, 0.0, 0.0],
};

/// The classical Runge–Kutta method: four evaluations, fourth order.
pub const RK4: ExplicitRk = ExplicitRk {
    name: "Runge–Kutta 4",
    order: 4,
    stages: 4,
    a: [
        [0.0; MAX_STAGES],
        [0.5, 0.0, 0.0, 0.0],
        [0.0, 0.5, 0.0, 0.0],
        [0.0, 0.0, 1.0, 0.0],
    ],
    b: [1.0 / 6.0, 1.0 / 3.0, 1.0 / 3.0, 1.0 / 6.0],
};

/// Every method a lab offers, in the order of its choice parameter (RK4 first: the default).
pub const RK_METHODS: [&ExplicitRk; 3] = [&RK4, &MIDPOINT, &EULER];

/// The names of [`RK_METHODS`], for a choice parameter.
pub const RK_METHOD_NAMES: [&str; 3] = [RK4.name, MIDPOINT.name, EULER.name];

impl ExplicitRk {
    /// One step of `ẋ = f(x)` from `x` over `h`. No heap: the stages live on the stack.
    pub fn step<const R: usize, const C: usize>(
        &self,
        x: &SMatrix<f64, R, C>,
        h: f64,
        f: impl Fn(&SMatrix<f64, R, C>) -> SMatrix<f64, R, C>,
    ) -> SMatrix<f64, R, C> {
        let mut k = [SMatrix::<f64, R, C>::zeros(); MAX_STAGES];
        for i in 0..self.stages {
            let mut stage = *x;
            for (j, kj) in k.iter().enumerate().take(i) {
                if self.a[i][j] != 0.0 {
                    stage += kj * (h * self.a[i][j]);
                }
            }
            k[i] = f(&stage);
        }
        let mut out = *x;
        for (b, ki) in self.b.iter().zip(&k).take(self.stages) {
            if *b != 0.0 {
                out += ki * (h * b);
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Matrix2;

    /// A rotation in the plane, ẋ = Ω x, over 1 s in `n` steps; error against the exact
    /// rotation.
    fn rotation_error(method: &ExplicitRk, n: usize) -> f64 {
        let omega = Matrix2::new(0.0, -1.0, 1.0, 0.0);
        let mut x = Matrix2::identity();
        for _ in 0..n {
            x = method.step(&x, 1.0 / n as f64, |x| omega * x);
        }
        let (s, c) = 1.0f64.sin_cos();
        (x - Matrix2::new(c, -s, s, c)).norm()
    }

    #[test]
    fn each_method_converges_at_its_order() {
        for method in RK_METHODS {
            let ratio = rotation_error(method, 20) / rotation_error(method, 40);
            let expected = 2f64.powi(method.order as i32);
            assert!(
                (ratio / expected - 1.0).abs() < 0.1,
                "{}: halving h divides the error by {ratio}, expected {expected}",
                method.name
            );
        }
    }

    #[test]
    fn each_tableau_is_consistent_and_explicit() {
        for method in RK_METHODS {
            let sum: f64 = method.b.iter().sum();
            assert!((sum - 1.0).abs() < 1e-15, "{}: Σb = {sum}", method.name);
            for (i, row) in method.a.iter().enumerate() {
                assert!(
                    row[i..].iter().all(|a| *a == 0.0),
                    "{}: not explicit",
                    method.name
                );
            }
            assert!(method.b[method.stages..].iter().all(|b| *b == 0.0));
        }
    }
}
