// Nothing jumps while a phone loads a page: every route at 412×823, in English and in
// Japanese, opened cold with the network and the CPU throttled as the first-load bench does
// (Lighthouse's mobile profile), sums its `layout-shift` entries without recent input from the
// start until 5 s after the route is settled: at most 0.02 (Lighthouse's CLS goal here). What
// stands below a page (the drill chain, the footer) waits for the page; the frame that stands
// in for it is laid out as the page's head will be. And what the phone painted first stays the
// largest paint: the largest is the head's heading or lede, which the frame paints before the
// app's code runs and the page keeps; no text or image the page paints later in its first
// screen is larger (else Lighthouse's largest paint waits for the page's code). A layout test,
// not a timing one: the throttling only makes the frame stand long enough to be painted, as on
// a phone.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { test } from 'node:test';
import { browser, DIST, serveApp, throttle } from './harness.mjs';

const app = serveApp();
const table = JSON.parse(readFileSync(join(DIST, 'pkg', 'routes.json'), 'utf8'));
const ROUTES = Object.keys(table.routes);
const MOST = 0.02;

/** Init script: every layout shift of the page, with what moved, and the largest paints. */
function watchShifts() {
  window.__shifts = [];
  window.__largest = [];
  new PerformanceObserver((list) => {
    for (const e of list.getEntries()) {
      const el = e.element;
      const name = el ? `${el.nodeName}${el.className ? `.${String(el.className).split(' ')[0]}` : ''}` : '?';
      // The head's heading, or its lede: the paragraph right after the heading.
      const head = el?.nodeName === 'H1' || (el?.nodeName === 'P' && el.previousElementSibling?.nodeName === 'H1');
      window.__largest.push({ at: Math.round(e.startTime), size: e.size, name, head });
    }
  }).observe({ type: 'largest-contentful-paint', buffered: true });
  new PerformanceObserver((list) => {
    for (const e of list.getEntries()) {
      if (e.hadRecentInput) continue;
      const moved = (e.sources ?? []).map((s) => {
        const node = s.node;
        const name = node ? `${node.nodeName}${node.id ? `#${node.id}` : ''}${node.className ? `.${String(node.className).split(' ')[0]}` : ''}` : '?';
        return `${name} ${Math.round(s.previousRect.y)}→${Math.round(s.currentRect.y)}`;
      });
      window.__shifts.push({ at: Math.round(e.startTime), value: e.value, moved });
    }
  }).observe({ type: 'layout-shift', buffered: true });
}

/** Loads `hash` cold at 412×823 under throttling: null, or what failed (the sum of its layout
 * shifts over the limit, a largest paint that is not the head's heading or lede). */
async function shiftsOf(hash) {
  const context = await (await browser()).newContext({ viewport: { width: 412, height: 823 }, serviceWorkers: 'block' });
  try {
    await context.addInitScript(watchShifts);
    const page = await context.newPage();
    await throttle(context, page, { cpu: true });
    await page.goto(`${app.url}/${hash}`);
    await page.waitForFunction(() => document.documentElement.dataset.appReady === '1', null, { timeout: 60000 });
    // The frame stood in for the page (the throttled network makes it wait for its code).
    await page.waitForTimeout(5000);
    const shifts = await page.evaluate(() => window.__shifts);
    const sum = shifts.reduce((s, e) => s + e.value, 0);
    const largest = await page.evaluate(() => window.__largest);
    const drawn = await page.locator('#app-main').innerText();
    assert.ok(drawn.length > 40, `${hash}: the page is shown`);
    assert.equal(await page.locator('#app[data-page-pending]').count(), 0, `${hash}: the page is no longer pending`);
    const last = largest.at(-1);
    if (sum > MOST) return `${hash}: shifts ${sum.toFixed(4)} ${JSON.stringify(shifts)}`;
    if (!last?.head) return `${hash}: the largest paint is not the head's: ${JSON.stringify(largest)}`;
    return null;
  } finally {
    await context.close();
  }
}

// Routes load five at a time, each in its own context (its own throttled tab): what is summed
// is layout, which the other tabs do not change.
const AT_ONCE = 5;

for (const lang of ['en', 'ja']) {
  test(`no route shifts its layout by more than ${MOST} while it loads on a phone, nor paints larger than its head (${lang})`, async () => {
    const hashes = ROUTES.map((route) => `${route === 'home' ? '#/' : `#/${route}`}${lang === 'ja' ? '?lang=ja' : ''}`);
    const failures = [];
    for (let i = 0; i < hashes.length; i += AT_ONCE) {
      const results = await Promise.all(hashes.slice(i, i + AT_ONCE).map(shiftsOf));
      failures.push(...results.filter(Boolean));
    }
    assert.deepEqual(failures, [], 'layout shifts over the limit, or a largest paint not the head\'s');
  });
}

test('while a page loads, its frame is the page\'s head and stands alone; the page keeps that head', async () => {
  const context = await (await browser()).newContext({ viewport: { width: 412, height: 823 }, serviceWorkers: 'block' });
  try {
    const page = await context.newPage();
    // The IK page's code is held back until the frame has been looked at.
    let release;
    const held = new Promise((resolve) => { release = resolve; });
    await page.route(/\/pkg\/pack_\w+\.bin/, async (route) => {
      await held;
      await route.continue();
    });
    await page.goto(`${app.url}/#/ik-2r`);
    await page.locator('[data-testid="page-loading"]').waitFor();
    assert.equal(await page.locator('#app[data-page-pending]').count(), 1);
    assert.equal(await page.locator('[data-testid="drill-chain"]').isVisible(), false);
    assert.equal(await page.locator('[data-testid="site-footer"]').isVisible(), false);
    // The frame is the page's head, in the page's words; the page keeps its heading and lede.
    assert.equal(await page.locator('[data-testid="page-frame"] h1').innerText(), 'Planar 2R IK playground');
    assert.match(await page.locator('[data-testid="page-frame"] .ik2r-lede').innerText(), /^Drag the orange tip/);
    await page.evaluate(() => {
      const frame = document.querySelector('[data-testid="page-frame"]');
      window.__frameNodes = [frame.querySelector('h1'), frame.querySelector('.ik2r-lede')];
    });
    release();
    await page.waitForFunction(() => document.documentElement.dataset.appReady === '1', null, { timeout: 20000 });
    await page.locator('[data-testid="ik-2r-page"]').waitFor();
    assert.equal(await page.locator('[data-testid="page-frame"], [data-testid="page-loading"]').count(), 0);
    assert.deepEqual(
      await page.evaluate(() => [
        window.__frameNodes[0] === document.querySelector('[data-testid="ik-2r-page"] h1'),
        window.__frameNodes[1] === document.querySelector('[data-testid="ik-2r-page"] .ik2r-lede'),
        window.__frameNodes[0].isConnected,
      ]),
      [true, true, true],
      'the page kept the frame\'s heading and lede',
    );
    assert.equal(await page.locator('[data-testid="drill-chain"]').isVisible(), true);
    assert.equal(await page.locator('[data-testid="site-footer"]').isVisible(), true);
    assert.equal(await page.locator('[data-testid="disclaimer"]').isVisible(), true);
  } finally {
    await context.close();
  }
});

// A returning pilot: the browser holds a session, so the page waits for the code that reads it
// (kit::late_page) under a line that stands below its heading and lede, where the frame had
// its loading line: nothing painted moves when the line comes or when the page is built.
for (const [route, key] of [['teleop', 'bsv.teleop'], ['so101', 'bsv.so101']]) {
  for (const lang of ['en', 'ja']) {
    test(`#/${route} with a stored session waits under its head without a layout shift (${lang})`, async () => {
      const context = await (await browser()).newContext({ viewport: { width: 412, height: 823 }, serviceWorkers: 'block' });
      try {
        const hash = `#/${route}?lang=${lang}`;
        const first = await context.newPage();
        await first.goto(`${app.url}/${hash}`);
        await first.waitForFunction(() => document.documentElement.dataset.appReady === '1');
        await first.locator('canvas[tabindex="0"]').first().focus();
        await first.keyboard.down('w');
        await first.waitForTimeout(300);
        await first.keyboard.up('w');
        await first.waitForFunction(
          (prefix) => Object.keys(localStorage).some((k) => k.startsWith(prefix)),
          key,
        );
        await first.close();
        await context.addInitScript(watchShifts);
        const page = await context.newPage();
        await throttle(context, page, { cpu: true });
        await page.goto(`${app.url}/${hash}`);
        const line = page.locator('[data-testid="late-page"]');
        await line.waitFor({ timeout: 30000 });
        // The line stands right under the heading's lede, the page's head where it was painted.
        assert.equal(
          await line.evaluate((el) => el.previousElementSibling?.previousElementSibling?.tagName),
          'H1',
        );
        await page.waitForFunction(() => document.documentElement.dataset.appReady === '1', null, { timeout: 60000 });
        await line.waitFor({ state: 'detached' });
        await page.waitForTimeout(1000);
        const shifts = await page.evaluate(() => window.__shifts);
        const sum = shifts.reduce((s, e) => s + e.value, 0);
        assert.ok(sum <= MOST, `${hash}: shifts ${sum.toFixed(4)} ${JSON.stringify(shifts)}`);
      } finally {
        await context.close();
      }
    });
  }
}
