//! The soak's body (the `soak` test in main.rs runs it).

use super::*;

/// One memory sample of the soak.
struct Sample {
    at_s: f64,
    lab: String,
    wasm_bytes: f64,
    js_heap_bytes: f64,
    recorder_bytes: f64,
    sim_steps: f64,
}

/// The soak: one page load, every lab in turn switched by its link in the open tab at the
/// highest speed, twice round, the JS heap and the wasm memory sampled (every minute, or more
/// often in a short soak). The first round sets the page's high-water mark (each lab's own
/// working set; wasm memory never shrinks), which is reported; the second round must not
/// grow beyond the recorder's budget — a leak would. Fails on that growth, any console
/// error, an app error, or a page that stopped simulating.
pub(crate) fn run() {
    let url = std::env::var("ATTLAB_PAGE_URL").expect("set ATTLAB_PAGE_URL to the served dist/");
    let minutes: f64 = std::env::var("ATTLAB_SOAK_MINUTES")
        .ok()
        .and_then(|m| m.parse().ok())
        .filter(|m: &f64| *m > 0.0)
        .unwrap_or(2.0);
    let base = url.split('#').next().unwrap_or(&url).to_string();
    let labs = attlab::labs::all();
    let total = Duration::from_secs_f64(minutes * 60.0);
    let rounds = 2;
    let per_lab = total / (rounds * labs.len() as u32);
    let every = Duration::from_secs(60).min(per_lab / 2);
    let mut end_of_first_round: Option<usize> = None;
    let driver = Driver::start();
    let session = Session::new(&driver);
    let first = labs[0].id();
    session
        .open(&format!("{base}#lab={first}&speed=1000"))
        .expect("navigate");
    let status = wait_for_frames(&session);
    let mut problems = status_problems(&status);
    let start = Instant::now();
    let mut samples: Vec<Sample> = Vec::new();
    let sample = |session: &Session<'_>, lab: &str| -> Result<Sample, String> {
        let v = session.execute(
            "const s = window.attlabStatus || {}; return JSON.stringify({ lab: s.lab, wasm: s.wasmBytes, rec: s.recorderBytes, steps: s.simSteps, errors: s.errors, js: performance.memory ? performance.memory.usedJSHeapSize : null });",
        )?;
        let v: Value =
            serde_json::from_str(v.as_str().unwrap_or("{}")).map_err(|e| e.to_string())?;
        if let Some(errors) = v["errors"].as_array().filter(|e| !e.is_empty()) {
            return Err(format!("app errors: {errors:?}"));
        }
        if v["lab"].as_str() != Some(lab) {
            return Err(format!("expected lab {lab}, the page shows {:?}", v["lab"]));
        }
        let num = |k: &str| v[k].as_f64().ok_or(format!("no {k} in the status: {v}"));
        Ok(Sample {
            at_s: start.elapsed().as_secs_f64(),
            lab: lab.to_string(),
            wasm_bytes: num("wasm")?,
            js_heap_bytes: num("js")?,
            recorder_bytes: num("rec")?,
            sim_steps: num("steps")?,
        })
    };
    let order: Vec<_> = (0..rounds as usize).flat_map(|_| labs.iter()).collect();
    for (k, lab) in order.iter().enumerate() {
        let id = lab.id();
        if k == labs.len() {
            end_of_first_round = samples.len().checked_sub(1);
        }
        if k > 0 {
            // A link pasted into the open tab: the app switches lab without a reload.
            let script = format!("location.hash = 'lab={id}&speed=1000'; return true;");
            if let Err(e) = session.execute(&script) {
                problems.push(format!("{id}: switching failed: {e}"));
            }
        }
        let lab_start = Instant::now();
        let mut steps_before: Option<f64> = None;
        while lab_start.elapsed() < per_lab {
            sleep(every.min(per_lab.saturating_sub(lab_start.elapsed())));
            match sample(&session, id) {
                Ok(s) => {
                    if steps_before.is_some_and(|b| s.sim_steps <= b) {
                        problems.push(format!(
                            "{id}: the simulation stopped at {} steps",
                            s.sim_steps
                        ));
                    }
                    steps_before = Some(s.sim_steps);
                    println!(
                        "soak: {:6.0} s {:14} wasm {:7.1} MiB · JS heap {:6.1} MiB · recorder {:5.1} MiB · {:9.0} steps",
                        s.at_s,
                        s.lab,
                        s.wasm_bytes / 1048576.0,
                        s.js_heap_bytes / 1048576.0,
                        s.recorder_bytes / 1048576.0,
                        s.sim_steps
                    );
                    samples.push(s);
                }
                Err(e) => problems.push(format!("{id}: {e}")),
            }
            match session.console() {
                Ok(entries) => problems.extend(
                    console_problems(&entries)
                        .into_iter()
                        .map(|p| format!("{id}: {p}")),
                ),
                Err(e) => problems.push(format!("{id}: reading the console failed: {e}")),
            }
        }
    }
    drop(session);
    let budget = samples.iter().map(|s| s.recorder_bytes).fold(0.0, f64::max);
    let mib = |b: f64| b / 1048576.0;
    match (
        samples.first(),
        end_of_first_round.and_then(|k| samples.get(k)),
        samples.last(),
    ) {
        (Some(a), Some(m), Some(b)) => {
            let wasm_growth = b.wasm_bytes - m.wasm_bytes;
            let js_growth = b.js_heap_bytes - m.js_heap_bytes;
            println!(
                "soak: {minutes} min, {rounds} rounds over {} labs: first round wasm {:.1} → {:.1} MiB (the high-water mark), second round {:+.1} MiB; JS heap second round {:+.1} MiB (recorder budget {:.1} MiB)",
                labs.len(),
                mib(a.wasm_bytes),
                mib(m.wasm_bytes),
                mib(wasm_growth),
                mib(js_growth),
                mib(budget)
            );
            if wasm_growth.is_nan() || wasm_growth > budget {
                problems.push(format!(
                    "wasm memory grew {wasm_growth} B in the second round, beyond the recorder's budget {budget} B"
                ));
            }
            if js_growth.is_nan() || js_growth > budget {
                problems.push(format!(
                    "JS heap grew {js_growth} B in the second round, beyond the recorder's budget {budget} B"
                ));
            }
        }
        _ => problems.push("too few memory samples for two rounds".into()),
    }
    assert!(
        problems.is_empty(),
        "soak failed:\n  - {}",
        problems.join("\n  - ")
    );
}
