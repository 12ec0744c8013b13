//! One filter row of paper 2's tables: the filter, its tuning, where the tuning comes from,
//! and the accuracies the paper gives for it.

use crate::estimators::{MekfConfig, StateSet};

/// Where a filter's q comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum QSource {
    /// Table 3, readable.
    Table3,
    /// Table 3 as the OCR reads it, with a digit or an exponent it is unsure of.
    Table3Uncertain,
    /// This project's: the OCR lost Table 3's.
    Ours,
}

impl QSource {
    /// How a table row names it.
    pub fn label(self) -> &'static str {
        match self {
            Self::Table3 => "q from Table 3",
            Self::Table3Uncertain => "q from Table 3 where the OCR is unsure of it",
            Self::Ours => "q ours: the OCR lost Table 3's",
        }
    }
}

impl FilterRow {
    /// The number of the paper's table this filter's values are from: 5 for a constant
    /// gain, 4 with the disturbance filter, else 3; `None` for Fig. 7's turn model.
    pub fn table(&self) -> Option<u8> {
        if self.config.states == StateSet::AttRateMagTurn {
            None
        } else if self.config.constant_gain {
            Some(5)
        } else if self.config.disturbance {
            Some(4)
        } else {
            Some(3)
        }
    }
}

/// One filter of the lab with the paper's tuning and results.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FilterRow {
    /// What it is.
    pub config: MekfConfig,
    /// q_Λ, q_ω, q_bias per 0.1-s prediction step (the paper's Table 3 where it is readable).
    pub q: [f64; 3],
    /// Where `q` comes from.
    pub q_from: QSource,
    /// Table 3's attitude σ (deg) and rate σ (deg/s); `None` where the OCR lost the number.
    pub paper_att_deg: Option<f64>,
    /// Table 3's rate σ (deg/s).
    pub paper_rate_deg_s: Option<f64>,
    /// The table's accuracy of the bias the filter estimates (deg/s for a gyro bias, nT for
    /// a magnetometer bias), where the OCR kept it.
    pub paper_bias: Option<f64>,
    /// The filter whose initial error this one starts from (a constant-gain variant starts
    /// as its EKF, so that the two differ only after the freeze); `None`: its own.
    pub starts_as: Option<&'static str>,
}
