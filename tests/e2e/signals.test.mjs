// The three signal pages (#/cubic-path, #/pid-step, #/trapezoid-profile) in headless Chromium:
// a drag or a slider changes the readouts as the kernel (the `bsv` CSV) says; the download equals
// `bsv` byte for byte for the defaults and for a URL with other values; a bad value shows its
// message beside the field and the page keeps the last valid plot and download; Japanese leaves
// no English UI text. Screenshots (EN/JA 1920×1080, projector, phone 390 px) go to
// tests/e2e/out/. The recompute + redraw time of slider drags is a figure of
// tests/bench/signals.bench.mjs.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { openApp, readouts, query, screenshots, OUT } from './harness.mjs';
import { serveAppWithCli, cli, cliCsv, download, assertSameBytes } from './cli.mjs';
import { englishStrings } from './locales.mjs';

const app = serveAppWithCli();
const open = (hash, opts = {}) => openApp(app.url, hash, opts);

/** The CSV of `bsv <args>` as rows of numbers, and the file's bytes. */
function run(file, args) {
  const { bytes, rows } = cliCsv(args, file);
  return { bytes, rows: rows.map((r) => r.map(Number)) };
}

/** `data-readout` → exact value (data-value, a number) of the page. */
const pageValues = (page) => readouts(page, { numbers: true });

/** Sets a slider as a drag does (value, then an input event) and lets a frame pass. */
async function slide(page, name, value) {
  await page.locator(`[data-slider="${name}"]`).evaluate((el, v) => {
    el.value = v;
    el.dispatchEvent(new Event('input', { bubbles: true }));
  }, String(value));
}

/** The pixels of the data layer of the page's plot. */
const dataLayer = (page) => page.evaluate(() => document.querySelectorAll('.sig-stage canvas')[1].toDataURL());

const maxAbs = (rows, col) => rows.reduce((best, r) => (Math.abs(r[col]) > Math.abs(best[col]) ? r : best), rows[0]);

test('cubic-path: dragging the end point moves q1 and T; readouts are the CSV\'s', async () => {
  const { page, errors, close } = await open('#/cubic-path');
  try {
    const canvas = page.locator('[data-testid="cubic-path-canvas"]');
    const box = await canvas.boundingBox();
    const end = await canvas.evaluate((c) => [Number(c.dataset.endX), Number(c.dataset.endY)]);
    await page.mouse.move(box.x + end[0], box.y + end[1]);
    await page.mouse.down();
    for (let k = 1; k <= 10; k++) await page.mouse.move(box.x + end[0] + 6 * k, box.y + end[1] + 5 * k);
    await page.mouse.up();
    await page.waitForFunction(() => /T=/.test(location.hash) && /q1=/.test(location.hash), null, { timeout: 3000 });
    const q = await query(page);
    assert.ok(Number(q.T) > 1 && Number(q.q1) < 1.2, JSON.stringify(q));
    assert.equal(await page.locator('[data-field="T"]').inputValue(), q.T);
    const { rows } = run('cubic_path.csv', ['cubic-path', '0.0', q.q1, q.T, '0.02']);
    const r = await pageValues(page);
    const peakV = maxAbs(rows, 2);
    const peakA = maxAbs(rows, 3);
    assert.equal(r['peak-velocity'], peakV[2]);
    assert.equal(r['peak-velocity-t'], peakV[0]);
    assert.equal(r['peak-acceleration'], peakA[3]);
    assert.equal(r.rows, rows.length);
    assert.equal(r.a2, (3 * Number(q.q1)) / (Number(q.T) * Number(q.T)));
    // A slider: q0 = 0.5 runs the kernel again.
    await slide(page, 'q0', 0.5);
    assert.equal(await page.locator('[data-field="q0"]').inputValue(), '0.5');
    const again = run('cubic_path.csv', ['cubic-path', '0.5', q.q1, q.T, '0.02']).rows;
    assert.equal((await pageValues(page))['peak-velocity'], maxAbs(again, 2)[2]);
    // Hovering a plot moves the cursor readout to the sample under it.
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    const c = await pageValues(page);
    const sample = again.find((row) => row[0] === c['cursor-t']);
    assert.ok(sample, `cursor t ${c['cursor-t']} is a sample time`);
    assert.deepEqual([c['cursor-q'], c['cursor-qd'], c['cursor-qdd']], [sample[1], sample[2], sample[3]]);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

const DOWNLOADS = [
  ['cubic-path', 'cubic_path.csv', ['0.0', '1.2', '1.0', '0.02'], '?q0=-0.4&q1=2.5&T=1.7&dt=0.013&quintic=1&trapezoid=1', ['-0.4', '2.5', '1.7', '0.013']],
  ['pid-step', 'pid_step.csv', ['1.2', '0.4', '0.05', '0.8', '80'], '?Kp=3&Ki=1.1&Kd=0.2&tau=0.5&steps=230', ['3', '1.1', '0.2', '0.5', '230']],
  ['trapezoid-profile', 'trap_profile.csv', ['1.0', '0.5', '1.0', '0.01'], '?distance=0.2&vmax=1.0&amax=2.0&dt=0.005', ['0.2', '1.0', '2.0', '0.005']],
];

for (const [id, file, defaults, search, args] of DOWNLOADS) {
  test(`${id}: the download equals bsv for the defaults and for a URL with other values`, async () => {
    for (const [hash, want] of [[`#/${id}`, defaults], [`#/${id}${search}`, args]]) {
      const { bytes } = run(file, [id, ...(hash.includes('?') ? want : [])]);
      const { page, errors, close } = await open(hash);
      try {
        assertSameBytes(await download(page, file), bytes, hash);
        const bsv = await page.locator('[data-cmd="bsv"]').innerText();
        assert.equal(bsv, `bsv ${id} ${want.join(' ')}`);
        const python = await page.locator('[data-cmd="python"]').innerText();
        assert.match(python, new RegExp(`^python \\w+\\.py ${want.join(' ').replaceAll('.', '\\.')}$`));
        assert.deepEqual(errors, []);
      } finally {
        await close();
      }
    }
  });
}

test('cubic-path: while a slider is held the axes only grow (the curve moves inside them); let go, they fit the data again', async () => {
  const { page, errors, close } = await open('#/cubic-path');
  try {
    const canvas = page.locator('[data-testid="cubic-path-canvas"]');
    const endY = () => canvas.evaluate((c) => Number(c.dataset.endY));
    const slider = page.locator('[data-slider="q1"]');
    await slider.scrollIntoViewIfNeeded();
    const box = await slider.boundingBox();
    // q1 runs from -3.2 to 3.2 along the slider: press at 3.0, move to 0.5 and hold.
    const at = (q) => box.x + 8 + ((q + 3.2) / 6.4) * (box.width - 16);
    await page.mouse.move(at(3.0), box.y + box.height / 2);
    await page.mouse.down();
    for (let k = 1; k <= 10; k++) await page.mouse.move(at(3.0 - 0.25 * k), box.y + box.height / 2);
    const q1 = Number(await page.locator('[data-field="q1"]').inputValue());
    assert.ok(Math.abs(q1 - 0.5) < 0.1, `q1 ${q1}`);
    const held = await endY();
    await page.mouse.up();
    await page.waitForFunction((y) => Number(document.querySelector('[data-testid="cubic-path-canvas"]').dataset.endY) < y - 20, held, { timeout: 3000 });
    // Fitted again, the end point (q1, T) sits near the top of the position panel; held, it
    // sat low in the range that still held q1 = 3.
    const fitted = await endY();
    assert.ok(fitted < held - 20, `held ${held} px, fitted ${fitted} px`);
    // The readouts are the CSV's for the value let go at.
    const { rows } = run('cubic_path.csv', ['cubic-path', '0.0', String(q1), '1.0', '0.02']);
    assert.equal((await pageValues(page)).rows, rows.length);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('pid-step: a Kp slider changes the figures as the CSV says; the ghost; divergence warns', async () => {
  const { page, errors, close } = await open('#/pid-step?steps=300');
  try {
    await slide(page, 'Kp', 2);
    await slide(page, 'Ki', 4);
    await page.locator('[data-slider="Ki"]').dispatchEvent('change');
    const { rows } = run('pid_step.csv', ['pid-step', '2', '4', '0.05', '0.8', '300']);
    const r = await pageValues(page);
    const first = (level) => rows.find((row) => row[2] >= level)[0];
    assert.equal(r['rise-time'], first(0.9) - first(0.1));
    const maxY = Math.max(...rows.map((row) => row[2]));
    assert.equal(r.overshoot, Math.max(0, ((maxY - 1) / 1) * 100));
    assert.ok(r.overshoot > 0);
    const lastOut = rows.findLastIndex((row) => Math.abs(row[2] - 1) > 0.02);
    assert.equal(r['settling-time'], rows[lastOut + 1][0]);
    assert.equal(r['steady-state-error'], 1 - rows[rows.length - 1][2]);
    const peak = maxAbs(rows, 3);
    assert.deepEqual([r['peak-u'], r['peak-u-t']], [peak[3], peak[0]]);
    assert.equal(await page.locator('[data-testid="pid-step-warning"]').isVisible(), false);
    // Hovering the plots moves the cursor readout to the CSV row under it.
    const box = await page.locator('[data-testid="pid-step-canvas"]').boundingBox();
    for (const f of [0.3, 0.7]) {
      await page.mouse.move(box.x + box.width * f, box.y + box.height / 3);
      const c = await pageValues(page);
      const row = rows.find((x) => x[0] === c['cursor-t']);
      assert.ok(row, `cursor t ${c['cursor-t']} is a CSV time`);
      assert.deepEqual([c['cursor-r'], c['cursor-y'], c['cursor-u']], [row[1], row[2], row[3]]);
    }
    // Kp = -5 runs away: the recipe's warning shows; the figures say "not reached".
    await page.locator('[data-field="Kp"]').fill('-5');
    await page.waitForSelector('[data-testid="pid-step-warning"]:not([hidden])');
    assert.match(await page.locator('[data-testid="pid-step-warning"]').innerText(), /unstable/);
    assert.equal((await pageValues(page))['rise-time'], null);
    // The live summary says "not reached" bare, a unit only after a number.
    const live = page.locator('[data-testid="pid-live"]');
    // (Announcements are throttled: wait for the one of Kp = -5, not an earlier one.)
    await page.waitForFunction(() => /^Rise time not reached/.test(document.querySelector('[data-testid="pid-live"]').textContent), null, { timeout: 5000 });
    const said = await live.textContent();
    assert.match(said, /^Rise time not reached, overshoot (not reached|\S+ %), settling time not reached\.$/, said);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('a run over 150,000 rows is computed a slice per frame: the last run stays until it is done, then the figures are the CSV\'s', async () => {
  // 400,000 steps of the PID (the CSV's rows): too many to compute within one frame.
  const { page, errors, close } = await open('#/pid-step?Kp=2&Ki=4&Kd=0.05&tau=0.8&steps=400000');
  const line = page.locator('[data-testid="pid-step-computing"]');
  try {
    await line.waitFor({ state: 'hidden', timeout: 20000 });
    const figuresOf = (rows) => {
      const first = (level) => rows.find((row) => row[2] >= level)[0];
      const lastOut = rows.findLastIndex((row) => Math.abs(row[2] - 1) > 0.02);
      return { rise: first(0.9) - first(0.1), settling: rows[lastOut + 1][0], sse: 1 - rows[rows.length - 1][2], final: rows[rows.length - 1][2] };
    };
    const shown = async () => {
      const r = await pageValues(page);
      return { rise: r['rise-time'], settling: r['settling-time'], sse: r['steady-state-error'], final: r['final-y'] };
    };
    const before = figuresOf(run('pid_step.csv', ['pid-step', '2', '4', '0.05', '0.8', '400000']).rows);
    assert.deepEqual(await shown(), before);
    // A change: the line says how far the new run is, in %, while the plot and the readouts
    // keep the last run; then the new run's figures are the CSV's.
    // (Typed and read in one task: 400,000 rows take only a few frames.)
    const during = await page.evaluate(() => {
      const field = document.querySelector('[data-field="Kp"]');
      field.value = '3';
      field.dispatchEvent(new Event('input', { bubbles: true }));
      const l = document.querySelector('[data-testid="pid-step-computing"]');
      return { hidden: l.hidden, text: l.textContent, final: Number(document.querySelector('[data-readout="final-y"]').dataset.value) };
    });
    assert.equal(during.hidden, false);
    assert.match(during.text, /^Computing 400,000 rows… \d+ %/);
    assert.equal(during.final, before.final, 'the last run stays while the new one is computed');
    await line.waitFor({ state: 'hidden', timeout: 20000 });
    const after = figuresOf(run('pid_step.csv', ['pid-step', '3', '4', '0.05', '0.8', '400000']).rows);
    assert.notDeepEqual(after, before);
    assert.deepEqual(await shown(), after);
    // Two changes while a run is being computed (a slider dragged): that run is shown, then
    // the latest change is computed; the one in between is never computed.
    await page.evaluate(() => {
      const field = document.querySelector('[data-field="Kp"]');
      for (const v of ['5', '6', '4']) {
        field.value = v;
        field.dispatchEvent(new Event('input', { bubbles: true }));
      }
    });
    await line.waitFor({ state: 'hidden', timeout: 20000 });
    const latest = figuresOf(run('pid_step.csv', ['pid-step', '4', '4', '0.05', '0.8', '400000']).rows);
    assert.deepEqual(await shown(), latest);
    // A small run again is drawn within its input's frame: no line.
    await page.locator('[data-field="steps"]').fill('300');
    await page.waitForFunction(() => document.querySelector('[data-readout="final-y"]').dataset.value !== undefined);
    assert.equal(await line.isVisible(), false);
    const small = figuresOf(run('pid_step.csv', ['pid-step', '4', '4', '0.05', '0.8', '300']).rows);
    assert.deepEqual(await shown(), small);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('trapezoid-profile: dragging vmax up on a short move makes a triangle', async () => {
  const { page, errors, close } = await open('#/trapezoid-profile');
  try {
    assert.equal(await page.locator('[data-testid="trapezoid-profile-triangle"]').isVisible(), false);
    assert.equal((await pageValues(page)).shape, 'trapezoid');
    const canvas = page.locator('[data-testid="trapezoid-profile-canvas"]');
    const box = await canvas.boundingBox();
    const h = await canvas.evaluate((c) => [Number(c.dataset.vmaxX), Number(c.dataset.vmaxY)]);
    await page.mouse.move(box.x + h[0], box.y + h[1]);
    await page.mouse.down();
    for (let k = 1; k <= 8; k++) await page.mouse.move(box.x + h[0], box.y + h[1] - 12 * k);
    await page.mouse.up();
    await page.waitForFunction(() => /vmax=/.test(location.hash), null, { timeout: 3000 });
    const q = await query(page);
    assert.ok(Number(q.vmax) > 0.5, q.vmax);
    const out = cli(['trapezoid-profile', '1.0', q.vmax, '1.0', '0.01']);
    const summary = /t_total=([\d.]+)s vmax_used=([\d.]+)/.exec(out.stdout);
    const r = await pageValues(page);
    assert.equal(r['t-total'].toFixed(4), summary[1]);
    assert.equal(r['v-peak'].toFixed(4), summary[2]);
    const rows = out.files.get('trap_profile.csv').toString().trim().split('\n').slice(1).map((l) => l.split(',').map(Number));
    assert.equal(r.rows, rows.length);
    assert.equal(r['final-s'], rows[rows.length - 1][1]);
    // Hovering the plots moves the cursor readout to the CSV row under it.
    for (const f of [0.25, 0.6]) {
      await page.mouse.move(box.x + box.width * f, box.y + box.height / 2);
      const c = await pageValues(page);
      const row = rows.find((x) => x[0] === c['cursor-t']);
      assert.ok(row, `cursor t ${c['cursor-t']} is a CSV time`);
      assert.deepEqual([c['cursor-s'], c['cursor-v'], c['cursor-a']], [row[1], row[2], row[3]]);
    }
    // Distance 0.2 with the slider: a triangle, said so.
    await slide(page, 'distance', 0.2);
    await page.waitForSelector('[data-testid="trapezoid-profile-triangle"]:not([hidden])');
    assert.equal((await pageValues(page)).shape, 'triangle');
    assert.equal((await pageValues(page))['t-flat'], 0);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

const BAD = [
  ['cubic-path', 'cubic_path.csv', 'T', [['abc', /not a number/], ['0', /greater than zero/], ['1e-12', /0\.000000001/]]],
  ['pid-step', 'pid_step.csv', 'steps', [['80.5', /whole number/], ['-1', /between 0 and 1,000,000/], ['1e9', /1,000,000/]]],
  ['trapezoid-profile', 'trap_profile.csv', 'dt', [['x', /not a number/], ['0', /greater than zero/], ['1e-7', /limit is 1,000,000/]]],
];

for (const [id, file, field, cases] of BAD) {
  test(`${id}: a bad ${field} shows its message and the page keeps the last valid plot`, async () => {
    const { bytes } = run(file, [id]);
    const { page, errors, close } = await open(`#/${id}`);
    try {
      const before = await dataLayer(page);
      const shown = await pageValues(page);
      const input = page.locator(`[data-field="${field}"]`);
      const message = page.locator(`[data-field-error="${field}"]`);
      assert.equal(await message.isVisible(), false);
      for (const [bad, pattern] of cases) {
        await input.fill(bad);
        assert.equal(await message.isVisible(), true, bad);
        assert.match(await message.innerText(), pattern, bad);
        assert.equal(await input.getAttribute('aria-invalid'), 'true');
      }
      assert.equal(await dataLayer(page), before, 'the plot is the last valid one');
      assert.deepEqual(await pageValues(page), shown);
      assertSameBytes(await download(page, file), bytes, `${id} with a bad ${field}`);
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  });
}

test('Japanese leaves no English UI text on the three pages', async () => {
  const english = englishStrings();
  for (const [hash, field, title] of [
    ['#/cubic-path?lang=ja&quintic=1', 'dt', /3 次経路/],
    ['#/pid-step?lang=ja&Kp=-5', 'tau', /PID ステップ応答/],
    ['#/trapezoid-profile?lang=ja&distance=0.2', 'vmax', /台形プロファイル/],
  ]) {
    const { page, errors, close } = await open(hash);
    try {
      await page.locator(`[data-field="${field}"]`).fill('abc');
      const text = await page.evaluate(() => document.body.innerText);
      const left = english.filter((s) => text.includes(s));
      assert.deepEqual(left, [], `${hash}: English left: ${left.join(' | ')}`);
      assert.match(text, title);
      assert.ok(await page.locator(`[data-field-error="${field}"]`).isVisible());
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
});

test('screenshots: EN and JA 1920×1080, projector, phone 390 px', async () => {
  const pages = [['cubic-path', '?quintic=1&trapezoid=1'], ['pid-step', '?Kp=2&Ki=4&steps=200'], ['trapezoid-profile', '']];
  for (const [id, search] of pages) {
    const shots = [
      [`${id}-en-1920.png`, `#/${id}${search}`, { viewport: { width: 1920, height: 1080 } }],
      [`${id}-ja-1920.png`, `#/${id}${search}${search ? '&' : '?'}lang=ja`, { viewport: { width: 1920, height: 1080 } }],
      [`${id}-projector-1920.png`, `#/${id}${search}`, { viewport: { width: 1920, height: 1080 }, storage: { 'bsv.projector': '1' } }],
      [`${id}-phone-390.png`, `#/${id}${search}${search ? '&' : '?'}lang=ja`, { viewport: { width: 390, height: 844 } }],
    ];
    await screenshots(app.url, shots, {
      prepare: async (page) => {
        if (id === 'pid-step') {
          await slide(page, 'Kp', 4);
          await page.locator('[data-slider="Kp"]').dispatchEvent('change');
          await slide(page, 'Kp', 2);
        }
        await page.waitForTimeout(300);
      },
    });
  }
});

test('pid-step opens saying why it stops short; "Try tuned gains" reaches the setpoint', async () => {
  for (const [hash, why] of [['#/pid-step', /Stops short of r/], ['#/pid-step?lang=ja', /目標値 r に届きません/]]) {
    const { page, errors, close } = await open(hash, { viewport: { width: 1366, height: 768 } });
    try {
      const short = page.locator('[data-testid="pid-step-short"]');
      assert.ok(await short.isVisible());
      assert.match(await short.textContent(), why);
      if (hash === '#/pid-step') {
        await page.screenshot({ path: 'target/pid-step-short-1366.png' });
      }
      await page.locator('[data-action="pid-tuned"]').click();
      await page.waitForFunction(() => location.hash.includes('Kp='), null, { timeout: 5000 });
      const url = new URL(page.url());
      const q = new URLSearchParams(url.hash.split('?')[1]);
      // Kd 0.05 is the recipe's default: the URL leaves it out.
      assert.deepEqual([q.get('Kp'), q.get('Ki'), q.get('Kd')], ['2', '3', null]);
      for (const [field, value] of [['Kp', '2'], ['Ki', '3'], ['Kd', '0.05']]) {
        assert.equal(await page.locator(`[data-field="${field}"]`).inputValue(), value);
      }
      const r = await pageValues(page);
      assert.ok(Number.isFinite(r['rise-time']) && r['rise-time'] > 0, `${r['rise-time']}`);
      assert.ok(await short.isHidden());
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
});

test('at 1366×768 the plot and the sliders share the first screen; the plot stays in view beside the side column', async () => {
  for (const [hash, first] of [['#/pid-step', 'Kp'], ['#/pid-step?lang=ja', 'Kp'], ['#/cubic-path', 'q0'], ['#/trapezoid-profile', 'distance']]) {
    const { page, errors, close } = await open(hash, { viewport: { width: 1366, height: 768 } });
    try {
      const box = (selector) => page.locator(selector).first().evaluate((e) => e.getBoundingClientRect().toJSON());
      const stage = await box('.sig-stage');
      const slider = await box(`[data-slider="${first}"]`);
      assert.ok(stage.top >= 0 && stage.bottom <= 768, `${hash}: the plot ${JSON.stringify(stage)} in the first 768 px`);
      assert.ok(slider.top >= 0 && slider.bottom <= 768, `${hash}: the ${first} slider ${JSON.stringify(slider)} in the first 768 px`);
      assert.ok(slider.left > stage.right, `${hash}: the slider beside the plot`);
      if (hash.startsWith('#/pid-step')) {
        // Why the defaults stop short, and the tuned gains, are on the first screen too.
        const short = await box('[data-testid="pid-step-short"] button');
        assert.ok(short.bottom <= 768, `${hash}: "Try tuned gains" ${JSON.stringify(short)} in the first 768 px`);
        // Scrolled down to the readouts, the curves are still on screen.
        await page.locator('[data-readout="final-y"]').scrollIntoViewIfNeeded();
        await page.waitForTimeout(100);
        const stuck = await box('.sig-stage');
        assert.ok(stuck.top >= 0 && stuck.bottom <= 768, `${hash}: the plot ${JSON.stringify(stuck)} still in view`);
        await page.evaluate(() => window.scrollTo(0, 0));
        await page.screenshot({ path: join(OUT, `pid-step-sliders-1366${hash.includes('ja') ? '-ja' : ''}.png`) });
      }
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
});
