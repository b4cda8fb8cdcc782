// The DH forward-kinematics page (#/dh-fk) in headless Chromium: the tip readouts and the pose
// table are the `bsv dh-fk` CSV's numbers (defaults, after a joint slider, from a URL); the
// download equals `bsv` byte for byte; a bad `angles` shows its message and keeps the last
// view; orbiting (drag, preset, keys, wheel) changes the pixels and never the numbers; "show one
// row" walks Rx, Tx, Rz, Tz with the stepper; Japanese leaves no English UI text. Screenshots
// (EN/JA 1920×1080, phone 390 px, projector) go to tests/e2e/out/.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { openApp, OUT, readouts } from './harness.mjs';
import { serveAppWithCli, cliCsv, download, assertSameBytes } from './cli.mjs';
import { englishStrings } from './locales.mjs';

// The CLI is built and dist/ served before the tests; all is closed after them.
const server = serveAppWithCli();

const open = (hash, opts = {}) => openApp(server.url, hash, opts);
const CANVAS = '[data-testid="dh-fk-canvas"]';
const KEYS = ['x', 'y', 'z', 'roll', 'pitch', 'yaw'];

/** `bsv dh-fk [angles]`: the CSV bytes and its data rows as cell texts. */
const run = (args) => cliCsv(['dh-fk', ...args], 'dh_fk.csv');

/** The exact readout values (data-value) of the tip. */
const tipReadouts = async (page) => {
  const r = await readouts(page);
  return Object.fromEntries(KEYS.map((k) => [k, r[k]]));
};

/** The pose table's cells, row by row. */
const poseCells = (page) => page.evaluate(() => [...document.querySelectorAll('[data-testid="dh-fk-pose-table"] tbody tr')]
  .map((tr) => [...tr.querySelectorAll('td')].map((td) => td.textContent)));

/** A CSV cell as the page shows it: a negative zero (`-0.0`) without its sign. */
const shown = (cell) => cell.replace(/^-(?=[0.]+$)/, '');

/** Asserts the readouts are the CSV's frame-3 row and the pose table is the CSV's rows. */
async function assertNumbers(page, want, label) {
  const tip = want.rows[3];
  assert.deepEqual(await tipReadouts(page), Object.fromEntries(KEYS.map((k, i) => [k, tip[i + 1]])), `${label}: readouts`);
  assert.deepEqual(await poseCells(page), want.rows.map((row) => row.map(shown)), `${label}: pose table`);
}

/** The canvas's own pixels (a data URL: independent of where the page is scrolled). */
const canvasShot = (page) => page.locator(CANVAS).evaluate((c) => c.toDataURL());

async function setSlider(page, name, value) {
  await page.locator(`[data-slider="${name}"]`).evaluate((el, v) => {
    el.value = v;
    el.dispatchEvent(new Event('input', { bubbles: true }));
  }, value);
}

test('defaults, a slider and a URL give the CLI numbers and bytes; bad angles keep the last view', async () => {
  const { page, errors, close } = await open('#/dh-fk', { viewport: { width: 1600, height: 1000 } });
  try {
    await page.waitForSelector(CANVAS);
    const defaults = run([]);
    await assertNumbers(page, defaults, 'defaults');
    assert.equal(await page.locator('[data-readout="x"]').innerText(), '0.2257');
    assertSameBytes(await download(page, 'dh_fk.csv'), defaults.bytes, 'defaults');
    assert.equal((await page.locator('[data-testid="dh-cmd-bsv"]').innerText()).trim(), 'bsv dh-fk 0.2,0.4,-0.3');
    // The DH table shows the current θ.
    assert.equal(await page.locator('[data-dh-row="2"] [data-cell="theta"]').innerText(), '0.4000');

    // Joint 2's slider: the angles field, readouts, table, URL and download follow.
    await setSlider(page, 'q2', '1.25');
    assert.equal(await page.locator('[data-field="angles"]').inputValue(), '0.2,1.25,-0.3');
    const moved = run(['0.2,1.25,-0.3']);
    await assertNumbers(page, moved, 'q2 = 1.25');
    assert.notDeepEqual(moved.rows[3], defaults.rows[3]);
    assert.equal(await page.locator('[data-dh-row="2"] [data-cell="theta"]').innerText(), '1.2500');
    await page.waitForFunction(() => location.hash === '#/dh-fk?angles=0.2,1.25,-0.3');
    assertSameBytes(await download(page, 'dh_fk.csv'), moved.bytes, 'q2 = 1.25');
    assert.equal((await page.locator('[data-testid="dh-cmd-bsv"]').innerText()).trim(), 'bsv dh-fk 0.2,1.25,-0.3');

    // Bad angles: the message beside the field; the numbers, the view and the download stay.
    const before = await canvasShot(page);
    for (const [text, pattern] of [['0.1,0.2', /3/], ['0.1,abc,0.3', /abc/]]) {
      await page.locator('[data-field="angles"]').fill(text);
      const message = page.locator('[data-field-error="angles"]');
      await message.waitFor({ state: 'visible' });
      assert.match(await message.innerText(), pattern);
      assert.equal(await page.locator('[data-field="angles"]').getAttribute('aria-invalid'), 'true');
      await assertNumbers(page, moved, `kept after ${text}`);
    }
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    assert.equal(await canvasShot(page), before, 'the view is unchanged by a bad value');
    assertSameBytes(await download(page, 'dh_fk.csv'), moved.bytes, 'kept');
    // A slider after a bad text writes the last valid angles with its new value.
    await setSlider(page, 'q1', '-0.5');
    assert.equal(await page.locator('[data-field="angles"]').inputValue(), '-0.5,1.25,-0.3');
    assert.equal(await page.locator('[data-field-error="angles"]').isVisible(), false);
    await assertNumbers(page, run(['-0.5,1.25,-0.3']), 'q1 after a bad text');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }

  // A link with other angles (the recipe's second golden run) and page keys.
  const linked = await open('#/dh-fk?angles=1.0,-0.5,2.0&view=top&axes=cb&row=7');
  try {
    await linked.page.waitForSelector(CANVAS);
    const want = run(['1.0,-0.5,2.0']);
    await assertNumbers(linked.page, want, 'URL angles');
    assertSameBytes(await download(linked.page, 'dh_fk.csv'), want.bytes, 'URL angles');
    assert.equal(await linked.page.locator('[data-action="view-top"]').getAttribute('aria-pressed'), 'true');
    assert.equal(await linked.page.locator('[data-option="cb-axes"]').isChecked(), true);
    assert.match(await linked.page.locator('[data-dh="url-notice"]').innerText(), /row/);
    assert.deepEqual(linked.errors, []);
  } finally {
    await linked.close();
  }
});

test('orbiting changes the pixels, never the numbers; presets, keys and the wheel', async () => {
  const { page, errors, close } = await open('#/dh-fk');
  try {
    await page.waitForSelector(CANVAS);
    const numbers = await tipReadouts(page);
    const shot0 = await canvasShot(page);
    assert.equal(await page.locator('[data-action="view-iso"]').getAttribute('aria-pressed'), 'true');
    const box = await page.locator(CANVAS).boundingBox();
    const [cx, cy] = [box.x + box.width / 2, box.y + box.height / 2];
    await page.mouse.move(cx, cy);
    await page.mouse.down();
    for (let k = 1; k <= 10; k++) await page.mouse.move(cx + 12 * k, cy + 3 * k);
    await page.mouse.up();
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    const shot1 = await canvasShot(page);
    assert.notEqual(shot1, shot0, 'a drag orbits the view');
    assert.deepEqual(await tipReadouts(page), numbers, 'orbiting leaves the numbers alone');
    assert.equal(await page.locator('[data-action="view-iso"]').getAttribute('aria-pressed'), 'false');
    // The drag focused the canvas: the arrow keys orbit it, + zooms.
    assert.equal(await page.evaluate(() => document.activeElement?.dataset.testid), 'dh-fk-canvas');
    await page.keyboard.press('ArrowLeft');
    await page.keyboard.press('+');
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    const shot2 = await canvasShot(page);
    assert.notEqual(shot2, shot1, 'keys orbit and zoom');
    // The wheel zooms.
    await page.mouse.move(cx, cy);
    await page.mouse.wheel(0, 300);
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    assert.notEqual(await canvasShot(page), shot2, 'the wheel zooms');
    // A two-finger pinch (touch pointers) zooms; one finger then orbits.
    const shot3 = await canvasShot(page);
    await page.locator('[data-orbit="stage"]').evaluate((stage) => {
      const r = stage.getBoundingClientRect();
      const [x, y] = [r.left + r.width / 2, r.top + r.height / 2];
      const fire = (type, pointerId, dx) => stage.dispatchEvent(new PointerEvent(type, {
        pointerId, pointerType: 'touch', isPrimary: pointerId === 11, clientX: x + dx, clientY: y, bubbles: true, cancelable: true,
      }));
      fire('pointerdown', 11, -20);
      fire('pointerdown', 12, 20);
      for (let k = 1; k <= 5; k++) { fire('pointermove', 11, -20 - 12 * k); fire('pointermove', 12, 20 + 12 * k); }
      fire('pointerup', 12, 80);
      fire('pointerup', 11, -80);
    });
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    assert.notEqual(await canvasShot(page), shot3, 'a pinch zooms');
    assert.deepEqual(await tipReadouts(page), numbers);
    // A preset: pressed, in the URL.
    await page.locator('[data-action="view-front"]').click();
    assert.equal(await page.locator('[data-action="view-front"]').getAttribute('aria-pressed'), 'true');
    await page.waitForFunction(() => location.hash.includes('view=front'));
    assert.deepEqual(await tipReadouts(page), numbers);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('show one row: the stepper walks Rx, Tx, Rz, Tz to the row frame', async () => {
  const { page, errors, close } = await open('#/dh-fk');
  try {
    await page.waitForSelector(CANVAS);
    await page.locator('[data-row="3"]').click();
    assert.equal(await page.locator('[data-row="3"]').getAttribute('aria-pressed'), 'true');
    const step = page.locator('[data-testid="dh-fk-stepper"] [data-action="step"]');
    const cellOf = (name, rc) => page.locator(`[data-testid="dh-fk-${name}"] [data-rc="${rc}"]`).innerText();
    // Row 3: α2 = 0, a2 = 0.25, θ3 = q3 = −0.3, d3 = 0.
    await step.click();
    assert.equal(await page.locator('[data-step="1"]').getAttribute('data-state'), 'current');
    await step.click();
    assert.equal(await cellOf('elementary', '03'), '0.2500', 'Tx(a2) moves 0.25 m along x');
    await step.click();
    assert.equal(await cellOf('elementary', '00'), Math.cos(-0.3).toFixed(4));
    assert.equal(await cellOf('elementary', '01'), (-Math.sin(-0.3)).toFixed(4));
    await step.click();
    assert.equal(await page.locator('[data-step="4"]').getAttribute('data-state'), 'current');
    // The product of the four is the link transform T_mdh(0, 0.25, 0, −0.3).
    assert.equal(await cellOf('product', '00'), Math.cos(-0.3).toFixed(4));
    assert.equal(await cellOf('product', '10'), Math.sin(-0.3).toFixed(4).replace('-', '−'));
    assert.equal(await cellOf('product', '03'), '0.2500');
    await page.waitForFunction(() => location.hash.includes('row=3&step=4'));
    // Back is exact; keys 1–3 pick a row (page focused, not a control).
    await page.locator('[data-testid="dh-fk-stepper"] [data-action="back"]').click();
    assert.equal(await page.locator('[data-step="3"]').getAttribute('data-state'), 'current');
    await page.locator('h1').click();
    await page.keyboard.press('2');
    assert.equal(await page.locator('[data-row="2"]').getAttribute('aria-pressed'), 'true');
    assert.equal(await page.locator('[data-step="1"]').getAttribute('data-state'), 'todo');
    await page.keyboard.press('ArrowRight');
    assert.equal(await page.locator('[data-step="1"]').getAttribute('data-state'), 'current');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('Japanese leaves no English UI text', async () => {
  const english = englishStrings();
  const { page, errors, close } = await open('#/dh-fk?lang=ja&row=2&step=3');
  try {
    await page.waitForSelector(CANVAS);
    await page.locator('[data-field="angles"]').fill('1,2');
    await page.locator('[data-field-error="angles"]').waitFor({ state: 'visible' });
    const text = await page.evaluate(() => document.body.innerText);
    const left = english.filter((s) => text.includes(s));
    assert.deepEqual(left, [], `English left: ${left.join(' | ')}`);
    assert.match(text, /DH 順運動学/);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('screenshots: EN and JA 1920×1080, phone 390 px, projector', async () => {
  for (const [name, hash, viewport, projector] of [
    ['en', '#/dh-fk?row=3&step=2', { width: 1920, height: 1080 }, false],
    ['ja', '#/dh-fk?lang=ja&row=2&step=1&axes=cb', { width: 1920, height: 1080 }, false],
    ['phone', '#/dh-fk', { width: 390, height: 844 }, false],
    ['projector', '#/dh-fk?row=3&step=4', { width: 1920, height: 1080 }, true],
  ]) {
    const { page, errors, close } = await open(hash, { viewport });
    try {
      await page.waitForSelector(CANVAS);
      if (projector) {
        await page.locator('h1').click();
        await page.keyboard.press('p');
        await page.waitForFunction(() => document.documentElement.classList.contains('projector'));
      }
      await page.waitForTimeout(700);
      if (projector) await page.locator('[data-dh="view"]').evaluate((el) => el.scrollIntoView());
      const overflow = await page.evaluate(() => document.documentElement.scrollWidth - document.documentElement.clientWidth);
      assert.ok(overflow <= 0, `${name}: no horizontal scroll (${overflow} px)`);
      await page.screenshot({ path: join(OUT, `dh-fk-${name}.png`), fullPage: name === 'ja' });
      if (name === 'phone') {
        await page.locator('[data-testid="dh-fk-dh-table"]').scrollIntoViewIfNeeded();
        await page.screenshot({ path: join(OUT, 'dh-fk-phone-tables.png') });
      }
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
});
