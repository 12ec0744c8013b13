//! Names, units and meaning of recorded series.

use super::key::{Measure, SeriesKey};
use super::quantity::Quantity;

/// Which plot a series belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize)]
pub enum SeriesGroup {
    /// The time axis.
    Time,
    /// Attitude angles.
    Attitude,
    /// Rates.
    Rate,
    /// Estimation errors.
    Error,
    /// Covariance elements.
    Covariance,
    /// Innovations.
    Innovation,
    /// Vertical in body axes and (u, v): what the Riemann-sphere view draws.
    Sphere,
    /// Anything lab specific.
    Lab,
}

impl SeriesGroup {
    /// Every group, in the order declared (a test checks each has its words).
    pub const ALL: [Self; 8] = [
        Self::Time,
        Self::Attitude,
        Self::Rate,
        Self::Error,
        Self::Covariance,
        Self::Innovation,
        Self::Sphere,
        Self::Lab,
    ];

    /// The id of the plot tab's title in the page's message catalogue (`group-attitude`…).
    pub fn message(self) -> &'static str {
        match self {
            Self::Time => "group-time",
            Self::Attitude => "group-attitude",
            Self::Rate => "group-rate",
            Self::Error => "group-error",
            Self::Covariance => "group-covariance",
            Self::Innovation => "group-innovation",
            Self::Sphere => "group-sphere",
            Self::Lab => "group-lab",
        }
    }

    /// The id of the noun its plots' y axis carries before the unit ("error [°]"), or `None`
    /// where the group's series measure different things (the sphere's, a lab's own).
    /// The unit alone, "[°]", turned on its side, reads as a small box.
    pub fn axis_message(self) -> Option<&'static str> {
        match self {
            Self::Attitude => Some("axis-attitude"),
            Self::Rate => Some("axis-rate"),
            Self::Error => Some("axis-error"),
            Self::Covariance => Some("axis-covariance"),
            Self::Innovation => Some("axis-innovation"),
            Self::Time | Self::Sphere | Self::Lab => None,
        }
    }

    /// Plot tab title.
    pub fn title(self) -> &'static str {
        match self {
            Self::Time => "Time",
            Self::Attitude => "Attitude",
            Self::Rate => "Rates",
            Self::Error => "Errors",
            Self::Covariance => "Covariance",
            Self::Innovation => "Innovation",
            Self::Sphere => "(u, v) and vertical",
            Self::Lab => "Lab",
        }
    }
}

/// Where a model or an estimator writes this step's values of its own series, each under
/// its quantity and in the order it declared them. In a debug build (every test) a value
/// written under another quantity than the one declared at its place fails at once, so a
/// value never lands in another series' column.
///
/// ```
/// # use attlab::model::{Extras, Quantity};
/// const A: Quantity = Quantity::new("a", "a", "");
/// const B: Quantity = Quantity::new("b", "b", "");
/// let keys: Vec<Box<str>> = vec!["a".into(), "b".into()];
/// let mut out = [0.0; 2];
/// let mut extras = Extras::new(&keys, &mut out);
/// extras.put(&A, 1.0);
/// extras.put(&B, 2.0);
/// assert_eq!(extras.written(), 2);
/// assert_eq!(out, [1.0, 2.0]);
/// ```
pub struct Extras<'a> {
    keys: &'a [Box<str>],
    out: &'a mut [f64],
    at: usize,
}

impl<'a> Extras<'a> {
    /// Values for the quantities with these keys, written into `out` (one slot per key).
    pub fn new(keys: &'a [Box<str>], out: &'a mut [f64]) -> Self {
        debug_assert_eq!(keys.len(), out.len(), "one slot per declared quantity");
        Self { keys, out, at: 0 }
    }

    /// This step's value of `quantity`, the next one declared.
    pub fn put(&mut self, quantity: &Quantity, value: f64) {
        debug_assert!(
            self.keys.get(self.at).is_some_and(|k| **k == *quantity.key),
            "extra value `{}` written where `{}` is declared",
            quantity.key,
            self.keys.get(self.at).map_or("nothing", |k| k)
        );
        if let Some(slot) = self.out.get_mut(self.at) {
            *slot = value;
        }
        self.at += 1;
    }

    /// The values of `quantities`, in order.
    pub fn put_all<'q>(
        &mut self,
        quantities: impl IntoIterator<Item = &'q Quantity>,
        values: impl IntoIterator<Item = f64>,
    ) {
        for (q, v) in quantities.into_iter().zip(values) {
            self.put(q, v);
        }
    }

    /// How many values were written.
    pub fn written(&self) -> usize {
        self.at
    }
}

/// A unit as a student reads it: degrees as °, the rest as written.
///
/// ```
/// # use attlab::model::display_unit;
/// assert_eq!(display_unit("deg/s"), "°/s");
/// assert_eq!(display_unit("nT"), "nT");
/// ```
pub fn display_unit(unit: &str) -> String {
    match unit.strip_prefix("deg") {
        Some(rest) => format!("°{rest}"),
        None => unit.to_string(),
    }
}

/// Name, unit and plot of one recorded series.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct SeriesSpec {
    /// `source.quantity`, e.g. `quat-rk4.err_deg`.
    pub name: String,
    /// What a legend shows, without the unit: the source and the quantity in words, e.g.
    /// "ST+Gyro \[λ,ω\]: attitude error about x" (the name itself until someone labels it).
    pub label: String,
    /// Unit ("" when dimensionless).
    pub unit: &'static str,
    /// Plot it belongs to.
    pub group: SeriesGroup,
    /// Who produced it: 0 = truth (or the lab), 1 + i = estimator i. Fixes its colour.
    pub source: usize,
    /// For an error series: the name of the variance series (SI units) that bounds it, and
    /// the factor from the SI standard deviation to this series' unit (e.g. rad → deg).
    #[serde(skip)]
    pub band: Option<(String, f64)>,
    /// The typed key it was named from (source and measure), from which a label in another
    /// language is derived (`i18n::series_label`); `None` for a series named by hand (a
    /// test's, the time column).
    #[serde(skip)]
    pub key: Option<SeriesKey>,
}

impl SeriesSpec {
    /// A series of the truth (source 0).
    pub fn new(name: impl Into<String>, unit: &'static str, group: SeriesGroup) -> Self {
        let name = name.into();
        Self {
            label: name.clone(),
            name,
            unit,
            group,
            source: 0,
            band: None,
            key: None,
        }
    }

    /// The series of `key` whose measure is a declared quantity: named by the key, labelled
    /// with the quantity's label, in its unit (a derived measure has no unit of its own here:
    /// the catalogue gives those).
    pub fn of(key: SeriesKey, group: SeriesGroup) -> Self {
        let (label, unit) = match key.measure {
            Measure::Quantity(q) => (q.label.to_string(), q.unit),
            _ => (key.key(), ""),
        };
        Self {
            label,
            key: Some(key),
            ..Self::new(key.name(), unit, group)
        }
    }

    /// The same, named from `key` (a derived measure: a variance, the NEES, the health).
    pub fn keyed(self, key: SeriesKey) -> Self {
        Self {
            name: key.name(),
            key: Some(key),
            ..self
        }
    }

    /// The same with this label (without its unit).
    pub fn labelled(self, label: impl Into<String>) -> Self {
        Self {
            label: label.into(),
            ..self
        }
    }

    /// Whether someone gave it a label (it is not just its name).
    pub fn has_label(&self) -> bool {
        self.label != self.name
    }

    /// The legend text: the label and the unit, e.g. "ST+Gyro: attitude error about x [°]".
    pub fn legend(&self) -> String {
        if self.unit.is_empty() {
            self.label.clone()
        } else {
            format!("{} [{}]", self.label, display_unit(self.unit))
        }
    }

    /// The same, produced by `source` (0 = truth, 1 + i = estimator i).
    pub fn from_source(self, source: usize) -> Self {
        Self { source, ..self }
    }

    /// The same, bounded by ±3σ from the variance series `variance` scaled by `scale`.
    pub fn with_band(self, variance: String, scale: f64) -> Self {
        Self {
            band: Some((variance, scale)),
            ..self
        }
    }

    /// CSV header cell: `name [unit]`.
    pub fn header(&self) -> String {
        if self.unit.is_empty() {
            self.name.clone()
        } else {
            format!("{} [{}]", self.name, self.unit)
        }
    }
}

/// A plot tab of the page: one of the lab's figures, or every series of a group.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PlotTab {
    /// The lab's figure with this id (`page::Figure::id`).
    Figure(&'static str),
    /// All series of a group.
    Group(SeriesGroup),
}
