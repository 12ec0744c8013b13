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

use super::log_lines::Row;
use crate::model::{LogGap, LogLineError};

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

fn note(row: &Row, reason: String) -> LogLineError {
    LogLineError {
        line: row.line,
        text: row.text.clone(),
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

/// Orders `rows` (time in `values[0]`, in units of `time_scale` s) by the module's rules;
/// rejected lines go to `errors`.
pub(crate) fn order(rows: Vec<Row>, time_scale: f64, errors: &mut Vec<LogLineError>) -> Timeline {
    let times: Vec<f64> = rows.iter().map(|r| r.values[0] * time_scale).collect();
    let mut out = Timeline {
        period_s: nominal_period(&times),
        ..Timeline::default()
    };
    // Without a step forward there is no period: equal times still merge, and every step
    // back is a reset, so the kept times still increase.
    let p = out.period_s.unwrap_or(f64::MIN_POSITIVE);
    let mut segment: Vec<Timed> = Vec::new();
    // Offset from the logged clock to the joined one, for the current segment.
    let mut shift = 0.0;
    for (i, row) in rows.into_iter().enumerate() {
        let t = times[i];
        let Some(last) = segment.last().map(|s| s.t_s - shift) else {
            segment.push(Timed {
                t_s: t,
                row,
                weight: 1.0,
            });
            continue;
        };
        let d = t - last;
        if (-REORDER_PERIODS * p..=GAP_PERIODS * p).contains(&d) {
            place(&mut segment, &mut out, row, t + shift, p);
            continue;
        }
        let continues = |k: usize| {
            times
                .get(i + k)
                .is_some_and(|tk| (0.0..=(k + 1) as f64 * GAP_PERIODS * p).contains(&(tk - last)))
        };
        if (1..=GLITCH_LOOKAHEAD).any(continues) {
            errors.push(note(
                &row,
                format!("time glitch: {t} s between {last} s and the lines after it"),
            ));
            continue;
        }
        let joined_end = last + shift;
        let join = if d > 0.0 { d } else { f64::INFINITY }.min((GAP_PERIODS * p).max(MIN_JOIN_S));
        shift = joined_end + join - t;
        out.gaps.push(LogGap {
            line: row.line,
            from_s: joined_end,
            to_s: joined_end + join,
            logged_from_s: last,
            logged_to_s: t,
        });
        out.samples.append(&mut segment);
        segment.push(Timed {
            t_s: t + shift,
            row,
            weight: 1.0,
        });
    }
    out.samples.append(&mut segment);
    out
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
        let what = if identical {
            "a duplicate of"
        } else {
            "averaged with"
        };
        out.notes.push(note(
            &row,
            format!("same time as line {}: {what} it", same.row.line),
        ));
        return;
    }
    if at < segment.len() {
        out.reordered += 1;
        out.notes.push(note(
            &row,
            format!("out of order: put before line {}", segment[at].row.line),
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
        let t = order(rows(&times), 1e-3, &mut errors);
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
        let t = order(rows(&times), 1e-3, &mut errors);
        assert!(errors.is_empty() && t.gaps.is_empty());
        assert_eq!(kept_lines(&t), vec![1, 2, 3, 5, 4, 6, 8]);
        assert_eq!((t.reordered, t.merged), (1, 1));
        // Line 7 (value 6) averaged into line 6 (value 5).
        assert_eq!(t.samples[5].row.values[1], 5.5);
    }

    #[test]
    fn without_a_step_forward_equal_times_merge_and_a_step_back_is_a_reset() {
        let mut errors = Vec::new();
        let t = order(rows(&[5.0, 5.0, 3.0, 3.0]), 1.0, &mut errors);
        assert_eq!(t.period_s, None);
        assert_eq!((kept_lines(&t), t.merged, t.gaps.len()), (vec![1, 3], 2, 1));
        assert!(t.samples[0].t_s < t.samples[1].t_s);
    }

    #[test]
    fn a_long_stop_is_a_gap_shortened_to_one_second() {
        let times = [0.0, 0.1, 0.2, 100.2, 100.3];
        let mut errors = Vec::new();
        let t = order(rows(&times), 1.0, &mut errors);
        assert_eq!(t.gaps.len(), 1);
        assert!((t.samples[3].t_s - 1.2).abs() < 1e-12, "{:?}", t.samples[3]);
        assert!((t.gaps[0].logged_to_s - t.gaps[0].logged_from_s - 100.0).abs() < 1e-9);
    }
}
