//! The recorder's unit tests: budgets, history buckets, gaps and the recent rows.

use super::*;
use crate::model::SeriesGroup;

fn rec(window: usize) -> Recorder {
    Recorder::with_window(
        vec![
            SeriesSpec::new("t_s", "s", SeriesGroup::Time),
            SeriesSpec::new("y", "", SeriesGroup::Lab),
        ],
        window,
    )
}

#[test]
fn memory_is_fixed_and_the_whole_run_stays_visible() {
    let mut r = rec(100);
    let bytes = r.memory_bytes();
    let n = 1_000_000;
    let window = r.window();
    for i in 0..n {
        let y = if i == 4321 {
            50.0
        } else {
            (i as f64 * 1e-3).sin()
        };
        r.push(&[i as f64, y]);
    }
    assert_eq!(r.memory_bytes(), bytes);
    assert!(r.len() > window - BLOCK && r.len() <= window, "{}", r.len());
    assert_eq!(r.total_rows(), n as u64);
    let pts = r.plot_points(1, 1000);
    assert!(pts.len() <= 1100, "{}", pts.len());
    assert_eq!(pts.first().unwrap()[0], 0.0, "starts at the first row");
    assert_eq!(pts.last().unwrap()[0], (n - 1) as f64);
    assert!(pts.iter().any(|p| p[1] == 50.0), "the spike survives");
    let lo = pts.iter().map(|p| p[1]).fold(f64::INFINITY, f64::min);
    assert!((lo + 1.0).abs() < 1e-6, "the minimum survives: {lo}");
    assert!(pts.windows(2).all(|w| w[0][0] <= w[1][0]), "time order");
}

#[test]
fn bucket_order_follows_the_data() {
    // A rising ramp: every bucket's min comes before its max.
    let mut r = rec(10);
    for i in 0..100_000 {
        r.push(&[i as f64, i as f64]);
    }
    let pts = r.plot_points(1, 400);
    assert!(
        pts.windows(2).all(|w| w[0][1] <= w[1][1]),
        "ramp stays monotone"
    );
}

#[test]
fn gaps_break_the_line_in_history_and_recent_rows() {
    let mut r = rec(50);
    for i in 0..10_000 {
        let y = if (400..405).contains(&i) || (9_980..9_985).contains(&i) {
            f64::NAN
        } else {
            1.0
        };
        r.push(&[i as f64, y]);
    }
    let pieces = Recorder::split_at_gaps(&r.plot_points(1, 4000));
    assert_eq!(pieces.len(), 3, "{pieces:?}");
}

/// Recorders of one budget hold one block of the same size whatever their series (a
/// lab switch frees exactly what the next lab needs), within the budget.
#[test]
fn one_budget_one_block_size() {
    let specs = |n: usize| -> Vec<SeriesSpec> {
        (0..n)
            .map(|i| SeriesSpec::new(format!("s{i}"), "", crate::model::SeriesGroup::Lab))
            .collect()
    };
    let budget = DEFAULT_BUDGET_BYTES;
    let blocks: Vec<usize> = [3, 36, 110]
        .iter()
        .map(|n| {
            let r = Recorder::with_budget(specs(*n), budget);
            assert!(
                r.memory_bytes() <= budget,
                "{n} series: {}",
                r.memory_bytes()
            );
            assert!(r.window() >= MIN_RECENT_ROWS);
            r.recent.capacity()
        })
        .collect();
    assert!(blocks.iter().all(|b| *b == blocks[0]), "{blocks:?}");
    assert_eq!(blocks[0], (budget - SMALL_RESERVE_BYTES) / 8);
}

#[test]
fn recent_rows_are_exact_and_in_order() {
    let mut r = rec(200);
    let window = r.window();
    assert_eq!(window, 256, "rounded up to whole blocks");
    for i in 0..(window + 7) {
        r.push(&[i as f64, 2.0 * i as f64]);
    }
    // The oldest block went to the history; the rows after it are held exactly.
    let held = r.len();
    assert_eq!(held, window - BLOCK + 7);
    let expected: Vec<f64> = (window + 7 - held..window + 7)
        .map(|i| 2.0 * i as f64)
        .collect();
    assert_eq!(r.recent_vec(1), expected);
    // A tail is the end of the same rows; asking for more than is held gives them all.
    assert_eq!(
        r.recent_tail(1, 10, 10),
        expected[expected.len() - 10..].to_vec()
    );
    assert_eq!(r.recent_tail(1, 10 * window, held), expected);
    assert!(r.recent_tail(9, 10, 10).is_empty());
    // Thinned: every third of the last 10 (stride 10 / 3 = 3) and the newest.
    let last10 = &expected[expected.len() - 10..];
    assert_eq!(
        r.recent_tail(1, 10, 3),
        vec![last10[0], last10[3], last10[6], last10[9]]
    );
    // Every other of the last 10: the newest (index 9) is not on the stride, so it is added.
    assert_eq!(
        r.recent_tail(1, 10, 5),
        vec![
            last10[0], last10[2], last10[4], last10[6], last10[8], last10[9]
        ]
    );
    assert_eq!(r.last(0), Some((window + 6) as f64));
    assert_eq!(r.last(7), None);
}

#[test]
fn the_budget_sets_the_window() {
    let specs: Vec<SeriesSpec> = (0..100)
        .map(|i| SeriesSpec::new(format!("s{i}"), "", SeriesGroup::Lab))
        .collect();
    let r = Recorder::with_budget(specs, 16 << 20);
    assert!(r.memory_bytes() <= 16 << 20, "{}", r.memory_bytes());
    assert!(r.window() > 10_000, "{}", r.window());
}
