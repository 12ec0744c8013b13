// Attitude Lab's sweep worker: a wasm instance of its own runs the sweep points the page
// hands it, one message each (web/src/sweep_workers.rs), and answers with the result.
// The page's first message hands over its compiled module (no second compile of the
// 6-MB wasm); without one the worker fetches and compiles the wasm itself.
//
// The page starts this worker under its own build's query (`sweep-worker.js?v=<hash>`), and
// the worker asks for the glue and the wasm under the same query: so it runs the page's
// build even when a new one was deployed since the page loaded, and the browser serves the
// glue from its cache (versioned files under pkg/ are kept; see attlab-serve).
const build = self.location.search;
const glue = import('./pkg/attlab_web.js' + build);
// A worker that cannot load the page's code says so once: the page stops starting workers
// and runs its sweeps in slices (web/src/sweep_workers.rs).
glue.catch((e) => self.postMessage({ fatal: String(e) }));

let ready = null;
// Failures of `ready` are reported with the point that waits on it (below).
const start = (init) => {
  ready = init;
  ready.catch(() => {});
};

/// The files under pkg/ this worker has fetched (its glue, and its wasm if it compiled its
/// own): the page test checks they are the page's build.
const fetched = () => performance.getEntriesByType('resource')
  .map((e) => e.name)
  .filter((name) => name.includes('/pkg/'));

self.onmessage = async (event) => {
  if ('module' in event.data) {
    start(glue.then(({ default: init }) => init({ module_or_path: event.data.module })));
    return;
  }
  const shared = ready !== null;
  if (!shared) {
    start(glue.then(({ default: init }) => init({ module_or_path: './pkg/attlab_web_bg.wasm' + build })));
  }
  const { id, job } = event.data;
  let out;
  try {
    await ready;
    const { sweep_point } = await glue;
    out = sweep_point(job);
  } catch (e) {
    // The page words it (WorkerError::Threw in web/src/sweep_workers.rs).
    out = JSON.stringify({ err: { Threw: { detail: String(e) } } });
  }
  self.postMessage({ id, out, shared, fetched: fetched() });
};
