//! Why an estimator is not healthy, typed and with its numbers, so that the page can say it
//! in the reader's language (the catalogue's `trouble-*` messages, through `i18n::trouble`).
//! It had been an English sentence formatted by the estimator, which the Russian page showed
//! as it was, and which cost an allocation at every step a filter stayed lost.

/// What went wrong with an estimator (the reason inside a [`super::EstimatorStatus`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Trouble {
    /// The state or its covariance holds a NaN or an infinity.
    NotFinite,
    /// Paper 5's Λ, U or p holds a NaN or an infinity.
    SensitivityNotFinite,
    /// An update was refused: the innovation covariance H P Hᵀ + R is not positive definite
    /// (a degenerate geometry, or R = 0 with P = 0); the filter keeps its prior.
    InnovationNotPositive,
    /// An update was refused: the measurement or the result is not finite.
    MeasurementNotFinite,
    /// After an update P is no longer positive semidefinite: R too small beside P for double
    /// precision.
    LostDefiniteness,
    /// The attitude's 2σ grew past `limit_deg`: the filter no longer knows the attitude.
    AttitudeLost {
        /// The largest 2σ of the three attitude-error angles (degrees).
        sigma_deg: f64,
        /// The limit it passed (degrees).
        limit_deg: f64,
    },
    /// Paper 1: the estimated angle ran this far from the integrated gyro angle (an unstable
    /// adaptation).
    AngleRanAway {
        /// The difference (degrees).
        deg: f64,
    },
    /// Paper 5, method 10: Uᵀ Q U + ε I is singular.
    SingularSensitivity,
    /// Paper 2: the sun and the field are within `within_deg` of parallel, and there is no
    /// star tracker, so the rotation about them is not observed.
    SunAlongField {
        /// The angle that counts as parallel (degrees).
        within_deg: f64,
    },
}

impl Trouble {
    /// One of each kind, for the tests that check the catalogue says every one.
    pub const EXAMPLES: [Trouble; 9] = [
        Trouble::NotFinite,
        Trouble::SensitivityNotFinite,
        Trouble::InnovationNotPositive,
        Trouble::MeasurementNotFinite,
        Trouble::LostDefiniteness,
        Trouble::AttitudeLost {
            sigma_deg: 47.0,
            limit_deg: 45.0,
        },
        Trouble::AngleRanAway { deg: 3_700.0 },
        Trouble::SingularSensitivity,
        Trouble::SunAlongField { within_deg: 2.0 },
    ];

    /// The catalogue's message for this reason.
    pub fn message_id(&self) -> &'static str {
        match self {
            Self::NotFinite => "trouble-not-finite",
            Self::SensitivityNotFinite => "trouble-sensitivity-not-finite",
            Self::InnovationNotPositive => "trouble-innovation-not-positive",
            Self::MeasurementNotFinite => "trouble-measurement-not-finite",
            Self::LostDefiniteness => "trouble-lost-definiteness",
            Self::AttitudeLost { .. } => "trouble-attitude-lost",
            Self::AngleRanAway { .. } => "trouble-angle-ran-away",
            Self::SingularSensitivity => "trouble-singular-sensitivity",
            Self::SunAlongField { .. } => "trouble-sun-along-field",
        }
    }

    /// The message's arguments: each number by its name, in whole degrees (the attitude's
    /// 2σ to a tenth, so that one just past its limit does not read as equal to it).
    pub fn arguments(&self) -> Vec<(&'static str, String)> {
        let deg = |x: f64| format!("{x:.0}");
        match *self {
            Self::AttitudeLost {
                sigma_deg,
                limit_deg,
            } => vec![
                ("sigma", format!("{sigma_deg:.1}")),
                ("limit", deg(limit_deg)),
            ],
            Self::AngleRanAway { deg: d } => vec![("deg", deg(d))],
            Self::SunAlongField { within_deg } => vec![("deg", deg(within_deg))],
            _ => Vec::new(),
        }
    }
}
