//! Sweeps in Web Workers: paper 4's γ sweep and paper 2's Q tuning run in the page twice,
//! with its workers and with `Worker` taken away (the per-frame slices the page falls back
//! to). The points the slices finish must equal the workers' to the last bit, and the
//! throughput of both is printed (finished runs per second of wall time) — the speed-up the
//! docs/measured.md reports.

use super::*;

const RUN: &str = "Run sweep";

/// A sweep's state in the page's status.
struct Seen {
    frames: f64,
    progress: f64,
    workers: u64,
    wall_s: Option<f64>,
    values: Vec<Option<f64>>,
}

fn seen(session: &Session<'_>) -> Option<Seen> {
    let status = session
        .execute("return window.attlabStatus || null;")
        .ok()?;
    let s = &status["sweep"];
    Some(Seen {
        frames: status["frames"].as_f64()?,
        progress: s["progress"].as_f64()?,
        workers: s["workers"].as_u64().unwrap_or(0),
        wall_s: s["wallS"].as_f64(),
        values: s["values"].as_array()?.iter().map(Value::as_f64).collect(),
    })
}

/// Runs the lab's first sweep for at most `window_s`; with `workers` false the page's
/// `Worker` is taken away first. Returns what was seen at the end, the seconds waited and
/// the page's frames per second meanwhile.
fn run_sweep(
    session: &Session<'_>,
    base: &str,
    lab: &str,
    workers: bool,
    window_s: f64,
) -> Result<(Seen, f64, f64), String> {
    session.open(&format!("{base}#lab={lab}&lang=en"))?;
    let status = wait_for_frames(session);
    if !status_problems(&status).is_empty() {
        return Err(format!("{lab}: the page did not start"));
    }
    if !workers {
        session.execute(
            "Object.defineProperty(window, 'Worker', { value: undefined }); return true;",
        )?;
    }
    if !eventually(|| click_mirrored(session, RUN)) {
        return Err(format!("{lab}: no `{RUN}` button in the mirror"));
    }
    let start = Instant::now();
    let frames0 = status["frames"].as_f64().unwrap_or(0.0);
    let mut last_progress = 0.0;
    loop {
        sleep(Duration::from_millis(500));
        let s = seen(session).ok_or_else(|| {
            let status = session.execute("return window.attlabStatus || null;");
            format!(
                "{lab}: the status shows no sweep: {:?}",
                status.map(|s| s["sweep"].clone())
            )
        })?;
        // The bar counts finished runs: it never goes back and never passes 1.
        if !(last_progress..=1.0).contains(&s.progress) {
            return Err(format!(
                "{lab}: the sweep's progress went from {last_progress} to {}",
                s.progress
            ));
        }
        last_progress = s.progress;
        let waited = start.elapsed().as_secs_f64();
        if s.wall_s.is_some() || waited > window_s {
            let fps = (s.frames - frames0) / waited;
            return Ok((s, waited, fps));
        }
    }
}

/// Runs per second: all of them over the sweep's wall time, or the share done over the
/// window.
fn throughput(s: &Seen, waited_s: f64, runs: f64) -> f64 {
    match s.wall_s {
        Some(wall) => runs / wall,
        None => s.progress * runs / waited_s,
    }
}

/// Runs of lab `lab`'s first sweep.
fn runs_of(lab: &str) -> f64 {
    let spec = attlab_tests::lab(lab).sweeps()[0];
    let cells = spec.values.len() * spec.grid.map_or(1, |g| g.values.len());
    (cells * spec.seeds.max(1) as usize) as f64
}

fn compare(lab: &str, window_s: f64, session: &Session<'_>, base: &str) -> Vec<String> {
    let runs = runs_of(lab);
    let (w, w_waited, w_fps) = match run_sweep(session, base, lab, true, window_s) {
        Ok(r) => r,
        Err(e) => return vec![format!("workers: {e}")],
    };
    // The workers were handed the page's compiled module, not left to compile their own.
    let shared = session
        .execute("return window.attlabWorkers ? window.attlabWorkers.shared === true : null;")
        .ok();
    // ...and ran the page's own build: every file under pkg/ they fetched (their glue) was
    // asked for under the page's build query.
    let builds = session
        .execute(
            "return [window.attlabBuild, window.attlabWorkers && window.attlabWorkers.fetched];",
        )
        .ok();
    let (s, s_waited, s_fps) = match run_sweep(session, base, lab, false, window_s) {
        Ok(r) => r,
        Err(e) => return vec![format!("workers: {e}")],
    };
    let mut problems = Vec::new();
    if w.workers == 0 {
        problems.push(format!("workers: {lab}: the sweep did not run in workers"));
    }
    if shared != Some(Value::Bool(true)) {
        problems.push(format!(
            "workers: {lab}: the workers did not use the page's compiled module ({shared:?})"
        ));
    }
    if let Some(problem) = build_problem(builds.as_ref()) {
        problems.push(format!("workers: {lab}: {problem}"));
    }
    if s.workers != 0 {
        problems.push(format!(
            "workers: {lab}: without Worker the sweep still claims workers"
        ));
    }
    let common = w.values.len().min(s.values.len());
    let same = (0..common).all(|k| match (w.values[k], s.values[k]) {
        (Some(a), Some(b)) => a.to_bits() == b.to_bits(),
        (a, b) => a.is_none() && b.is_none(),
    });
    if common == 0 || !same {
        problems.push(format!(
            "workers: {lab}: workers' points {:?} differ from the slices' {:?}",
            &w.values[..common.min(w.values.len())],
            &s.values[..common]
        ));
    }
    let (tw, ts) = (
        throughput(&w, w_waited, runs),
        throughput(&s, s_waited, runs),
    );
    println!(
        "page test: workers: {lab}: {} worker(s) {tw:.2} runs/s at {w_fps:.1} frames/s, slices \
         {ts:.3} runs/s at {s_fps:.1} frames/s: {:.1}× ({common} points equal)",
        w.workers,
        tw / ts.max(1e-9)
    );
    problems
}

#[test]
#[ignore = "needs the built site; `cargo xtask test` runs it with ATTLAB_PAGE_URL"]
fn sweeps_run_in_web_workers_with_the_numbers_of_the_slices() {
    page_test("workers", |session, base| {
        let mut problems = timed("sweep workers p4", || compare("p4", 40.0, session, base));
        problems.extend(timed("sweep workers p2", || {
            compare("p2", 30.0, session, base)
        }));
        problems
    });
}

/// What is wrong with `[the page's build query, the URLs under pkg/ a worker fetched]`, if
/// anything: the query must be `?v=` and sixteen hex digits (the hash `cargo xtask dist`
/// writes), and every URL (at least the glue) must carry it.
fn build_problem(builds: Option<&Value>) -> Option<String> {
    let pair = builds.and_then(Value::as_array);
    let page = pair.and_then(|p| p.first()).and_then(Value::as_str);
    let fetched = pair.and_then(|p| p.get(1)).and_then(Value::as_array);
    let versioned = |q: &str| {
        q.strip_prefix("?v=")
            .is_some_and(|h| h.len() == 16 && h.bytes().all(|b| b.is_ascii_hexdigit()))
    };
    let ok = match (page, fetched) {
        (Some(page), Some(urls)) => {
            versioned(page)
                && urls
                    .iter()
                    .any(|u| u.as_str().is_some_and(|u| u.contains("/pkg/attlab_web.js")))
                && urls
                    .iter()
                    .all(|u| u.as_str().is_some_and(|u| u.ends_with(page)))
        }
        _ => false,
    };
    (!ok).then(|| format!("the workers did not load the page's build (page, fetched: {builds:?})"))
}

#[test]
fn a_worker_on_another_build_or_an_unversioned_one_is_a_problem() {
    let hash = "?v=0123456789abcdef";
    let glue = |q: &str| format!("http://h/pkg/attlab_web.js{q}");
    let case = |page: &str, urls: &[String]| build_problem(Some(&serde_json::json!([page, urls])));
    assert_eq!(case(hash, &[glue(hash)]), None);
    assert_eq!(
        case(
            hash,
            &[glue(hash), format!("http://h/pkg/attlab_web_bg.wasm{hash}")]
        ),
        None
    );
    assert!(case(hash, &[glue("")]).is_some());
    assert!(case(hash, &[glue("?v=0123456789abcdee")]).is_some());
    assert!(
        case(
            hash,
            &[glue(hash), "http://h/pkg/attlab_web_bg.wasm".into()]
        )
        .is_some()
    );
    assert!(case(hash, &[]).is_some());
    assert!(case("?v=__ATTLAB_BUILD__", &[glue("?v=__ATTLAB_BUILD__")]).is_some());
    assert!(build_problem(Some(&serde_json::json!([hash, null]))).is_some());
    assert!(build_problem(None).is_some());
}
