//! Names, units and meaning of recorded series.

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

/// Name, unit and plot of one recorded series.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct SeriesSpec {
    /// `source.quantity`, e.g. `quat-rk4.err_deg`.
    pub name: String,
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
}

impl SeriesSpec {
    /// A series of the truth (source 0).
    pub fn new(name: impl Into<String>, unit: &'static str, group: SeriesGroup) -> Self {
        Self {
            name: name.into(),
            unit,
            group,
            source: 0,
            band: None,
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
    /// The lab's figure with this index.
    Figure(usize),
    /// All series of a group.
    Group(SeriesGroup),
}
