//! Typed series keys: who records a series and what it measures. The series' name
//! (`source.key`, the machine name in CSV headers and links) is derived from the key, never
//! typed; the catalogue builds every name through [`SeriesKey::name`], and figures, sweeps,
//! outages and reproductions name their series by key.

use super::quantity::{Quantity, StateInfo};
use std::borrow::Cow;
use std::fmt;

/// The name of the time column, the first of every recording (s).
pub const TIME: &str = "t_s";
/// The source of the truth's series (and of a lab's own truth quantities).
pub const TRUTH: &str = "truth";
/// The source of the sensors' own series (biases, availability flags).
pub const SENSORS: &str = "sensors";

/// What a series measures.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Measure {
    /// A declared quantity: its key, label and unit.
    Quantity(&'static Quantity),
    /// The variance of one covariance state.
    Variance(&'static StateInfo),
    /// The covariance of two states.
    Covariance(&'static StateInfo, &'static StateInfo),
    /// The attitude NEES eᵀP⁻¹e.
    NeesAtt,
    /// The estimator's health (0 = ok).
    Status,
}

/// A series: its source (`truth`, `sensors` or an estimator's id) and what it measures.
///
/// ```
/// # use attlab::model::{Quantity, SeriesKey};
/// const ERR: Quantity = Quantity::new("err_deg", "attitude error", "deg");
/// let key = SeriesKey::new("st-gyro", &ERR);
/// assert_eq!(key.name(), "st-gyro.err_deg");
/// assert!(key.is("st-gyro.err_deg") && !key.is("st.err_deg"));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SeriesKey {
    /// Who records it.
    pub source: &'static str,
    /// What it is.
    pub measure: Measure,
}

impl SeriesKey {
    /// `quantity` of `source`.
    pub const fn new(source: &'static str, quantity: &'static Quantity) -> Self {
        Self {
            source,
            measure: Measure::Quantity(quantity),
        }
    }

    /// A quantity of the truth.
    pub const fn truth(quantity: &'static Quantity) -> Self {
        Self::new(TRUTH, quantity)
    }

    /// A quantity of the sensors.
    pub const fn sensors(quantity: &'static Quantity) -> Self {
        Self::new(SENSORS, quantity)
    }

    /// The variance of `state` in `source`'s covariance.
    pub const fn variance(source: &'static str, state: &'static StateInfo) -> Self {
        Self {
            source,
            measure: Measure::Variance(state),
        }
    }

    /// The covariance of states `a` and `b` in `source`'s covariance.
    pub const fn covariance(
        source: &'static str,
        a: &'static StateInfo,
        b: &'static StateInfo,
    ) -> Self {
        Self {
            source,
            measure: Measure::Covariance(a, b),
        }
    }

    /// `source`'s attitude NEES.
    pub const fn nees_att(source: &'static str) -> Self {
        Self {
            source,
            measure: Measure::NeesAtt,
        }
    }

    /// `source`'s health.
    pub const fn status(source: &'static str) -> Self {
        Self {
            source,
            measure: Measure::Status,
        }
    }

    /// The same measure of another source.
    pub const fn of(self, source: &'static str) -> Self {
        Self { source, ..self }
    }

    /// The second half of the name, e.g. `err_deg`, `var_att_x`.
    pub fn key(&self) -> String {
        match self.measure {
            Measure::Quantity(q) => q.key.to_string(),
            Measure::Variance(s) => format!("var_{}", s.key),
            Measure::Covariance(a, b) => format!("cov_{}_{}", a.key, b.key),
            Measure::NeesAtt => "nees_att".into(),
            Measure::Status => "status".into(),
        }
    }

    /// The series' name, `source.key`.
    pub fn name(&self) -> String {
        format!("{}.{}", self.source, self.key())
    }

    /// Whether `name` is this series' name.
    pub fn is(&self, name: &str) -> bool {
        name.strip_prefix(self.source)
            .and_then(|rest| rest.strip_prefix('.'))
            .is_some_and(|key| key == self.key())
    }
}

impl fmt::Display for SeriesKey {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}.{}", self.source, self.key())
    }
}

/// A series named by its key or by its name as recorded (a CSV column, a log's header).
pub trait SeriesRef {
    /// The series' name.
    fn series_name(&self) -> Cow<'_, str>;
}

impl SeriesRef for SeriesKey {
    fn series_name(&self) -> Cow<'_, str> {
        Cow::Owned(self.name())
    }
}

impl SeriesRef for str {
    fn series_name(&self) -> Cow<'_, str> {
        Cow::Borrowed(self)
    }
}

impl SeriesRef for String {
    fn series_name(&self) -> Cow<'_, str> {
        Cow::Borrowed(self)
    }
}

impl<T: SeriesRef + ?Sized> SeriesRef for &T {
    fn series_name(&self) -> Cow<'_, str> {
        (**self).series_name()
    }
}

/// The names of `keys`, in order.
pub fn names(keys: &[SeriesKey]) -> Vec<String> {
    keys.iter().map(SeriesKey::name).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::StateKind;

    const ATT_X: StateInfo = StateInfo::new("att_x", "rad", StateKind::AttitudeAxis(0));
    const RATE: StateInfo = StateInfo::new("rate", "rad/s", StateKind::Rate);
    const ERR: Quantity = Quantity::new("err_deg", "attitude error", "deg");

    #[test]
    fn every_measure_names_its_series() {
        let cases = [
            (SeriesKey::new("kf", &ERR), "kf.err_deg"),
            (SeriesKey::truth(&ERR), "truth.err_deg"),
            (SeriesKey::sensors(&ERR), "sensors.err_deg"),
            (SeriesKey::variance("st-gyro", &ATT_X), "st-gyro.var_att_x"),
            (
                SeriesKey::covariance("kf", &ATT_X, &RATE),
                "kf.cov_att_x_rate",
            ),
            (SeriesKey::nees_att("st"), "st.nees_att"),
            (SeriesKey::status("kf"), "kf.status"),
            (SeriesKey::new("kf", &ERR).of("aekf"), "aekf.err_deg"),
        ];
        for (key, name) in cases {
            assert_eq!(key.name(), name);
            assert_eq!(key.to_string(), name);
            assert!(key.is(name), "{name}");
        }
    }

    #[test]
    fn a_key_is_not_a_longer_or_other_name() {
        let key = SeriesKey::new("st", &ERR);
        for other in [
            "st-gyro.err_deg",
            "st.err_deg_x",
            "st.err",
            "st",
            "xst.err_deg",
            "",
        ] {
            assert!(!key.is(other), "{other}");
        }
    }
}
