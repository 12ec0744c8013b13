//! Registry conformance: every lab in `labs::all()` obeys the lab contract.
#![cfg(not(target_arch = "wasm32"))]

use attlab::labs;
use attlab::model::{Extras, ParamKind, ParamValues, SeriesKey};
use attlab::page::Lab;
use attlab::sim::{Selection, SimOptions, Simulation};
use rand::SeedableRng;
use std::collections::HashSet;

mod params;

fn every_series() -> SimOptions {
    SimOptions {
        selection: Selection::All,
        budget_bytes: 1 << 20,
    }
}

#[test]
fn ids_are_unique_and_params_presets_and_figures_are_well_formed() {
    let mut ids = HashSet::new();
    for lab in labs::all() {
        assert!(ids.insert(lab.id()), "duplicate lab id {}", lab.id());
        assert!(!lab.summary().is_empty() && !lab.title().is_empty());
        let mut keys = HashSet::new();
        for p in lab.params() {
            assert!(keys.insert(p.key), "{}: duplicate key {}", lab.id(), p.key);
            assert!(
                p.min <= p.default && p.default <= p.max,
                "{}: {} default out of range",
                lab.id(),
                p.key
            );
            assert!(
                p.validate(p.default).is_ok(),
                "{}: {} default invalid",
                lab.id(),
                p.key
            );
            if let ParamKind::Choice(options) = p.kind {
                assert_eq!(p.max as usize + 1, options.len(), "{}: {}", lab.id(), p.key);
            }
            if let Some(dep) = p.requires {
                assert!(
                    lab.params().iter().any(|s| s.key == dep),
                    "{}: {} requires unknown {dep}",
                    lab.id(),
                    p.key
                );
            }
        }
        for preset in lab.presets() {
            let mut p = ParamValues::defaults(lab.params());
            for (k, v) in preset.values {
                p.set(lab.params(), k, *v)
                    .unwrap_or_else(|e| panic!("{} preset {}: {e}", lab.id(), preset.name));
            }
        }
        // Every series a figure, sweep, sweep scoring or outage names exists.
        let mut drawn: Vec<SeriesKey> = lab
            .page()
            .figures
            .iter()
            .flat_map(|f| f.series.iter().copied())
            .collect();
        for s in lab.sweeps() {
            drawn.extend_from_slice(s.series);
            for scoring in s.scoring.iter().chain(&s.log_scoring) {
                drawn.extend_from_slice(scoring.series);
            }
        }
        drawn.extend(lab.page().outages.iter().map(|o| o.series));
        let names = attlab::model::names(&drawn);
        let names: Vec<&str> = names.iter().map(String::as_str).collect();
        let p = ParamValues::defaults(lab.params());
        if let Err(e) = Simulation::with_options(*lab, p, 1, SimOptions::named(&names)) {
            panic!(
                "{}: a figure, sweep or outage names a series that does not exist: {e}",
                lab.id()
            );
        }
        for s in lab.sweeps() {
            assert!(
                lab.params().iter().any(|p| p.key == s.key),
                "{}: sweep over unknown {}",
                lab.id(),
                s.key
            );
        }
    }
}

fn run(lab: &'static dyn Lab, params: ParamValues, seed: u64, steps: usize) -> Simulation {
    let mut sim = Simulation::with_options(lab, params, seed, every_series()).expect("all series");
    for _ in 0..steps {
        sim.step();
    }
    sim
}

/// Two rows are the same bit for bit (NaN equals NaN here: the same missing value).
fn same_bits(a: &[f64], b: &[f64]) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(p, q)| p.to_bits() == q.to_bits())
}

#[test]
fn same_lab_params_and_seed_give_the_identical_run_and_reset_reproduces_it() {
    for lab in labs::all() {
        let p = ParamValues::defaults(lab.params());
        let mut a = Simulation::with_options(*lab, p.clone(), 5, every_series()).unwrap();
        let mut b = Simulation::with_options(*lab, p.clone(), 5, every_series()).unwrap();
        let mut c = run(*lab, p, 99, 123);
        c.reset(5);
        for k in 0..300 {
            a.step();
            b.step();
            c.step();
            assert!(
                same_bits(a.last_row(), b.last_row()),
                "{} is not deterministic (step {k})",
                lab.id()
            );
            assert!(
                same_bits(a.last_row(), c.last_row()),
                "{}: reset does not reproduce a fresh run (step {k})",
                lab.id()
            );
        }
    }
}

#[test]
fn estimators_publish_what_they_describe() {
    for lab in labs::all() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(1);
        let run = lab.build(&ParamValues::defaults(lab.params()), &mut rng);
        for e in &run.estimators {
            let states = e.covariance_states();
            match e.covariance() {
                Some(c) => {
                    assert_eq!(c.states, states, "{}", e.id());
                    assert_eq!(c.matrix.len(), states.len() * states.len(), "{}", e.id());
                }
                None => assert!(
                    states.is_empty(),
                    "{}: describes states but publishes no covariance",
                    e.id()
                ),
            }
            assert_eq!(
                e.innovation().len(),
                e.innovation_quantities().len(),
                "{}",
                e.id()
            );
            let keys: Vec<Box<str>> = e.extra_quantities().iter().map(|q| q.key.into()).collect();
            let mut values = vec![f64::NAN; keys.len()];
            let mut extras = Extras::new(&keys, &mut values);
            e.extras(&mut extras);
            assert_eq!(extras.written(), keys.len(), "{}: extras written", e.id());
            assert!(
                values.iter().all(|v| !v.is_nan()),
                "{}: extras not all written",
                e.id()
            );
        }
        // The truth's and the sensors' own series: every declared value written, under its
        // own quantity (Extras checks the order).
        let key_of = |s: &attlab::model::SeriesSpec| -> Box<str> {
            s.name.split_once('.').map_or(&*s.name, |(_, k)| k).into()
        };
        let keys: Vec<Box<str>> = run.truth.extra_series().iter().map(key_of).collect();
        let mut values = vec![f64::NAN; keys.len()];
        let mut extras = Extras::new(&keys, &mut values);
        run.truth.extra_values(&mut extras);
        assert_eq!(extras.written(), keys.len(), "{}: truth extras", lab.id());
        let keys: Vec<Box<str>> = run.sensors.extra_series().iter().map(key_of).collect();
        let mut values = vec![f64::NAN; keys.len()];
        let mut extras = Extras::new(&keys, &mut values);
        run.sensors.extra_values(&mut extras);
        assert_eq!(extras.written(), keys.len(), "{}: sensor extras", lab.id());
    }
}

#[test]
fn every_row_has_one_value_per_series_and_no_series_is_always_missing() {
    for lab in labs::all() {
        let mut sim = run(*lab, ParamValues::defaults(lab.params()), 1, 0);
        assert_eq!(
            sim.last_row().len(),
            sim.specs().len(),
            "{} at t = 0",
            lab.id()
        );
        let mut seen = vec![false; sim.specs().len()];
        for _ in 0..500 {
            sim.step();
            assert_eq!(
                sim.last_row().len(),
                sim.specs().len(),
                "{} after a step",
                lab.id()
            );
            for (s, v) in seen.iter_mut().zip(sim.last_row()) {
                *s |= !v.is_nan();
            }
        }
        for (spec, s) in sim.specs().iter().zip(seen) {
            assert!(
                s,
                "{}: series {} never has a value (a series that does not apply must not exist)",
                lab.id(),
                spec.name
            );
        }
    }
}

#[test]
fn recorder_memory_stays_fixed_over_a_long_run() {
    for lab in labs::all() {
        let mut sim = Simulation::new(*lab, ParamValues::defaults(lab.params()), 1);
        let bytes = sim.recorder().memory_bytes();
        assert!(
            bytes <= attlab::record::DEFAULT_BUDGET_BYTES,
            "{}: {bytes} B",
            lab.id()
        );
        for _ in 0..(2 * sim.recorder().window() + 5000) {
            sim.step();
        }
        assert_eq!(sim.recorder().memory_bytes(), bytes, "{}", lab.id());
        let pts = sim.recorder().plot_points(1, 1000);
        assert!(
            pts.first().is_some_and(|p| p[0] == 0.0),
            "{}: the plot starts at t = 0",
            lab.id()
        );
    }
}

#[test]
fn a_csv_export_rerun_matches_the_live_run_with_its_parameter_changes() {
    for lab in labs::all() {
        let p = ParamValues::defaults(lab.params());
        let mut live = Simulation::with_options(*lab, p, 4, every_series()).unwrap();
        let live_spec = lab
            .params()
            .iter()
            .find(|s| !s.needs_reset)
            .expect("a live parameter");
        let mut rows = vec![live.last_row().to_vec()];
        for k in 0..600 {
            if k == 300 {
                let v = if live.params().get(live_spec.key) == live_spec.max {
                    live_spec.min
                } else {
                    live_spec.max
                };
                live.set_param(live_spec.key, v).unwrap();
            }
            live.step();
            rows.push(live.last_row().to_vec());
        }
        let mut replayed = Vec::new();
        let n = live
            .rerun(Selection::All, |item| {
                if let attlab::sim::RerunItem::Row(r) = item {
                    replayed.push(r.to_vec());
                }
                Ok::<(), String>(())
            })
            .unwrap();
        assert_eq!(n as usize, rows.len(), "{}", lab.id());
        for (k, (a, b)) in rows.iter().zip(&replayed).enumerate() {
            assert!(same_bits(a, b), "{}: re-run differs at row {k}", lab.id());
        }
        let mut csv = Vec::new();
        assert_eq!(live.export_csv(&mut csv).unwrap() as usize, rows.len());
        let text = String::from_utf8(csv).unwrap();
        assert_eq!(
            text.lines().count(),
            rows.len() + 1,
            "{}: header + one line per row",
            lab.id()
        );
        assert!(
            !text.contains("NaN"),
            "{}: a missing sample is an empty cell",
            lab.id()
        );
    }
}

/// Every series a lab records has a label a student can read: words, not its machine name,
/// and its unit in the legend.
#[test]
fn every_series_has_a_human_label_and_its_unit_in_the_legend() {
    for lab in labs::all() {
        let sim = run(*lab, ParamValues::defaults(lab.params()), 1, 0);
        for s in sim.specs() {
            let machine = s.label.split([' ', '(', ')', ':']).any(|w| {
                w.split_once('.').is_some_and(|(a, b)| {
                    !a.is_empty()
                        && !b.is_empty()
                        && a.chars()
                            .all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_')
                })
            });
            assert!(
                s.has_label() && !machine,
                "{}: `{}` is labelled `{}`",
                lab.id(),
                s.name,
                s.label
            );
            let unit = attlab::model::display_unit(s.unit);
            assert!(
                s.unit.is_empty() || s.legend().ends_with(&format!("[{unit}]")),
                "{}: {} has no unit in `{}`",
                lab.id(),
                s.name,
                s.legend()
            );
        }
    }
}

/// Re-selecting in place (one recorder's memory at a time) gives the same run as a
/// re-selected copy: every series equal, the same step count, a live parameter change kept.
#[test]
fn reselect_in_place_equals_a_reselected_copy() {
    for lab in labs::all() {
        let mut sim = Simulation::new(*lab, ParamValues::defaults(lab.params()), 3);
        for _ in 0..150 {
            sim.step();
        }
        if let Some(p) = lab
            .params()
            .iter()
            .find(|p| !p.needs_reset && !p.outside_run)
        {
            let _ = sim.set_param(p.key, p.max);
        }
        for _ in 0..50 {
            sim.step();
        }
        let copy = sim.reselected(Selection::All).expect("re-selected copy");
        sim.reselect(Selection::All).expect("re-selected in place");
        assert_eq!(sim.steps(), copy.steps(), "{}", lab.id());
        assert_eq!(sim.params(), copy.params(), "{}", lab.id());
        let (a, b) = (sim.recorder(), copy.recorder());
        assert_eq!(a.specs(), b.specs(), "{}", lab.id());
        for j in 0..a.specs().len() {
            let (x, y) = (a.recent_vec(j), b.recent_vec(j));
            assert!(
                x.len() == y.len()
                    && x.iter()
                        .zip(&y)
                        .all(|(u, v)| u == v || (u.is_nan() && v.is_nan())),
                "{}: series {} differs",
                lab.id(),
                a.specs()[j].name
            );
        }
    }
}

/// A re-run advanced a few steps at a time (the page's job) ends where the re-run in one go
/// does, and adopting it keeps a change made to the run while it ran.
#[test]
fn a_rerun_job_in_slices_equals_the_rerun_in_one_go() {
    for lab in labs::all() {
        let mut sim = Simulation::new(*lab, ParamValues::defaults(lab.params()), 2);
        let live = lab
            .params()
            .iter()
            .find(|p| !p.needs_reset && !p.outside_run);
        for k in 0..120 {
            if k == 60
                && let Some(p) = live
            {
                sim.set_param(p.key, p.max).unwrap();
            }
            sim.step();
        }
        let whole = sim.reselected(Selection::All).expect("re-selected copy");
        let mut job = sim
            .rerun_job(Selection::All, sim.options().budget_bytes)
            .unwrap();
        let mut slices = 0;
        while !job.advance(7, |_| Ok::<(), ()>(())).unwrap() {
            slices += 1;
            assert!(job.progress() < 1.0 && slices < 100, "{}", lab.id());
        }
        assert_eq!(slices, 120 / 7, "{}: one slice per 7 steps", lab.id());
        if let Some(p) = live {
            sim.set_param(p.key, p.min).unwrap();
        }
        sim.adopt(job).unwrap();
        assert_eq!(sim.steps(), whole.steps(), "{}", lab.id());
        let (a, b) = (sim.recorder(), whole.recorder());
        assert_eq!(a.specs(), b.specs(), "{}", lab.id());
        for j in 0..a.specs().len() {
            assert!(
                same_bits(&a.recent_vec(j), &b.recent_vec(j)),
                "{}: series {} differs",
                lab.id(),
                a.specs()[j].name
            );
        }
        if let Some(p) = live {
            assert_eq!(
                sim.params().get(p.key),
                p.min,
                "{}: the later change is kept",
                lab.id()
            );
            assert_eq!(sim.applied_params().get(p.key), p.min, "{}", lab.id());
        }
    }
}

/// A diagram point that names an estimator names one the lab runs (it takes that
/// estimator's colour in the page and hides with it); p5's eigenvalue points all do.
#[test]
fn diagram_points_name_estimators_the_lab_runs() {
    let mut named = 0;
    for lab in labs::all() {
        let params = ParamValues::defaults(lab.params());
        let sim = Simulation::new(*lab, params.clone(), 1);
        let ids: Vec<&str> = sim.estimators().iter().map(|e| e.id()).collect();
        for d in lab.page().diagrams(&params) {
            for p in &d.points {
                if let Some(id) = p.source {
                    assert!(
                        ids.contains(&id),
                        "{}: `{}` names `{id}`, not in {ids:?}",
                        lab.id(),
                        p.label
                    );
                    named += 1;
                }
            }
        }
    }
    assert!(
        named >= 6,
        "p5's six eigenvalues name their filters ({named} do)"
    );
}
