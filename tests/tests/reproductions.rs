//! Every lab's reproduction: no row fails (a check that does not match is declared, with
//! its reason), and the README shows exactly the tables the code measures now. One test per
//! lab so they run in parallel; a lab added to the registry without one fails
//! `every_registered_lab_has_a_reproduction_test`.
#![cfg(not(target_arch = "wasm32"))]

use attlab::analysis::readme;
use attlab::labs;

const README: &str = include_str!("../../README.md");
const TESTED: &[&str] = &["free-rotation", "p1", "p2", "p3", "p4", "p5"];

fn reproduces_and_the_readme_shows_it(id: &str) {
    let lab = labs::find(id).expect("registered");
    let rep = lab.reproduce().unwrap_or_else(|e| panic!("{id}: {e}"));
    assert!(!rep.rows.is_empty(), "{id} has no rows");
    assert!(
        rep.all_as_declared(),
        "{id}:\n{}\nfailures:\n{}",
        rep.to_table(),
        rep.failures().join("\n")
    );
    let shown = readme::block(README, id)
        .unwrap_or_else(|| panic!("README has no <!-- reproduce:{id} --> block"));
    assert_eq!(
        shown,
        rep.to_markdown().trim_matches('\n'),
        "README table of {id} drifted from what the code measures: run `cargo run -p attlab --release -- reproduce all --readme README.md`"
    );
}

#[test]
fn every_registered_lab_has_a_reproduction_test() {
    let ids: Vec<&str> = labs::all().iter().map(|l| l.id()).collect();
    assert_eq!(ids, TESTED);
}

#[test]
fn free_rotation_reproduces() {
    reproduces_and_the_readme_shows_it("free-rotation");
}

#[test]
fn p1_reproduces() {
    reproduces_and_the_readme_shows_it("p1");
}

#[test]
fn p2_reproduces() {
    reproduces_and_the_readme_shows_it("p2");
}

#[test]
fn p3_reproduces() {
    reproduces_and_the_readme_shows_it("p3");
}

#[test]
fn p4_reproduces() {
    reproduces_and_the_readme_shows_it("p4");
}

#[test]
fn p5_reproduces() {
    reproduces_and_the_readme_shows_it("p5");
}
