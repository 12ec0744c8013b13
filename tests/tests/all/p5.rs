//! Paper 5 lab: the paper's output file and the update rules.
#![cfg(not(target_arch = "wasm32"))]

use attlab::math::{KrylovAngles, wrap_pi};
use attlab::model::ParamValues;
use attlab_tests::lab;

#[test]
fn the_output_file_ends_at_the_first_row_within_tolerance() {
    let lab = lab("p5");
    let p = ParamValues::defaults(lab.params());
    let file = lab.output_file(&p).expect("paper 5 defines an output file");
    let mut buf = Vec::new();
    let (rows, stopped) = attlab::sim::write_output_file(lab, p, 1, 30.0, &file, &mut buf).unwrap();
    assert!(
        stopped,
        "the paper's case reaches the tolerance within 30 s"
    );
    let text = String::from_utf8(buf).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines[0], "time,angle1,angle2,angle3");
    assert_eq!(lines.len() as u64, rows + 1);
    let last: Vec<f64> = lines[lines.len() - 1]
        .split(',')
        .map(|c| c.parse().unwrap())
        .collect();
    let reference = KrylovAngles::new(0.01, 0.02, 0.01).to_array();
    for (a, r) in last[1..].iter().zip(reference) {
        assert!(wrap_pi(a - r).abs() <= 0.01, "last row {last:?}");
    }
    // The row before is not within tolerance (it is the first such row).
    let before: Vec<f64> = lines[lines.len() - 2]
        .split(',')
        .map(|c| c.parse().unwrap())
        .collect();
    assert!(
        before[1..]
            .iter()
            .zip(reference)
            .any(|(a, r)| wrap_pi(a - r).abs() > 0.01),
        "{before:?}"
    );
    // Just after 2Δt with Δt = 1 s (the digest's re-simulation: 2.02).
    assert!((2.0..2.1).contains(&last[0]), "first hit at {}", last[0]);
}
