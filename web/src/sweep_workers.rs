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
      if ('fatal' in e.data) { W.broken = true; W.failed = String(e.data.fatal); W.cancel(); return; }
      W.pending--; W.done.push(e.data.id, e.data.out); W.shared = e.data.shared; W.fetched = e.data.fetched; next(w);
    };
    w.onerror = (e) => { e.preventDefault(); W.broken = true; W.failed = e.message || ''; W.cancel(); };
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
    pub failed: Option<WorkerError>,
}

#[cfg(target_arch = "wasm32")]
fn call(
    method: &str,
    args: &[wasm_bindgen::JsValue],
) -> Result<wasm_bindgen::JsValue, crate::live_io::GlueError> {
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
            failed: get("failed")
                .as_string()
                .map(|detail| WorkerError::CouldNotStart { detail }),
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
        .map_err(|e| WorkerError::BadJob {
            detail: e.to_string(),
        })
        .and_then(|j| {
            let lab = attlab::labs::find(&j.lab)
                .ok_or_else(|| WorkerError::NoLab { lab: j.lab.clone() })?;
            run_point_job(lab, &j).map_err(WorkerError::Point)
        });
    let answer = match done {
        Ok(done) => serde_json::json!({ "ok": done }),
        Err(why) => serde_json::json!({ "err": why }),
    };
    answer.to_string()
}

/// Reads an [`answer`].
pub fn read_answer(text: &str) -> Result<attlab::analysis::sweep::PointDone, WorkerError> {
    #[derive(serde::Deserialize)]
    #[serde(rename_all = "lowercase")]
    enum Answer {
        Ok(attlab::analysis::sweep::PointDone),
        Err(WorkerError),
    }
    match serde_json::from_str::<Answer>(text) {
        Ok(Answer::Ok(done)) => Ok(done),
        Ok(Answer::Err(why)) => Err(why),
        Err(e) => Err(WorkerError::Unreadable {
            detail: e.to_string(),
        }),
    }
}

/// Why a sweep's workers could not give a point (the page then runs it in slices).
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub enum WorkerError {
    /// The job could not be read (serde's words).
    BadJob {
        /// What the reader said.
        detail: String,
    },
    /// The job names a lab the worker's build does not have.
    NoLab {
        /// The lab's id.
        lab: String,
    },
    /// The point could not be run.
    Point(attlab::analysis::sweep::SweepError),
    /// The answer could not be read (serde's words).
    Unreadable {
        /// What the reader said.
        detail: String,
    },
    /// The worker's code threw (the browser's words; `sweep-worker.js` writes it).
    Threw {
        /// What it threw.
        detail: String,
    },
    /// A worker could not start or load the page's code (the browser's words).
    CouldNotStart {
        /// What the browser said ("" when it said nothing).
        detail: String,
    },
}

impl attlab::i18n::errors::Worded for WorkerError {
    fn words(&self, lang: attlab::i18n::Lang, lab: &dyn attlab::page::Lab) -> String {
        use attlab::i18n::t_with;
        let detail =
            |id: &str, detail: &str| t_with(lang, id, &[("detail", detail.to_string().into())]);
        match self {
            WorkerError::BadJob { detail: d } => detail("error-worker-bad-job", d),
            WorkerError::NoLab { lab: id } => detail("error-worker-no-lab", id),
            WorkerError::Point(e) => e.words(lang, lab),
            WorkerError::Unreadable { detail: d } => detail("error-worker-unreadable", d),
            WorkerError::Threw { detail: d } => detail("error-worker-threw", d),
            WorkerError::CouldNotStart { detail: d } => detail("error-worker-could-not-start", d),
        }
    }
}

impl WorkerError {
    /// One of each kind (the match fails to compile when a kind is added and not listed).
    pub fn examples() -> Vec<WorkerError> {
        let all = vec![
            WorkerError::BadJob {
                detail: "expected value at line 1 column 1".into(),
            },
            WorkerError::NoLab { lab: "p9".into() },
            WorkerError::Point(attlab::analysis::sweep::SweepError::NoPoint {
                sweep: 0,
                point: 40,
            }),
            WorkerError::Unreadable {
                detail: "EOF while parsing".into(),
            },
            WorkerError::Threw {
                detail: "RuntimeError: unreachable".into(),
            },
            WorkerError::CouldNotStart {
                detail: String::new(),
            },
        ];
        for e in &all {
            match e {
                WorkerError::BadJob { .. }
                | WorkerError::NoLab { .. }
                | WorkerError::Point(_)
                | WorkerError::Unreadable { .. }
                | WorkerError::Threw { .. }
                | WorkerError::CouldNotStart { .. } => {}
            }
        }
        all
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use attlab::i18n::Lang;
    use attlab::i18n::errors::Worded;

    #[test]
    fn every_worker_error_is_said_in_both_languages_and_crosses_as_json() {
        let lab = attlab::labs::find("p4").expect("registered");
        for e in WorkerError::examples() {
            let (en, ru) = (e.words(Lang::En, lab), e.words(Lang::Ru, lab));
            assert!(!en.contains("{$") && !en.contains("error-"), "{e:?}: {en}");
            assert!(!ru.contains("{$") && ru != en, "{e:?}: {ru}");
            let answer = serde_json::json!({ "err": e }).to_string();
            assert_eq!(read_answer(&answer), Err(e.clone()));
        }
        // What sweep-worker.js writes when the worker's code throws.
        let thrown = r#"{"err":{"Threw":{"detail":"RuntimeError: unreachable"}}}"#;
        assert!(matches!(
            read_answer(thrown),
            Err(WorkerError::Threw { .. })
        ));
        assert!(matches!(
            read_answer("{"),
            Err(WorkerError::Unreadable { .. })
        ));
        let bad = answer("not a job");
        assert!(matches!(read_answer(&bad), Err(WorkerError::BadJob { .. })));
    }
}
