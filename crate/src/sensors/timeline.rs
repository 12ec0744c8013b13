//! A log's clock, repaired by stated rules so that every good sample is kept and nothing is
//! stretched or overwritten. `P` is the nominal period: the median of the positive steps
//! between successive lines.
//!
//! 1. A time equal to a kept one (within 10⁻⁶ P) is **merged** into it: the values are
//!    averaged (an exact duplicate line changes nothing).
//! 2. A time up to 3 P before the latest is **out of order**: it is put in its place.
//! 3. A step forward of up to 10 P is kept as logged (a dropped sample, jitter).
//! 4. Any other step is a **glitch** when one of the next three lines continues the clock
//!    from before it (a corrupted time field): the line is rejected.
//! 5. Otherwise a step forward is a **gap** and a step back a **reset** (a sketch restarted,
//!    `millis()` from 0): a new segment starts, joined to the last after the gap as logged
//!    but at most max(10 P, 1 s) (a reset: exactly that), so a stopped log does not stretch
//!    the run. The replay shows the join as steps without a sample.

use super::row::{Row, shortened};
use crate::model::{LineFault, LogGap, LogLineError};

/// Rule 1: times this close (in periods) are one time.
const SAME_TIME_PERIODS: f64 = 1e-6;
/// Rule 2: how far back (in periods) a time is out of order rather than a reset.
const REORDER_PERIODS: f64 = 3.0;
/// Rule 3: the longest forward step (in periods) that is not a gap.
const GAP_PERIODS: f64 = 10.0;
/// Rule 4: how many lines ahead a glitch looks for the clock to continue.
const GLITCH_LOOKAHEAD: usize = 3;
/// Rule 5: the shortest join shown (s), when 10 periods are shorter.
const MIN_JOIN_S: f64 = 1.0;

/// A kept sample: its time on the replay's clock (s), its values (time first, as logged)
/// and line.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Timed {
    /// Time on the joined clock (s).
    pub t_s: f64,
    /// The row (values averaged over merged lines).
    pub row: Row,
    weight: f64,
}

/// The repaired clock of a log.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct Timeline {
    /// Kept samples, strictly increasing in time.
    pub samples: Vec<Timed>,
    /// The nominal period P (s); `None` with fewer than two increasing times.
    pub period_s: Option<f64>,
    /// Where segments were joined.
    pub gaps: Vec<LogGap>,
    /// Lines kept but moved (rule 2) or merged (rule 1), by number and what was done.
    pub notes: Vec<LogLineError>,
    /// How many lines were put in their place (rule 2).
    pub reordered: usize,
    /// How many lines were merged into another (rule 1).
    pub merged: usize,
}

fn note(row: &Row, reason: LineFault) -> LogLineError {
    LogLineError {
        line: row.line,
        text: shortened(&row.text),
        reason,
    }
}

/// The median positive step between successive times.
fn nominal_period(times: &[f64]) -> Option<f64> {
    let mut d: Vec<f64> = times
        .windows(2)
        .map(|w| w[1] - w[0])
        .filter(|d| *d > 0.0)
        .collect();
    d.sort_by(f64::total_cmp);
    d.get(d.len() / 2).copied()
}

/// Orders `rows` (time in `values[0]`, in units of `time_scale` s) by the module's rules
/// with the nominal period `period_s`, or the median step of `rows` when `None`; rejected
/// lines go to `errors`. It is [`Orderer`] fed every row and finished, so a log read at
/// once and one read as it arrives are ordered alike.
pub(crate) fn order(
    rows: Vec<Row>,
    time_scale: f64,
    period_s: Option<f64>,
    errors: &mut Vec<LogLineError>,
) -> Timeline {
    let period_s = period_s.or_else(|| {
        let times: Vec<f64> = rows.iter().map(|r| r.values[0] * time_scale).collect();
        nominal_period(&times)
    });
    let mut orderer = Orderer::new(time_scale, period_s);
    let mut out = Timeline {
        period_s,
        ..Timeline::default()
    };
    for row in rows {
        orderer.push(row);
        orderer.drain(&mut out, errors, false);
    }
    orderer.drain(&mut out, errors, true);
    out
}

/// The median positive step of the times of `rows` (in units of `time_scale` s): the
/// nominal period of a log whose first rows are these.
pub(crate) fn period_of(rows: &[Row], time_scale: f64) -> Option<f64> {
    let times: Vec<f64> = rows.iter().map(|r| r.values[0] * time_scale).collect();
    nominal_period(&times)
}

/// The module's rules applied to rows as they arrive. A row that jumps waits for the next
/// [`GLITCH_LOOKAHEAD`] rows (or the end) to be judged; a kept sample is final once no
/// later row can be put before it or merged into it (it is more than 3 P before the latest,
/// or its segment has ended).
#[derive(Clone, Debug)]
pub(crate) struct Orderer {
    time_scale: f64,
    p: f64,
    /// Rows not yet judged, in arrival order.
    waiting: std::collections::VecDeque<Row>,
    /// The current segment's samples, in time order; some may still move.
    segment: Vec<Timed>,
    /// Offset from the logged clock to the joined one, for the current segment.
    shift: f64,
}

impl Orderer {
    /// Rules with nominal period `period_s` (without one, equal times still merge and
    /// every step back is a reset, so the kept times still increase).
    pub(crate) fn new(time_scale: f64, period_s: Option<f64>) -> Self {
        Self {
            time_scale,
            p: period_s.unwrap_or(f64::MIN_POSITIVE),
            waiting: Default::default(),
            segment: Vec::new(),
            shift: 0.0,
        }
    }

    /// Takes the next row (time in `values[0]`).
    pub(crate) fn push(&mut self, row: Row) {
        self.waiting.push_back(row);
    }

    /// Judges every waiting row that can be judged (all of them at the `end`), then moves
    /// the samples that are final into `out` (all of them at the `end`).
    pub(crate) fn drain(&mut self, out: &mut Timeline, errors: &mut Vec<LogLineError>, end: bool) {
        while let Some(row) = self.waiting.pop_front() {
            let t = row.values[0] * self.time_scale;
            let Some(last) = self.segment.last().map(|s| s.t_s - self.shift) else {
                let t_s = t + self.shift;
                self.segment.push(Timed {
                    t_s,
                    row,
                    weight: 1.0,
                });
                continue;
            };
            let d = t - last;
            let p = self.p;
            if (-REORDER_PERIODS * p..=GAP_PERIODS * p).contains(&d) {
                place(&mut self.segment, out, row, t + self.shift, p);
                continue;
            }
            // A jump is judged by the lines after it: wait for them (the row goes back).
            if !end && self.waiting.len() < GLITCH_LOOKAHEAD {
                self.waiting.push_front(row);
                break;
            }
            // A later line continues the clock from before the jump: within its steps of
            // `last`, and (for a jump forward) before the jumped time, which a real gap's
            // lines are not.
            let continues = |k: usize| {
                self.waiting.get(k - 1).is_some_and(|r| {
                    let dk = r.values[0] * self.time_scale - last;
                    (0.0..=(k + 1) as f64 * GAP_PERIODS * p).contains(&dk) && (d < 0.0 || dk < d)
                })
            };
            if (1..=GLITCH_LOOKAHEAD).any(continues) {
                errors.push(note(
                    &row,
                    LineFault::TimeGlitch {
                        t_s: t,
                        last_s: last,
                    },
                ));
                continue;
            }
            let joined_end = last + self.shift;
            let join =
                if d > 0.0 { d } else { f64::INFINITY }.min((GAP_PERIODS * p).max(MIN_JOIN_S));
            self.shift = joined_end + join - t;
            out.gaps.push(LogGap {
                line: row.line,
                from_s: joined_end,
                to_s: joined_end + join,
                logged_from_s: last,
                logged_to_s: t,
            });
            out.samples.append(&mut self.segment);
            let t_s = t + self.shift;
            self.segment.push(Timed {
                t_s,
                row,
                weight: 1.0,
            });
        }
        let settled = if end {
            self.segment.len()
        } else {
            let latest = self.segment.last().map_or(f64::NEG_INFINITY, |s| s.t_s);
            let before = latest - (REORDER_PERIODS + 2.0 * SAME_TIME_PERIODS) * self.p;
            self.segment.partition_point(|s| s.t_s < before)
        };
        out.samples.extend(self.segment.drain(..settled));
    }
}

/// Puts `row` (at joined time `t`) into `segment`: merged into a sample at the same time,
/// or inserted in order.
fn place(segment: &mut Vec<Timed>, out: &mut Timeline, row: Row, t: f64, p: f64) {
    let at = segment.partition_point(|s| s.t_s < t - SAME_TIME_PERIODS * p);
    if let Some(same) = segment
        .get_mut(at)
        .filter(|s| (s.t_s - t).abs() <= SAME_TIME_PERIODS * p)
    {
        let w = same.weight;
        let identical = same.row.values == row.values;
        for (a, b) in same.row.values.iter_mut().zip(&row.values).skip(1) {
            *a = (*a * w + b) / (w + 1.0);
        }
        same.weight += 1.0;
        out.merged += 1;
        let line = same.row.line;
        let fault = if identical {
            LineFault::Duplicate { line }
        } else {
            LineFault::Averaged { line }
        };
        out.notes.push(note(&row, fault));
        return;
    }
    if at < segment.len() {
        out.reordered += 1;
        out.notes.push(note(
            &row,
            LineFault::OutOfOrder {
                line: segment[at].row.line,
            },
        ));
    }
    segment.insert(
        at,
        Timed {
            t_s: t,
            row,
            weight: 1.0,
        },
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rows(times: &[f64]) -> Vec<Row> {
        times
            .iter()
            .enumerate()
            .map(|(i, t)| Row {
                line: i + 1,
                values: vec![*t, i as f64],
                text: format!("{t},{i}"),
            })
            .collect()
    }

    fn kept_lines(t: &Timeline) -> Vec<usize> {
        t.samples.iter().map(|s| s.row.line).collect()
    }

    #[test]
    fn a_glitch_is_rejected_and_a_reset_joins_a_new_segment_after_a_gap() {
        let times = [0.0, 10.0, 20.0, 4.29e9, 30.0, 40.0, 0.0, 10.0, 20.0];
        let mut errors = Vec::new();
        let t = order(rows(&times), 1e-3, None, &mut errors);
        assert_eq!(t.period_s, Some(0.01));
        assert_eq!(errors.iter().map(|e| e.line).collect::<Vec<_>>(), vec![4]);
        assert_eq!(kept_lines(&t), vec![1, 2, 3, 5, 6, 7, 8, 9]);
        // The reset at line 7 starts 1 s (max(10 P, 1 s)) after line 6's 0.04 s.
        assert_eq!(t.gaps.len(), 1);
        assert_eq!((t.gaps[0].line, t.gaps[0].from_s), (7, 0.04));
        let joined: Vec<f64> = t.samples.iter().map(|s| s.t_s).collect();
        assert!((joined[5] - 1.04).abs() < 1e-12 && (joined[7] - 1.06).abs() < 1e-12);
    }

    #[test]
    fn jitter_is_kept_swaps_are_reordered_and_equal_times_merged() {
        let times = [0.0, 12.0, 19.0, 31.0, 29.0, 40.0, 40.0, 50.0];
        let mut errors = Vec::new();
        let t = order(rows(&times), 1e-3, None, &mut errors);
        assert!(errors.is_empty() && t.gaps.is_empty());
        assert_eq!(kept_lines(&t), vec![1, 2, 3, 5, 4, 6, 8]);
        assert_eq!((t.reordered, t.merged), (1, 1));
        // Line 7 (value 6) averaged into line 6 (value 5).
        assert_eq!(t.samples[5].row.values[1], 5.5);
    }

    #[test]
    fn without_a_step_forward_equal_times_merge_and_a_step_back_is_a_reset() {
        let mut errors = Vec::new();
        let t = order(rows(&[5.0, 5.0, 3.0, 3.0]), 1.0, None, &mut errors);
        assert_eq!(t.period_s, None);
        assert_eq!((kept_lines(&t), t.merged, t.gaps.len()), (vec![1, 3], 2, 1));
        assert!(t.samples[0].t_s < t.samples[1].t_s);
    }

    #[test]
    fn a_stall_of_fifteen_periods_is_a_gap_and_loses_no_sample() {
        // The lines after a stall are after its jumped time: not a glitch's clock.
        let times: Vec<f64> = (0..10).chain(25..60).map(|k| 10.0 * k as f64).collect();
        let mut errors = Vec::new();
        let t = order(rows(&times), 1e-3, None, &mut errors);
        assert!(errors.is_empty(), "{errors:?}");
        assert_eq!(t.samples.len(), times.len());
        assert_eq!(t.gaps.len(), 1);
        assert!((t.samples[10].t_s - 0.25).abs() < 1e-12, "joined as logged");
    }

    #[test]
    fn a_long_stop_is_a_gap_shortened_to_one_second() {
        let times = [0.0, 0.1, 0.2, 100.2, 100.3];
        let mut errors = Vec::new();
        let t = order(rows(&times), 1.0, None, &mut errors);
        assert_eq!(t.gaps.len(), 1);
        assert!((t.samples[3].t_s - 1.2).abs() < 1e-12, "{:?}", t.samples[3]);
        assert!((t.gaps[0].logged_to_s - t.gaps[0].logged_from_s - 100.0).abs() < 1e-9);
    }
}
