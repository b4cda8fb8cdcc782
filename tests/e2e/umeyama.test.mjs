// The Umeyama page (#/umeyama-2d) in headless Chromium: dragging a point, a handle or a slider
// changes the readouts to the numbers of `bsv umeyama-2d` with the page's arguments (its CSV);
// the downloads equal `bsv` byte for byte for the defaults and for a URL with other values (an
// edited run's umeyama_points.csv too); bad values show their messages and the page keeps the
// last valid view; the stepper walks the fit's steps (the mirror preset shows the reflection
// fix); points are added and removed within the limits; Japanese leaves no English UI text.
// Screenshots (EN/JA 1920×1080, projector, phone 390 px) go to tests/e2e/out/.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { openApp, readouts, query, screenshots, OUT } from './harness.mjs';
import { serveAppWithCli, cliCsv, download, assertSameBytes } from './cli.mjs';
import { englishStrings } from './locales.mjs';

// The CLI is built and dist/ served before the tests; all is closed after them.
const server = serveAppWithCli();

/** Opens `hash`; resolves once the exports (the page's second stage) are in. */
async function open(hash, opts = {}) {
  const app = await openApp(server.url, hash, opts);
  await app.page.waitForSelector('[data-ume="later"]:not([hidden])', { state: 'attached', timeout: 15000 });
  return app;
}
const CSV = 'umeyama_2d.csv';
const POINTS = 'umeyama_points.csv';

/** `bsv umeyama-2d <args>`: the CSV's numbers by column name, and the files' bytes. */
function run(args) {
  const { head, rows, files, stdout } = cliCsv(['umeyama-2d', ...args], CSV);
  return { values: Object.fromEntries(head.map((k, i) => [k, Number(rows[0][i])])), files, stdout };
}

/** `data-readout` → exact value (data-value, a number) of the page. */
const pageValues = (page) => readouts(page, { numbers: true });

/** The readouts equal the CSV's estimate, exactly. */
function assertFit(r, values, label) {
  assert.deepEqual(
    [r.scale, r.angle, r.tx, r.ty, r.rmse],
    [values.scale, values.rotation_deg, values.tx, values.ty, values.rmse],
    label,
  );
}

/** The CLI arguments of the page's URL (the keys are the CLI's). */
function argsOf(q) {
  const args = [q.sigma ?? '0.02', q.seed ?? '3', q.n ?? '12'];
  for (const k of ['scale', 'angle', 'tx', 'ty', 'mirror', 'x']) if (q[k] !== undefined) args.push(`--${k}`, q[k]);
  return args;
}

const canvas = (page) => page.locator('[data-testid="umeyama-2d-canvas"]');
const pixels = (page) => canvas(page).evaluate((c) => c.toDataURL());
const pointsPx = (page) => canvas(page).evaluate((c) => c.dataset.pointsPx.split(';').map((p) => p.split(',').map(Number)));

/** Sets a slider as a drag does (value, then an input event). */
async function slide(page, name, value) {
  await page.locator(`[data-slider="${name}"]`).evaluate((el, v) => {
    el.value = v;
    el.dispatchEvent(new Event('input', { bubbles: true }));
  }, String(value));
}

/** Drags with the mouse from canvas px `from` by `(dx, dy)` in `steps` moves. */
async function drag(page, from, dx, dy, steps = 10) {
  await canvas(page).scrollIntoViewIfNeeded();
  const box = await canvas(page).boundingBox();
  await page.mouse.move(box.x + from[0], box.y + from[1]);
  await page.mouse.down();
  for (let k = 1; k <= steps; k++) await page.mouse.move(box.x + from[0] + (dx * k) / steps, box.y + from[1] + (dy * k) / steps);
  await page.mouse.up();
}

test('opens on the recipe\'s fit with its numbers, ready to step', async () => {
  const { values } = run([]);
  const { page, errors, close } = await open('#/umeyama-2d');
  try {
    const r = await pageValues(page);
    assertFit(r, values, 'defaults');
    assert.deepEqual([r['scale-true'], r['angle-true'], r['tx-true'], r['ty-true']], [1.3, 35, 0.4, -0.2]);
    assert.equal((await pointsPx(page)).length, 12);
    assert.equal(await page.locator('[data-testid="umeyama-2d-edited"]').isVisible(), false);
    assert.equal(await page.locator(`[data-download="${POINTS}"]`).isVisible(), false);
    assert.match(await page.locator('[data-testid="umeyama-2d-step"] h3').innerText(), /^The whole fit$/);
    assert.equal(await page.locator('[data-cmd="bsv"]').innerText(), 'bsv umeyama-2d 0.02 3 12');
    assert.equal(await page.locator('[data-cmd="python"]').innerText(), 'python umeyama_align_2d.py 0.02 3 12');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('dragging a point changes the readouts to the kernel\'s; the edited run exports its points', async () => {
  const { page, errors, close } = await open('#/umeyama-2d');
  try {
    const before = await pageValues(page);
    const px = await pointsPx(page);
    await drag(page, px[0], 60, -40);
    await page.waitForFunction(() => /[?&]x=/.test(location.hash), null, { timeout: 3000 });
    const q = await query(page);
    assert.equal(q.x.split(';').length, 12);
    const { values, files } = run(argsOf(q));
    const r = await pageValues(page);
    assertFit(r, values, `after the drag: ${JSON.stringify(q)}`);
    assert.notEqual(r.scale, before.scale);
    assert.equal(await page.locator('[data-testid="umeyama-2d-edited"]').isVisible(), true);
    assert.equal(await page.locator('[data-field="x"]').inputValue(), q.x);
    // Both downloads are the CLI's with the options, and the command line carries them.
    assertSameBytes(await download(page, CSV), files.get(CSV), 'csv after the drag');
    assertSameBytes(await download(page, POINTS), files.get(POINTS), 'points after the drag');
    const bsv = await page.locator('[data-cmd="bsv"]').innerText();
    assert.equal(bsv, `bsv umeyama-2d 0.02 3 12 --x '${q.x}'`);
    // The rotation handle turns the truth: angle and scale follow, the readouts too.
    const h = await canvas(page).evaluate((c) => c.dataset.handleR.split(',').map(Number));
    await drag(page, h, -50, -60);
    await page.waitForFunction(() => /[?&]angle=/.test(location.hash), null, { timeout: 3000 });
    const q2 = await query(page);
    assert.notEqual(Number(q2.angle), 35);
    assertFit(await pageValues(page), run(argsOf(q2)).values, 'after the rotation handle');
    // A slider: sigma 0.2 runs the kernel again.
    await slide(page, 'sigma', 0.2);
    assert.equal(await page.locator('[data-field="sigma"]').inputValue(), '0.2');
    assertFit(await pageValues(page), run(argsOf({ ...q2, sigma: '0.2' })).values, 'after the sigma slider');
    // Back to the recipe: the edited notice goes, the download is the recipe's again.
    await page.locator('[data-action="recipe"]').click();
    assert.equal(await page.locator('[data-testid="umeyama-2d-edited"]').isVisible(), false);
    assertFit(await pageValues(page), run(['0.2']).values, 'the recipe again');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('the downloads equal bsv for the defaults and for a URL with other values', async () => {
  const cases = [
    ['#/umeyama-2d', [], 'bsv umeyama-2d 0.02 3 12', false],
    ['#/umeyama-2d?sigma=0.1&seed=7&n=20', ['0.1', '7', '20'], 'bsv umeyama-2d 0.1 7 20', false],
    ['#/umeyama-2d?sigma=0.05&seed=11&n=5&scale=0.7&angle=-120&tx=1&ty=2&mirror=yes',
      ['0.05', '11', '5', '--scale', '0.7', '--angle', '-120', '--tx', '1', '--ty', '2', '--mirror', 'yes'],
      'bsv umeyama-2d 0.05 11 5 --scale 0.7 --angle -120 --tx 1 --ty 2 --mirror yes', true],
  ];
  for (const [hash, args, line, edited] of cases) {
    const { files, values } = run(args);
    const { page, errors, close } = await open(hash);
    try {
      assertSameBytes(await download(page, CSV), files.get(CSV), hash);
      if (edited) assertSameBytes(await download(page, POINTS), files.get(POINTS), `${hash} points`);
      else assert.equal(files.has(POINTS), false);
      assert.equal(await page.locator('[data-cmd="bsv"]').innerText(), line);
      assertFit(await pageValues(page), values, hash);
      assert.equal(await page.locator('[data-testid="umeyama-2d-edited"]').isVisible(), edited);
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
});

test('bad values show their messages and the page keeps the last valid view', async () => {
  const { files } = run([]);
  const { page, errors, close } = await open('#/umeyama-2d');
  try {
    const view = await pixels(page);
    const shown = await pageValues(page);
    for (const [field, bad, pattern] of [
      ['sigma', '-1', /0 or more|at least 0|between/],
      ['n', '1', /between 2 and 100,000/],
      ['scale', '0', /more than 0|greater than zero|between/],
      ['x', '1,2;3', /2 values/],
      ['angle', 'abc', /not a number/],
    ]) {
      const input = page.locator(`[data-field="${field}"]`);
      const message = page.locator(`[data-field-error="${field}"]`);
      const was = await input.inputValue();
      await input.fill(bad);
      assert.equal(await message.isVisible(), true, `${field}=${bad}`);
      assert.match(await message.innerText(), pattern, `${field}=${bad}`);
      assert.equal(await input.getAttribute('aria-invalid'), 'true');
      assert.equal(await pixels(page), view, `${field}=${bad}: the view is the last valid one`);
      assert.deepEqual(await pageValues(page), shown);
      assertSameBytes(await download(page, CSV), files.get(CSV), `${field}=${bad}`);
      await input.fill(was);
      assert.equal(await message.isVisible(), false, `${field} restored`);
    }
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('the stepper walks the fit; the mirror preset shows the reflection fix', async () => {
  const { page, errors, close } = await open('#/umeyama-2d');
  try {
    await canvas(page).focus();
    const titles = [];
    const mats = [];
    for (let k = 0; k < 8; k++) {
      await page.keyboard.press('ArrowRight');
      titles.push(await page.locator('[data-testid="umeyama-2d-step"] h3').innerText());
      mats.push(await page.locator('[data-ume="step-mats"]').getAttribute('data-step'));
    }
    assert.deepEqual(mats, ['centroids', 'centred', 'covariance', 'svd', 'reflection', 'scale', 'translation', 'rmse']);
    assert.match(titles[0], /^Centroids$/);
    assert.match(titles[7], /^Residual error$/);
    await page.waitForFunction(() => /step=8/.test(location.hash), null, { timeout: 3000 });
    // The rmse step shows the CSV's rmse.
    const rmse = await page.locator('[data-ume="step-mats"] td').first().getAttribute('data-value');
    assert.equal(Number(rmse), run([]).values.rmse);
    // Back to the reflection step: no fix needed for the recipe's data.
    for (let k = 0; k < 3; k++) await page.keyboard.press('ArrowLeft');
    assert.match(await page.locator('[data-ume="step-text"]').innerText(), /= \+1/);
    // The mirror preset: det(UVᵀ) = −1, the fix shown, the recipe's quirk in the scale step.
    await page.locator('[data-action="mirror"]').click();
    assert.equal(await page.locator('[data-ume="step-mats"]').getAttribute('data-step'), 'reflection');
    assert.match(await page.locator('[data-ume="step-text"]').innerText(), /= −1/);
    assert.equal(Number(await page.locator('[data-ume="step-mats"] td').first().getAttribute('data-value')), -1);
    await canvas(page).focus();
    await page.keyboard.press('ArrowRight');
    assert.match(await page.locator('[data-ume="step-text"]').innerText(), /Umeyama’s method would use S₁ − S₂/);
    assertFit(await pageValues(page), run(['0.02', '3', '12', '--mirror', 'yes']).values, 'mirrored');
    // Keys in a field do not step.
    await page.locator('[data-field="seed"]').focus();
    await page.keyboard.press('ArrowRight');
    assert.equal(await page.locator('[data-ume="step-mats"]').getAttribute('data-step'), 'scale');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('points are added by a click and removed with Delete, within 2 to 40', async () => {
  const { page, errors, close } = await open('#/umeyama-2d?sigma=0&n=3');
  try {
    await canvas(page).scrollIntoViewIfNeeded();
    const box = await canvas(page).boundingBox();
    // A click on empty space (a corner of the view) adds a point there.
    await page.mouse.click(box.x + 20, box.y + 20);
    assert.equal((await pointsPx(page)).length, 4);
    await page.waitForFunction(() => /n=4/.test(location.hash), null, { timeout: 3000 });
    const q = await query(page);
    assertFit(await pageValues(page), run(argsOf(q)).values, 'after the click');
    // Delete removes the selected (new) point; the last two cannot go.
    await canvas(page).focus();
    await page.keyboard.press('Delete');
    await page.keyboard.press('Delete');
    assert.equal((await pointsPx(page)).length, 2);
    await page.keyboard.press('Delete');
    assert.equal((await pointsPx(page)).length, 2);
    const message = page.locator('[data-testid="umeyama-2d-message"]');
    assert.equal(await message.isVisible(), true);
    assert.match(await message.innerText(), /at least 2 points/);
    // The button adds up to 40.
    for (let k = 0; k < 38; k++) await page.locator('[data-action="add"]').click();
    assert.equal((await pointsPx(page)).length, 40);
    await page.locator('[data-action="add"]').click();
    assert.match(await message.innerText(), /already 40 points/);
    assertFit(await pageValues(page), run(argsOf(await query(page))).values, '40 points');
    // A new n draws the recipe's points again.
    await page.locator('[data-field="n"]').fill('6');
    await page.waitForFunction(() => !/[?&]x=/.test(location.hash) && /n=6/.test(location.hash), null, { timeout: 3000 });
    assertFit(await pageValues(page), run(['0', '3', '6']).values, 'n = 6');
    assert.equal(await page.locator('[data-testid="umeyama-2d-edited"]').isVisible(), false);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

/** `v` on the grid `step` as the page's editor puts it (view::umeyama_2d::snap_to). */
function snap(v, step) {
  const digits = Math.max(0, -Math.floor(Math.log10(step)));
  const s = Number((Math.sign(v) * Math.round(Math.abs(v) / step) * step).toFixed(digits));
  return s === 0 ? 0 : s;
}

/** The points of an `umeyama_points.csv` (its x, y columns). */
const pointsOf = (bytes) => bytes.toString('utf8').trim().split('\n').slice(1).map((l) => l.split(',').slice(0, 2).map(Number));

/** The text `--x` takes. */
const xText = (points) => points.map(([a, b]) => `${a},${b}`).join(';');

/** Whether the selection ring (amber, 9 px out) is drawn around point `i` of the view. */
const ringAt = (page, i) => canvas(page).evaluate((c, i) => {
  const [x, y] = c.dataset.pointsPx.split(';')[i].split(',').map(Number);
  const dpr = c.width / c.getBoundingClientRect().width;
  const ctx = c.getContext('2d');
  let amber = 0;
  for (let a = 0; a < 360; a += 15) {
    const t = (a * Math.PI) / 180;
    const [r, g, b] = ctx.getImageData(Math.round((x + 9 * Math.cos(t)) * dpr), Math.round((y + 9 * Math.sin(t)) * dpr), 1, 1).data;
    if (Math.abs(r - 245) < 30 && Math.abs(g - 158) < 40 && b < 80) amber++;
  }
  return amber >= 12;
}, i);

test('by keyboard: n selects point 3, Shift + arrows move it as a drag does (x, readouts, exports = bsv), Delete removes it', async () => {
  // The recipe's points X at full precision: an option that changes only the truth makes bsv
  // write them; the editor holds them on its 0.001 grid.
  const editor = pointsOf(run(['0.02', '3', '12', '--tx', '0.5']).files.get(POINTS)).map(([a, b]) => [snap(a, 0.001), snap(b, 0.001)]);
  const { page, errors, close } = await open('#/umeyama-2d');
  try {
    const status = page.locator('[data-testid="umeyama-2d-selection"]');
    assert.equal(await status.getAttribute('role'), 'status');
    assert.equal(await status.getAttribute('aria-live'), 'polite');
    assert.equal(await status.innerText(), 'No point selected (12 points). Press n to select the next point, Shift + n the previous one.');
    await canvas(page).focus();
    for (let k = 0; k < 3; k++) await page.keyboard.press('n');
    await page.keyboard.press('Shift+N');
    assert.equal(await canvas(page).getAttribute('data-selected'), '1', 'Shift + n: the previous point');
    await page.keyboard.press('n');
    assert.equal(await canvas(page).getAttribute('data-selected'), '2');
    const said = (p) => `Point 3 of 12 selected, at (${p[0]}, ${p[1]}). Shift + arrows move it by 0.01; Delete removes it.`;
    assert.equal(await status.innerText(), said(editor[2]));
    assert.equal(await ringAt(page, 2), true, 'the selection ring around point 3');
    assert.equal(await ringAt(page, 0), false, 'no ring around point 1');
    assert.equal(await page.locator('[data-field="x"]').inputValue(), '', 'selecting edits nothing');

    // Shift + arrows: the first step lands on the drag grid (0.01), each next one moves 0.01.
    let p = editor[2];
    for (const [key, dx, dy] of [['ArrowRight', 1, 0], ['ArrowRight', 1, 0], ['ArrowRight', 1, 0], ['ArrowUp', 0, 1], ['ArrowUp', 0, 1]]) {
      await page.keyboard.press(`Shift+${key}`);
      p = [snap(p[0] + dx * 0.01, 0.01), snap(p[1] + dy * 0.01, 0.01)];
    }
    const moved = editor.map((q, i) => (i === 2 ? p : q));
    const x = xText(moved);
    await page.waitForFunction((x) => new URLSearchParams(location.hash.split('?')[1]).get('x') === x, x, { timeout: 3000 });
    assert.equal(await page.locator('[data-field="x"]').inputValue(), x);
    const { values, files } = run(['0.02', '3', '12', '--x', x]);
    assertFit(await pageValues(page), values, `moved by keys: ${x}`);
    assertSameBytes(await download(page, CSV), files.get(CSV), 'csv after the key moves');
    assertSameBytes(await download(page, POINTS), files.get(POINTS), 'points after the key moves');
    assert.equal(await page.locator('[data-cmd="bsv"]').innerText(), `bsv umeyama-2d 0.02 3 12 --x '${x}'`);
    assert.equal(await page.locator('[data-testid="umeyama-2d-edited"]').isVisible(), true);
    await page.waitForFunction(([el, text]) => el.textContent === text, [await status.elementHandle(), said(p)], { timeout: 3000 });
    assert.equal(await ringAt(page, 2), true, 'the ring follows the point');

    // A key held down: ten moves in one burst change the status line once, after they settle.
    await page.evaluate(() => {
      const el = document.querySelector('[data-testid="umeyama-2d-selection"]');
      window.__selectionSaid = [];
      new MutationObserver(() => window.__selectionSaid.push(el.textContent)).observe(el, { childList: true, characterData: true, subtree: true });
      const c = document.querySelector('[data-testid="umeyama-2d-canvas"]');
      for (let k = 0; k < 10; k++) c.dispatchEvent(new KeyboardEvent('keydown', { key: 'ArrowDown', shiftKey: true, bubbles: true, cancelable: true }));
    });
    assert.deepEqual(await page.evaluate(() => window.__selectionSaid), [], 'nothing said while the key moves');
    p = [p[0], snap(p[1] - 0.1, 0.01)];
    await page.waitForFunction(() => window.__selectionSaid.length > 0, null, { timeout: 3000 });
    await page.waitForTimeout(500);
    assert.deepEqual(await page.evaluate(() => window.__selectionSaid), [said(p)]);
    const x2 = xText(editor.map((q, i) => (i === 2 ? p : q)));
    assert.equal(await page.locator('[data-field="x"]').inputValue(), x2);
    assertFit(await pageValues(page), run(['0.02', '3', '12', '--x', x2]).values, `after the burst: ${x2}`);

    // Page keys do nothing while a control has focus.
    await page.locator('[data-action="mirror"]').focus();
    for (const key of ['n', 'Shift+ArrowRight', 'Delete']) await page.keyboard.press(key);
    assert.equal(await canvas(page).getAttribute('data-selected'), '2');
    assert.equal(await page.locator('[data-field="x"]').inputValue(), x2);

    // Delete removes point 3: 11 points, none selected.
    await canvas(page).focus();
    await page.keyboard.press('Delete');
    const left = xText(editor.filter((_, i) => i !== 2));
    await page.waitForFunction((x) => /[?&]n=11/.test(location.hash) && new URLSearchParams(location.hash.split('?')[1]).get('x') === x, left, { timeout: 3000 });
    assert.equal(await page.locator('[data-field="x"]').inputValue(), left);
    assert.equal((await pointsPx(page)).length, 11);
    assertFit(await pageValues(page), run(['0.02', '3', '11', '--x', left]).values, 'after Delete');
    assert.equal(await status.innerText(), 'No point selected (11 points). Press n to select the next point, Shift + n the previous one.');
    assert.equal(await canvas(page).getAttribute('data-selected'), '');

    // The ? overlay lists the keys.
    await page.keyboard.press('?');
    const keys = await page.locator('[data-testid="page-keys"]').innerText();
    assert.match(keys, /n\s+Shift \+ n\s+Select the next point, then the translation handle t, then the rotation handle s·R \(Shift \+ n: the previous one\)/);
    assert.match(keys, /Shift \+ ← ↑ → ↓\s+Move the selected point or t by 0\.01, as a drag does; turn s·R by 0\.5° \(← →\) or scale it by 0\.01 \(↑ ↓\)/);
    await page.keyboard.press('Escape');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
  // In Japanese: the status line and the keys.
  const { page: ja, errors: jaErrors, close: closeJa } = await open('#/umeyama-2d?lang=ja');
  try {
    await canvas(ja).focus();
    // Back from none: the rotation handle, the translation handle, then the last point.
    for (let k = 0; k < 3; k++) await ja.keyboard.press('Shift+N');
    const text = await ja.locator('[data-testid="umeyama-2d-selection"]').innerText();
    assert.equal(text, `点 12（全 12 点）を選択中：位置 (${editor[11][0]}, ${editor[11][1]})。Shift + 矢印キーで 0.01 ずつ動かし、Delete で削除できます。`);
    await ja.keyboard.press('?');
    assert.match(await ja.locator('[data-testid="page-keys"]').innerText(), /次の点を選ぶ。最後の点の次は平行移動のハンドル t、その次は回転のハンドル s·R（Shift \+ n で前へ）/);
    assert.deepEqual(jaErrors, []);
  } finally {
    await closeJa();
  }
});

test('by keyboard: n goes on to the translation and rotation handles; Shift + arrows move t, turn and scale s·R as a drag does (fields, readouts = bsv)', async () => {
  const { page, errors, close } = await open('#/umeyama-2d');
  try {
    const field = async (name) => page.locator(`[data-field="${name}"]`).inputValue();
    const status = page.locator('[data-testid="umeyama-2d-selection"]');
    await canvas(page).focus();
    for (let k = 0; k < 13; k++) await page.keyboard.press('n');
    assert.equal(await canvas(page).getAttribute('data-selected'), 't', 'after the 12 points: the translation handle');
    const [tx, ty] = [Number(await field('tx')), Number(await field('ty'))];
    assert.equal(await status.innerText(), `Translation handle t selected, at (${tx}, ${ty}). Shift + arrows move it by 0.01.`);
    for (const key of ['ArrowRight', 'ArrowRight', 'ArrowUp']) await page.keyboard.press(`Shift+${key}`);
    const [tx2, ty2] = [snap(snap(tx + 0.01, 0.01) + 0.01, 0.01), snap(ty + 0.01, 0.01)];
    assert.deepEqual([Number(await field('tx')), Number(await field('ty'))], [tx2, ty2]);
    await page.keyboard.press('n');
    assert.equal(await canvas(page).getAttribute('data-selected'), 'r');
    const [angle, scale] = [Number(await field('angle')), Number(await field('scale'))];
    assert.equal(await status.innerText(), `Rotation handle s·R selected: angle ${angle}°, scale ${scale}. Shift + ← → turn it by 0.5°, Shift + ↑ ↓ scale it by 0.01.`);
    for (const key of ['ArrowRight', 'ArrowUp', 'ArrowUp']) await page.keyboard.press(`Shift+${key}`);
    assert.deepEqual([Number(await field('angle')), Number(await field('scale'))], [snap(angle + 0.5, 0.5), snap(snap(scale + 0.01, 0.01) + 0.01, 0.01)]);
    assert.deepEqual([Number(await field('tx')), Number(await field('ty'))], [tx2, ty2], 'turning s·R keeps t');
    const args = ['0.02', '3', '12', '--scale', await field('scale'), '--angle', await field('angle'), '--tx', await field('tx'), '--ty', await field('ty')];
    assertFit(await pageValues(page), run(args).values, `handles moved by keys: ${args.join(' ')}`);
    // And round again: the first point.
    await page.keyboard.press('n');
    assert.equal(await canvas(page).getAttribute('data-selected'), '0');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('Japanese leaves no English UI text', async () => {
  const english = englishStrings();
  for (const hash of ['#/umeyama-2d?lang=ja&step=5&mirror=yes', '#/umeyama-2d?lang=ja&step=6']) {
    const { page, errors, close } = await open(hash);
    try {
      await page.locator('[data-field="sigma"]').fill('abc');
      await page.locator('[data-action="remove"]').click();
      const text = await page.evaluate(() => document.body.innerText);
      const left = english.filter((s) => text.includes(s));
      assert.deepEqual(left, [], `${hash}: English left: ${left.join(' | ')}`);
      assert.match(text, /Umeyama 法の位置合わせ/);
      assert.ok(await page.locator('[data-field-error="sigma"]').isVisible());
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
});

test('screenshots: EN and JA 1920×1080, projector, phone 390 px', async () => {
  const shots = [
    ['umeyama-en-1920.png', '#/umeyama-2d', { viewport: { width: 1920, height: 1080 } }],
    ['umeyama-ja-1920.png', '#/umeyama-2d?lang=ja&step=4', { viewport: { width: 1920, height: 1080 } }],
    ['umeyama-mirror-en-1920.png', '#/umeyama-2d?mirror=yes&step=5', { viewport: { width: 1920, height: 1080 } }],
    ['umeyama-projector-1920.png', '#/umeyama-2d?step=6', { viewport: { width: 1920, height: 1080 }, storage: { 'bsv.projector': '1' } }],
    ['umeyama-phone-390.png', '#/umeyama-2d?lang=ja&step=1', { viewport: { width: 390, height: 844 } }],
  ];
  await screenshots(server.url, shots);
});

test('a huge sigma (1e308: targets near ±1e308 and infinite) leaves the page working, with the CLI\'s nan fit and bytes', async () => {
  const { files } = run(['1e308']);
  const { page, errors, close } = await open('#/umeyama-2d');
  try {
    await page.locator('[data-field="sigma"]').evaluate((e) => {
      e.value = '1e308';
      e.dispatchEvent(new Event('input', { bubbles: true }));
    });
    await page.waitForFunction(() => document.querySelector('[data-cmd="bsv"]')?.innerText === 'bsv umeyama-2d 1e308 3 12');
    // The tab did not hang or die: it still answers, and draws a frame.
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => r())));
    assertSameBytes(await download(page, CSV), files.get(CSV), 'sigma 1e308');
    // Back to a small sigma: the fit and the grid come back.
    await slide(page, 'sigma', '0.02');
    await page.waitForFunction(() => document.querySelector('[data-cmd="bsv"]')?.innerText === 'bsv umeyama-2d 0.02 3 12');
    assertFit(await pageValues(page), run([]).values, 'back to the default');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('the axes carry tick labels of round values, placed on the grid and inside the canvas', async () => {
  const { page, errors, close } = await open('#/umeyama-2d', { viewport: { width: 1366, height: 768 } });
  try {
    await page.waitForSelector('[data-testid="umeyama-2d-canvas"][data-ticks-x]');
    const { ticks, w, h } = await canvas(page).evaluate((c) => ({
      ticks: [c.dataset.ticksX, c.dataset.ticksY].map((t) => t.split(';').filter(Boolean).map((v) => v.split('@').map(Number))),
      w: c.clientWidth,
      h: c.clientHeight,
    }));
    for (const [axis, list, size] of [['x', ticks[0], w], ['y', ticks[1], h]]) {
      assert.ok(list.length >= 3, `${axis} ticks: ${JSON.stringify(list)}`);
      const step = list[1][0] - list[0][0];
      const px = list[1][1] - list[0][1];
      for (const [i, [v, at]] of list.entries()) {
        assert.ok(Number.isFinite(v) && at > 0 && at < size, `${axis} tick ${v} at ${at}`);
        // Evenly spaced values and pixels: the labels sit on the grid.
        assert.ok(Math.abs(v - list[0][0] - i * step) < 1e-9 * Math.max(1, Math.abs(v)), `${axis} tick ${v}`);
        assert.ok(Math.abs(at - list[0][1] - i * px) < 1, `${axis} tick ${v} at ${at}`);
      }
      // Round values: 1, 2 or 5 times a power of ten apart.
      const mant = Math.abs(step) / 10 ** Math.floor(Math.log10(Math.abs(step)));
      assert.ok([1, 2, 5, 10].some((m) => Math.abs(mant - m) < 1e-6), `${axis} step ${step}`);
    }
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('projector mode at 1280×800: the estimate table fits its card, the Truth column whole', async () => {
  for (const lang of ['en', 'ja']) {
    const { page, errors, close } = await open(`#/umeyama-2d?lang=${lang}`, { viewport: { width: 1280, height: 800 }, storage: { 'bsv.projector': '1' } });
    try {
      assert.equal(await page.evaluate(() => document.documentElement.classList.contains('projector')), true);
      const fit = await page.locator('[data-testid="umeyama-2d-readouts"]').evaluate((table) => {
        const card = table.closest('.sig-card').getBoundingClientRect();
        const cells = [...table.querySelectorAll('th, td')].map((c) => c.getBoundingClientRect().right);
        return { card: card.right, table: table.getBoundingClientRect().right, cells: Math.max(...cells), page: document.documentElement.scrollWidth };
      });
      assert.ok(fit.table <= fit.card && fit.cells <= fit.card, `${lang}: ${JSON.stringify(fit)}`);
      assert.ok(fit.page <= 1280, `${lang}: the page is ${fit.page} px wide`);
      // Every cell is at least the projector's 24 px type.
      const smallest = await page.locator('[data-testid="umeyama-2d-readouts"] td').evaluateAll((tds) => Math.min(...tds.map((td) => parseFloat(getComputedStyle(td).fontSize))));
      assert.ok(smallest >= 24, `${lang}: ${smallest} px`);
      await page.screenshot({ path: join(OUT, `umeyama-projector-1280-${lang}.png`) });
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
});
