//! Tests of the reproduction rows: verdicts, NaN, formatting.

use super::*;

#[test]
fn a_check_matches_differs_or_fails_as_declared() {
    let e = Expectation::WithinFactor {
        lo: 0.01,
        hi: 0.015,
        factor: 2.0,
    };
    assert_eq!(
        Row::check("q", "p", 0.02, "deg", e).outcome(),
        Outcome::Matches
    );
    assert!(matches!(
        Row::check("q", "p", 0.2, "deg", e).outcome(),
        Outcome::Fails(_)
    ));
    assert_eq!(
        Row::check("q", "p", 0.2, "deg", e)
            .known_to_differ("why")
            .outcome(),
        Outcome::Differs("why".into())
    );
    assert!(matches!(
        Row::check("q", "p", 0.02, "deg", e)
            .known_to_differ("why")
            .outcome(),
        Outcome::Fails(_)
    ));
    assert!(matches!(
        Row::check("q", "p", f64::NAN, "deg", e)
            .known_to_differ("why")
            .outcome(),
        Outcome::Fails(_)
    ));
    assert!(matches!(
        Row::measurement("q", "p", f64::NAN, "deg").outcome(),
        Outcome::Fails(_)
    ));
    assert!(!Expectation::below(f64::NAN).holds(1.0));
}

#[test]
fn markdown_and_text_show_the_three_kinds() {
    let rep = Reproduction {
        lab: "x".into(),
        rows: vec![
            Row::measurement("m", "—", 1.0, "s"),
            Row::check(
                "c",
                "1",
                1.0,
                "",
                Expectation::Near {
                    value: 1.0,
                    tol: 0.1,
                },
            ),
            Row::check(
                "d",
                "5",
                1.0,
                "",
                Expectation::Near {
                    value: 5.0,
                    tol: 0.1,
                },
            )
            .known_to_differ("a reason"),
        ],
        notes: vec![],
    };
    let md = rep.to_markdown();
    assert!(md.contains("| measurement |"));
    assert!(md.contains("| matches |"));
    assert!(md.contains("| differs: a reason |"));
    assert!(rep.all_as_declared());
    let json = serde_json::to_string(&rep).unwrap();
    assert!(json.contains("\"outcome\":\"differs\""), "{json}");
}
