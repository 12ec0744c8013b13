// Attitude Lab's service worker: the page works offline after one visit.
//
// Network first, cache as the fallback: a reachable server always gives the newest build
// (and refreshes the cache); without a network the last build seen is served. Only
// same-origin GET requests are handled. The core files are cached at install, so the first
// visit alone is enough.
//
// The wasm and its glue are kept once per build: under their build's URL (`pkg/…?v=<hash>`)
// they never change, so the cache is not written again with 6 MB on every load.
const CACHE = 'attitude-lab-v5';
// This build's query, as index.html asks for the wasm and its glue (`cargo xtask dist`
// writes the hash of both here, as there).
const BUILD = '?v=__ATTLAB_BUILD__';
const CORE = [
  './',
  './index.html',
  './manifest.json',
  './icon-192.png',
  './icon-512.png',
  './pkg/attlab_web.js' + BUILD,
  './pkg/attlab_web_bg.wasm' + BUILD,
  './sweep-worker.js',
  './assets/fonts/AttLabSans.ttf',
  './assets/fonts/AttLabMono.ttf',
  './assets/fonts/DejaVuSans-symbols.ttf',
  './assets/locales/ru.ftl',
];

/// A file of one build: under pkg/, with a `v` query.
const isBuildFile = (url) => url.pathname.includes('/pkg/') && url.searchParams.get('v');

self.addEventListener('install', (event) => {
  // This build's wasm and glue are fetched only when not kept already: the last worker
  // kept them when the page first loaded this build (below), and each is 6 MB.
  const add = (cache, path) => (isBuildFile(new URL(path, self.location.href))
    ? cache.match(path).then((hit) => hit || cache.add(path))
    : cache.add(path));
  event.waitUntil(caches.open(CACHE)
    .then((cache) => Promise.all(CORE.map((path) => add(cache, path))))
    .then(() => self.skipWaiting()));
});

self.addEventListener('activate', (event) => {
  // Older caches go, and so do other builds' wasm and glue in this one: each is 6 MB.
  const stale = (request) => {
    const url = new URL(request.url);
    return isBuildFile(url) && url.search !== BUILD;
  };
  event.waitUntil(
    caches.keys()
      .then((keys) => Promise.all(keys.filter((k) => k !== CACHE).map((k) => caches.delete(k))))
      .then(() => caches.open(CACHE))
      .then((cache) => cache.keys().then((requests) =>
        Promise.all(requests.filter(stale).map((r) => cache.delete(r))),
      ))
      .then(() => self.clients.claim()),
  );
});

// A wasm or glue of one build. Still from the network (the browser's HTTP cache answers: the
// file is immutable, and there V8 keeps the wasm's compiled code), but put into this
// worker's cache only once: each is 6 MB. A newer build's is kept too: the page loads it
// before that build's worker takes over, and the index.html kept beside it asks for it.
// The next activation deletes every other build's. When the network fails or has no such
// file any more (a newer build deployed), the kept copy; never another build's file,
// whose glue would not run with this page's wasm.
async function buildFile(event, request) {
  const kept = caches.open(CACHE)
    .then((cache) => cache.match(request))
    .catch(() => undefined);
  let response;
  try {
    response = await fetch(request);
  } catch (error) {
    const copy = await kept;
    if (copy) {
      return copy;
    }
    throw error;
  }
  const copy = await kept;
  if (!response.ok) {
    return copy || response;
  }
  if (!copy) {
    const saved = response.clone();
    event.waitUntil(
      caches.open(CACHE)
        .then((cache) => cache.put(request, saved))
        .catch((e) => console.warn('Attitude Lab: the offline copy of a file was not kept:', e)),
    );
  }
  return response;
}

self.addEventListener('fetch', (event) => {
  const request = event.request;
  const url = new URL(request.url);
  if (request.method !== 'GET' || url.origin !== self.location.origin) return;
  if (isBuildFile(url)) {
    event.respondWith(buildFile(event, request));
    return;
  }
  event.respondWith(
    fetch(request)
      .then((response) => {
        if (response.ok) {
          const copy = response.clone();
          // One entry per file, whatever its query (the sweep worker's `?v=`); lookups
          // ignore the query too.
          const key = new URL(request.url);
          key.search = '';
          caches.open(CACHE).then((cache) => cache.put(key.href, copy));
        }
        return response;
      })
      .catch(() =>
        caches.match(request, { ignoreSearch: true }).then((hit) => hit || caches.match('./index.html')),
      ),
  );
});
