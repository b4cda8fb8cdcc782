// Speed of the Umeyama page (#/umeyama-2d) in headless Chromium at 1920×1080, on the dist folder
// named by BSV_DIST (default dist/); it needs a wasm built with `--features bench` (the page
// then keeps each frame's work in window.__umeyamaFrameMs: from the pointer move or slider
// input to the drawn view, the form's check, the kernel's fit, the step panel and the readouts
// included). `make bench` (scripts/bench.sh) assembles such a dist in target/bench-dist.
// Cases: dragging a point (12 and 40 points), dragging the sigma and angle sliders, and moving
// a point with Shift + arrows (40 points). The page's mount is not a frame of these.
//
// Budget: frame work p95 < 4 ms. With UMEYAMA_BENCH_STRICT=1 the exit code is 1 when it is
// missed; otherwise this only reports.
import { openApp } from '../e2e/harness.mjs';
import { BenchTable, nextFrame, runBench } from './bench-table.mjs';

const VIEWPORT = { width: 1920, height: 1080 };
const MOVES = 150;
const BUDGET_MS = 4;
const table = new BenchTable();

async function dragPoint(page) {
  const canvas = page.locator('[data-testid="umeyama-2d-canvas"]');
  const box = await canvas.boundingBox();
  const [x, y] = await canvas.evaluate((c) => c.dataset.pointsPx.split(';')[0].split(',').map(Number));
  await page.mouse.move(box.x + x, box.y + y);
  await page.mouse.down();
  for (let k = 1; k <= MOVES; k++) {
    const a = (k / MOVES) * 2 * Math.PI;
    await page.mouse.move(box.x + x + 80 * Math.sin(a), box.y + y + 60 * (1 - Math.cos(a)));
    await nextFrame(page);
  }
  await page.mouse.up();
}

async function dragSlider(page, name) {
  const slider = page.locator(`[data-slider="${name}"]`);
  await slider.scrollIntoViewIfNeeded();
  const box = await slider.boundingBox();
  await page.mouse.move(box.x + 4, box.y + box.height / 2);
  await page.mouse.down();
  for (let k = 0; k <= MOVES; k++) {
    await page.mouse.move(box.x + 4 + (k / MOVES) * (box.width - 8), box.y + box.height / 2);
    await nextFrame(page);
  }
  await page.mouse.up();
}

/** Point 1 selected with `n`, then moved by Shift + arrows, one press a frame (back and forth). */
async function keyMoves(page) {
  await page.locator('[data-testid="umeyama-2d-canvas"]').focus();
  await page.keyboard.press('n');
  for (let k = 0; k < MOVES; k++) {
    await page.keyboard.press(k % 40 < 20 ? 'Shift+ArrowRight' : 'Shift+ArrowLeft');
    await nextFrame(page);
  }
}

const cases = [
  ['point drag, 12 points', '#/umeyama-2d', dragPoint],
  ['point drag, 40 points', '#/umeyama-2d?n=40', dragPoint],
  ['sigma slider, 12 points', '#/umeyama-2d', (page) => dragSlider(page, 'sigma')],
  ['angle slider, 40 points', '#/umeyama-2d?n=40&step=3', (page) => dragSlider(page, 'angle')],
  ['Shift+arrow keys, 40 pts', '#/umeyama-2d?n=40', keyMoves],
];

await runBench({ table, strict: 'UMEYAMA_BENCH_STRICT' }, async (url) => {
  for (const [name, hash, act] of cases) {
    const { page, close } = await openApp(url, hash, { viewport: VIEWPORT });
    try {
      if (!(await page.evaluate(() => Array.isArray(window.__umeyamaFrameMs)))) {
        throw new Error('no window.__umeyamaFrameMs: serve a dist built with --features bench (make bench)');
      }
      // Only the input's frames: the records of the page's mount (its first draw makes the
      // grid layer and the label images, tens of ms once) are dropped.
      await page.evaluate(() => {
        for (const k of ['__umeyamaFrameMs', '__umeyamaFormMs', '__umeyamaDrawMs']) window[k] = [];
      });
      await act(page);
      table.report(name, await page.evaluate(() => window.__umeyamaFrameMs.slice()), BUDGET_MS);
      // Of it: the form's check and the canvas drawing.
      table.report('  of it: form check', await page.evaluate(() => window.__umeyamaFormMs?.slice() ?? []));
      table.report('  of it: canvas draw', await page.evaluate(() => window.__umeyamaDrawMs?.slice() ?? []));
    } finally {
      await close();
    }
  }
});
