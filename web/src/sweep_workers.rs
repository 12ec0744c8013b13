//! Sweeps on every core in the page: Web Workers (`sweep-worker.js`), each with its own
//! wasm instance (the page's compiled module, instantiated again), are handed a sweep's
//! points as messages, one per point and up to sixteen queued in each worker ([`PointJob`] as
//! JSON; no SharedArrayBuffer, which static hosts cannot enable), and answer with each
//! point's result. The frame loop takes the answers every frame ([`poll`]), so the page
//! keeps drawing at full rate. Where workers cannot start (the desktop, a browser without
//! module workers, a worker that fails), the caller falls back to per-frame slices.
//!
//! [`PointJob`]: attlab::analysis::sweep::PointJob

#[cfg(target_arch = "wasm32")]
const GLUE: &str = r#"
if (!window.attlabWorkers) {
  const W = window.attlabWorkers = { pool: [], queue: [], done: [], failed: null, pending: 0, broken: false };
  // Points queued in each worker: it goes on to the next without waiting for the page's
  // thread to hand it over, which is busy drawing (a frame can take 100 ms on a slow
  // machine; a point of p4 takes 5-30). Handed out in turns, so the workers share evenly.
  const DEPTH = 16;
  const next = (w) => { const j = W.queue.shift(); if (j) { W.pending++; w.postMessage(j); } };
  const spawn = () => {
    // Under the page's build (index.html sets it), so the worker loads the same glue and wasm.
    const w = new Worker('./sweep-worker.js' + (window.attlabBuild || ''), { type: 'module' });
    w.onmessage = (e) => {
      if ('fatal' in e.data) { W.broken = true; W.failed = e.data.fatal; W.cancel(); return; }
      W.pending--; W.done.push(e.data.id, e.data.out); W.shared = e.data.shared; W.fetched = e.data.fetched; next(w);
    };
    w.onerror = (e) => { e.preventDefault(); W.broken = true; W.failed = e.message || 'a worker could not start'; W.cancel(); };
    // The page's compiled module, so the worker need not compile the wasm again; a
    // browser that cannot send one leaves the worker to fetch it.
    if (window.attlabWasmModule) {
      try { w.postMessage({ module: window.attlabWasmModule }); } catch (e) { console.info('Attitude Lab: a worker compiles its own wasm:', e); }
    }
    W.pool.push(w);
  };
  W.cancel = () => { for (const w of W.pool) { w.terminate(); } W.pool = []; W.queue = []; W.pending = 0; };
  // Workers loaded ahead, while a sweep can be started: loading one takes about half a
  // second on a slow machine, which a sweep would otherwise wait for.
  W.warm = (n) => {
    if (W.broken || typeof Worker === 'undefined') { return 0; }
    try { while (W.pool.length < n) { spawn(); } } catch (e) { W.broken = true; W.cancel(); }
    return W.pool.length;
  };
  W.start = (jobs, cores) => {
    // Idle workers are reused; workers still busy with a stopped sweep are dropped.
    if (W.pending > 0) { W.cancel(); }
    W.queue = []; W.done = []; W.failed = null;
    // Workers that could not load the page's code once will not now either: slices.
    if (W.broken || typeof Worker === 'undefined') { return 0; }
    W.queue = jobs.map((job, id) => ({ id, job }));
    const n = Math.max(1, Math.min(cores, jobs.length));
    try { while (W.pool.length < n) { spawn(); } } catch (e) { W.failed = String(e); W.cancel(); return 0; }
    const used = W.pool.slice(0, n);
    for (let k = 0; k < DEPTH; k++) { for (const w of used) { next(w); } }
    return used.length;
  };
  W.poll = () => { const out = { done: W.done, failed: W.failed }; W.done = []; W.failed = null; return out; };
}
"#;

/// What the workers answered since the last [`poll`].
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Answers {
    /// `(job index, answer JSON)`, in the order they arrived.
    pub done: Vec<(usize, String)>,
    /// Why the workers stopped, if they failed (what is left falls back to slices).
    pub failed: Option<String>,
}

#[cfg(target_arch = "wasm32")]
fn call(method: &str, args: &[wasm_bindgen::JsValue]) -> Result<wasm_bindgen::JsValue, String> {
    crate::live_io::call_glue("attlabWorkers", GLUE, method, args)
}

/// The cores a sweep may use besides the page's own thread (at least one).
pub fn cores() -> usize {
    #[cfg(target_arch = "wasm32")]
    {
        let n = web_sys::window().map_or(2.0, |w| w.navigator().hardware_concurrency());
        ((n as usize).saturating_sub(1)).clamp(1, 8)
    }
    #[cfg(not(target_arch = "wasm32"))]
    1
}

/// Hands `jobs` (JSON) to up to `cores` workers; how many started (0: none, use slices).
pub fn start(jobs: &[String], cores: usize) -> usize {
    #[cfg(target_arch = "wasm32")]
    {
        let list: js_sys::Array = jobs
            .iter()
            .map(|j| wasm_bindgen::JsValue::from_str(j))
            .collect();
        call("start", &[list.into(), (cores as f64).into()])
            .ok()
            .and_then(|n| n.as_f64())
            .map_or(0, |n| n as usize)
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        let _ = (jobs, cores);
        0
    }
}

/// Loads up to `cores` workers ahead of a sweep, so it need not wait for them; nothing
/// where workers cannot start (or failed once).
pub fn warm(cores: usize) {
    #[cfg(target_arch = "wasm32")]
    let _ = call("warm", &[(cores as f64).into()]);
    #[cfg(not(target_arch = "wasm32"))]
    let _ = cores;
}

/// Stops every worker.
pub fn cancel() {
    #[cfg(target_arch = "wasm32")]
    let _ = call("cancel", &[]);
}

/// Takes the answers that arrived.
pub fn poll() -> Answers {
    #[cfg(target_arch = "wasm32")]
    {
        let Ok(o) = call("poll", &[]) else {
            return Answers::default();
        };
        let get = |k: &str| js_sys::Reflect::get(&o, &k.into()).unwrap_or_default();
        let flat: Vec<wasm_bindgen::JsValue> = js_sys::Array::from(&get("done")).to_vec();
        let done = flat
            .chunks_exact(2)
            .filter_map(|p| Some((p[0].as_f64()? as usize, p[1].as_string()?)))
            .collect();
        Answers {
            done,
            failed: get("failed").as_string(),
        }
    }
    #[cfg(not(target_arch = "wasm32"))]
    Answers::default()
}

/// A worker's answer to a [`attlab::analysis::sweep::PointJob`]: the JSON of
/// `{"ok": PointDone}` or `{"err": why}`.
pub fn answer(job: &str) -> String {
    use attlab::analysis::sweep::{PointJob, run_point_job};
    let done = serde_json::from_str::<PointJob>(job)
        .map_err(|e| format!("a bad sweep job: {e}"))
        .and_then(|j| {
            let lab = attlab::labs::find(&j.lab).ok_or_else(|| format!("no lab `{}`", j.lab))?;
            run_point_job(lab, &j)
        });
    let answer = match done {
        Ok(done) => serde_json::json!({ "ok": done }),
        Err(why) => serde_json::json!({ "err": why }),
    };
    answer.to_string()
}

/// Reads an [`answer`].
pub fn read_answer(text: &str) -> Result<attlab::analysis::sweep::PointDone, String> {
    #[derive(serde::Deserialize)]
    #[serde(rename_all = "lowercase")]
    enum Answer {
        Ok(attlab::analysis::sweep::PointDone),
        Err(String),
    }
    match serde_json::from_str::<Answer>(text) {
        Ok(Answer::Ok(done)) => Ok(done),
        Ok(Answer::Err(why)) => Err(why),
        Err(e) => Err(format!("an unreadable answer: {e}")),
    }
}
