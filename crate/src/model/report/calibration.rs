//! Calibrated matches: a check that holds because this project chose a setting the paper
//! does not give. The row says so ("matches after calibration", naming the setting), and the
//! same quantity measured at the setting −50 % and +50 % sits beside it, so a reader sees
//! how much the match depends on the choice.

use super::{Row, RowKind, fmt_sig};

/// A setting the paper does not give, chosen here so that a check matches.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Calibration<'a> {
    /// The setting's name for a reader, e.g. "gyro rate".
    pub name: &'a str,
    /// Its chosen value.
    pub value: f64,
    /// Its unit ("" when it has none).
    pub unit: &'a str,
    /// How it was set, when not by a slider of its own (e.g. "through the body's inertia").
    pub how: &'a str,
}

/// The factors of the chosen value the sensitivity rows are measured at.
pub const SENSITIVITY_FACTORS: [f64; 2] = [0.5, 1.5];

impl Calibration<'_> {
    /// A setting named `name` at `value` `unit`.
    pub fn new<'a>(name: &'a str, value: f64, unit: &'a str) -> Calibration<'a> {
        Calibration {
            name,
            value,
            unit,
            how: "",
        }
    }

    /// `name = value unit` at `factor` of the chosen value.
    fn text_at(&self, factor: f64) -> String {
        let unit = if self.unit.is_empty() {
            String::new()
        } else {
            format!(" {}", self.unit)
        };
        format!("{} = {}{unit}", self.name, fmt_sig(self.value * factor))
    }

    /// What the calibrated row names: `gyro rate = 10 Hz, chosen here (not in the paper)`.
    pub fn describe(&self) -> String {
        let how = if self.how.is_empty() {
            String::new()
        } else {
            format!(", {}", self.how)
        };
        format!("{}{how}, chosen here (not in the paper)", self.text_at(1.0))
    }

    /// `check` marked as calibrated by this setting, followed by the same quantity measured
    /// at the setting × 0.5 and × 1.5 (`measure` takes that factor): measurements, whose
    /// paper column says whether the check would hold there.
    pub fn rows<E>(
        &self,
        check: Row,
        mut measure: impl FnMut(f64) -> Result<f64, E>,
    ) -> Result<Vec<Row>, E> {
        let mut rows = vec![check.clone().calibrated_by(self.describe())];
        for factor in SENSITIVITY_FACTORS {
            let measured = measure(factor)?;
            rows.push(self.sensitivity_row(&check, factor, measured));
        }
        Ok(rows)
    }

    /// The measurement of `check`'s quantity at `factor` of the chosen setting.
    fn sensitivity_row(&self, check: &Row, factor: f64, measured: f64) -> Row {
        let holds = match &check.kind {
            RowKind::Check { expect, .. } => expect.holds(measured),
            RowKind::Measurement => false,
        };
        let percent = (factor - 1.0) * 100.0;
        let sign = if percent < 0.0 { "−" } else { "+" };
        Row::measurement(
            format!(
                "{} — at {} ({sign}{:.0} %)",
                check.quantity,
                self.text_at(factor),
                percent.abs()
            ),
            format!(
                "— (calibration sensitivity: the check above would {}hold here, expecting {})",
                if holds { "" } else { "not " },
                check.expected_text()
            ),
            measured,
            check.unit,
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{Expectation, Outcome};

    fn check(measured: f64) -> Row {
        Row::check(
            "σ",
            "0.02°",
            measured,
            "deg",
            Expectation::within_factor_of(0.02, 3.0),
        )
    }

    #[test]
    fn a_calibrated_row_says_so_and_sits_beside_its_setting_at_plus_minus_half() {
        let setting = Calibration::new("gyro rate", 10.0, "Hz");
        // The quantity falls as the rate rises: 0.04 at 10 Hz, 0.1 at 5, 0.01 at 15.
        let rows = setting
            .rows(check(0.04), |f| Ok::<_, ()>(0.04 / f.powi(2)))
            .unwrap();
        assert_eq!(rows.len(), 3);
        assert_eq!(
            rows[0].outcome(),
            Outcome::MatchesAfterCalibration(
                "gyro rate = 10 Hz, chosen here (not in the paper)".into()
            )
        );
        assert_eq!(rows[0].outcome().word(), "matches after calibration");
        assert!(
            rows[1].quantity.contains("gyro rate = 5 Hz (−50 %)"),
            "{}",
            rows[1].quantity
        );
        assert!(
            rows[2].quantity.contains("gyro rate = 15 Hz (+50 %)"),
            "{}",
            rows[2].quantity
        );
        assert_eq!(rows[1].measured, 0.16);
        assert!(
            rows[1].paper.contains("would not hold"),
            "{}",
            rows[1].paper
        );
        assert!(rows[2].paper.contains("would hold"), "{}", rows[2].paper);
        assert_eq!(rows[1].outcome(), Outcome::Measurement);
    }

    #[test]
    fn a_calibrated_check_that_stops_holding_still_fails() {
        let row = check(1.0).calibrated_by("x = 1");
        assert!(matches!(row.outcome(), Outcome::Fails(_)));
        let declared = check(1.0).calibrated_by("x = 1").known_to_differ("why");
        assert_eq!(declared.outcome(), Outcome::Differs("why".into()));
    }

    #[test]
    fn a_failed_measurement_at_a_sensitivity_point_is_passed_on() {
        let setting = Calibration::new("ζ", 0.05, "");
        let err = setting.rows(check(0.04), |_| Err("no run")).unwrap_err();
        assert_eq!(err, "no run");
    }
}
