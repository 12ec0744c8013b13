//! One predict/update cycle of a small linear Kalman filter, as numbers: what the page's
//! step-through panel shows beside the equations x̂⁻ = Φx̂, P⁻ = ΦPΦᵀ + Q,
//! K = P⁻Hᵀ(HP⁻Hᵀ + R)⁻¹, x̂⁺ = x̂⁻ + K(z − Hx̂⁻), P⁺ = (I − KH)P⁻(I − KH)ᵀ + KRKᵀ.
//! Filters of up to [`CYCLE_STATES`] states and [`CYCLE_ROWS`] measurement rows keep one
//! (paper 1's and paper 4's); it is plain data, no heap.

use super::quantity::StateInfo;

/// The most states a cycle holds.
pub const CYCLE_STATES: usize = 3;
/// The most measurement rows a cycle holds.
pub const CYCLE_ROWS: usize = 2;

/// A square matrix of up to [`CYCLE_STATES`] states (the top-left `n`×`n` is used).
pub type StateMatrix = [[f64; CYCLE_STATES]; CYCLE_STATES];
/// A state vector of up to [`CYCLE_STATES`] states.
pub type StateVector = [f64; CYCLE_STATES];

/// The last cycle of a filter: its prediction and, when a measurement came, its update.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct KalmanCycle {
    /// The states, in order (their number is `n`).
    pub states: &'static [StateInfo],
    /// Φ of the prediction.
    pub phi: StateMatrix,
    /// Q of the prediction.
    pub q: StateMatrix,
    /// x̂ before the prediction (the last step's x̂⁺).
    pub x_before: StateVector,
    /// P before the prediction.
    pub p_before: StateMatrix,
    /// x̂⁻ = Φx̂ (plus the control input where the filter has one).
    pub x_prior: StateVector,
    /// P⁻ = ΦPΦᵀ + Q.
    pub p_prior: StateMatrix,
    /// The update of this step, if a measurement came.
    pub update: Option<CycleUpdate>,
    /// The filter's state after the whole step (after the update and any adaptation).
    pub x_after: StateVector,
    /// The filter's covariance after the whole step.
    pub p_after: StateMatrix,
    /// What the filter did after the update that the equations do not show (an adaptation
    /// window ending and replacing P), in words, if anything.
    pub note: Option<&'static str>,
}

/// The update half of a cycle.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CycleUpdate {
    /// Rows measured.
    pub m: usize,
    /// What each row measures (short, with its unit), in order.
    pub rows: [&'static str; CYCLE_ROWS],
    /// H (m × n).
    pub h: [[f64; CYCLE_STATES]; CYCLE_ROWS],
    /// R (m × m).
    pub r: [[f64; CYCLE_ROWS]; CYCLE_ROWS],
    /// The measurement z.
    pub z: [f64; CYCLE_ROWS],
    /// The innovation z − Hx̂⁻.
    pub residual: [f64; CYCLE_ROWS],
    /// S = HP⁻Hᵀ + R.
    pub s: [[f64; CYCLE_ROWS]; CYCLE_ROWS],
    /// K = P⁻HᵀS⁻¹ (n × m).
    pub k: [[f64; CYCLE_ROWS]; CYCLE_STATES],
    /// x̂⁺ = x̂⁻ + K(z − Hx̂⁻).
    pub x_post: StateVector,
    /// P⁺ (Joseph form).
    pub p_post: StateMatrix,
}

impl KalmanCycle {
    /// The number of states.
    pub fn n(&self) -> usize {
        self.states.len().min(CYCLE_STATES)
    }
}

/// What a filter small enough to teach with shows of itself, beyond the estimate every
/// estimator publishes: an optional part of an estimator ([`super::Estimator::teaching`]).
pub trait Teaching {
    /// The last predict/update cycle as numbers.
    fn cycle(&self) -> &KalmanCycle;
}
