// Attitude Lab's service worker: the page works offline after one visit.
//
// Network first, cache as the fallback: a reachable server always gives the newest build
// (and refreshes the cache); without a network the last build seen is served. Only
// same-origin GET requests are handled. The core files are cached at install, so the first
// visit alone is enough.
const CACHE = 'attitude-lab-v4';
const CORE = [
  './',
  './index.html',
  './manifest.json',
  './icon-192.png',
  './icon-512.png',
  './pkg/attlab_web.js',
  './pkg/attlab_web_bg.wasm',
  './sweep-worker.js',
  './assets/fonts/AttLabSans.ttf',
  './assets/fonts/AttLabMono.ttf',
  './assets/fonts/DejaVuSans-symbols.ttf',
  './assets/locales/ru.ftl',
];

self.addEventListener('install', (event) => {
  event.waitUntil(caches.open(CACHE).then((cache) => cache.addAll(CORE)).then(() => self.skipWaiting()));
});

self.addEventListener('activate', (event) => {
  event.waitUntil(
    caches.keys()
      .then((keys) => Promise.all(keys.filter((k) => k !== CACHE).map((k) => caches.delete(k))))
      .then(() => self.clients.claim()),
  );
});

self.addEventListener('fetch', (event) => {
  const request = event.request;
  if (request.method !== 'GET' || new URL(request.url).origin !== self.location.origin) return;
  event.respondWith(
    fetch(request)
      .then((response) => {
        if (response.ok) {
          const copy = response.clone();
          // One entry per file, whatever its build query (`?v=`): a new build replaces the
          // last one's bytes instead of adding 6 MB more (lookups ignore the query too).
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
