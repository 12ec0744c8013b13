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
    let mut end_of_first_round: Option<usize> = None;
    let driver = Driver::start();
    let session = Session::new(&driver);
    let first = labs[0].id();
    session
        .open(&format!("{base}#lab={first}&speed=1000"))
        .expect("navigate");
    let status = wait_for_frames(&session);
    let mut soak = Soak {
        start: Instant::now(),
        per_lab,
        every: Duration::from_secs(60).min(per_lab / 2),
        samples: Vec::new(),
        problems: status_problems(&status),
    };
    let order: Vec<_> = (0..rounds as usize).flat_map(|_| labs.iter()).collect();
    for (k, lab) in order.iter().enumerate() {
        let id = lab.id();
        if k == labs.len() {
            end_of_first_round = soak.samples.len().checked_sub(1);
        }
        if k > 0 {
            // A link pasted into the open tab: the app switches lab without a reload.
            let script = format!("location.hash = 'lab={id}&speed=1000'; return true;");
            if let Err(e) = session.execute(&script) {
                soak.problems.push(format!("{id}: switching failed: {e}"));
            }
        }
        soak.one_lab(&session, id);
    }
    drop(session);
    let label = format!("{minutes} min, {rounds} rounds over {} labs", labs.len());
    soak.judge(end_of_first_round, &label);
    assert!(
        soak.problems.is_empty(),
        "soak failed:\n  - {}",
        soak.problems.join("\n  - ")
    );
}

/// A soak under way: its clock, the samples so far and the problems found.
struct Soak {
    start: Instant,
    per_lab: Duration,
    every: Duration,
    samples: Vec<Sample>,
    problems: Vec<String>,
}

impl Soak {
    /// The page's memory and steps now, on lab `lab`.
    fn sample(&self, session: &Session<'_>, lab: &str) -> Result<Sample, String> {
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
            at_s: self.start.elapsed().as_secs_f64(),
            lab: lab.to_string(),
            wasm_bytes: num("wasm")?,
            js_heap_bytes: num("js")?,
            recorder_bytes: num("rec")?,
            sim_steps: num("steps")?,
        })
    }

    /// Lab `id` for its share of the soak: samples every so often, the simulation must
    /// move on between them and the console stay clean.
    fn one_lab(&mut self, session: &Session<'_>, id: &str) {
        // The switch first (the first sample would report a page that never made it): in
        // `cargo xtask test` the soak runs niced, and its page may take a while to get a frame.
        let switch = Instant::now();
        while switch.elapsed() < FRAME_TIMEOUT {
            let lab = session.execute("return (window.attlabStatus || {}).lab ?? null;");
            if lab.is_ok_and(|v| v.as_str() == Some(id)) {
                break;
            }
            sleep(Duration::from_millis(100));
        }
        let lab_start = Instant::now();
        let mut steps_before: Option<f64> = None;
        while lab_start.elapsed() < self.per_lab {
            sleep(
                self.every
                    .min(self.per_lab.saturating_sub(lab_start.elapsed())),
            );
            match self.sample(session, id) {
                Ok(s) => {
                    if steps_before.is_some_and(|b| s.sim_steps <= b) {
                        let stopped =
                            format!("{id}: the simulation stopped at {} steps", s.sim_steps);
                        self.problems.push(stopped);
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
                    self.samples.push(s);
                }
                Err(e) => self.problems.push(format!("{id}: {e}")),
            }
            match session.console() {
                Ok(entries) => self.problems.extend(
                    console_problems(&entries)
                        .into_iter()
                        .map(|p| format!("{id}: {p}")),
                ),
                Err(e) => self
                    .problems
                    .push(format!("{id}: reading the console failed: {e}")),
            }
        }
    }

    /// The second round's growth of wasm memory and JS heap against the recorder's budget.
    fn judge(&mut self, end_of_first_round: Option<usize>, label: &str) {
        let samples = &self.samples;
        let budget = samples.iter().map(|s| s.recorder_bytes).fold(0.0, f64::max);
        let mib = |b: f64| b / 1048576.0;
        let (Some(a), Some(m), Some(b)) = (
            samples.first(),
            end_of_first_round.and_then(|k| samples.get(k)),
            samples.last(),
        ) else {
            return self
                .problems
                .push("too few memory samples for two rounds".into());
        };
        let wasm_growth = b.wasm_bytes - m.wasm_bytes;
        let js_growth = b.js_heap_bytes - m.js_heap_bytes;
        println!(
            "soak: {label}: first round wasm {:.1} → {:.1} MiB (the high-water mark), second round {:+.1} MiB; JS heap second round {:+.1} MiB (recorder budget {:.1} MiB)",
            mib(a.wasm_bytes),
            mib(m.wasm_bytes),
            mib(wasm_growth),
            mib(js_growth),
            mib(budget)
        );
        for (what, growth) in [("wasm memory", wasm_growth), ("JS heap", js_growth)] {
            if growth.is_nan() || growth > budget {
                self.problems.push(format!(
                    "{what} grew {growth} B in the second round, beyond the recorder's budget {budget} B"
                ));
            }
        }
    }
}
