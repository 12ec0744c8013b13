//! The catalogue's ids are the lab's stable ids, never positions: every preset, figure,
//! outage, sweep, diagram and lesson step has a slug of its own, and a lab whose lists are
//! put in another order keeps each translation on its own item.

use super::*;
use crate::model::{LabRun, LabSpec, ParamValues};
use crate::page::{Lab, Lesson, Page};
use rand_chacha::ChaCha8Rng;
use std::collections::{BTreeMap, HashSet};

/// Whether `id` is a slug: lowercase ASCII letters, digits and inner hyphens, a letter in it.
fn is_slug(id: &str) -> bool {
    !id.is_empty()
        && !id.starts_with('-')
        && !id.ends_with('-')
        && !id.contains("--")
        && id.chars().any(|c| c.is_ascii_lowercase())
        && id
            .chars()
            .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '-')
}

#[test]
fn every_id_is_a_slug_and_unique_in_its_list() {
    let mut problems = Vec::new();
    for lab in crate::labs::all() {
        let defaults = ParamValues::defaults(lab.params());
        let lists: [(&str, Vec<&str>); 6] = [
            ("preset", lab.presets().iter().map(|p| p.id).collect()),
            ("figure", lab.page().figures.iter().map(|f| f.id).collect()),
            ("outage", lab.page().outages.iter().map(|o| o.id).collect()),
            ("sweep", lab.sweeps().iter().map(|s| s.id).collect()),
            (
                "diagram",
                (lab.page().diagrams(&defaults).iter())
                    .map(|d| d.id)
                    .collect(),
            ),
            (
                "lesson step",
                (lab.lesson().iter().flat_map(|l| l.steps.iter()))
                    .map(|s| s.id)
                    .collect(),
            ),
        ];
        for (kind, ids) in lists {
            let mut seen = HashSet::new();
            for id in ids {
                if !is_slug(id) {
                    problems.push(format!("{}: {kind} id `{id}` is not a slug", lab.id()));
                }
                if !seen.insert(id) {
                    problems.push(format!("{}: {kind} id `{id}` twice", lab.id()));
                }
            }
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

/// A lab whose presets, figures, outages and lesson steps stand in the reverse order.
struct Reversed(&'static dyn Lab);

fn reversed<T: Clone>(items: &[T]) -> &'static [T] {
    Box::leak(
        items
            .iter()
            .rev()
            .cloned()
            .collect::<Vec<T>>()
            .into_boxed_slice(),
    )
}

impl Lab for Reversed {
    fn spec(&self) -> &'static LabSpec {
        let spec = self.0.spec();
        Box::leak(Box::new(LabSpec {
            presets: reversed(spec.presets),
            ..*spec
        }))
    }
    fn dt_s(&self, params: &ParamValues) -> f64 {
        self.0.dt_s(params)
    }
    fn build(&self, params: &ParamValues, rng: &mut ChaCha8Rng) -> LabRun {
        self.0.build(params, rng)
    }
    fn page(&self) -> &'static Page {
        let page = self.0.page();
        Box::leak(Box::new(Page {
            figures: reversed(page.figures),
            outages: reversed(page.outages),
            ..*page
        }))
    }
    fn study(&self) -> Option<&dyn crate::model::Study> {
        self.0.study()
    }
    fn accuracy_table(&self) -> Option<crate::page::AccuracyTable> {
        self.0.accuracy_table()
    }
    fn lesson(&self) -> Option<&'static Lesson> {
        let lesson = self.0.lesson()?;
        Some(Box::leak(Box::new(Lesson {
            steps: reversed(lesson.steps),
            ..*lesson
        })))
    }
}

/// Each English word of `lab` with its Russian, by the English (a word the lab says twice
/// must have one Russian).
fn russian_by_english(lab: &'static dyn Lab) -> BTreeMap<&'static str, String> {
    lab_words(lab)
        .into_iter()
        .map(|(id, english)| (english, lab_text(Lang::Ru, &id, english)))
        .collect()
}

#[test]
fn reordering_a_labs_lists_keeps_every_translation_on_its_own_item() {
    for lab in crate::labs::all() {
        let before = russian_by_english(*lab);
        let turned: &'static dyn Lab = Box::leak(Box::new(Reversed(*lab)));
        let after = russian_by_english(turned);
        let moved: Vec<String> = (before.iter())
            .filter(|(english, ru)| after.get(*english) != Some(*ru))
            .map(|(english, ru)| format!("“{english}”: “{ru}” → {:?}", after.get(english)))
            .collect();
        assert!(moved.is_empty(), "{}:\n{}", lab.id(), moved.join("\n"));
    }
}
