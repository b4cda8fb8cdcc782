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
//   network.
'use strict';

const BUILD = '__BSV_BUILD__';
const FILES = __BSV_FILES__;
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
      ?? (request.mode === 'navigate' ? await cache.match(new URL('index.html', self.registration.scope)) : undefined);
    return hit ?? fetch(request);
  })());
});
