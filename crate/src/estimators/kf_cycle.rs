//! Recording a small filter's cycle ([`KalmanCycle`]) from the shared [`super::kf`] types:
//! the filter calls [`CycleRecorder::predicted`] around its prediction and
//! [`CycleRecorder::updated`] around its update, then [`CycleRecorder::finish`] with its
//! final state. The gain shown is K = P⁻HᵀS⁻¹ of the same P⁻, H and S the update used.

use super::kf::{Innovation, KalmanState};
use crate::model::{CYCLE_ROWS, CYCLE_STATES, CycleUpdate, KalmanCycle, StateInfo, StateMatrix};
use nalgebra::{SMatrix, SVector};

/// The top-left block of `m` in a fixed array.
fn block<const R: usize, const C: usize, const RO: usize, const CO: usize>(
    m: &SMatrix<f64, R, C>,
) -> [[f64; CO]; RO] {
    let mut out = [[0.0; CO]; RO];
    for (i, row) in out.iter_mut().enumerate().take(R) {
        for (j, v) in row.iter_mut().enumerate().take(C) {
            *v = m[(i, j)];
        }
    }
    out
}

fn vector<const N: usize, const O: usize>(v: &SVector<f64, N>) -> [f64; O] {
    let mut out = [0.0; O];
    for (o, x) in out.iter_mut().zip(v.iter()) {
        *o = *x;
    }
    out
}

fn square<const N: usize>(m: &SMatrix<f64, N, N>) -> StateMatrix {
    block::<N, N, CYCLE_STATES, CYCLE_STATES>(m)
}

/// Builds a filter's [`KalmanCycle`] step by step (filters of ≤ 3 states, ≤ 2 rows).
#[derive(Clone, Copy, Debug, Default)]
pub struct CycleRecorder {
    cycle: KalmanCycle,
}

impl CycleRecorder {
    /// A recorder for a filter with these states.
    pub fn new(states: &'static [StateInfo]) -> Self {
        Self {
            cycle: KalmanCycle {
                states,
                ..KalmanCycle::default()
            },
        }
    }

    /// The prediction from `before` to `after` with Φ and Q; starts a new cycle.
    pub fn predicted<const N: usize>(
        &mut self,
        before: &KalmanState<N>,
        phi: &SMatrix<f64, N, N>,
        q: &SMatrix<f64, N, N>,
        after: &KalmanState<N>,
    ) {
        let c = &mut self.cycle;
        c.phi = square(phi);
        c.q = square(q);
        c.x_before = vector(&before.x);
        c.p_before = square(&before.p);
        c.x_prior = vector(&after.x);
        c.p_prior = square(&after.p);
        c.update = None;
        c.note = None;
    }

    /// The update of `prior` to `post` with H, R, the measurement rows `z` (named by
    /// `rows`) and the innovation the update returned.
    #[allow(clippy::too_many_arguments)]
    pub fn updated<const N: usize, const M: usize>(
        &mut self,
        prior: &KalmanState<N>,
        h: &SMatrix<f64, M, N>,
        r: &SMatrix<f64, M, M>,
        rows: [&'static str; CYCLE_ROWS],
        innovation: &Innovation<M>,
        post: &KalmanState<N>,
    ) {
        let pht = prior.p * h.transpose();
        let k = innovation
            .s
            .cholesky()
            .map(|c| c.solve(&pht.transpose()).transpose())
            .unwrap_or_else(SMatrix::zeros);
        let z = innovation.residual + h * prior.x;
        self.cycle.update = Some(CycleUpdate {
            m: M.min(CYCLE_ROWS),
            rows,
            h: block::<M, N, CYCLE_ROWS, CYCLE_STATES>(h),
            r: block::<M, M, CYCLE_ROWS, CYCLE_ROWS>(r),
            z: vector(&z),
            residual: vector(&innovation.residual),
            s: block::<M, M, CYCLE_ROWS, CYCLE_ROWS>(&innovation.s),
            k: block::<N, M, CYCLE_STATES, CYCLE_ROWS>(&k),
            x_post: vector(&post.x),
            p_post: square(&post.p),
        });
    }

    /// The filter's state after the whole step, and what it did beyond the equations.
    pub fn finish<const N: usize>(&mut self, state: &KalmanState<N>, note: Option<&'static str>) {
        self.cycle.x_after = vector(&state.x);
        self.cycle.p_after = square(&state.p);
        self.cycle.note = note;
    }

    /// The cycle recorded.
    pub fn cycle(&self) -> &KalmanCycle {
        &self.cycle
    }
}
