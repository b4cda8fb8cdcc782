// Loads the wasm and starts the app. Nothing is fetched from the network beyond this site:
// the module, the main wasm, the visitor's language and page (packs of wasm chunks, fetched
// by pkg/__wasm_split.js) all come from dist/.
// If loading fails, a bilingual message replaces the "Loading…" line (see index.html).
try {
  const { default: init, startApp } = await import('../pkg/bsv_playground.js');
  // www/boot.js has asked for the main wasm already (it watches its progress).
  await init(window.bsvMainWasm ? { module_or_path: window.bsvMainWasm } : undefined);
  // Marks that tests/bench/firstframe.bench.mjs reads (wasm compiled and instantiated; the
  // shell and the route mounted).
  performance.mark('bsv-wasm-ready');
  // The app takes the route's frame over only once www/boot.js has painted it (at once when
  // there is none): on a fast load the wasm can be ready first, and a frame replaced before its
  // paint would leave the page's own head, painted with the page, as the largest paint.
  await window.bsvFramePainted;
  await startApp();
  performance.mark('bsv-app-ready');
  whenQuiet(registerServiceWorker);
} catch (error) {
  console.error('BSV Playground could not start:', error);
  if (typeof window.bsvBootError === 'function') {
    window.bsvBootError('wasm', error);
  }
}

// Calls `fn` once the main thread has had two whole idle periods in a row (the page's later
// parts and its idle-time work are done), at the latest after 5 s (a page that animates is
// never wholly idle): the service worker's install, which fetches and stores every file of the
// build, then does not compete with the page's first seconds.
function whenQuiet(fn) {
  if (typeof requestIdleCallback !== 'function') return setTimeout(fn, 2000);
  const started = performance.now();
  let quiet = 0;
  const check = (deadline) => {
    quiet = deadline.timeRemaining() >= 45 ? quiet + 1 : 0;
    if (quiet >= 2 || performance.now() - started > 5000) fn();
    else requestIdleCallback(check, { timeout: 1000 });
  };
  requestIdleCallback(check, { timeout: 1000 });
}

// Offline install: the service worker (dist/sw.js, written per build by scripts/sw-build.mjs)
// caches exactly one build. A newer build installs in the background and waits; the page is
// told with a `bsv-update-ready` event (window.bsvUpdateReady is set too), shows its localized
// "reload to update" offer, and calls window.bsvApplyUpdate() when the user accepts: the new
// worker takes over and the page reloads once, so old and new files never mix.
function registerServiceWorker() {
  if (!('serviceWorker' in navigator) || location.protocol === 'file:') return;
  let accepted = false;
  navigator.serviceWorker.addEventListener('controllerchange', () => {
    if (accepted) location.reload();
  });
  navigator.serviceWorker
    .register(new URL('../sw.js', import.meta.url))
    .then((registration) => {
      const offer = () => {
        if (registration.waiting && navigator.serviceWorker.controller) {
          window.bsvUpdateReady = true;
          document.dispatchEvent(new CustomEvent('bsv-update-ready'));
        }
      };
      window.bsvApplyUpdate = () => {
        if (!registration.waiting) return false;
        accepted = true;
        registration.waiting.postMessage('bsv-apply-update');
        return true;
      };
      window.bsvCheckForUpdate = () => registration.update().catch(() => {});
      offer();
      registration.addEventListener('updatefound', () => {
        const worker = registration.installing;
        worker?.addEventListener('statechange', () => {
          if (worker.state === 'installed') offer();
        });
      });
    })
    // No service worker (blocked, private mode, an http origin that is not localhost): the app
    // still runs, it just needs its server.
    .catch(() => {});
}
