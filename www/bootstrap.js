// Loads the wasm and starts the app. Nothing is fetched from the network beyond this site:
// the module, the wasm and the translations (compiled into the wasm) all come from dist/.
// If loading fails, a bilingual message replaces the "Loading…" line (see index.html).
try {
  const { default: init, startApp } = await import('../pkg/bsv_playground.js');
  await init();
  startApp();
} catch (error) {
  console.error('BSV Playground could not start:', error);
  if (typeof window.bsvBootError === 'function') {
    window.bsvBootError('wasm', error);
  }
}
