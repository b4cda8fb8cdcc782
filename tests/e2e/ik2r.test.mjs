// The Planar 2R IK page (#/ik-2r) in headless Chromium: dragging the tip gives the IK solution
// of the pointer (checked against the formulas of src/planar2r.rs, re-done here in JS), the
// heatmap marker follows, the elbow switch flips q2, links turn one joint, out-of-reach points
// are pinned with a note; every download equals the `bsv` CLI's output byte for byte; Japanese
// leaves no English UI string; invalid values are flagged beside their field while the arm
// keeps working; a URL restores the state; keys; heatmap clicks; a phone-sized touch drag.
// Screenshots (1920×1080 English and Japanese, 390×844 phone) go to tests/e2e/out/.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { existsSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { openApp, OUT, ROOT, readouts } from './harness.mjs';
import { serveAppWithCli, cli, download, assertSameBytes } from './cli.mjs';
import { englishStrings } from './locales.mjs';

// The CLI is built and dist/ served before the tests; all is closed after them.
const server = serveAppWithCli();

// ---------- The kinematics of src/planar2r.rs, in JS ----------

const L1 = 0.12;
const L2 = 0.10;

function ik(x, y, l1, l2, elbowUp = false) {
  const c2 = (x * x + y * y - l1 * l1 - l2 * l2) / (2 * l1 * l2);
  if (!(Math.abs(c2) <= 1)) return null;
  let q2 = Math.acos(Math.min(1, Math.max(-1, c2)));
  if (elbowUp) q2 = -q2;
  const q1 = Math.atan2(y, x) - Math.atan2(l2 * Math.sin(q2), l1 + l2 * Math.cos(q2));
  return { q1, q2 };
}

function fk(q1, q2, l1, l2) {
  return [l1 * Math.cos(q1) + l2 * Math.cos(q1 + q2), l1 * Math.sin(q1) + l2 * Math.sin(q1 + q2)];
}

function jacobian(q1, q2, l1, l2) {
  const s1 = Math.sin(q1), c1 = Math.cos(q1), s12 = Math.sin(q1 + q2), c12 = Math.cos(q1 + q2);
  return [[-l1 * s1 - l2 * s12, -l2 * s12], [l1 * c1 + l2 * c12, l2 * c12]];
}

function singularValues([[a, b], [c, d]]) {
  const q = Math.hypot((a + d) / 2, (c - b) / 2);
  const r = Math.hypot((a - d) / 2, (c + b) / 2);
  const smax = q + r;
  return [smax > 0 ? Math.abs(a * d - b * c) / smax : 0, smax];
}

function wrap(q) {
  let w = ((q + Math.PI) % (2 * Math.PI) + 2 * Math.PI) % (2 * Math.PI) - Math.PI;
  return w <= -Math.PI ? w + 2 * Math.PI : w;
}

/** Everything the readouts should show for a pose. */
function expected(q1, q2, l1 = L1, l2 = L2) {
  const [x, y] = fk(q1, q2, l1, l2);
  const J = jacobian(q1, q2, l1, l2);
  const det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
  const [smin, smax] = singularValues(J);
  return {
    q1, q2, x_mm: x * 1000, y_mm: y * 1000, det_j: det, manipulability: Math.abs(det),
    sigma_min: smin, sigma_max: smax, j11: J[0][0], j12: J[0][1], j21: J[1][0], j22: J[1][1],
  };
}

// ---------- Page helpers ----------

const READOUTS = ['q1', 'q2', 'q1_deg', 'q2_deg', 'x_mm', 'y_mm', 'det_j', 'manipulability',
  'sigma_min', 'sigma_max', 'j11', 'j12', 'j21', 'j22'];

/** The READOUTS as shown, as numbers (NaN where one is missing). */
async function shownNumbers(page) {
  const r = await readouts(page, { text: true });
  return Object.fromEntries(READOUTS.map((n) => [n, Number(r[n] ?? NaN)]));
}

/**
 * Readouts match `exp`: angles to 1e-6 rad, mm to 1e-3, the rest to 6 significant digits.
 * `loose` widens the tolerances when `exp` itself was computed from rounded readouts.
 */
function assertReadouts(got, exp, label = '', loose = 1) {
  const close = (name, tol) => assert.ok(Math.abs(got[name] - exp[name]) <= tol * loose,
    `${label} ${name}: page ${got[name]} vs expected ${exp[name]}`);
  close('q1', 1e-6);
  close('q2', 1e-6);
  close('x_mm', 1e-3);
  close('y_mm', 1e-3);
  for (const n of ['det_j', 'manipulability', 'sigma_min', 'sigma_max', 'j11', 'j12', 'j21', 'j22']) {
    close(n, Math.abs(exp[n]) * 1e-5 + 1e-12);
  }
  assert.ok(Math.abs(got.q1_deg - (exp.q1 * 180) / Math.PI) <= 1e-3 * loose, `${label} q1_deg`);
  assert.ok(Math.abs(got.q2_deg - (exp.q2 * 180) / Math.PI) <= 1e-3 * loose, `${label} q2_deg`);
}

/** Arm canvas geometry: its client rect, the base on screen and the scale (px per m). */
async function armGeometry(page) {
  return page.evaluate(() => {
    const c = document.querySelector('[data-testid="ik-2r-canvas"]');
    const r = c.getBoundingClientRect();
    const d = c.dataset;
    return {
      left: r.left, top: r.top, width: r.width, height: r.height,
      ox: +d.originX, oy: +d.originY, s: +d.pxPerM,
      tipX: +d.tipX, tipY: +d.tipY, elbowX: +d.elbowX, elbowY: +d.elbowY,
    };
  });
}

/** The world point (m) under client pixel (cx, cy). */
function worldAt(g, cx, cy) {
  return [(cx - g.left - g.ox) / g.s, -(cy - g.top - g.oy) / g.s];
}

/** Integer client pixel nearest to world point (x, y). */
function clientAt(g, x, y) {
  return [Math.round(g.left + g.ox + x * g.s), Math.round(g.top + g.oy - y * g.s)];
}

async function settle(page) {
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
}

/** Presses at client (fx, fy), moves in steps to (tx, ty) and optionally releases. */
async function drag(page, [fx, fy], [tx, ty], { release = true } = {}) {
  await page.mouse.move(fx, fy);
  await page.mouse.down();
  await page.mouse.move(tx, ty, { steps: 6 });
  await settle(page);
  if (release) {
    await page.mouse.up();
    await settle(page);
  }
}

async function dragTipTo(page, target) {
  const g = await armGeometry(page);
  await drag(page, [Math.round(g.left + g.tipX), Math.round(g.top + g.tipY)], target);
}

async function marker(page) {
  return page.evaluate(() => {
    const d = document.querySelector('[data-testid="ik-2r-heatmap"]').dataset;
    return { q1: +d.markerQ1, q2: +d.markerQ2 };
  });
}

async function openIk(hash = '#/ik-2r', opts = {}) {
  const app = await openApp(server.url, hash, { viewport: { width: 1920, height: 1080 }, ...opts });
  await app.page.waitForSelector('[data-testid="ik-2r-canvas"][data-tip-x]');
  // The heatmap, plot, form and downloads (the page's second stage) are in.
  await app.page.waitForSelector('[data-testid="ik-2r-heatmap"][data-marker-q1]');
  await settle(app.page);
  return app;
}

// ---------- Tests ----------

test('dragging the tip gives the IK of the pointer; the marker follows; the elbow flips q2', async () => {
  const { page, errors, close } = await openIk();
  try {
    // Defaults: q1 = 0.3, q2 = 0.8.
    assertReadouts(await shownNumbers(page), expected(0.3, 0.8), 'initial');

    const g = await armGeometry(page);
    let last;
    for (const [x, y] of [[0.15, 0.05], [-0.08, 0.13], [0.02, -0.17]]) {
      const target = clientAt(g, x, y);
      await dragTipTo(page, target);
      const [wx, wy] = worldAt(g, ...target);
      last = [wx, wy];
      const sol = ik(wx, wy, L1, L2);
      assert.ok(sol, `(${wx}, ${wy}) is reachable`);
      assertReadouts(await shownNumbers(page), expected(sol.q1, sol.q2), `tip at (${x}, ${y})`);
      const m = await marker(page);
      assert.ok(Math.abs(m.q1 - wrap(sol.q1)) < 1e-9 && Math.abs(m.q2 - wrap(sol.q2)) < 1e-9,
        `heatmap marker ${JSON.stringify(m)} vs ${sol.q1}, ${sol.q2}`);
      assert.ok(sol.q2 >= 0, 'elbow-down by default');
    }

    // The elbow switch: same tip, q2 changes sign; the other branch of the same point.
    const before = await shownNumbers(page);
    await page.locator('[data-testid="ik-2r-elbow-up"]').check();
    await settle(page);
    const up = await shownNumbers(page);
    assert.ok(up.q2 < 0 && Math.abs(up.q2 + before.q2) < 1e-6, `q2 ${before.q2} -> ${up.q2}`);
    assert.ok(Math.abs(up.x_mm - before.x_mm) < 1e-3 && Math.abs(up.y_mm - before.y_mm) < 1e-3);
    const other = ik(...last, L1, L2, true);
    assertReadouts(up, expected(other.q1, other.q2), 'elbow-up');
    // A drag now follows the elbow-up branch.
    const target = clientAt(g, 0.1, 0.1);
    await dragTipTo(page, target);
    const solUp = ik(...worldAt(g, ...target), L1, L2, true);
    assertReadouts(await shownNumbers(page), expected(solUp.q1, solUp.q2), 'elbow-up drag');
    // Key e flips back.
    await page.locator('body').click({ position: { x: 5, y: 5 } });
    await page.keyboard.press('e');
    await settle(page);
    assert.ok((await shownNumbers(page)).q2 > 0);
    assert.equal(await page.locator('[data-testid="ik-2r-elbow-down"]').isChecked(), true);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('a pointer out of reach pins the tip to the annulus and says so; links turn one joint', async () => {
  const { page, errors, close } = await openIk();
  try {
    const g = await armGeometry(page);
    const note = page.locator('[data-testid="ik-2r-clamp-note"]');
    assert.equal(await note.isVisible(), false);
    // Hold the tip far outside the reach (0.4 m along 30°).
    const far = clientAt(g, 0.4 * Math.cos(0.5), 0.4 * Math.sin(0.5));
    await drag(page, [Math.round(g.left + g.tipX), Math.round(g.top + g.tipY)], far, { release: false });
    assert.equal(await note.isVisible(), true);
    assert.match(await note.innerText(), /Out of reach/);
    const pinned = await shownNumbers(page);
    const r = Math.hypot(pinned.x_mm, pinned.y_mm);
    assert.ok(Math.abs(r - 220) < 2e-3, `pinned at r = ${r} mm`);
    const [wx, wy] = worldAt(g, ...far);
    assert.ok(Math.abs(Math.atan2(pinned.y_mm, pinned.x_mm) - Math.atan2(wy, wx)) < 2e-5, 'same direction');
    assert.ok(Math.abs(pinned.q2) < 1e-4, 'stretched out: q2 ≈ 0');
    await page.mouse.up();
    await settle(page);
    assert.equal(await note.isVisible(), false);

    // Drag link 2 (its midpoint): q1 stays, q2 follows the pointer.
    await page.keyboard.press('r');
    await settle(page);
    let g2 = await armGeometry(page);
    const start = await shownNumbers(page);
    const mid = [Math.round(g2.left + (g2.elbowX + g2.tipX) / 2), Math.round(g2.top + (g2.elbowY + g2.tipY) / 2)];
    const to = [mid[0] - 40, mid[1] + 60];
    await drag(page, mid, to);
    const afterQ2 = await shownNumbers(page);
    assert.ok(Math.abs(afterQ2.q1 - start.q1) < 1e-12, 'link 2 leaves q1 alone');
    const [px, py] = worldAt(g2, ...to);
    const [ex, ey] = [L1 * Math.cos(start.q1), L1 * Math.sin(start.q1)];
    const q2Expected = wrap(Math.atan2(py - ey, px - ex) - start.q1);
    assert.ok(Math.abs(afterQ2.q2 - q2Expected) < 1e-5, `q2 ${afterQ2.q2} vs ${q2Expected}`);
    assertReadouts(afterQ2, expected(afterQ2.q1, q2Expected), 'link 2 drag');

    // Drag link 1 (its midpoint): q2 stays, q1 = atan2 of the pointer.
    g2 = await armGeometry(page);
    const mid1 = [Math.round(g2.left + (g2.ox + g2.elbowX) / 2), Math.round(g2.top + (g2.oy + g2.elbowY) / 2)];
    const to1 = [mid1[0] - 30, mid1[1] - 50];
    await drag(page, mid1, to1);
    const afterQ1 = await shownNumbers(page);
    const [p1x, p1y] = worldAt(g2, ...to1);
    assert.ok(Math.abs(afterQ1.q2 - afterQ2.q2) < 1e-6, 'link 1 leaves q2 alone');
    assert.ok(Math.abs(afterQ1.q1 - Math.atan2(p1y, p1x)) < 1e-5);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

// ---------- Downloads = CLI ----------

async function command(page, file, kind) {
  return (await page.locator(`[data-cmd="${file}:${kind}"]`).innerText()).trim();
}

/**
 * Compares two CSVs: same header and layout; numbers within 1e-12 relative or 1e-12 absolute
 * (fk_err_mm is rounding noise of order 1e-14).
 */
function assertCsvClose(got, want, label) {
  const a = got.toString('utf8').split('\r\n');
  const b = want.toString('utf8').split('\r\n');
  assert.equal(a.length, b.length, `${label}: row count`);
  for (let i = 0; i < a.length; i++) {
    if (a[i] === b[i]) continue;
    const ca = a[i].split(','), cb = b[i].split(',');
    assert.equal(ca.length, cb.length, `${label} line ${i + 1}`);
    for (let k = 0; k < ca.length; k++) {
      if (ca[k] === cb[k]) continue;
      const x = Number(ca[k]), y = Number(cb[k]);
      assert.ok(Math.abs(x - y) <= 1e-12 * Math.max(Math.abs(x), Math.abs(y), 1),
        `${label} line ${i + 1}: ${a[i]} vs ${b[i]}`);
    }
  }
}

const CSVS = [
  ['ik_workspace.csv', 'ik-workspace', 'planar_ik_workspace.py', 'ik_default'],
  ['jacobian_2r.csv', 'jacobian-2r', 'jacobian_planar_2r.py', 'jacobian_default'],
  ['manip_ellipse.csv', 'manip-grid', 'manip_ellipse_2r.py', 'manip_default'],
];

test('each download is byte for byte the CLI output for the command shown under it', async () => {
  // The Jacobian sweep is taken at the pose's q2: start the page at the recipe's q2 = 0.8.
  const { page, errors, close } = await openIk('#/ik-2r?q1=0.3&q2=0.8');
  try {
    for (const [file, id, py, golden] of CSVS) {
      const bytes = await download(page, file);
      const bsvCmd = await command(page, file, 'bsv');
      const pyCmd = await command(page, file, 'python');
      const args = bsvCmd.split(/\s+/).slice(2);
      assert.equal(bsvCmd.split(/\s+/)[1], id);
      assert.equal(pyCmd, `python ${py} ${args.join(' ')}`);
      assertSameBytes(bytes, cli([id, ...args]).files.get(file), `${file} vs bsv ${id} ${args.join(' ')}`);
      // The defaults reproduce the Python reference run.
      assertCsvClose(bytes, readFileSync(join(ROOT, 'tests', 'golden', golden, file)), file);
    }
    assert.equal(await command(page, 'ik_workspace.csv', 'bsv'), 'bsv ik-workspace 0.12 0.1 200 10');
    assert.equal(await command(page, 'manip_ellipse.csv', 'python'), 'python manip_ellipse_2r.py 0.12 0.1 24');

    // Other parameters and another pose: still the CLI's bytes.
    await page.locator('[data-field="L2"]').fill('0.15');
    await page.locator('[data-field="step_mm"]').fill('25');
    await page.locator('[data-field="q1_step"]').fill('0.05');
    await page.locator('[data-field="n"]').fill('7');
    const g = await armGeometry(page);
    await dragTipTo(page, clientAt(g, -0.1, 0.12));
    for (const [file, id] of CSVS) {
      const bytes = await download(page, file);
      const args = (await command(page, file, 'bsv')).split(/\s+/).slice(2);
      assertSameBytes(bytes, cli([id, ...args]).files.get(file), `${file} after edits vs bsv ${id} ${args.join(' ')}`);
    }
    assert.match(await command(page, 'ik_workspace.csv', 'bsv'), /^bsv ik-workspace 0\.12 0\.15 200 25$/);
    const q2 = (await shownNumbers(page)).q2;
    const jac = (await command(page, 'jacobian_2r.csv', 'bsv')).split(/\s+/);
    assert.ok(Math.abs(Number(jac.at(-1)) - q2) < 1e-6, 'the sweep uses the current q2');

    // Copy puts the command on the clipboard and says so.
    await page.context().grantPermissions(['clipboard-read', 'clipboard-write']);
    await page.locator('[data-copy="manip_ellipse.csv:bsv"]').click();
    await page.waitForFunction(() => document.querySelector('[data-ik2r="copy-status"]').textContent !== '');
    assert.match(await page.locator('[data-ik2r="copy-status"]').innerText(), /copied/);
    assert.equal(await page.evaluate(() => navigator.clipboard.readText()), await command(page, 'manip_ellipse.csv', 'bsv'));

    const png = await download(page, 'ik_2r_arm.png');
    assert.ok(png.subarray(0, 8).equals(Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a])));
    assert.ok(png.length > 5000, `PNG of ${png.length} bytes`);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

// ---------- Japanese ----------

test('with Japanese selected no English UI string remains on the page', async () => {
  const english = englishStrings();
  assert.ok(english.length > 100, `collected ${english.length} English strings`);
  assert.ok(english.includes('Drag the orange tip and both joints follow by inverse kinematics; drag a link to turn one joint. Every number on this page moves with the arm.'));
  const { page, errors, close } = await openIk('#/ik-2r?lang=ja&ws=1');
  try {
    // Bring out the texts the page formats itself: an invalid field, a heatmap preview,
    // a copy, the out-of-reach note.
    await page.locator('[data-field="L2"]').fill('abc');
    const heat = await page.evaluate(() => {
      const c = document.querySelector('[data-testid="ik-2r-heatmap"]');
      const r = c.getBoundingClientRect();
      return { x: r.left + +c.dataset.plotX + 20, y: r.top + +c.dataset.plotY + 30 };
    });
    await page.mouse.move(heat.x, heat.y);
    await settle(page);
    const hovering = await page.evaluate(() => document.body.innerText);
    const g = await armGeometry(page);
    await drag(page, [Math.round(g.left + g.tipX), Math.round(g.top + g.tipY)], clientAt(g, 0.5, 0.1), { release: false });
    const text = hovering + '\n' + (await page.evaluate(() => document.body.innerText));
    await page.mouse.up();
    const left = english.filter((s) => text.includes(s));
    assert.deepEqual(left, [], `English left on the Japanese page: ${left.join(' | ')}`);
    assert.match(text, /平面2リンク IK プレイグラウンド/);
    assert.match(text, /届きません/);
    assert.match(text, /プレビュー：q1 = /);
    assert.match(text, /作業領域グリッド \d+ × \d+/);
    assert.match(text, /L2/);
    assert.ok(await page.locator('[data-field-error="L2"]').isVisible());
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

// ---------- Invalid input, URL state ----------

test('an invalid L2 is flagged beside the field, the last valid L2 stays, the arm stays usable', async () => {
  const { page, errors, close } = await openIk();
  try {
    const field = page.locator('[data-field="L2"]');
    const message = page.locator('[data-field-error="L2"]');
    assert.equal(await message.isVisible(), false);
    for (const [bad, pattern] of [['abc', /L2: “abc” is not a number\./], ['-1', /L2 must be between/], ['', /not a number/]]) {
      await field.fill(bad);
      assert.equal(await message.isVisible(), true, `message for ${JSON.stringify(bad)}`);
      assert.match(await message.innerText(), pattern);
      assert.equal(await field.getAttribute('aria-invalid'), 'true');
      // The arm still uses L2 = 0.10 and still follows a drag.
      const g = await armGeometry(page);
      const target = clientAt(g, 0.05 + Math.random() * 0.05, 0.12);
      await dragTipTo(page, target);
      const sol = ik(...worldAt(g, ...target), L1, L2);
      assertReadouts(await shownNumbers(page), expected(sol.q1, sol.q2), `with L2 field "${bad}"`);
      assert.match(await command(page, 'ik_workspace.csv', 'bsv'), /^bsv ik-workspace 0\.12 0\.1 200 10$/);
    }
    // A valid value clears the message and is used at once.
    await field.fill('0.08');
    assert.equal(await message.isVisible(), false);
    await settle(page);
    const r = await shownNumbers(page);
    assertReadouts(r, expected(r.q1, r.q2, L1, 0.08), 'L2 = 0.08');
    await page.waitForFunction(() => /L2=0\.08&/.test(location.hash), null, { timeout: 3000 });
    // The heatmap is recomputed (debounced) for a new resolution; out-of-range ones are refused.
    await page.locator('[data-field="res"]').fill('64');
    await page.waitForFunction(() => document.querySelector('[data-testid="ik-2r-heatmap"]').dataset.gridN === '64', null, { timeout: 3000 });
    await page.locator('[data-field="res"]').fill('2000');
    assert.match(await page.locator('[data-field-error="res"]').innerText(), /Heatmap resolution must be between 64 and 1,024 \(it is 2,000\)/);
    // Japanese messages for the same mistake.
    await page.locator('[data-testid="lang-switch"]').click();
    await field.fill('abc');
    assert.doesNotMatch(await message.innerText(), /is not a number/);
    assert.match(await message.innerText(), /L2/);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('a URL with state restores it exactly; invalid URL values are ignored with a notice', async () => {
  const q1 = 0.5123456789012345;
  const q2 = -1.2;
  const hash = `#/ik-2r?L1=0.15&L2=0.08&q1=${q1}&q2=${q2}&elbow=up&ws=1&wsc=manip&res=128&n=30&q1_start=-1&q1_stop=1&q1_step=0.25&half_mm=300&step_mm=15`;
  const { page, errors, close } = await openIk(hash);
  try {
    const r = await shownNumbers(page);
    assertReadouts(r, expected(q1, q2, 0.15, 0.08), 'from URL');
    assert.equal(await page.locator('[data-field="L1"]').inputValue(), '0.15');
    assert.equal(await page.locator('[data-field="res"]').inputValue(), '128');
    assert.equal(await page.locator('[data-testid="ik-2r-elbow-up"]').isChecked(), true);
    assert.equal(await page.locator('[data-testid="ik-2r-ws-toggle"]').isChecked(), true);
    assert.equal(await page.locator('[data-testid="ik-2r-ws-color"]').inputValue(), 'manip');
    assert.equal(await page.locator('[data-testid="ik-2r-heatmap"]').getAttribute('data-grid-n'), '128');
    assert.equal(await page.locator('[data-testid="ik-2r-url-notice"]').isVisible(), false);
    assert.equal(await command(page, 'jacobian_2r.csv', 'bsv'), `bsv jacobian-2r 0.15 0.08 -1 1 0.25 ${q2}`);
    assert.equal(await command(page, 'ik_workspace.csv', 'bsv'), 'bsv ik-workspace 0.15 0.08 300 15');
    // 2·300/15 + 1 = 41 cells per axis.
    assert.match(await page.locator('[data-ik2r="ws-summary"]').innerText(), /41 × 41 = 1681 cells/);
    // The page writes its state back: reopening the written URL gives the same numbers.
    await page.keyboard.press(']');
    await settle(page);
    await page.waitForFunction(() => /q1=0\.52/.test(location.hash), null, { timeout: 3000 });
    const url = page.url();
    const now = await shownNumbers(page);
    const again = await openIk(url.slice(url.indexOf('#')));
    try {
      assert.deepEqual(await shownNumbers(again.page), now);
    } finally {
      await again.close();
    }
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }

  const bad = await openIk('#/ik-2r?L2=abc&q1=zz&res=5000&elbow=sideways&half_mm=1&step_mm=0.0001');
  try {
    const notice = bad.page.locator('[data-testid="ik-2r-url-notice"]');
    assert.equal(await notice.isVisible(), true);
    const text = await notice.innerText();
    for (const key of ['L2', 'q1', 'res', 'elbow', 'half_mm', 'step_mm']) assert.match(text, new RegExp(key));
    assertReadouts(await shownNumbers(bad.page), expected(0.3, 0.8), 'defaults after a bad URL');
    assert.deepEqual(bad.errors, []);
  } finally {
    await bad.close();
  }
});

// ---------- Keys, heatmap, phone ----------

test('keys nudge the tip and the joints, toggle the grid and reset; a heatmap click sets the pose', async () => {
  const { page, errors, close } = await openIk();
  try {
    await page.locator('body').click({ position: { x: 5, y: 5 } });
    let r0 = await shownNumbers(page);
    await page.keyboard.press('ArrowRight');
    await settle(page);
    let r = await shownNumbers(page);
    // Expected values from rounded readouts (x, y to 1 µm): tolerances × 20.
    let sol = ik((r0.x_mm + 1) / 1000, r0.y_mm / 1000, L1, L2);
    assertReadouts(r, expected(sol.q1, sol.q2), 'ArrowRight', 20);
    await page.keyboard.press('Shift+ArrowUp');
    await settle(page);
    r0 = r;
    r = await shownNumbers(page);
    sol = ik(r0.x_mm / 1000, (r0.y_mm + 10) / 1000, L1, L2);
    assertReadouts(r, expected(sol.q1, sol.q2), 'Shift+ArrowUp', 20);
    await page.keyboard.press('[');
    await settle(page);
    assert.ok(Math.abs((await shownNumbers(page)).q1 - wrap(r.q1 - 0.01)) < 1e-6);
    await page.keyboard.press('=');
    await settle(page);
    assert.ok(Math.abs((await shownNumbers(page)).q2 - wrap(r.q2 + 0.01)) < 1e-6);
    await page.keyboard.press('w');
    assert.equal(await page.locator('[data-testid="ik-2r-ws-toggle"]').isChecked(), true);
    await page.keyboard.press('r');
    await settle(page);
    assertReadouts(await shownNumbers(page), expected(0.3, 0.8), 'after reset');
    assert.equal(await page.locator('[data-testid="ik-2r-ws-toggle"]').isChecked(), false);

    // Click the heatmap cell (i, j) = (64, 200) of 256: the pose becomes that cell's angles.
    const cell = await page.evaluate(() => {
      const c = document.querySelector('[data-testid="ik-2r-heatmap"]');
      const r = c.getBoundingClientRect();
      const d = c.dataset;
      const n = +d.gridN, size = +d.plotSize;
      const at = (i) => (i / (n - 1)) * size;
      return { n, x: r.left + +d.plotX + at(64), y: r.top + +d.plotY + size - at(200) };
    });
    await page.mouse.click(cell.x, cell.y);
    await settle(page);
    const q = (i) => -Math.PI + (2 * Math.PI * i) / (cell.n - 1);
    assertReadouts(await shownNumbers(page), expected(q(64), q(200)), 'heatmap click');
    const m = await marker(page);
    assert.ok(Math.abs(m.q1 - q(64)) < 1e-12 && Math.abs(m.q2 - q(200)) < 1e-12);
    // The ? overlay lists the page's keys.
    await page.keyboard.press('?');
    // Its code comes on the first press.
    await page.locator('[data-testid="shortcut-overlay"]').waitFor();
    const overlay = await page.evaluate(() => document.body.innerText);
    assert.match(overlay, /Flip the elbow/);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('keys to full stretch say out of reach; the live region says the pose; no bench hooks', async () => {
  const { page, errors, close } = await openIk();
  try {
    const note = page.locator('[data-testid="ik-2r-clamp-note"]');
    const live = page.locator('[data-testid="ik-2r-live"]');
    assert.equal(await live.getAttribute('aria-live'), 'polite');
    assert.equal(await live.innerText(), '', 'nothing to say before anything moved');
    await page.locator('body').click({ position: { x: 5, y: 5 } });
    // From x = 160 mm, 10 mm steps right reach the 220 mm stretch in a few presses.
    for (let k = 0; k < 12; k++) await page.keyboard.press('Shift+ArrowRight');
    await settle(page);
    assert.equal(await note.isVisible(), true, 'out-of-reach note after key moves');
    const r = await shownNumbers(page);
    assert.ok(Math.abs(Math.hypot(r.x_mm, r.y_mm) - 220) < 2e-3, `stretched: r = ${Math.hypot(r.x_mm, r.y_mm)}`);
    // The polite summary follows once the keys stop: the pose in whole degrees and mm.
    await page.waitForFunction(() => document.querySelector('[data-testid="ik-2r-live"]').textContent !== '', null, { timeout: 3000 });
    const said = await live.innerText();
    assert.match(said, /Out of reach/);
    assert.match(said, new RegExp(`q1 ${Math.round(r.q1_deg)}°`));
    assert.match(said, new RegExp(`x ${Math.round(r.x_mm)} mm`));
    // The note goes away by itself after a key move (no pointer to let go of).
    await page.waitForFunction(() => document.querySelector('[data-testid="ik-2r-clamp-note"]').hidden, null, { timeout: 5000 });
    // The app build has no bench hooks.
    assert.equal(await page.evaluate(() => typeof window.__ik2rBench), 'undefined');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('a limit over several fields names the one changed and marks the others', async () => {
  const { page, errors, close } = await openIk();
  try {
    await page.locator('[data-field="half_mm"]').fill('1000');
    assert.equal(await page.locator('[data-field-error="half_mm"]').isVisible(), false, '201 × 201 cells is fine');
    await page.locator('[data-field="step_mm"]').fill('1');
    assert.equal(await page.locator('[data-field-error="step_mm"]').isVisible(), true, 'the message is on the field changed');
    assert.equal(await page.locator('[data-field="step_mm"]').getAttribute('aria-invalid'), 'true');
    assert.equal(await page.locator('[data-field="half_mm"]').getAttribute('aria-invalid'), 'true', 'the other field of the limit is marked');
    assert.match(await page.locator('[data-field-error="half_mm"]').innerText(), /Step/);
    // The last valid values stay in use.
    assert.equal(await command(page, 'ik_workspace.csv', 'bsv'), 'bsv ik-workspace 0.12 0.1 1000 10');
    await page.locator('[data-field="step_mm"]').fill('5');
    for (const f of ['half_mm', 'step_mm']) {
      assert.equal(await page.locator(`[data-field-error="${f}"]`).isVisible(), false);
      assert.equal(await page.locator(`[data-field="${f}"]`).getAttribute('aria-invalid'), 'false');
    }
    assert.equal(await command(page, 'ik_workspace.csv', 'bsv'), 'bsv ik-workspace 0.12 0.1 1000 5');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('on a phone the page fits the width and a touch drag moves the arm', async () => {
  const { page, errors, close } = await openApp(server.url, '#/ik-2r', { viewport: { width: 390, height: 844 } });
  try {
    await page.waitForSelector('[data-testid="ik-2r-canvas"][data-tip-x]');
    await settle(page);
    const overflow = await page.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
    assert.ok(overflow <= 0, `horizontal overflow of ${overflow}px`);
    const g = await armGeometry(page);
    assert.ok(g.width > 300, `arm view ${g.width}px wide`);
    // Touch pointer events (what a finger sends), from the tip to a new point.
    const target = clientAt(g, -0.12, 0.1);
    await page.evaluate(({ from, to }) => {
      const c = document.querySelector('[data-testid="ik-2r-canvas"]');
      const ev = (type, [x, y]) => c.dispatchEvent(new PointerEvent(type, {
        pointerId: 7, pointerType: 'touch', isPrimary: true, clientX: x, clientY: y,
        bubbles: true, cancelable: true, buttons: type === 'pointerup' ? 0 : 1,
      }));
      ev('pointerdown', from);
      for (let k = 1; k <= 5; k++) ev('pointermove', [from[0] + ((to[0] - from[0]) * k) / 5, from[1] + ((to[1] - from[1]) * k) / 5]);
      ev('pointerup', to);
    }, { from: [g.left + g.tipX, g.top + g.tipY], to: target });
    await settle(page);
    const sol = ik(...worldAt(g, ...target), L1, L2);
    assertReadouts(await shownNumbers(page), expected(sol.q1, sol.q2), 'touch drag');
    assert.equal(await page.locator('[data-testid="ik-2r-canvas"]').evaluate((c) => getComputedStyle(c).touchAction), 'none');
    await page.screenshot({ path: join(OUT, 'ik2r-phone-390.png') });

    // A finger scrolls the page unless it lands on the arm: only the handles over the tip and
    // the links take the gesture (touch-action: none); the rest of the view lets it pan.
    await page.locator('[data-ik2r="arm-stage"]').evaluate((s) => s.scrollIntoView({ block: 'center' }));
    await settle(page);
    const g2 = await armGeometry(page);
    const empty = clientAt(g2, 0.02, -0.2);
    const touchAction = await page.evaluate(({ tip, empty }) => {
      const at = ([x, y]) => getComputedStyle(document.elementFromPoint(x, y)).touchAction;
      const stage = document.querySelector('[data-ik2r="arm-stage"]');
      return { tip: at(tip), empty: at(empty), stage: getComputedStyle(stage).touchAction };
    }, { tip: [g2.left + g2.tipX, g2.top + g2.tipY], empty });
    assert.equal(touchAction.tip, 'none', 'the tip keeps a finger');
    assert.notEqual(touchAction.empty, 'none', 'empty space lets the page scroll');
    assert.equal(touchAction.stage, 'manipulation');
    // A tap on empty space moves the tip there (IK), as a click does.
    await page.evaluate(([x, y]) => {
      const c = document.querySelector('[data-testid="ik-2r-canvas"]');
      for (const type of ['pointerdown', 'pointerup']) {
        c.dispatchEvent(new PointerEvent(type, {
          pointerId: 8, pointerType: 'touch', isPrimary: true, clientX: x, clientY: y,
          bubbles: true, cancelable: true, buttons: type === 'pointerup' ? 0 : 1,
        }));
      }
    }, empty);
    await settle(page);
    const [ex, ey] = worldAt(g2, ...empty);
    const tapped = await shownNumbers(page);
    assert.ok(Math.abs(tapped.x_mm - ex * 1000) < 1e-3 && Math.abs(tapped.y_mm - ey * 1000) < 1e-3,
      `tap at (${ex * 1000}, ${ey * 1000}) mm, tip at (${tapped.x_mm}, ${tapped.y_mm})`);
    // The key numbers sit right above the arm view at phone width (sticky while it shows).
    const strip = page.locator('.ik2r-strip');
    assert.equal(await strip.isVisible(), true);
    const box = await strip.boundingBox();
    assert.ok(box.y + box.height <= g2.top + 1 && box.y + box.height >= g2.top - 40, `strip just above the arm view: ${JSON.stringify(box)}, arm top ${g2.top}`);
    const q1Deg = Number(await page.locator('[data-strip="q1"]').innerText());
    assert.ok(Math.abs(q1Deg - tapped.q1_deg) <= 0.05, `strip q1 ${q1Deg} vs ${tapped.q1_deg}`);
    assert.ok(Math.abs(Number(await page.locator('[data-strip="w"]').innerText()) - tapped.manipulability) <= tapped.manipulability * 5e-3);
    await page.screenshot({ path: join(OUT, 'ik2r-phone-390-arm.png') });
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('screenshots: English and Japanese at 1920×1080, projector mode', async () => {
  for (const [lang, name] of [['en', 'ik2r-en-1920'], ['ja', 'ik2r-ja-1920']]) {
    const { page, errors, close } = await openIk(`#/ik-2r?ws=1&wsc=manip&q1=0.4&q2=1.1&lang=${lang}`);
    try {
      // A heatmap hover shows the ghost arm in the screenshot.
      const h = await page.evaluate(() => {
        const c = document.querySelector('[data-testid="ik-2r-heatmap"]');
        const r = c.getBoundingClientRect();
        return { x: r.left + +c.dataset.plotX + +c.dataset.plotSize * 0.7, y: r.top + +c.dataset.plotY + +c.dataset.plotSize * 0.3 };
      });
      await page.mouse.move(h.x, h.y);
      await settle(page);
      assert.notEqual(await page.locator('[data-testid="ik-2r-heatmap-hover"]').innerText(), '');
      await page.screenshot({ path: join(OUT, `${name}.png`) });
      await page.screenshot({ path: join(OUT, `${name}.jpg`), type: 'jpeg', quality: 50 });
      await page.screenshot({ path: join(OUT, `${name}-full.png`), fullPage: true });
      await page.locator('[data-ik2r="plot-stage"]').screenshot({ path: join(OUT, `${name}-plot.png`) });
      assert.ok(existsSync(join(OUT, `${name}.png`)));
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
  const { page, errors, close } = await openIk('#/ik-2r', { storage: { 'bsv.projector': '1' } });
  try {
    await page.screenshot({ path: join(OUT, 'ik2r-projector-1920.png') });
    await page.locator('[data-ik2r="plot-stage"]').screenshot({ path: join(OUT, 'ik2r-projector-plot.png') });
    await page.locator('[data-ik2r="heat-stage"]').screenshot({ path: join(OUT, 'ik2r-projector-heat.png') });
    // The canvases follow the window size (ResizeObserver), at the device pixel ratio.
    const width = () => page.locator('[data-testid="ik-2r-canvas"]').evaluate((c) => [c.width, c.getBoundingClientRect().width]);
    const [w1] = await width();
    await page.setViewportSize({ width: 1200, height: 900 });
    await page.waitForFunction((w) => document.querySelector('[data-testid="ik-2r-canvas"]').width !== w, w1, { timeout: 3000 });
    const [w2, css2] = await width();
    assert.ok(Math.abs(w2 - css2) <= 1, `backing store ${w2} px for ${css2} CSS px`);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('projector at 1280x800: each readout value is one line of a fixed width; x labels stay inside the canvas', async () => {
  const { page, errors, close } = await openIk('#/ik-2r?lang=ja', {
    viewport: { width: 1280, height: 800 }, storage: { 'bsv.projector': '1' },
  });
  try {
    assert.ok(await page.evaluate(() => document.documentElement.classList.contains('projector')));
    // Each value's box, and whether the values of a row share a line.
    const boxes = () => page.evaluate(() => [...document.querySelectorAll('.ik2r-readouts [data-readout]')].map((e) => {
      const r = e.getBoundingClientRect();
      const lh = parseFloat(getComputedStyle(e).lineHeight) || 1.2 * parseFloat(getComputedStyle(e).fontSize);
      const row = [...(e.closest('dd, .ik2r-matrix-row')?.querySelectorAll('[data-readout]') ?? [])];
      const oneRow = row.every((o) => Math.abs(o.getBoundingClientRect().top - r.top) < 2);
      return { name: e.dataset.readout, w: r.width, h: r.height, lh, oneRow };
    }));
    const g = await armGeometry(page);
    await dragTipTo(page, clientAt(g, 0.05, 0.19));
    const a = await boxes();
    await dragTipTo(page, clientAt(g, -0.17, -0.03));
    const b = await boxes();
    assert.equal(a.length, 14);
    for (const [i, box] of a.entries()) {
      assert.ok(box.h <= 1.5 * box.lh, `${box.name}: ${box.h} px tall, line ${box.lh} px`);
      assert.ok(box.oneRow, `${box.name}: its row's values share a line`);
      assert.ok(Math.abs(box.w - b[i].w) < 0.5, `${box.name}: width ${box.w} then ${b[i].w}`);
    }
    // The arm view's x labels are whole inside the canvas, and there are some.
    const labels = await page.evaluate(() => document.querySelector('[data-testid="ik-2r-canvas"]').dataset.xLabels
      .split(';').filter(Boolean).map((l) => l.split('@')[1].split(',').map(Number)));
    assert.ok(labels.length >= 2, `x labels: ${labels.length}`);
    for (const [left, right] of labels) {
      assert.ok(left >= 0 && right <= g.width, `x label [${left}, ${right}] inside 0..${g.width}`);
    }
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});
