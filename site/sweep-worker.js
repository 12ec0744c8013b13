// Attitude Lab's sweep worker: a wasm instance of its own runs the sweep points the page
// hands it, one message each (web/src/sweep_workers.rs), and answers with the result.
// The page's first message hands over its compiled module (no second compile of the
// 6-MB wasm); without one the worker fetches and compiles the wasm itself.
import init, { sweep_point } from './pkg/attlab_web.js';

let ready = null;

self.onmessage = async (event) => {
  if ('module' in event.data) {
    ready = init({ module_or_path: event.data.module });
    return;
  }
  const shared = ready !== null;
  ready ??= init();
  const { id, job } = event.data;
  let out;
  try {
    await ready;
    out = sweep_point(job);
  } catch (e) {
    out = JSON.stringify({ err: 'the worker failed: ' + e });
  }
  self.postMessage({ id, out, shared });
};
