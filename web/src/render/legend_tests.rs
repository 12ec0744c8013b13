//! The legend's grouping of entries by the words they share, and its placement.

use super::*;

fn parts(owner: Option<&str>, what: &str) -> LegendParts {
    LegendParts {
        owner: owner.map(str::to_string),
        what: what.to_string(),
    }
}

fn texts(rows: &[Row]) -> Vec<String> {
    rows.iter()
        .map(|r| match r {
            Row::Heading(t) => format!("# {t}"),
            Row::Entry { text, under, .. } if *under => format!("  {text}"),
            Row::Entry { text, .. } => text.clone(),
        })
        .collect()
}

#[test]
fn one_owners_series_stand_under_its_name() {
    let legends = [
        parts(Some("8 ST+Gyro"), "error about x [°]"),
        parts(Some("8 ST+Gyro"), "error about y [°]"),
        parts(Some("truth"), "rate [°/s]"),
    ];
    assert_eq!(
        texts(&rows(&legends)),
        [
            "# 8 ST+Gyro",
            "  error about x [°]",
            "  error about y [°]",
            "truth: rate [°/s]"
        ]
    );
}

#[test]
fn owners_of_one_measure_stand_under_the_measure() {
    let legends = [
        parts(Some("1 ST+Gyro+Mag+Sun"), "log10 whole angle [°]"),
        parts(Some("8 ST+Gyro"), "log10 whole angle [°]"),
    ];
    let rows = rows(&legends);
    assert_eq!(
        texts(&rows),
        [
            "# log10 whole angle [°]",
            "  1 ST+Gyro+Mag+Sun",
            "  8 ST+Gyro"
        ]
    );
    // Each entry keeps its series' position (its colour and pattern come from it).
    let indices: Vec<usize> = rows
        .iter()
        .filter_map(|r| match r {
            Row::Entry { index, .. } => Some(*index),
            Row::Heading(_) => None,
        })
        .collect();
    assert_eq!(indices, [0, 1]);
}

#[test]
fn nothing_shared_keeps_every_full_label() {
    let legends = [
        parts(Some("KF"), "angle [°]"),
        parts(Some("truth"), "rate [°/s]"),
        parts(None, "time [s]"),
    ];
    assert_eq!(
        texts(&rows(&legends)),
        ["KF: angle [°]", "truth: rate [°/s]", "time [s]"]
    );
    // One series: its whole legend, even though it "shares" its measure with itself.
    assert_eq!(texts(&rows(&legends[..1])), ["KF: angle [°]"]);
    assert!(rows(&[]).is_empty());
}

#[test]
fn a_series_without_an_owner_ends_its_neighbours_run() {
    let legends = [
        parts(Some("KF"), "angle [°]"),
        parts(Some("KF"), "rate [°/s]"),
        parts(None, "time [s]"),
        parts(Some("KF"), "bias [°/s]"),
    ];
    assert_eq!(
        texts(&rows(&legends)),
        [
            "# KF",
            "  angle [°]",
            "  rate [°/s]",
            "time [s]",
            "KF: bias [°/s]"
        ]
    );
}
