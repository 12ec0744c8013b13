//! Every lab's reproduction: no row fails (a check that does not match is declared, with
//! its reason), and the README shows exactly the tables the code measures now. The labs run
//! side by side, one thread each, straight from the registry: a new lab is tested without
//! an edit here.
#![cfg(not(target_arch = "wasm32"))]

use attlab::analysis::readme;
use attlab::labs;
use attlab::model::Lab;

const README: &str = include_str!("../../README.md");

/// What is wrong with `lab`'s reproduction or its README table, if anything.
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
    let Some(shown) = readme::block(README, id) else {
        return Some(format!("README has no <!-- reproduce:{id} --> block"));
    };
    (shown != rep.to_markdown().trim_matches('\n')).then(|| {
        format!(
            "README table of {id} drifted from what the code measures: run \
             `cargo run -p attlab --release -- reproduce all --readme README.md`"
        )
    })
}

#[test]
fn every_lab_reproduces_and_the_readme_shows_it() {
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
