// Speed of the DH page (#/dh-fk) in headless Chromium at 1920×1080, on the dist folder named by
// BSV_DIST (default dist/); it needs a wasm built with `--features bench` (the timing hooks are
// not in the app build): `make bench` (scripts/bench.sh) assembles one in target/bench-dist.
// Prints p50 / p95 / max per kind of work, from the page's own records:
//
// - orbit drag: mouse drags on the 3D view, one move per animation frame; each frame's draw
//   (scene of the chain, projection, painter's sort, canvas paint) — window.__dhFrameMs;
// - slider drag: joint 2's slider dragged end to end, one move per frame; each input's
//   recompute (kernel FK, CSV rows, tables, readouts, row walk) — window.__dhChangeMs — and
//   the frame drawn after it.
//
// Budget: p95 < 4 ms for each. With DH_BENCH_STRICT=1 the exit code is 1 when it is missed.
import { openApp } from '../e2e/harness.mjs';
import { BenchTable, nextFrame, runBench } from './bench-table.mjs';

const VIEWPORT = { width: 1920, height: 1080 };
const table = new BenchTable();

const taken = (page) => page.evaluate(() => ({ frame: (window.__dhFrameMs || []).length, change: (window.__dhChangeMs || []).length }));
const since = (page, c) => page.evaluate((c) => ({ frame: window.__dhFrameMs.slice(c.frame), change: (window.__dhChangeMs || []).slice(c.change) }), c);

await runBench({ table, strict: 'DH_BENCH_STRICT' }, async (url) => {
  const app = await openApp(url, '#/dh-fk?row=3&step=2', { viewport: VIEWPORT });
  const { page } = app;
  await page.waitForSelector('[data-testid="dh-fk-canvas"]');
  await nextFrame(page);
  if (!(await page.evaluate(() => Array.isArray(window.__dhFrameMs)))) {
    throw new Error('no window.__dhFrameMs: serve a dist built with --features bench (make bench)');
  }

  // Orbit drags: circles over the view, one pointer move per frame.
  const box = await page.locator('[data-testid="dh-fk-canvas"]').boundingBox();
  const [cx, cy] = [box.x + box.width / 2, box.y + box.height / 2];
  let c = await taken(page);
  await page.mouse.move(cx, cy);
  await page.mouse.down();
  for (let k = 0; k < 400; k++) {
    await page.mouse.move(cx + 150 * Math.sin(k / 23), cy + 80 * Math.sin(k / 37));
    await nextFrame(page);
  }
  await page.mouse.up();
  table.report('orbit drag: frame draw', (await since(page, c)).frame, 4);

  // The joint 2 slider dragged end to end and back.
  const slider = await page.locator('[data-slider="q2"]').boundingBox();
  const y = slider.y + slider.height / 2;
  c = await taken(page);
  await page.mouse.move(slider.x + 4, y);
  await page.mouse.down();
  for (let k = 0; k <= 300; k++) {
    const f = 0.5 - 0.5 * Math.cos((2 * Math.PI * k) / 150);
    await page.mouse.move(slider.x + 4 + f * (slider.width - 8), y);
    await nextFrame(page);
  }
  await page.mouse.up();
  const s = await since(page, c);
  table.report('slider drag: recompute (FK, tables, readouts)', s.change, 4);
  table.report('slider drag: frame draw', s.frame, 4);
  await app.close();
});
