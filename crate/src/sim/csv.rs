//! Rows to CSV as they are made: a header of `name [unit]` cells, one row per step, and an
//! empty cell where a sample is missing or not finite (a NaN: a value that does not exist at
//! that step, such as (u, v) near the pole or an error during a replay without truth; an
//! infinity: the condition number of a singular matrix). No cell ever reads `inf` or `NaN`.

use crate::model::SeriesSpec;
use std::io::Write;

/// A CSV cell: the shortest representation that reads back to the same f64; empty when
/// missing or not finite.
///
/// ```
/// # use attlab::sim::csv_cell;
/// assert_eq!(csv_cell(0.1), "0.1");
/// assert_eq!(csv_cell(f64::NAN), "");
/// assert_eq!(csv_cell(f64::NEG_INFINITY), "");
/// ```
pub fn csv_cell(v: f64) -> String {
    if !v.is_finite() {
        String::new()
    } else {
        format!("{v}")
    }
}

/// Writes rows to CSV as they come.
pub struct CsvSink<W: Write> {
    writer: csv::Writer<W>,
    rows: u64,
}

impl<W: Write> CsvSink<W> {
    /// Writes the header.
    pub fn new(out: W, specs: &[SeriesSpec]) -> Result<Self, csv::Error> {
        let mut writer = csv::Writer::from_writer(out);
        writer.write_record(specs.iter().map(SeriesSpec::header))?;
        Ok(Self { writer, rows: 0 })
    }

    /// Writes one row.
    pub fn row(&mut self, row: &[f64]) -> Result<(), csv::Error> {
        self.writer.write_record(row.iter().map(|v| csv_cell(*v)))?;
        self.rows += 1;
        Ok(())
    }

    /// Flushes; returns the number of rows written.
    pub fn finish(mut self) -> Result<u64, csv::Error> {
        self.writer.flush()?;
        Ok(self.rows)
    }

    /// Flushes and hands the writer back with the number of rows written.
    pub fn into_inner(self) -> Result<(W, u64), super::SimError> {
        let rows = self.rows;
        Ok((self.writer.into_inner()?, rows))
    }
}
