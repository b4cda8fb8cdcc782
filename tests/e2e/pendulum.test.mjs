// The pendulum page (#/pendulum-energy) in headless Chromium: after n steps the readouts show
// row n of the CSV `bsv pendulum-energy` writes; End then download equals the CLI byte for byte
// (defaults, and a URL setting every parameter); play advances t; compare mode shows both
// drifts with RK4's smaller; Japanese leaves no English UI text; a bad timestep shows its
// message and the run keeps the last valid timestep; the Python line only when just the duration
// differs; the PNG holds both plots; the timestep slider sets h (field, URL, run); a damped run
// that has come to rest offers Replay and damping 0; the opening run loops until a key; a line
// beside the readouts says why the two energies differ (EN, JA). Screenshots (EN/JA
// 1920×1080, projector, phone 390 px) go to tests/e2e/out/. The frame work while playing is a figure of
// tests/bench/pendulum.bench.mjs.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { openApp, OUT, readouts, screenshots } from './harness.mjs';
import { serveAppWithCli, cli, download, assertSameBytes } from './cli.mjs';
import { englishStrings } from './locales.mjs';

// The CLI is built and dist/ served before the tests; all is closed after them.
const server = serveAppWithCli();

const open = (hash = '#/pendulum-energy', opts = {}) => openApp(server.url, hash, opts);

function csvRows(buf) {
  const lines = buf.toString('utf8').trim().split('\n');
  return lines.slice(1).map((l) => l.split(',').map(Number));
}

/** `data-readout` → exact value (data-value, a number) of the page. */
const pageValues = (page) => readouts(page, { numbers: true });

async function toStart(page) {
  await page.locator('[data-action="reset"]').click();
  await page.waitForFunction(() => document.querySelector('[data-action="run"]').getAttribute('aria-pressed') === 'false');
}

test('after n steps the readouts show row n of the CSV; back is exact', async () => {
  const want = csvRows(cli(['pendulum-energy', '5']).files.get('pendulum_energy.csv'));
  assert.equal(want.length, 2500);
  const { page, errors, close } = await open();
  try {
    await toStart(page);
    const r0 = await pageValues(page);
    assert.equal(r0.t, 0);
    assert.ok(Math.abs(r0.theta - (120 * Math.PI) / 180) < 1e-15);
    assert.equal(r0.omega, 0);
    const canvas = page.locator('[data-testid="pendulum-energy-canvas"]');
    await canvas.focus();
    let n = 0;
    for (const k of [1, 2, 3, 10, 25]) {
      while (n < k) {
        await page.keyboard.press(n % 2 ? 'ArrowRight' : 'PageDown');
        n += 1;
      }
      const r = await pageValues(page);
      const [t, theta, omega, ke, pe, total] = want[k - 1];
      assert.deepEqual([r.t, r.theta, r.omega, r.ke, r.pe, r.total], [t, theta, omega, ke, pe, total], `row ${k}`);
    }
    await page.keyboard.press('ArrowLeft');
    await page.locator('[data-action="back"]').click();
    const r = await pageValues(page);
    assert.deepEqual([r.t, r.theta, r.omega, r.total], [want[22][0], want[22][1], want[22][2], want[22][5]]);
    // Step buttons too.
    await page.locator('[data-action="step"]').click();
    assert.equal((await pageValues(page)).theta, want[23][1]);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('End then download equals bsv: defaults and a URL setting every parameter', async () => {
  const cases = [
    ['#/pendulum-energy', ['5']],
    [
      '#/pendulum-energy?duration_s=1.5&damping=0.1&angle-deg=60&timestep=0.001&length=0.5&mass=0.3&radius=0.02&integrator=rk4',
      ['1.5', '--damping', '0.1', '--angle-deg', '60', '--timestep', '0.001', '--length', '0.5', '--mass', '0.3', '--radius', '0.02', '--integrator', 'rk4'],
    ],
  ];
  for (const [hash, args] of cases) {
    const want = cli(['pendulum-energy', ...args]).files.get('pendulum_energy.csv');
    const rows = csvRows(want);
    const { page, errors, close } = await open(hash);
    try {
      await page.locator('[data-action="end"]').click();
      const r = await pageValues(page);
      const last = rows[rows.length - 1];
      assert.deepEqual([r.t, r.theta, r.omega, r.total], [last[0], last[1], last[2], last[5]], hash);
      assertSameBytes(await download(page, 'pendulum_energy.csv'), want, hash);
      const bsv = await page.locator('[data-cmd="bsv"]').innerText();
      assert.equal(bsv, `bsv pendulum-energy ${args.length === 1 ? '5 --damping 0.05 --angle-deg 120 --timestep 0.002 --length 0.3 --mass 0.2 --radius 0.01 --integrator euler' : args.join(' ')}`);
      const python = await page.locator('[data-cmd="python"]').innerText();
      assert.equal(python, args.length === 1 ? 'python mujoco_pendulum_energy.py 5' : '');
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
});

test('the Python line shows when only the duration differs; the PNG holds both plots', async () => {
  const { page, errors, close } = await open('#/pendulum-energy?duration_s=2');
  try {
    assert.equal(await page.locator('[data-cmd="python"]').innerText(), 'python mujoco_pendulum_energy.py 2');
    assert.equal(await page.locator('[data-copy="python"]').isVisible(), true);
    assert.equal(await page.locator('[data-pend="python-note"]').isVisible(), false);
    await page.locator('[data-field="mass"]').fill('0.4');
    await page.waitForFunction(() => document.querySelector('[data-cmd="python"]').textContent === '');
    assert.equal(await page.locator('[data-copy="python"]').isVisible(), false);
    assert.equal(await page.locator('[data-pend="python-note"]').isVisible(), true);
    assert.match(await page.locator('[data-cmd="bsv"]').innerText(), / --mass 0\.4 /);
    const png = await download(page, 'pendulum_energy_plots.png');
    assert.deepEqual([...png.subarray(0, 8)], [0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]);
    const width = png.readUInt32BE(16);
    const sizes = await page.evaluate(() => [...document.querySelectorAll('.pend-plots .pend-stage canvas:first-child')].map((c) => c.width));
    assert.equal(width, sizes[0] + sizes[1], `PNG ${width} px wide, plots ${sizes}`);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('the timestep control sets h (field, URL, run); the end of a damped run offers a replay', async () => {
  const { page, errors, close } = await open();
  try {
    await toStart(page);
    const slider = page.locator('[data-pend="h-slider"]');
    // 0.002 s is the third choice.
    assert.equal(await slider.inputValue(), '2');
    await slider.fill('6');
    assert.equal(await page.locator('[data-field="timestep"]').inputValue(), '0.05');
    await page.waitForFunction(() => /timestep=0\.05/.test(location.hash), null, { timeout: 3000 });
    const want = csvRows(cli(['pendulum-energy', '5', '--timestep', '0.05']).files.get('pendulum_energy.csv'));
    assert.equal(want.length, 100);
    await page.locator('[data-action="step"]').click();
    assert.equal((await pageValues(page)).theta, want[0][1]);
    const notice = page.locator('[data-pend="end"]');
    assert.equal(await notice.isVisible(), false);
    await page.locator('[data-action="end"]').click();
    assert.equal(await notice.isVisible(), true);
    assert.match(await notice.innerText(), /come to rest/);
    await page.locator('[data-action="undamped"]').click();
    assert.equal(await page.locator('[data-field="damping"]').inputValue(), '0');
    await page.waitForFunction(() => document.querySelector('[data-action="run"]').getAttribute('aria-pressed') === 'true');
    // The run button's label follows play and pause (set only when it changes).
    const run = page.locator('[data-action="run"]');
    assert.equal(await run.getAttribute('aria-label'), 'Pause (Space)');
    await run.click();
    assert.equal(await run.getAttribute('aria-label'), 'Play (Space)');
    await run.click();
    assert.equal(await run.getAttribute('aria-label'), 'Pause (Space)');
    assert.equal(await notice.isVisible(), false);
    await page.waitForFunction(() => /damping=0(&|$)/.test(location.hash), null, { timeout: 3000 });
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('the default view swings by itself; play advances t; reduced motion does not autoplay', async () => {
  const { page, errors, close } = await open();
  try {
    await page.waitForFunction(() => Number(document.querySelector('[data-readout="t"]').dataset.value) > 0.05, null, { timeout: 5000 });
    await toStart(page);
    await page.locator('[data-action="run"]').click();
    await page.waitForTimeout(600);
    const t1 = (await pageValues(page)).t;
    assert.ok(t1 > 0.2 && t1 < 2, `t after 0.6 s at 1×: ${t1}`);
    // The URL follows the state.
    await page.waitForFunction(() => /[?&]t=/.test(location.hash), null, { timeout: 3000 });
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
  const ctx = await (await import('./harness.mjs')).browser();
  const c = await ctx.newContext({ reducedMotion: 'reduce' });
  const p = await c.newPage();
  await p.goto(`${server.url}/#/pendulum-energy`);
  await p.waitForFunction(() => document.documentElement.dataset.appReady === '1');
  await p.waitForTimeout(500);
  assert.equal(await p.locator('[data-readout="t"]').getAttribute('data-value'), '0.0');
  await c.close();
});

test('compare mode shows both drifts, RK4 far smaller', async () => {
  const { page, errors, close } = await open('#/pendulum-energy?compare=1&damping=0');
  try {
    assert.equal(await page.locator('[data-field="compare"]').isChecked(), true);
    await page.locator('[data-action="end"]').click();
    const r = await pageValues(page);
    assert.ok(await page.locator('[data-readout="drift-euler"]').isVisible());
    assert.ok(await page.locator('[data-readout="drift-rk4"]').isVisible());
    assert.ok(Math.abs(r['drift-euler']) > 1e-5, `euler ${r['drift-euler']}`);
    assert.ok(Math.abs(r['drift-rk4']) < Math.abs(r['drift-euler']) / 100, `rk4 ${r['drift-rk4']} vs euler ${r['drift-euler']}`);
    assert.equal(r.drift, r['drift-euler']);
    // Every plot panel holds both integrators' curves, each with every step of the run
    // (5 s / 0.002 s = 2500 rows): the plots' own record of their series (data-series).
    const panels = async (role) => (await page.locator(`[data-pend="${role}"]`).getAttribute('data-series'))
      .split(';').map((panel) => Object.fromEntries(panel.split('|').map((s) => {
        const at = s.lastIndexOf('=');
        return [s.slice(0, at), Number(s.slice(at + 1))];
      })));
    const [energy, theta, omega, error] = await panels('time-stage');
    const [phase] = await panels('phase-stage');
    const want = {};
    for (const what of ['ke', 'pe', 'total', 'true energy']) {
      for (const int of ['Euler', 'RK4']) want[`${what} (${int})`] = 2500;
    }
    assert.deepEqual(energy, want);
    assert.ok(phase.separatrix > 100, `separatrix ${phase.separatrix} points`);
    delete phase.separatrix;
    for (const [name, panel] of [['theta', theta], ['omega', omega], ['error', error], ['phase', phase]]) {
      assert.deepEqual(panel, { Euler: 2500, RK4: 2500 }, name);
    }
    // Off again: the drift readouts go, and the plots hold one integrator's curves.
    await page.locator('[data-field="compare"]').uncheck();
    assert.equal(await page.locator('[data-readout="drift-rk4"]').isVisible(), false);
    await page.locator('[data-action="end"]').click();
    const [energyOne] = await panels('time-stage');
    assert.deepEqual(Object.keys(energyOne), ['ke', 'pe', 'total', 'true energy']);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('a bad timestep shows its message and the run keeps the last valid timestep', async () => {
  const want = cli(['pendulum-energy', '5']).files.get('pendulum_energy.csv');
  const rows = csvRows(want);
  const { page, errors, close } = await open();
  try {
    await toStart(page);
    const field = page.locator('[data-field="timestep"]');
    const message = page.locator('[data-field-error="timestep"]');
    assert.equal(await message.isVisible(), false);
    for (const [bad, pattern] of [['abc', /not a number/], ['0', /Integrator step h/], ['1e-9', /1,000,000/]]) {
      await field.fill(bad);
      assert.equal(await message.isVisible(), true, bad);
      assert.match(await message.innerText(), pattern);
      assert.equal(await field.getAttribute('aria-invalid'), 'true');
    }
    await page.locator('[data-action="step"]').click();
    await page.locator('[data-action="step"]').click();
    const r = await pageValues(page);
    assert.deepEqual([r.t, r.theta], [rows[1][0], rows[1][1]]);
    assertSameBytes(await download(page, 'pendulum_energy.csv'), want, 'bad timestep keeps 0.002');
    await field.fill('0.004');
    assert.equal(await message.isVisible(), false);
    await page.waitForFunction(() => /timestep=0\.004/.test(location.hash), null, { timeout: 3000 });
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('Japanese leaves no English UI text', async () => {
  const english = englishStrings();
  const { page, errors, close } = await open('#/pendulum-energy?lang=ja&compare=1');
  try {
    await page.locator('[data-field="timestep"]').fill('abc');
    await page.locator('[data-field="mass"]').fill('-1');
    // Command lines and file names (in <code>) are not UI text.
    const text = await page.evaluate(() => {
      let all = document.body.innerText;
      for (const code of document.querySelectorAll('code')) all = all.replace(code.innerText, '');
      for (const b of document.querySelectorAll('[data-download]')) all = all.replaceAll(b.dataset.download, '');
      return all;
    });
    const left = english.filter((s) => text.includes(s));
    assert.deepEqual(left, [], `English left on the Japanese page: ${left.join(' | ')}`);
    assert.match(text, /振り子のエネルギー/);
    assert.match(text, /セパラトリクス/);
    assert.ok(await page.locator('[data-field-error="timestep"]').isVisible());
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('screenshots: EN and JA 1920×1080, projector, phone 390 px', async () => {
  const shots = [
    ['pendulum-en-1920.png', '#/pendulum-energy?compare=1', { viewport: { width: 1920, height: 1080 } }],
    ['pendulum-ja-1920.png', '#/pendulum-energy?compare=1&lang=ja', { viewport: { width: 1920, height: 1080 } }],
    ['pendulum-projector-1920.png', '#/pendulum-energy?compare=1', { viewport: { width: 1920, height: 1080 }, storage: { 'bsv.projector': '1' } }],
    ['pendulum-phone-390.png', '#/pendulum-energy?lang=ja&compare=1', { viewport: { width: 390, height: 844 } }],
    ['pendulum-phone-390-en.png', '#/pendulum-energy?compare=1', { viewport: { width: 390, height: 844 } }],
  ];
  await screenshots(server.url, shots, {
    prepare: async (page) => {
      await page.waitForTimeout(1200);
      await page.locator('[data-action="run"]').click();
    },
    shot: { caret: 'initial' },
    // An element screenshot taller than the viewport makes Playwright inject a style the CSP
    // blocks (now and then): a phone gets one picture per plot.
    then: async (page, file) => {
      const plots = page.locator('.pend-plots');
      if ((await plots.boundingBox()).height <= page.viewportSize().height) {
        await plots.screenshot({ path: join(OUT, file.replace('.png', '-plots.png')), caret: 'initial' });
      } else {
        for (const which of ['time', 'phase']) {
          await page.locator(`.pend-stage-${which}`).screenshot({ path: join(OUT, file.replace('.png', `-${which}.png`)), caret: 'initial' });
        }
      }
    },
  });
});

test('the opening run loops until a key; then it stops at its end', async () => {
  // A 1 s run (no t= in the URL): it plays by itself, pauses at its end, plays again from 0.
  const { page, errors, close } = await open('#/pendulum-energy?duration_s=1');
  try {
    const t = async () => (await pageValues(page)).t;
    await page.waitForFunction(() => Number(document.querySelector('[data-readout="t"]').dataset.value) >= 0.99, null, { timeout: 5000 });
    const run = page.locator('[data-action="run"]');
    // At the end it pauses (not playing) before it starts again.
    await page.waitForFunction(() => document.querySelector('[data-action="run"]').getAttribute('aria-pressed') === 'false', null, { timeout: 2000 });
    assert.ok((await t()) >= 0.99);
    await page.waitForFunction(() => Number(document.querySelector('[data-readout="t"]').dataset.value) < 0.5, null, { timeout: 4000 });
    const t0 = await t();
    await page.waitForFunction((t0) => Number(document.querySelector('[data-readout="t"]').dataset.value) > t0 + 0.1, t0, { timeout: 3000 });
    assert.equal(await run.getAttribute('aria-pressed'), 'true');
    // A key (space pauses, space plays on): from now on the run stops at its end.
    await page.locator('[data-testid="pendulum-energy-canvas"]').focus();
    await page.keyboard.press(' ');
    assert.equal(await run.getAttribute('aria-pressed'), 'false');
    await page.keyboard.press(' ');
    await page.waitForFunction(() => Number(document.querySelector('[data-readout="t"]').dataset.value) >= 0.99, null, { timeout: 5000 });
    await page.waitForTimeout(2500);
    assert.ok((await t()) >= 0.99, `t ${await t()} after the end and the pause`);
    assert.equal(await run.getAttribute('aria-pressed'), 'false');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('a line beside the readouts says why the two energies differ, EN and JA', async () => {
  for (const [lang, pattern] of [['en', /point mass/], ['ja', /質点/]]) {
    const { page, errors, close } = await open(`#/pendulum-energy?damping=0&lang=${lang}`);
    try {
      const note = page.locator('[data-pend="energy-note"]');
      assert.equal(await note.isVisible(), true, lang);
      assert.match(await note.innerText(), pattern);
      assert.match(await note.innerText(), /I/);
      // In the same card as the two readouts it explains.
      const card = note.locator('xpath=ancestor::section[1]');
      assert.equal(await card.locator('[data-readout="total"]').count(), 1);
      assert.equal(await card.locator('[data-readout="true-energy"]').count(), 1);
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
});
