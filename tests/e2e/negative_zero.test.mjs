// No page shows a negative zero: after load, every readout (`[data-readout]`) and every table
// cell of the Robot Pilot pages, the IK playground and a few drills writes a value that rounds
// to zero as `0`, `0.0`, `0.000`, never `-0.0` or `−0.0` (src/numtext.rs).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { serveApp, openApp } from './harness.mjs';

const server = serveApp();

const ROUTES = ['#/so101', '#/teleop', '#/ik-2r', '#/se3-relative', '#/dh-fk', '#/pendulum-energy', '#/umeyama-2d', '#/rrt-2d'];

/** The shown numbers of `text` that are a signed zero (`-0`, `−0.00`, `-0.0e0`). */
function negativeZeros(text) {
  return [...text.matchAll(/[-−](\d+(?:\.\d+)?)(?![\d.]*[1-9])/g)].filter((m) => /^[0.]+$/.test(m[1])).map((m) => m[0]);
}

test('the checker finds signed zeros only', () => {
  assert.deepEqual(negativeZeros('−0.0 mm, -0 °, -0.000e0'), ['−0.0', '-0', '-0.000']);
  assert.deepEqual(negativeZeros('0.0 mm, −0.1°, -10.0, (−110.0…110.0), -0.05'), []);
});

for (const route of ROUTES) {
  test(`${route} shows no negative zero after load`, async () => {
    const { page, errors, close } = await openApp(server.url, route);
    try {
      await page.waitForFunction(() => [...document.querySelectorAll('[data-readout]')].some((e) => e.textContent.trim() !== ''), null, { timeout: 20000 });
      // A few frames for the readouts that follow the first draw.
      await page.waitForTimeout(500);
      const shown = await page.evaluate(() =>
        [...document.querySelectorAll('[data-readout], main td, main th')].map((e) => [e.dataset.readout ?? e.tagName, e.textContent.trim()]),
      );
      assert.ok(shown.length > 3, `${route}: ${shown.length} readouts`);
      const bad = shown.filter(([, text]) => negativeZeros(text).length > 0);
      assert.deepEqual(bad, [], `${route}: negative zeros`);
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  });
}
