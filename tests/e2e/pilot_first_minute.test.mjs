// A new pilot's first minute on the two Robot Pilot pages (#/so101, #/teleop) in headless
// Chromium: one control state shown over the view (`data-control`), agreeing with the button,
// the readout and Space; the gripper's button says what pressing it does while its readout says
// what is; the flying keys reach the arm after a click on a tab, a button, a check box or a
// select, but not while a text field is edited; the arm's view is on the first screen at
// 1366×768 and 1280×720 and first on a phone, where a touch-only device starts on touch; the
// SO-101's readouts are a table, one value a line, never a negative zero; its checklist is a
// list and each module's panels show under their own tab only.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { serveApp, openApp, readouts } from './harness.mjs';

const server = serveApp();
const open = (hash, opts = {}) => openApp(server.url, hash, opts);
const values = (page) => readouts(page, { numbers: true, text: 'fallback' });
const control = (page) => page.locator('[data-testid="control-state"]');

async function hold(page, key, ms) {
  await page.keyboard.down(key);
  await page.waitForTimeout(ms);
  await page.keyboard.up(key);
  await page.waitForTimeout(60);
}

/** The tool's x on either page (the SO-101's tool, the planar arm's tip). */
const toolX = async (page) => (await values(page)).x;

for (const [route, lang] of [['so101', 'en'], ['so101', 'ja'], ['teleop', 'en'], ['teleop', 'ja']]) {
  test(`#/${route} (${lang}): one control state; the page's own instruction moves the arm`, async () => {
    const { page, errors, close } = await open(`#/${route}?lang=${lang}`, { viewport: { width: 1366, height: 768 } });
    try {
      // Engaged as the page opens: said over the view, by the button, by the readout.
      assert.equal(await control(page).getAttribute('data-control'), 'engaged');
      assert.ok(await control(page).isVisible());
      assert.equal(await page.locator('[data-action="engage"]').getAttribute('aria-pressed'), 'true');
      assert.equal((await values(page)).state, 'engaged');
      // The lede never tells the pilot to press Space to start (it would pause the arm).
      const lede = await page.locator('main').innerText();
      assert.doesNotMatch(lede, /Press Space to engage|スペースで操作を開始/);
      // W moves the arm at once, with nothing clicked.
      const x0 = await toolX(page);
      await hold(page, 'w', 300);
      assert.ok((await toolX(page)) > x0, `W moved x from ${x0}`);
      // Space pauses: all four agree, and W then moves nothing.
      await page.locator('h1').click();
      await page.keyboard.press('Space');
      assert.equal(await control(page).getAttribute('data-control'), 'paused');
      assert.equal(await page.locator('[data-action="engage"]').getAttribute('aria-pressed'), 'false');
      assert.equal((await values(page)).state, 'paused');
      const x1 = await toolX(page);
      await hold(page, 'w', 200);
      assert.equal(await toolX(page), x1);
      // K while paused changes nothing: the button still offers to close, the gripper is open.
      const gripper = page.locator('[data-action="gripper"]');
      const offer = await gripper.innerText();
      await page.keyboard.press('k');
      assert.equal(await gripper.innerText(), offer);
      assert.equal((await values(page)).gripper, 'open');
      // Space again: engaged, and K closes: the button now offers to open, the readout is closed.
      await page.keyboard.press('Space');
      assert.equal(await control(page).getAttribute('data-control'), 'engaged');
      await page.keyboard.press('k');
      await page.waitForFunction(() => document.querySelector('[data-readout="gripper"]').dataset.value === 'closed');
      assert.notEqual(await gripper.innerText(), offer);
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  });
}

test('the flying keys reach the arm after a click on a tab, a button, a check box or a select; not in a text field', async () => {
  for (const route of ['so101', 'teleop']) {
    const { page, errors, close } = await open(`#/${route}`, { viewport: { width: 1366, height: 768 } });
    try {
      const moves = async (what) => {
        const x0 = await toolX(page);
        await hold(page, 'w', 250);
        const x1 = await toolX(page);
        assert.ok(x1 > x0, `${route}: W after ${what} moved nothing (${x0} → ${x1})`);
        // Back, so the arm stays clear of its limits.
        await hold(page, 's', 250);
      };
      await page.locator('[data-device="keyboard"]').click();
      await moves('a device button');
      await page.locator('[data-module="basic-control"]').click();
      await moves('a module tab');
      if (route === 'so101') {
        await page.locator('.so101-settings summary').click();
        await moves('a disclosure');
        const check = page.locator('[data-field="obstacle"]');
        await check.focus();
        await moves('a check box');
      }
      const select = page.locator('select[data-field="ik"]');
      await select.focus();
      const method = await select.inputValue();
      await moves('a select');
      assert.equal(await select.inputValue(), method, `${route}: W changed the select`);
      // A text field keeps its letters: W types, the arm stays.
      const pilot = page.locator('input[data-field="pilot"]');
      await pilot.click();
      await pilot.fill('');
      const x0 = await toolX(page);
      await hold(page, 'w', 200);
      assert.equal(await toolX(page), x0, `${route}: W in the pilot field moved the arm`);
      assert.equal(await pilot.inputValue(), 'w');
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
});

test('the arm, the cube and the goal are on the first screen at 1366×768 and 1280×720, both pages, EN and JA', async () => {
  for (const route of ['so101', 'teleop']) {
    const testid = route === 'so101' ? 'so101-canvas' : 'teleop-canvas';
    for (const viewport of [{ width: 1366, height: 768 }, { width: 1280, height: 720 }]) {
      for (const lang of ['en', 'ja']) {
        const { page, errors, close } = await open(`#/${route}?lang=${lang}`, { viewport });
        try {
          const view = await page.locator(`[data-testid="${testid}"]`).boundingBox();
          // The whole view is on the screen: the scene's camera frames the arm, the cube and
          // the goal inside it.
          assert.ok(view.y >= 0 && view.y + view.height <= viewport.height,
            `${route} ${lang} ${viewport.width}×${viewport.height}: view from ${view.y} to ${view.y + view.height}`);
          assert.ok(view.height >= 300, `${route} ${lang}: the view is only ${view.height} px tall`);
          assert.deepEqual(errors, []);
        } finally {
          await close();
        }
      }
    }
  }
});

test('on a touch-only phone the view comes first and touch is the device', async () => {
  for (const route of ['so101', 'teleop']) {
    const testid = route === 'so101' ? 'so101-canvas' : 'teleop-canvas';
    const { page, errors, close } = await open(`#/${route}?lang=ja`, { viewport: { width: 390, height: 844 }, touch: true });
    try {
      const view = await page.locator(`[data-testid="${testid}"]`).boundingBox();
      // Right under the head, its heading and lede (and the SO-101's camera buttons), in the
      // first screen's upper half and whole on it, before the modules and the rest.
      const head = await page.locator(route === 'so101' ? '.so101-task' : '.tele-task').boundingBox();
      assert.ok(view.y >= head.y + head.height && view.y < 844 / 2 && view.y + view.height <= 844,
        `${route}: view at ${view.y}–${view.y + view.height}, the head's lede ending at ${head.y + head.height}`);
      const modules = await page.locator('[data-module="preflight"]').boundingBox();
      assert.ok(modules.y > view.y + view.height, `${route}: the modules (${modules.y}) come before the view`);
      const pointer = page.locator('[data-device="pointer"]');
      const pressed = route === 'so101' ? 'aria-pressed' : 'aria-checked';
      assert.equal(await pointer.getAttribute(pressed), 'true', `${route}: touch is not the device`);
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
  // A desktop with a mouse starts on the keyboard.
  const { page, close } = await open('#/so101');
  try {
    assert.equal(await page.locator('[data-device="keyboard"]').getAttribute('aria-pressed'), 'true');
  } finally {
    await close();
  }
});

test('the SO-101 readouts: a table, one value a line, no negative zero; a checklist list; panels under their own tab', async () => {
  for (const [lang, width] of [['en', 1366], ['ja', 390]]) {
    const { page, errors, close } = await open(`#/so101?lang=${lang}`, { viewport: { width, height: 844 } });
    try {
      // Move and come back, so that values near zero have been both signs.
      await hold(page, 'c', 150);
      await hold(page, 'v', 150);
      const rows = page.locator('#so101-readouts table tbody tr');
      assert.equal(await rows.count(), 17);
      const cells = await page.evaluate(() => [...document.querySelectorAll('#so101-readouts td, #so101-readouts th')].map((c) => {
        const r = c.getBoundingClientRect();
        const line = parseFloat(getComputedStyle(c).lineHeight) || 20;
        return { text: c.textContent, lines: Math.round((r.height - 4) / line) };
      }));
      for (const c of cells) {
        assert.ok(c.lines <= 1, `${lang}: "${c.text}" takes ${c.lines} lines`);
        assert.doesNotMatch(c.text, /[-−]0(\.0+)?(?![\d.])/, `${lang}: negative zero "${c.text}"`);
      }
      // Each joint's limits are a cell of their own.
      assert.match(await page.locator('#so101-readouts tr:has([data-readout="q1"]) .so101-ro-limit').innerText(), /^−\d+\.\d … \d+\.\d$/);
      // The preflight's checklist is a list; no repeatability under the preflight.
      assert.equal(await page.locator('[data-so101="preflight"] li').count(), 2);
      assert.ok(await page.locator('[data-so101="preflight"]').isVisible());
      assert.ok(!(await page.locator('[data-so101="summary-block"]').isVisible()));
      assert.ok(!(await page.locator('[data-so101="repeat"]').isVisible()));
      await page.locator('[data-module="repeatability"]').click();
      assert.ok(await page.locator('[data-so101="summary-block"]').isVisible());
      assert.ok(await page.locator('[data-so101="repeat"]').isVisible());
      assert.ok(!(await page.locator('[data-so101="preflight"]').isVisible()));
      // The session line has no doubled word and a real plural.
      const line = await page.locator('[data-so101="session-line"]').innerText();
      assert.doesNotMatch(line, /\b(\w+) \1\b/i);
      if (lang === 'en') assert.match(line, /no episodes yet/);
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
});
