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
// A glue that fails to load is reported with the first point (below), not as an
// unhandled rejection.
glue.catch(() => {});

let ready = null;

self.onmessage = async (event) => {
  if ('module' in event.data) {
    ready = glue.then(({ default: init }) => init({ module_or_path: event.data.module }));
    return;
  }
  const shared = ready !== null;
  ready ??= glue.then(({ default: init }) =>
    init({ module_or_path: './pkg/attlab_web_bg.wasm' + build }),
  );
  const { id, job } = event.data;
  let out;
  try {
    await ready;
    const { sweep_point } = await glue;
    out = sweep_point(job);
  } catch (e) {
    out = JSON.stringify({ err: 'the worker failed: ' + e });
  }
  self.postMessage({ id, out, shared, build });
};
