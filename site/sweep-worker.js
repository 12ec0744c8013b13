// Attitude Lab's sweep worker: a wasm instance of its own runs the sweep points the page
// hands it, one message each (web/src/sweep_workers.rs), and answers with the result.
import init, { sweep_point } from './pkg/attlab_web.js';

const ready = init();

self.onmessage = async (event) => {
  const { id, job } = event.data;
  let out;
  try {
    await ready;
    out = sweep_point(job);
  } catch (e) {
    out = JSON.stringify({ err: 'the worker failed: ' + e });
  }
  self.postMessage({ id, out });
};
