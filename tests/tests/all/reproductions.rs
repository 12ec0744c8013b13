//! Every lab's reproduction: no row fails (a check that does not match is declared, with
//! its reason), and each lab's chapter (`README.md` in its folder) shows exactly the table
//! the code measures now. The labs run
//! side by side, one thread each, straight from the registry: a new lab is tested without
//! an edit here.
#![cfg(not(target_arch = "wasm32"))]

use attlab::analysis::readme;
use attlab::labs;
use attlab::model::{Outcome, Row};
use attlab::page::Lab;

/// What is wrong with `lab`'s reproduction or its chapter's table, if anything.
fn reproduction_problem(lab: &dyn Lab) -> Option<String> {
    let id = lab.id();
    let rep = match lab.reproduce() {
        Ok(rep) => rep,
        Err(e) => return Some(format!("{id}: {e}")),
    };
    if rep.rows.is_empty() {
        return Some(format!("{id} has no rows"));
    }
    if !rep.all_as_declared() {
        return Some(format!(
            "{id}:\n{}\nfailures:\n{}",
            rep.to_table(),
            rep.failures().join("\n")
        ));
    }
    if let Some(problem) = unpaired_calibration(&rep.rows) {
        return Some(format!("{id}: {problem}"));
    }
    let chapter = lab.study()?.chapter();
    let path = chapter.path();
    let Some(shown) = readme::block(chapter.text, id) else {
        return Some(format!(
            "{} has no <!-- reproduce:{id} --> block",
            path.display()
        ));
    };
    (shown != rep.to_markdown().trim_matches('\n')).then(|| {
        format!(
            "the table in {} drifted from what the code measures: run \
             `cargo run -p attlab --release -- reproduce all --readme`",
            path.display()
        )
    })
}

/// A match after calibration must be followed by the same quantity at the setting −50 % and
/// +50 % (measurements): what is wrong, if anything.
fn unpaired_calibration(rows: &[Row]) -> Option<String> {
    for (k, row) in rows.iter().enumerate() {
        if !matches!(row.outcome(), Outcome::MatchesAfterCalibration(_)) {
            continue;
        }
        for (offset, tag) in [(1, "(−50 %)"), (2, "(+50 %)")] {
            let beside = rows.get(k + offset);
            let paired = beside.is_some_and(|b| {
                b.outcome() == Outcome::Measurement
                    && b.quantity.starts_with(&row.quantity)
                    && b.quantity.ends_with(tag)
                    && b.unit == row.unit
            });
            if !paired {
                return Some(format!(
                    "the calibrated row `{}` has no {tag} row beside it",
                    row.quantity
                ));
            }
        }
    }
    None
}

#[test]
fn a_calibrated_row_without_its_sensitivity_rows_is_caught() {
    use attlab::model::{Calibration, Expectation};
    let check = Row::check("σ", "1", 1.0, "deg", Expectation::below(2.0));
    let setting = Calibration::new("rate", 1.0, "Hz");
    let rows = setting.rows(check.clone(), Ok::<_, ()>).unwrap();
    assert_eq!(unpaired_calibration(&rows), None);
    let alone = vec![check.calibrated_by("rate = 1 Hz")];
    assert!(unpaired_calibration(&alone).is_some());
    assert!(unpaired_calibration(&rows[..2]).is_some());
}

#[test]
fn every_lab_reproduces_and_its_chapter_shows_it() {
    let problems: Vec<String> = std::thread::scope(|s| {
        let runs: Vec<_> = labs::all()
            .iter()
            .map(|lab| s.spawn(move || reproduction_problem(*lab)))
            .collect();
        runs.into_iter()
            .zip(labs::all())
            .filter_map(|(run, lab)| match run.join() {
                Ok(problem) => problem,
                Err(_) => Some(format!("{}: the reproduction panicked", lab.id())),
            })
            .collect()
    });
    assert!(problems.is_empty(), "{}", problems.join("\n\n"));
    assert!(labs::all().len() >= 6, "the registry lost labs");
}
