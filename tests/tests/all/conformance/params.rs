//! The parameter contract: a live change acts without a restart, a reset-only one waits for
//! Reset, and every value at the ends of its range runs without a panic or a silent NaN.

use super::{run, same_bits};
use attlab::labs;
use attlab::model::ParamValues;
use attlab::page::Lab;

/// Runs `lab` 50 steps, changes `key` to `value` live, runs 2000 more steps (some
/// parameters act only after a while, e.g. an adaptation window) and tells whether any
/// row since differs from an unchanged run.
fn live_change_shows(lab: &'static dyn Lab, p: &ParamValues, key: &str, value: f64) -> bool {
    let mut a = run(lab, p.clone(), 3, 50);
    let mut b = run(lab, p.clone(), 3, 50);
    b.set_param(key, value).unwrap();
    assert_eq!(
        b.t_s(),
        a.t_s(),
        "{}: set_param restarted the run",
        lab.id()
    );
    let mut differs = false;
    for _ in 0..2000 {
        a.step();
        b.step();
        differs |= !same_bits(a.last_row(), b.last_row());
    }
    differs
}

#[test]
fn a_live_parameter_change_acts_without_restart() {
    for lab in labs::all() {
        for spec in lab
            .params()
            .iter()
            .filter(|s| !s.needs_reset && (!s.outside_run || s.requires.is_some()))
        {
            let mut p = ParamValues::defaults(lab.params());
            if let Some(dep) = spec.requires {
                // From the lab's preset that turns `dep` on, where one does (it sets what
                // else the parameter needs to act: the 5-DOF body's mass acts once it is
                // tilted), else from `dep` at its largest.
                let dep_spec = lab.params().iter().find(|s| s.key == dep).expect("exists");
                let on = spec.acting_value(dep_spec.max).expect("it requires one");
                p.set(lab.params(), dep, on).unwrap();
                let turns_on = |preset: &&attlab::model::Preset| {
                    preset.values.iter().any(|(k, v)| *k == dep && *v != 0.0)
                };
                if let Some(preset) = lab.presets().iter().find(turns_on) {
                    for (k, v) in preset.values {
                        p.set(lab.params(), k, *v).unwrap();
                    }
                }
            }
            // Parameters that only act through this one (the time of a bump acts through its
            // size) are moved to the start of the run, where the test looks.
            for dependent in lab.params().iter().filter(|d| d.requires == Some(spec.key)) {
                p.set(lab.params(), dependent.key, dependent.min).unwrap();
            }
            // A live change must show at one end of the range at least (an impulse moved
            // from 300 s to 600 s does nothing in the first seconds, moved to 0 s it does).
            let shows = [spec.min, spec.max]
                .iter()
                .filter(|v| **v != p.get(spec.key))
                .any(|v| live_change_shows(*lab, &p, spec.key, *v));
            assert!(shows, "{}: changing {} had no effect", lab.id(), spec.key);
        }
    }
}

/// A parameter that requires another (the page greys its slider out) changes nothing in
/// the run while that one does not let it act, at either end of its range: built with it
/// (it may apply at Reset only) or moved while the run goes on. The sliders of the motions
/// a choice does not select (paper 5's rate in its still case, paper 3's tumble rate in
/// the paper's motion) had stayed live.
#[test]
fn a_parameter_greyed_out_changes_nothing_in_the_run() {
    let mut checked = 0;
    for lab in labs::all() {
        for spec in lab
            .params()
            .iter()
            .filter(|s| s.requires.is_some() && !s.outside_run)
        {
            let mut p = ParamValues::defaults(lab.params());
            let dep = spec.requires.expect("filtered");
            let dep_spec = lab.params().iter().find(|s| s.key == dep).expect("exists");
            let off = [0.0, dep_spec.min, dep_spec.max, 1.0, 2.0, 3.0]
                .into_iter()
                .find(|v| {
                    let mut q = p.clone();
                    q.set(lab.params(), dep, *v).is_ok() && !spec.acts_in(&q)
                });
            let Some(off) = off else { continue };
            p.set(lab.params(), dep, off).unwrap();
            // Every series, 500 steps, built with the value at each end.
            let rows = |v: f64| {
                let mut q = p.clone();
                q.set(lab.params(), spec.key, v).unwrap();
                let mut sim = run(*lab, q, 1, 0);
                (0..500)
                    .map(|_| {
                        sim.step();
                        sim.last_row().to_vec()
                    })
                    .collect::<Vec<_>>()
            };
            let (lo, hi) = (rows(spec.min), rows(spec.max));
            let same = lo.iter().zip(&hi).all(|(a, b)| same_bits(a, b));
            assert!(
                same,
                "{}: {} changed the run while greyed out",
                lab.id(),
                spec.key
            );
            for v in [spec.min, spec.max] {
                assert!(
                    !live_change_shows(*lab, &p, spec.key, v),
                    "{}: {} moved live changed the run while greyed out",
                    lab.id(),
                    spec.key
                );
            }
            checked += 1;
        }
    }
    assert!(
        checked >= 8,
        "only {checked} greyed-out parameters were checked"
    );
}

/// A parameter marked as shaping only what is shown or exported beside the run (a note, an
/// output file's columns) changes nothing in the run at either end of its range — while the
/// parameter it requires, if any, is zero (with it non-zero, the live test above applies).
#[test]
fn a_parameter_outside_the_run_changes_nothing_in_it() {
    let mut checked = 0;
    for lab in labs::all() {
        for spec in lab.params().iter().filter(|s| s.outside_run) {
            let mut p = ParamValues::defaults(lab.params());
            if let Some(dep) = spec.requires {
                p.set(lab.params(), dep, 0.0).unwrap();
            }
            for v in [spec.min, spec.max] {
                assert!(
                    !live_change_shows(*lab, &p, spec.key, v),
                    "{}: {} is marked outside the run but changed it",
                    lab.id(),
                    spec.key
                );
            }
            checked += 1;
        }
    }
    assert!(
        checked >= 3,
        "only {checked} parameters outside the run were checked"
    );
}

/// A parameter marked "applies at Reset" changes nothing in the running simulation — not
/// a value, not the step length — and after Reset the run is the one built with the new value.
#[test]
fn a_reset_only_parameter_waits_for_reset() {
    let mut moved = 0;
    for lab in labs::all() {
        for spec in lab.params().iter().filter(|s| s.needs_reset) {
            let p = ParamValues::defaults(lab.params());
            let value = if p.get(spec.key) == spec.max {
                spec.min
            } else {
                spec.max
            };
            let mut a = run(*lab, p.clone(), 5, 40);
            let mut b = run(*lab, p.clone(), 5, 40);
            b.set_param(spec.key, value).unwrap();
            assert_eq!(
                b.params().get(spec.key),
                value,
                "{}: {}",
                lab.id(),
                spec.key
            );
            assert_eq!(b.pending_reset(), vec![spec.key], "{}", lab.id());
            for k in 0..300 {
                a.step();
                b.step();
                assert!(
                    a.dt_s() == b.dt_s() && same_bits(a.last_row(), b.last_row()),
                    "{}: moving reset-only {} changed the run {k} steps later",
                    lab.id(),
                    spec.key
                );
            }
            b.reset(6);
            assert!(b.pending_reset().is_empty(), "{}", lab.id());
            let mut moved_p = p.clone();
            moved_p.set(lab.params(), spec.key, value).unwrap();
            let mut fresh = run(*lab, moved_p, 6, 0);
            for _ in 0..50 {
                b.step();
                fresh.step();
            }
            assert!(
                same_bits(b.last_row(), fresh.last_row()),
                "{}: after Reset, {} = {value} is not the run built with it",
                lab.id(),
                spec.key
            );
            moved += 1;
        }
    }
    assert!(moved >= 20, "every lab's reset-only parameters ({moved})");
}

#[test]
fn every_parameter_at_its_extremes_runs_without_panic_or_silent_nan() {
    for lab in labs::all() {
        for spec in lab.params() {
            for value in [spec.min, spec.max] {
                let mut p = ParamValues::defaults(lab.params());
                p.set(lab.params(), spec.key, value).unwrap();
                let sim = run(*lab, p, 1, 400);
                for ((e, est), status) in sim
                    .estimators()
                    .iter()
                    .zip(sim.estimates())
                    .zip(sim.statuses())
                {
                    let finite = est.is_finite();
                    assert!(
                        finite || !status.is_ok(),
                        "{}: {} non-finite but not flagged ({}={value})",
                        lab.id(),
                        e.id(),
                        spec.key
                    );
                }
            }
        }
    }
}
