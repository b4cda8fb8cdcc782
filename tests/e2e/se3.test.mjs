// The relative SE(3) pose page (#/se3-relative) in headless Chromium: the readouts are the
// `bsv se3-relative` CSV row for the defaults, for a URL with other values, after a typed field
// and after a drag of B's origin in the 3D view; the download equals `bsv` byte for byte; the
// rad/deg switch shows degrees while the URL, the command line and the CSV stay in radians; a
// bad value shows its message beside the field and keeps the last valid result; an orbit drag
// turns the view; Japanese leaves no English UI text. Screenshots (EN, JA in degrees,
// projector, phone 390 px) go to tests/e2e/out/.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { openApp, readouts, query, screenshots } from './harness.mjs';
import { serveAppWithCli, cliCsv, download, assertSameBytes } from './cli.mjs';
import { englishStrings } from './locales.mjs';

// The CLI is built and dist/ served before the tests; all is closed after them.
const server = serveAppWithCli();

const open = (hash, opts = {}) => openApp(server.url, hash, opts);
const NAMES = ['ax', 'ay', 'az', 'ar', 'ap', 'aw', 'bx', 'by', 'bz', 'br', 'bp', 'bw'];
const DEFAULTS = ['0', '0', '0', '0', '0', '0', '0.1', '0.05', '0.02', '0.2', '0.1', '-0.3'];
const KEYS = ['x', 'y', 'z', 'roll', 'pitch', 'yaw'];

/** `bsv se3-relative <args>`: the CSV bytes and its one row of numbers. */
function run(args) {
  const { bytes, rows } = cliCsv(['se3-relative', ...args], 'se3_relative.csv');
  return { bytes, row: rows[0].map(Number) };
}

/** The relative pose readouts' exact values (data-value). */
const pose = async (page) => {
  const r = await readouts(page, { numbers: true });
  return KEYS.map((k) => r[k]);
};

/** The twelve recipe arguments the URL holds (defaults filled in). */
async function urlArgs(page) {
  const q = await query(page);
  return NAMES.map((n, i) => q[n] ?? DEFAULTS[i]);
}

/** Waits for the debounced URL write. */
const settle = (page) => page.waitForTimeout(450);

test('defaults: readouts, CSV row and download equal bsv se3-relative', async () => {
  const { page, errors, close } = await open('#/se3-relative');
  try {
    const want = run([]);
    assert.deepEqual(await pose(page), want.row);
    assert.equal(await page.locator('[data-testid="se3-relative-row"]').innerText(), want.bytes.toString('utf8').trim().replace(/\r\n/g, '\n'));
    assertSameBytes(await download(page, 'se3_relative.csv'), want.bytes, 'defaults');
    assert.match(await page.locator('[data-testid="se3-cmd-bsv"]').innerText(), /^bsv se3-relative 0 0 0 0 0 0 0\.1 0\.05 0\.02 0\.2 0\.1 -0\.3$/);
    // T_A (T_A⁻¹ T_B) = T_B to rounding.
    assert.ok(Number(await page.locator('[data-readout="check-error"]').getAttribute('data-value')) < 1e-15);
    // The intrinsic x-y'-z'' reading of B's angles is another rotation.
    assert.ok(Number(await page.locator('[data-readout="rot-diff"]').getAttribute('data-value')) > 0.01);
    // The PNG of the view.
    const png = await download(page, 'se3_relative.png');
    assert.equal(png.subarray(1, 4).toString('latin1'), 'PNG');
    // The page's keys are in the ? overlay.
    await page.locator('h1').click();
    await page.keyboard.press('?');
    const overlay = await page.locator('[data-testid="shortcut-overlay"]').innerText();
    assert.match(overlay, /Switch the angles between radians and degrees/);
    assert.match(overlay, /Iso, top, front and side view/);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('a URL with other values: readouts and download equal bsv with the same arguments', async () => {
  const args = ['0.3', '-0.2', '0.1', '0.5', '-0.4', '1.2', '-0.2', '0.5', '0.05', '0.1', '-1.1', '-2.5'];
  const hash = '#/se3-relative?' + NAMES.map((n, i) => `${n}=${args[i]}`).join('&') + '&view=top';
  const { page, errors, close } = await open(hash);
  try {
    const want = run(args);
    assert.deepEqual(await pose(page), want.row);
    assertSameBytes(await download(page, 'se3_relative.csv'), want.bytes, 'URL values');
    assert.equal(await page.locator('[data-testid="se3-cmd-bsv"]').innerText(), `bsv se3-relative ${args.join(' ')}`);
    assert.equal(await page.locator('[data-testid="se3-relative-canvas"]').getAttribute('data-view'), 'top');
    assert.equal(await page.locator('[data-field="bp"]').inputValue(), '-1.1');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('a typed field changes the readouts as the kernel says; a bad value keeps the last result', async () => {
  const { page, errors, close } = await open('#/se3-relative');
  try {
    await page.locator('[data-field="az"]').fill('-0.25');
    await page.locator('[data-field="bw"]').fill('1.3');
    await settle(page);
    const args = await urlArgs(page);
    assert.equal(args[2], '-0.25');
    assert.equal(args[11], '1.3');
    const want = run(args);
    assert.deepEqual(await pose(page), want.row);
    // A bad value: its message beside the field, the result and the download stay.
    await page.locator('[data-field="by"]').fill('abc');
    const message = page.locator('[data-field-error="by"]');
    assert.ok(await message.isVisible());
    assert.match(await message.innerText(), /Frame B: y/);
    assert.equal(await page.locator('[data-field="by"]').getAttribute('aria-invalid'), 'true');
    assert.deepEqual(await pose(page), want.row);
    assertSameBytes(await download(page, 'se3_relative.csv'), want.bytes, 'last valid after a bad value');
    await settle(page);
    assert.deepEqual(await urlArgs(page), args, 'the URL keeps the last valid values');
    // Fixed: the message goes.
    await page.locator('[data-field="by"]').fill('0.05');
    assert.ok(!(await message.isVisible()));
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('degrees: fields and readouts in degrees, URL, command line and CSV in radians', async () => {
  const { page, errors, close } = await open('#/se3-relative');
  try {
    await page.locator('[data-angle-unit="deg"]').check();
    assert.equal(await page.locator('[data-field="br"]').inputValue(), '11.4591559026');
    assert.equal(await page.locator('[data-field="bx"]').inputValue(), '0.1', 'metres stay metres');
    assert.match(await page.locator('label[for="se3-f-br"]').innerText(), /°/);
    await page.locator('[data-field="ar"]').fill('30');
    await settle(page);
    const q = await query(page);
    assert.equal(q.angles, 'deg');
    assert.equal(q.ar, '0.5235987755982988');
    assert.equal(q.br, undefined, 'untouched angles keep their radians');
    const args = await urlArgs(page);
    const want = run(args);
    assert.deepEqual(await pose(page), want.row, 'exact values stay radians');
    const yawShown = Number(await page.locator('[data-readout="yaw"]').innerText());
    assert.ok(Math.abs(yawShown - (want.row[5] * 180) / Math.PI) < 1e-3, `${yawShown}`);
    assertSameBytes(await download(page, 'se3_relative.csv'), want.bytes, 'degree mode');
    assert.match(await page.locator('[data-testid="se3-cmd-bsv"]').innerText(), / 0\.5235987755982988 /);
    // Back to radians: the same values, in radians.
    await page.locator('[data-angle-unit="rad"]').check();
    assert.equal(await page.locator('[data-field="ar"]').inputValue(), '0.5235987755982988');
    assert.equal(await page.locator('[data-field="br"]').inputValue(), '0.2');
    // The `u` key switches too (focus on the view, not a field).
    await page.locator('[data-testid="se3-relative-canvas"]').focus();
    await page.keyboard.press('u');
    assert.equal(await page.locator('[data-field="ar"]').inputValue(), '30');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('dragging B\'s origin moves B in the view plane; the readouts follow the kernel; orbit turns the view', async () => {
  const { page, errors, close } = await open('#/se3-relative');
  try {
    const canvas = page.locator('[data-testid="se3-relative-canvas"]');
    await canvas.scrollIntoViewIfNeeded();
    const box = await canvas.boundingBox();
    const bx = box.x + Number(await canvas.getAttribute('data-b-x'));
    const by = box.y + Number(await canvas.getAttribute('data-b-y'));
    await page.mouse.move(bx, by);
    await page.mouse.down();
    for (let k = 1; k <= 10; k++) await page.mouse.move(bx + 6 * k, by - 4 * k);
    await page.mouse.up();
    await settle(page);
    const args = await urlArgs(page);
    assert.notDeepEqual(args.slice(6, 9), DEFAULTS.slice(6, 9), 'B moved');
    assert.deepEqual(args.slice(9), DEFAULTS.slice(9), 'B is not turned');
    assert.deepEqual(args.slice(0, 6), DEFAULTS.slice(0, 6), 'A stays');
    for (const [i, n] of [[6, 'bx'], [7, 'by'], [8, 'bz']]) {
      assert.equal(await page.locator(`[data-field="${n}"]`).inputValue(), args[i]);
    }
    const want = run(args);
    assert.deepEqual(await pose(page), want.row);
    assertSameBytes(await download(page, 'se3_relative.csv'), want.bytes, 'after a drag');
    // B's origin is drawn where the pointer let go (to the millimetre).
    const nx = box.x + Number(await canvas.getAttribute('data-b-x'));
    const ny = box.y + Number(await canvas.getAttribute('data-b-y'));
    assert.ok(Math.hypot(nx - (bx + 60), ny - (by - 40)) < 6, `${nx},${ny}`);
    // An orbit drag off the origins turns the view; the poses stay.
    const az = Number(await canvas.getAttribute('data-azimuth'));
    await canvas.scrollIntoViewIfNeeded();
    const view = await canvas.boundingBox();
    await page.mouse.move(view.x + 30, view.y + 30);
    await page.mouse.down();
    for (let k = 1; k <= 5; k++) await page.mouse.move(view.x + 30 + 20 * k, view.y + 30);
    await page.mouse.up();
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => r())));
    assert.ok(Math.abs(Number(await canvas.getAttribute('data-azimuth')) - az) > 0.5);
    await settle(page);
    assert.deepEqual(await urlArgs(page), args);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('dragging A\'s yaw ring changes A\'s yaw alone, to the kernel\'s numbers; in degrees to 0.1°', async () => {
  const { page, errors, close } = await open('#/se3-relative?angles=deg');
  try {
    const canvas = page.locator('[data-testid="se3-relative-canvas"]');
    await canvas.scrollIntoViewIfNeeded();
    const box = await canvas.boundingBox();
    const rx = box.x + Number(await canvas.getAttribute('data-a-ring-x'));
    const ry = box.y + Number(await canvas.getAttribute('data-a-ring-y'));
    await page.mouse.move(rx, ry);
    await page.mouse.down();
    for (let k = 1; k <= 8; k++) await page.mouse.move(rx + 5 * k, ry + 4 * k);
    await page.mouse.up();
    await settle(page);
    const args = await urlArgs(page);
    assert.notEqual(args[5], '0', 'A turned');
    assert.deepEqual(args.slice(0, 5), DEFAULTS.slice(0, 5), 'A stays put and keeps roll and pitch');
    assert.deepEqual(args.slice(6), DEFAULTS.slice(6), 'B stays');
    assert.match(await page.locator('[data-field="aw"]').inputValue(), /^-?\d+(\.\d)?$/, 'a round number of degrees');
    const want = run(args);
    assert.deepEqual(await pose(page), want.row);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('Japanese leaves no English UI text', async () => {
  const english = englishStrings();
  const { page, errors, close } = await open('#/se3-relative?lang=ja&angles=deg');
  try {
    await page.locator('[data-field="ap"]').fill('abc');
    const text = await page.evaluate(() => document.body.innerText);
    const left = english.filter((s) => text.includes(s));
    assert.deepEqual(left, [], `English left: ${left.join(' | ')}`);
    assert.match(text, /相対 SE\(3\) 姿勢/);
    assert.ok(await page.locator('[data-field-error="ap"]').isVisible());
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('screenshots: EN and JA 1920×1080, projector, phone 390 px', async () => {
  const shots = [
    ['se3-relative-en-1920.png', '#/se3-relative?aw=0.6&bx=0.15&by=0.1&bz=0.08', { viewport: { width: 1920, height: 1080 } }],
    ['se3-relative-ja-1920.png', '#/se3-relative?lang=ja&angles=deg&aw=0.6&bx=0.15&by=0.1&bz=0.08', { viewport: { width: 1920, height: 1080 } }],
    ['se3-relative-projector-1920.png', '#/se3-relative?aw=0.6&bx=0.15&by=0.1&bz=0.08', { viewport: { width: 1920, height: 1080 }, storage: { 'bsv.projector': '1' } }],
    ['se3-relative-phone-390.png', '#/se3-relative?lang=ja', { viewport: { width: 390, height: 844 } }],
  ];
  await screenshots(server.url, shots);
});
