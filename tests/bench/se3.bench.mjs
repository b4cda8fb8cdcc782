// Speed of the relative SE(3) pose page (#/se3-relative) in headless Chromium at 1920×1080, on
// the dist folder named by BSV_DIST (default dist/); it needs a wasm built with
// `--features bench` (`make bench` assembles one in target/bench-dist). Prints p50 / p95 / max
// of the page's own record of each drag frame's work (window.__se3FrameMs: drag maths, the
// form, the solve, matrices, readouts, the rotations panel and both canvases):
//
// - gizmo drag: B's origin dragged around a circle, one pointer move per animation frame;
// - orbit drag: the view turned by dragging off the origins, the same way.
//
// Budget: p95 < 4 ms. With SE3_BENCH_STRICT=1 the exit code is 1 when it is missed; otherwise
// this only reports.
import { openApp } from '../e2e/harness.mjs';
import { BenchTable, nextFrame, runBench } from './bench-table.mjs';

const VIEWPORT = { width: 1920, height: 1080 };
const BUDGET_MS = 4;
const table = new BenchTable();

const recorded = (page) => page.evaluate(() => (window.__se3FrameMs ?? []).length);

await runBench({ table, strict: 'SE3_BENCH_STRICT' }, async (url) => {
  const { page } = await openApp(url, '#/se3-relative', { viewport: VIEWPORT });
  const canvas = page.locator('[data-testid="se3-relative-canvas"]');
  await canvas.scrollIntoViewIfNeeded();
  const box = await canvas.boundingBox();
  const drag = async (x0, y0, at) => {
    const before = await recorded(page);
    await page.mouse.move(x0, y0);
    await page.mouse.down();
    for (let k = 1; k <= 300; k++) {
      const [x, y] = at(k);
      await page.mouse.move(x, y);
      await nextFrame(page);
    }
    await page.mouse.up();
    return page.evaluate((n) => window.__se3FrameMs.slice(n), before);
  };
  const bx = box.x + Number(await canvas.getAttribute('data-b-x'));
  const by = box.y + Number(await canvas.getAttribute('data-b-y'));
  const gizmo = await drag(bx, by, (k) => [bx + 80 * Math.sin(k / 20), by + 60 * (1 - Math.cos(k / 20))]);
  const orbit = await drag(box.x + 30, box.y + 30, (k) => [box.x + 30 + 150 * Math.sin(k / 30), box.y + 30 + 40 * Math.sin(k / 45)]);
  if (gizmo.length === 0) {
    throw new Error('no window.__se3FrameMs: serve a dist built with --features bench (make bench)');
  }
  table.report('gizmo drag frame', gizmo, BUDGET_MS);
  table.report('orbit drag frame', orbit, BUDGET_MS);
});
