// A finger on a phone (390×844, a touch screen), with real touch events (CDP
// Input.dispatchTouchEvent, which Chromium turns into touch and pointer events and scrolls with
// as it would for a finger): a swipe that does not start on a handle scrolls the page and
// leaves the page's values alone, on every kind of canvas (an arm view with handles, plots,
// a 3D orbit view, the home page's live arm); a drag that starts on a handle moves it and the
// page stays put.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { serveApp, openApp, readouts, OUT } from './harness.mjs';

const server = serveApp();
const PHONE = { width: 390, height: 844 };

/** Opens `hash` on a touch phone; `{ page, cdp, errors, close }`. */
async function openPhone(hash, locale = 'en-US') {
  const app = await openApp(server.url, hash, { viewport: PHONE, locale, touch: true });
  return { ...app, cdp: await app.context.newCDPSession(app.page) };
}

/** One finger from `from` to `to` (client px) in `steps` moves, then lifted. */
async function swipe(page, cdp, from, to, steps = 10) {
  const at = (k) => [{ x: from[0] + ((to[0] - from[0]) * k) / steps, y: from[1] + ((to[1] - from[1]) * k) / steps }];
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: at(0) });
  for (let k = 1; k <= steps; k += 1) {
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: at(k) });
    await page.waitForTimeout(16);
  }
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
  await page.waitForTimeout(250);
}

/** window.scrollY once it holds still (a swipe's fling has ended). */
async function scrollY(page) {
  let last = await page.evaluate(() => window.scrollY);
  for (let i = 0; i < 40; i += 1) {
    await page.waitForTimeout(100);
    const now = await page.evaluate(() => window.scrollY);
    if (now === last) return now;
    last = now;
  }
  return last;
}

/** The box of `selector` after it is scrolled to the middle of the screen. */
async function centred(page, selector) {
  await page.locator(selector).evaluate((e) => e.scrollIntoView({ block: 'center' }));
  await page.waitForTimeout(150);
  return page.locator(selector).evaluate((e) => e.getBoundingClientRect().toJSON());
}

/** Whether a finger at (x, y) lands on a drag handle (the kit's touch overlay). */
const onHandle = (page, [x, y]) => page.evaluate(([x, y]) => Boolean(document.elementFromPoint(x, y)?.closest('.kit-handle')), [x, y]);

test('IK page: a swipe beside the arm scrolls the page; a drag from the tip moves the arm and not the page', async () => {
  const { page, cdp, errors, close } = await openPhone('#/ik-2r');
  try {
    await page.waitForSelector('[data-testid="ik-2r-canvas"][data-tip-x]');
    const box = await centred(page, '[data-testid="ik-2r-canvas"]');
    const before = await readouts(page, { text: true });
    const y0 = await scrollY(page);
    // Up the left edge of the view, well away from the arm (which starts right of the base).
    const from = [box.left + box.width * 0.08, box.top + box.height * 0.8];
    assert.equal(await onHandle(page, from), false);
    await swipe(page, cdp, from, [from[0], from[1] - 200]);
    const y1 = await scrollY(page);
    assert.ok(y1 > y0 + 100, `the page scrolled: ${y0} -> ${y1}`);
    assert.deepEqual(await readouts(page, { text: true }), before, 'the arm did not move');

    // A drag that starts on the tip moves it; the page stays. (The view back in the middle
    // of the screen first: a long fling can carry the tip above its top.)
    await centred(page, '[data-testid="ik-2r-canvas"]');
    const y2 = await scrollY(page);
    const tip = await page.locator('[data-testid="ik-2r-canvas"]').evaluate((c) => {
      const r = c.getBoundingClientRect();
      return [r.left + Number(c.dataset.tipX), r.top + Number(c.dataset.tipY)];
    });
    assert.equal(await onHandle(page, tip), true, `the tip at ${tip} is on its handle`);
    await swipe(page, cdp, tip, [tip[0] - 40, tip[1] + 60]);
    assert.equal(await scrollY(page), y2, 'the page did not scroll');
    assert.notDeepEqual(await readouts(page, { text: true }), before, 'the arm moved');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('home: the live arm is on the first screen; a swipe beside it scrolls, a drag from its tip turns the joints', async () => {
  for (const lang of ['en-US', 'ja-JP']) {
    const { page, cdp, errors, close } = await openPhone('#/', lang);
    try {
      const canvas = page.locator('[data-testid="home-arm-canvas"]');
      await page.waitForSelector('[data-testid="home-arm-canvas"][data-tip-x]');
      const first = await canvas.evaluate((c) => c.getBoundingClientRect().toJSON());
      assert.ok(first.top < PHONE.height - 100 && first.height > 150, `the arm shows on the first screen: ${JSON.stringify(first)}`);
      const q = async () => [await page.locator('[data-testid="home-arm-q1"]').textContent(), await page.locator('[data-testid="home-arm-q2"]').textContent()];
      const start = await q();
      assert.deepEqual(start, ['17.2°', '45.8°']);
      const box = await centred(page, '[data-testid="home-arm-canvas"]');
      const y0 = await scrollY(page);
      const from = [box.left + box.width * 0.1, box.top + box.height * 0.85];
      assert.equal(await onHandle(page, from), false);
      await swipe(page, cdp, from, [from[0], from[1] - 200]);
      const y1 = await scrollY(page);
      assert.ok(y1 > y0 + 100, `${lang}: the page scrolled: ${y0} -> ${y1}`);
      assert.deepEqual(await q(), start, 'the arm did not move');

      const tip = await canvas.evaluate((c) => {
        const r = c.getBoundingClientRect();
        return [r.left + Number(c.dataset.tipX), r.top + Number(c.dataset.tipY)];
      });
      await swipe(page, cdp, tip, [tip[0] - 50, tip[1] + 70]);
      assert.equal(await scrollY(page), y1, `${lang}: the page did not scroll`);
      const moved = await q();
      assert.notDeepEqual(moved, start);
      // The link opens this pose on the IK page.
      const href = await page.locator('[data-testid="home-arm-open"]').getAttribute('href');
      const query = new URLSearchParams(href.split('?')[1]);
      assert.ok(Math.abs(Number(query.get('q1')) - (Number.parseFloat(moved[0]) * Math.PI) / 180) < 0.001, href);
      if (lang === 'ja-JP') await page.screenshot({ path: join(OUT, 'touch-home-arm-390-ja.png') });
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
});

test('plots and 3D views: a vertical swipe that starts on the canvas scrolls the page', async () => {
  // The pendulum swings by itself: its readouts change anyway.
  for (const [hash, selector, still = true] of [
    ['#/pendulum-energy', '[data-testid="pendulum-energy-canvas"]', false],
    ['#/traj-resample', '[data-testid="traj-resample-canvas"]'],
    ['#/pid-step', '[data-testid="pid-step-canvas"]'],
    ['#/rrt-2d', '[data-testid="rrt-2d-canvas"]'],
    ['#/umeyama-2d', '[data-testid="umeyama-2d-canvas"]'],
    ['#/dh-fk', '[data-testid="dh-fk-canvas"]'],
  ]) {
    const { page, cdp, errors, close } = await openPhone(hash);
    try {
      await page.waitForTimeout(300);
      const box = await centred(page, selector);
      // The first point down the left side of the view that is not a handle.
      let from = null;
      for (const fy of [0.85, 0.7, 0.55, 0.4]) {
        const p = [box.left + box.width * 0.06, box.top + box.height * fy];
        if (!(await onHandle(page, p))) { from = p; break; }
      }
      assert.ok(from, `${hash}: a point off the handles`);
      const before = await readouts(page, { text: 'fallback' });
      const y0 = await scrollY(page);
      await swipe(page, cdp, from, [from[0], from[1] - 160]);
      const y1 = await scrollY(page);
      assert.ok(y1 > y0 + 80, `${hash}: the page scrolled: ${y0} -> ${y1}`);
      if (still) assert.deepEqual(await readouts(page, { text: 'fallback' }), before, `${hash}: nothing changed`);
      assert.deepEqual(errors, [], hash);
    } finally {
      await close();
    }
  }
});

test('a 3D view orbits with a sideways drag and keeps its view when a vertical swipe scrolls', async () => {
  const { page, cdp, errors, close } = await openPhone('#/dh-fk');
  try {
    const pressed = () => page.locator('[data-action^="view-"][aria-pressed="true"]').count();
    const box = await centred(page, '[data-testid="dh-fk-canvas"]');
    assert.equal(await pressed(), 1, 'a preset view at start');
    const from = [box.left + box.width * 0.3, box.top + box.height * 0.75];
    await swipe(page, cdp, from, [from[0], from[1] - 160]);
    assert.equal(await pressed(), 1, 'a swipe that scrolled left the view as it was');
    const box2 = await page.locator('[data-testid="dh-fk-canvas"]').evaluate((e) => e.getBoundingClientRect().toJSON());
    const y0 = await scrollY(page);
    const side = [box2.left + box2.width * 0.25, box2.top + box2.height * 0.5];
    await swipe(page, cdp, side, [side[0] + 150, side[1]]);
    assert.equal(await pressed(), 0, 'a sideways drag orbited (no preset view any more)');
    assert.equal(await scrollY(page), y0);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});
