//! `attlab bench` and the timing table of `attlab reproduce`: nanoseconds per step of the
//! loop against its estimators alone (measured here, never in tests).

use super::run::all_series;
use attlab::analysis::sweep::Sweep;
use attlab::labs;
use attlab::model::ParamValues;
use attlab::page::Lab;
use attlab::sim::{SimOptions, Simulation};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use std::io::Write;
use std::time::Instant;

/// Times the lab's timing items and prints each against the first (the cost comparison).
pub(super) fn print_timings(lab: &'static dyn Lab, reps: usize) {
    let mut items = lab.timing_items();
    if items.is_empty() {
        return;
    }
    println!("cost (native, release build, {reps} repetitions each; measured, not a test):");
    let mut base = None;
    for item in &mut items {
        for _ in 0..reps / 10 {
            (item.run)();
        }
        let t0 = Instant::now();
        for _ in 0..reps {
            (item.run)();
        }
        let ns = t0.elapsed().as_nanos() as f64 / reps as f64;
        let b = *base.get_or_insert(ns);
        let flops = item.flops.map_or(String::new(), |f| {
            format!("   {f} FLOP counted, {:.1} FLOP/ns", f as f64 / ns)
        });
        println!(
            "  {:<40} {:>8.1} ns   ×{:.2} of the first{flops}",
            item.name,
            ns,
            ns / b
        );
    }
    println!();
}

/// Nanoseconds per call of `f`: the best of five batches of `n / 5` calls after a
/// warm-up (the least disturbed measurement on a shared machine).
fn time_ns(n: usize, mut f: impl FnMut()) -> f64 {
    for _ in 0..n / 10 {
        f();
    }
    let batch = (n / 5).max(1);
    (0..5)
        .map(|_| {
            let t0 = Instant::now();
            for _ in 0..batch {
                f();
            }
            t0.elapsed().as_nanos() as f64 / batch as f64
        })
        .fold(f64::INFINITY, f64::min)
}

pub(super) fn bench(steps: usize, only: Option<&'static dyn Lab>) {
    println!(
        "{:<14} {:<38} {:>10} {:>10}",
        "lab", "item", "ns/step", "note"
    );
    let selected: Vec<&'static dyn Lab> = only.map_or_else(|| labs::all().to_vec(), |l| vec![l]);
    for lab in &selected {
        bench_lab(*lab, steps);
        print_timings(*lab, steps * 10);
    }
    bench_sweeps(&selected);
    let _ = std::io::stdout().flush();
}

/// Each lab's sweeps to their end in one thread and on every core (the same numbers: see
/// `tests/tests/all/sweeps.rs`), and the speed-up.
fn bench_sweeps(selected: &[&'static dyn Lab]) {
    let cores = rayon::current_num_threads();
    println!("sweeps (native, release build; wall time, measured, not a test):");
    for lab in selected {
        for spec in lab.sweeps() {
            let run = |threads: usize| {
                let sweep = Sweep::new(*lab, *spec, ParamValues::defaults(lab.params()), 1);
                let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build();
                let t0 = Instant::now();
                let points = match pool {
                    Ok(pool) => pool.install(|| sweep.run_to_end()).points.len(),
                    Err(_) => sweep.run_in_order().points.len(),
                };
                (t0.elapsed().as_secs_f64(), points)
            };
            let (one, points) = run(1);
            let (all, _) = run(cores);
            println!(
                "  {:<6} {:<66} {points:>4} points  1 thread {one:>6.2} s  {cores} threads {all:>6.2} s  ×{:.2}",
                lab.id(),
                spec.title,
                one / all
            );
        }
    }
}

/// Nanoseconds per step of `lab`'s simulation recording `options`, best of five chunks
/// (NaN if the selection does not exist).
fn step_ns(lab: &'static dyn Lab, params: &ParamValues, steps: usize, options: SimOptions) -> f64 {
    match Simulation::with_options(lab, params.clone(), 1, options) {
        Ok(mut sim) => time_ns(steps, || sim.step()),
        Err(_) => f64::NAN,
    }
}

/// Each estimator's nanoseconds per step on the same measurements, best of five chunks.
fn estimator_ns(lab: &'static dyn Lab, params: &ParamValues, steps: usize) -> Vec<(String, f64)> {
    let mut rng = ChaCha8Rng::seed_from_u64(1);
    let mut run = lab.build(params, &mut rng);
    let dt = lab.dt_s(params);
    let trace = run.measurement_trace(dt, steps, &mut rng);
    let mut lines = Vec::new();
    for est in &mut run.estimators {
        let ns = trace
            .chunks(trace.len().div_ceil(5).max(1))
            .map(|chunk| {
                let t0 = Instant::now();
                for m in chunk {
                    est.step(m, dt);
                }
                t0.elapsed().as_nanos() as f64 / chunk.len() as f64
            })
            .fold(f64::INFINITY, f64::min);
        std::hint::black_box(est.estimate());
        lines.push((format!("estimator {}", est.id()), ns));
    }
    lines
}

/// One lab's table: the page's step against the aim of 2 × its estimators + 500 ns, the
/// step recording every series and none, each estimator, and the recorder's memory.
fn bench_lab(lab: &'static dyn Lab, steps: usize) {
    let params = ParamValues::defaults(lab.params());
    // The page's run keeps its time-travel snapshots: their cost is in its step.
    let mut sim = Simulation::new(lab, params.clone(), 1);
    sim.keep_history(attlab::sim::HISTORY_BUDGET_BYTES);
    let page_ns = time_ns(steps, || sim.step());
    let mut plain = Simulation::new(lab, params.clone(), 1);
    let plain_ns = time_ns(steps, || plain.step());
    let all_ns = step_ns(lab, &params, steps, all_series());
    let bare_ns = step_ns(lab, &params, steps, SimOptions::named(&[]));
    let lines = estimator_ns(lab, &params, steps);
    let sum: f64 = lines.iter().map(|(_, ns)| ns).sum();
    let aim = 2.0 * sum + 500.0;
    let verdict = if page_ns <= aim {
        "within aim"
    } else {
        "OVER AIM"
    };
    let series = sim.specs().len();
    let row = |name: &str, ns: f64, note: &str| {
        println!("{:<14} {:<38} {:>10.0} {:>10}", "", name, ns, note);
    };
    println!(
        "{:<14} {:<38} {:>10.0} {:>10}",
        lab.id(),
        format!("simulation step (page: {series} series)"),
        page_ns,
        verdict
    );
    row(
        "simulation step (page, no time travel)",
        plain_ns,
        &format!("×{:.2}", page_ns / plain_ns.max(1.0)),
    );
    row("simulation step (every series)", all_ns, "");
    row("simulation step (time only)", bare_ns, "");
    for (name, ns) in &lines {
        row(name, *ns, "");
    }
    row(
        "sum of estimator steps",
        sum,
        &format!("×{:.2}", page_ns / sum.max(1.0)),
    );
    row(
        "aim: 2 × sum + 500 ns",
        aim,
        &format!("{:.2} of aim", page_ns / aim),
    );
    println!(
        "{:<14} {:<38} {:>10.1} {:>10}",
        "",
        "recorder memory (MiB, fixed)",
        sim.recorder().memory_bytes() as f64 / (1 << 20) as f64,
        format!("{} rows full rate", sim.recorder().window())
    );
    bench_travel(&sim);
}

/// Time travel on the page's run after the steps above: a seek to mid-run (restore a
/// snapshot, step on to the moment), a branch's start there, and the snapshots' memory.
fn bench_travel(sim: &Simulation) {
    let t = 0.5 * sim.t_s() + 0.37 * sim.dt_s();
    let seek_ns = time_ns(20, || {
        if let Ok(mut seek) = sim.seek(t) {
            while !seek.advance(sim, 256) {}
        }
    });
    let options = SimOptions {
        selection: attlab::sim::Selection::Standard,
        budget_bytes: 4 << 20,
    };
    let branch_ns = time_ns(20, || {
        let _ = sim.branch(t, &[], options.clone());
    });
    let used = sim.history_use();
    let row = |name: &str, value: String, note: String| {
        println!("{:<14} {:<38} {:>10} {:>10}", "", name, value, note);
    };
    let ms = |ns: f64| format!("{:.2}", ns / 1e6);
    let interval = format!("≤ {} steps", used.interval_steps);
    row("seek to mid-run (ms)", ms(seek_ns), interval.clone());
    row("branch start at mid-run (ms)", ms(branch_ns), interval);
    row(
        "snapshots (KiB each, MiB in all)",
        format!(
            "{:.1}",
            used.bytes as f64 / used.snapshots.max(1) as f64 / 1024.0
        ),
        format!(
            "{} = {:.2} MiB",
            used.snapshots,
            used.bytes as f64 / (1 << 20) as f64
        ),
    );
}
