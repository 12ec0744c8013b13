//! What a number is: the quantities sources record and the states of a covariance, by
//! key, label, unit and meaning — the vocabulary the rest of `model` names values by.

/// A quantity a source records: its machine key (the second half of the series name, with
/// its unit in it), the student's label and the unit. Declared once, with the values it names.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Quantity {
    /// Key in series names and CSV headers, e.g. `gbias_x_deg_s`.
    pub key: &'static str,
    /// What a student reads in a legend, in the paper's notation, e.g. "gyro bias Δω_x".
    pub label: &'static str,
    /// Unit ("" when dimensionless).
    pub unit: &'static str,
}

impl Quantity {
    /// A quantity.
    pub const fn new(key: &'static str, label: &'static str, unit: &'static str) -> Self {
        Self { key, label, unit }
    }
}

/// What one state of an estimator's covariance stands for. The app draws ±3σ bands and
/// ellipses from this, never from series names.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum StateKind {
    /// Small attitude error about body axis 0, 1 or 2 (rad).
    AttitudeAxis(u8),
    /// The angle of a single-axis estimator (rad).
    Angle,
    /// Body rate about axis 0, 1 or 2 (rad/s).
    RateAxis(u8),
    /// The rate of a single-axis estimator (rad/s).
    Rate,
    /// Paper 3's u = Re w (dimensionless, in the estimator's current chart).
    WzU,
    /// Paper 3's v = Im w.
    WzV,
    /// Gyro bias about axis 0, 1 or 2 (rad/s).
    GyroBias(u8),
    /// Magnetometer bias along axis 0, 1 or 2 (nT).
    MagBias(u8),
    /// Magnetometer bias as a turn of the field about axis 0, 1 or 2 (rad).
    MagTurn(u8),
    /// Anything else (its unit says what).
    Other,
}

/// One state of an estimator's covariance: short key (used in series names), unit, meaning.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StateInfo {
    /// Short ASCII key, e.g. `phi`, `att_x`.
    pub key: &'static str,
    /// SI unit of the state (the variance has its square), e.g. `rad`.
    pub unit: &'static str,
    /// What it is.
    pub kind: StateKind,
}

impl StateInfo {
    /// A state description.
    pub const fn new(key: &'static str, unit: &'static str, kind: StateKind) -> Self {
        Self { key, unit, kind }
    }
}
