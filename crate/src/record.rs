//! Named series in bounded ring buffers: what plots, exports and tests read.

use std::collections::VecDeque;

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
}

impl SeriesSpec {
    /// A series spec.
    pub fn new(name: impl Into<String>, unit: &'static str, group: SeriesGroup) -> Self {
        Self {
            name: name.into(),
            unit,
            group,
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

/// Rows of all series, keeping at most `capacity` rows (oldest dropped): memory stays
/// flat however long the simulation runs.
#[derive(Clone, Debug)]
pub struct Recorder {
    specs: Vec<SeriesSpec>,
    columns: Vec<VecDeque<f64>>,
    capacity: usize,
    total_rows: u64,
}

impl Recorder {
    /// A recorder for `specs` holding at most `capacity` (≥ 2) rows.
    pub fn new(specs: Vec<SeriesSpec>, capacity: usize) -> Self {
        let capacity = capacity.max(2);
        let columns = specs
            .iter()
            .map(|_| VecDeque::with_capacity(capacity))
            .collect();
        Self {
            specs,
            columns,
            capacity,
            total_rows: 0,
        }
    }

    /// The series.
    pub fn specs(&self) -> &[SeriesSpec] {
        &self.specs
    }

    /// Index of the series named `name`.
    pub fn index_of(&self, name: &str) -> Option<usize> {
        self.specs.iter().position(|s| s.name == name)
    }

    /// Appends a row (one value per series; missing values become NaN, extra are ignored).
    pub fn push(&mut self, row: &[f64]) {
        for (i, col) in self.columns.iter_mut().enumerate() {
            if col.len() == self.capacity {
                col.pop_front();
            }
            col.push_back(row.get(i).copied().unwrap_or(f64::NAN));
        }
        self.total_rows += 1;
    }

    /// Rows held now.
    pub fn len(&self) -> usize {
        self.columns.first().map_or(0, VecDeque::len)
    }

    /// No rows held.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Rows ever pushed (including dropped ones).
    pub fn total_rows(&self) -> u64 {
        self.total_rows
    }

    /// Most rows kept.
    pub fn capacity(&self) -> usize {
        self.capacity
    }

    /// Drops all rows.
    pub fn clear(&mut self) {
        self.columns.iter_mut().for_each(VecDeque::clear);
        self.total_rows = 0;
    }

    /// The values of series `index`, oldest first.
    pub fn column(&self, index: usize) -> Option<&VecDeque<f64>> {
        self.columns.get(index)
    }

    /// The latest value of series `index`.
    pub fn last(&self, index: usize) -> Option<f64> {
        self.columns.get(index).and_then(|c| c.back().copied())
    }

    /// (x, y) points of two series for drawing, at most about `max_points`: rows are grouped
    /// into buckets and each bucket keeps its minimum and maximum y, so spikes survive
    /// decimation. A bucket with missing (non-finite) y values adds a `[x, NaN]` gap marker,
    /// so lines can be broken there instead of bridging the gap.
    pub fn decimated(&self, x: usize, y: usize, max_points: usize) -> Vec<[f64; 2]> {
        let (Some(xs), Some(ys)) = (self.columns.get(x), self.columns.get(y)) else {
            return Vec::new();
        };
        let n = xs.len();
        let buckets = (max_points / 2).max(1);
        let per = n.div_ceil(buckets).max(1);
        let mut out = Vec::with_capacity(2 * buckets + 2);
        let mut start = 0;
        while start < n {
            let end = (start + per).min(n);
            let (mut lo, mut hi, mut gap): (Option<usize>, Option<usize>, Option<usize>) =
                (None, None, None);
            for i in start..end {
                let v = ys[i];
                if !v.is_finite() {
                    gap = gap.or(Some(i));
                    continue;
                }
                if lo.is_none_or(|j| v < ys[j]) {
                    lo = Some(i);
                }
                if hi.is_none_or(|j| v > ys[j]) {
                    hi = Some(i);
                }
            }
            let mut pick: Vec<usize> = lo.into_iter().chain(hi).chain(gap).collect();
            pick.sort_unstable();
            pick.dedup();
            out.extend(
                pick.into_iter()
                    .map(|i| [xs[i], if ys[i].is_finite() { ys[i] } else { f64::NAN }]),
            );
            start = end;
        }
        out
    }

    /// Splits decimated points at their gap markers into drawable pieces.
    pub fn split_at_gaps(points: &[[f64; 2]]) -> Vec<Vec<[f64; 2]>> {
        points
            .split(|p| !p[1].is_finite())
            .filter(|s| !s.is_empty())
            .map(<[_]>::to_vec)
            .collect()
    }

    /// Writes all held rows as CSV with a `name [unit]` header.
    pub fn write_csv<W: std::io::Write>(&self, writer: W) -> Result<(), csv::Error> {
        let mut w = csv::Writer::from_writer(writer);
        w.write_record(self.specs.iter().map(SeriesSpec::header))?;
        for r in 0..self.len() {
            w.write_record(self.columns.iter().map(|c| format_value(c[r])))?;
        }
        w.flush()?;
        Ok(())
    }
}

/// A CSV cell: shortest round-trip representation, `NaN` for missing.
pub fn format_value(v: f64) -> String {
    if v.is_finite() {
        format!("{v}")
    } else {
        "NaN".to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rec(cap: usize) -> Recorder {
        Recorder::new(
            vec![
                SeriesSpec::new("t_s", "s", SeriesGroup::Time),
                SeriesSpec::new("y", "", SeriesGroup::Lab),
            ],
            cap,
        )
    }

    #[test]
    fn memory_stays_bounded() {
        let mut r = rec(100);
        for i in 0..10_000 {
            r.push(&[i as f64, (i as f64).sin()]);
        }
        assert_eq!(r.len(), 100);
        assert_eq!(r.total_rows(), 10_000);
        assert_eq!(r.column(0).unwrap().front().copied(), Some(9900.0));
    }

    #[test]
    fn decimation_keeps_extremes() {
        let mut r = rec(10_000);
        for i in 0..10_000 {
            let y = if i == 4321 {
                50.0
            } else {
                (i as f64 * 0.01).sin()
            };
            r.push(&[i as f64, y]);
        }
        let pts = r.decimated(0, 1, 200);
        assert!(pts.len() <= 202, "{}", pts.len());
        assert!(pts.iter().all(|p| p[1].is_finite()));
        assert!(pts.iter().any(|p| p == &[4321.0, 50.0]));
        assert!(pts.windows(2).all(|w| w[0][0] < w[1][0]));
    }

    #[test]
    fn gaps_break_the_line() {
        let mut r = rec(100);
        for i in 0..100 {
            let y = if (40..45).contains(&i) { f64::NAN } else { 1.0 };
            r.push(&[i as f64, y]);
        }
        let pieces = Recorder::split_at_gaps(&r.decimated(0, 1, 1000));
        assert_eq!(pieces.len(), 2);
        assert_eq!(pieces[0].last().unwrap()[0], 39.0);
        assert_eq!(pieces[1].first().unwrap()[0], 45.0);
    }

    #[test]
    fn csv_has_units_in_header() {
        let mut r = rec(10);
        r.push(&[0.5, f64::NAN]);
        let mut buf = Vec::new();
        r.write_csv(&mut buf).unwrap();
        assert_eq!(String::from_utf8(buf).unwrap(), "t_s [s],y\n0.5,NaN\n");
    }
}
