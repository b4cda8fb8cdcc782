// The service worker of one build: it makes the app work with no server and no network once
// it has been opened. scripts/sw-build.mjs writes the copy in dist/sw.js with this build's id
// (a hash of every file) and its file list; this template is not served.
//
// - install: every file of the build goes into one cache, `bsv-<build>`, in one atomic step
//   (`addAll`), fetched past the HTTP cache. The first install takes over at once; a later
//   one waits until the page accepts it ("reload to update"), so a page never mixes files
//   of two builds.
// - activate: the caches of other builds are deleted, so the cache holds exactly the files
//   of one build.
// - fetch: same-origin GETs come from the cache (navigations get index.html), else the
//   network. A first-visit pack (`pkg/pack_<split>.bin`, not cached: its modules are) is
//   made from the cached modules it holds (PACKS), so a second visit fetches a page's code in
//   one request, as a first visit does, instead of one per module; `?only=` asks for some of
//   its modules (those a page does not hold yet).
'use strict';

const BUILD = '__BSV_BUILD__';
const FILES = __BSV_FILES__;
// Each pack's modules, in order (the names of pkg/chunks/<name>.wasm).
const PACKS = __BSV_PACKS__;
const CACHE = `bsv-${BUILD}`;
const PREFIX = 'bsv-';

self.addEventListener('install', (event) => {
  event.waitUntil((async () => {
    const cache = await caches.open(CACHE);
    await cache.addAll(FILES.map((file) => new Request(new URL(file, self.registration.scope), { cache: 'reload' })));
    if (!self.registration.active) await self.skipWaiting();
  })());
});

self.addEventListener('activate', (event) => {
  event.waitUntil((async () => {
    for (const key of await caches.keys()) {
      if (key.startsWith(PREFIX) && key !== CACHE) await caches.delete(key);
    }
    await self.clients.claim();
  })());
});

self.addEventListener('message', (event) => {
  if (event.data === 'bsv-apply-update') self.skipWaiting();
});

self.addEventListener('fetch', (event) => {
  const request = event.request;
  if (request.method !== 'GET' || new URL(request.url).origin !== self.location.origin) return;
  event.respondWith((async () => {
    const cache = await caches.open(CACHE);
    const hit = (await cache.match(request, { ignoreSearch: true }))
      ?? (request.mode === 'navigate' ? await cache.match(new URL('index.html', self.registration.scope)) : undefined)
      ?? (await packOf(cache, new URL(request.url)));
    return hit ?? fetch(request);
  })());
});

/** The pack `url` names, made from the cached modules (its format: scripts/split-link.mjs),
 * or undefined (not a pack, or a module is not cached). With `?only=a,b` (the loader's ask
 * when some of a split point's modules are in already), of those of its modules only. */
async function packOf(cache, url) {
  const all = PACKS[url.pathname.slice(url.pathname.lastIndexOf('/') + 1)];
  if (!all || !url.pathname.includes('/pkg/')) return undefined;
  const only = url.searchParams.get('only');
  const wanted = only === null ? null : new Set(only.split(','));
  const names = wanted ? all.filter((name) => wanted.has(name)) : all;
  const scope = self.registration.scope;
  const found = await Promise.all(names.map((name) => cache.match(new URL(`pkg/chunks/${name}.wasm`, scope))));
  if (found.some((response) => !response)) return undefined;
  const modules = await Promise.all(found.map((response) => response.arrayBuffer()));
  const text = new TextEncoder();
  const parts = [text.encode('BSVP'), u32(names.length)];
  names.forEach((name, i) => {
    const id = text.encode(name);
    parts.push(u32(id.length), id, u32(modules[i].byteLength), new Uint8Array(modules[i]));
  });
  return new Response(new Blob(parts), { headers: { 'Content-Type': 'application/octet-stream' } });
}

function u32(n) {
  const bytes = new Uint8Array(4);
  new DataView(bytes.buffer).setUint32(0, n, true);
  return bytes;
}
