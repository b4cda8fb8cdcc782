// Embedded pages (`embed=1`) and their postMessage API, in headless Chromium: examples/embed.html,
// served from another port than the app, embeds #/ik-2r and #/pendulum-energy; setState sets a
// pose and getReadouts gives the `bsv` CLI's numbers for it (jacobian-2r's row, pendulum-energy's
// CSV row); step and reset walk the pendulum; a drag inside the frame sends a statechange; each
// of a dozen malformed messages gets an error reply and messages of another namespace none; no
// console error in either frame. The embedded layout at 320×240 and 800×500 (no site chrome,
// the main view inside the frame without scrolling), the "Open in BSV Playground ↗" link's
// address. Screenshots (the course page in English, the frame in Japanese) go to tests/e2e/out/.
import { after, before, test } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { browser, OUT, ROOT } from './harness.mjs';
import { cliCsv, serveAppWithCli } from './cli.mjs';
import { startStaticServer } from '../../scripts/serve.mjs';

// The CLI is built and dist/ served before the tests; all is closed after them.
const app = serveAppWithCli();
// The host: examples/ on a port of its own (another origin than the app).
let host;
before(async () => {
  host = await startStaticServer(join(ROOT, 'examples'));
});
after(() => host?.close());

/** A fresh page of the shared browser, and every console error or page error of any frame. */
async function newPage(viewport) {
  const context = await (await browser()).newContext({ viewport, deviceScaleFactor: 1 });
  const page = await context.newPage();
  const errors = [];
  page.on('console', (m) => {
    if (m.type() === 'error') errors.push(`${m.location()?.url ?? ''}: ${m.text()}`);
  });
  page.on('pageerror', (e) => errors.push(String(e)));
  return { page, errors, close: () => context.close() };
}

/** Opens the course page and waits until both drills said `ready`. */
async function openCoursePage(viewport = { width: 900, height: 1300 }) {
  const opened = await newPage(viewport);
  await opened.page.goto(`${host.url}/embed.html?app=${encodeURIComponent(`${app.url}/`)}`);
  await opened.page.evaluate(() => Promise.all([window.bsvDemo.ik.ready, window.bsvDemo.pendulum.ready]));
  return opened;
}

/** `frame.call(method, ...args)` in the course page: `{ result }` or `{ error, reply }`. */
function call(page, drill, method, ...args) {
  return page.evaluate(
    ([drill, method, args]) => window.bsvDemo[drill].call(method, ...args).then(
      (result) => ({ result }),
      (error) => ({ error: error.message, reply: error.reply }),
    ),
    [drill, method, args],
  );
}

/** The readouts as `{ key: value }` (numbers), and their units. */
async function readouts(page, drill) {
  const { result } = await call(page, drill, 'getReadouts');
  const values = Object.fromEntries(Object.entries(result).map(([k, r]) => [k, r.value]));
  const units = Object.fromEntries(Object.entries(result).map(([k, r]) => [k, r.unit]));
  return { values, units };
}

/** Asserts `got` within `tol` of `want` (relative for |want| > 1). */
function near(got, want, tol, label) {
  assert.ok(Math.abs(got - want) <= tol * Math.max(1, Math.abs(want)), `${label}: ${got} vs ${want}`);
}

test('a host page on another port sets poses and reads the CLI numbers back', async () => {
  const { page, errors, close } = await openCoursePage();
  try {
    assert.notEqual(new URL(host.url).port, new URL(app.url).port);

    // Planar 2R: one pose, the CLI's one-point sweep at the same angles.
    const set = await call(page, 'ik', 'setState', { q1: 0.6, q2: 1.1, elbow: 'down' });
    assert.equal(set.result.q1, '0.6');
    assert.equal(set.result.q2, '1.1');
    assert.deepEqual((await call(page, 'ik', 'getState')).result, set.result);
    const { head, rows } = cliCsv(['jacobian-2r', '0.12', '0.10', '0.6', '0.6', '1', '1.1'], 'jacobian_2r.csv');
    assert.equal(rows.length, 1);
    const want = Object.fromEntries(head.map((h, i) => [h, Number(rows[0][i])]));
    const { values: ik, units: ikUnits } = await readouts(page, 'ik');
    assert.equal(ik.q1, 0.6);
    assert.equal(ik.q2, 1.1);
    near(ik.x_mm, want.x_m * 1000, 5e-4, 'x_mm');
    near(ik.y_mm, want.y_m * 1000, 5e-4, 'y_mm');
    for (const key of ['det_j', 'manipulability', 'sigma_min', 'sigma_max']) near(ik[key], want[key], 5e-6, key);
    assert.deepEqual([ikUnits.q1, ikUnits.x_mm, ikUnits.det_j, ikUnits.sigma_min, ikUnits.j11], ['rad', 'mm', 'm²', 'm', 'm/rad']);

    // Bad keys are named; the last good values stay.
    const bad = await call(page, 'ik', 'setState', { q1: 'abc', q2: 0.9, zoom: 2, lang: 'ja' });
    assert.match(bad.error, /q1 \(invalid\)/);
    assert.deepEqual(bad.reply.ignored.map((k) => k.key).sort(), ['lang', 'q1', 'zoom']);
    assert.equal(bad.reply.state.q1, '0.6');
    assert.equal(bad.reply.state.q2, '0.9');
    assert.equal((await readouts(page, 'ik')).values.q1, 0.6);

    // The pendulum: after setState at t = 0.5 s (50 steps of 0.01 s) the readouts are row 50
    // of the CLI's CSV; step and reset walk it.
    const csv = cliCsv(['pendulum-energy', '5', '--angle-deg', '90', '--timestep', '0.01'], 'pendulum_energy.csv');
    const row = (k) => csv.rows[k - 1].map(Number);
    const pendulumRow = async () => {
      const { values: r } = await readouts(page, 'pendulum');
      return [r.t, r.theta, r.omega, r.ke, r.pe, r.total];
    };
    const setPendulum = await call(page, 'pendulum', 'setState', { 'angle-deg': 90, timestep: 0.01, t: 0.5 });
    assert.equal(setPendulum.error, undefined, setPendulum.error);
    assert.deepEqual(await pendulumRow(), row(50));
    assert.equal((await call(page, 'pendulum', 'step', 3)).result, 53);
    assert.deepEqual(await pendulumRow(), row(53));
    assert.equal((await call(page, 'pendulum', 'step', -1)).result, 52);
    assert.deepEqual(await pendulumRow(), row(52));
    assert.equal((await call(page, 'pendulum', 'reset')).result, 0);
    const start = await readouts(page, 'pendulum');
    assert.equal(start.values.t, 0);
    assert.equal(start.values.theta, Math.PI / 2);
    assert.equal(start.units.ke, 'J');
    // The planar arm has no stepper.
    assert.match((await call(page, 'ik', 'step', 1)).error, /does not step/);

    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('a drag inside the frame sends statechange; malformed messages get error replies', async () => {
  const { page, errors, close } = await openCoursePage();
  try {
    await call(page, 'ik', 'setState', { q1: 0.6, q2: 1.1, elbow: 'down' });
    await page.evaluate(() => {
      window.stateChanges = [];
      window.bsvDemo.ik.on('statechange', (m) => window.stateChanges.push(m.state));
    });
    const frame = page.frames().find((f) => f.url().includes('#/ik-2r'));
    const box = await page.locator('iframe[data-drill="ik-2r"]').boundingBox();
    const tip = await frame.evaluate(() => {
      const c = document.querySelector('[data-testid="ik-2r-canvas"]');
      const r = c.getBoundingClientRect();
      return { x: r.left + Number(c.dataset.tipX), y: r.top + Number(c.dataset.tipY) };
    });
    await page.mouse.move(box.x + tip.x, box.y + tip.y);
    await page.mouse.down();
    await page.mouse.move(box.x + tip.x - 40, box.y + tip.y + 30, { steps: 6 });
    await page.mouse.up();
    await page.waitForFunction(() => window.stateChanges.length > 0, null, { timeout: 5000 });

    // A wheel turn over the canvas in use (pressed since the pointer came in) scrolls neither
    // the frame nor the host; once the pointer has left the frame and come back, one does.
    const scrolled = async () => (await page.evaluate(() => scrollY)) + (await frame.evaluate(() => scrollY));
    const over = { x: box.x + tip.x - 120, y: box.y + tip.y + 60 };
    await page.mouse.move(over.x, over.y);
    await page.mouse.wheel(0, 200);
    await page.mouse.move(2, 2);
    await page.mouse.move(over.x, over.y);
    await page.mouse.wheel(0, 200);
    let total = 0;
    for (let i = 0; i < 40 && total === 0; i += 1) {
      total = await scrolled();
      if (total === 0) await page.waitForTimeout(50);
    }
    assert.ok(total > 0 && total <= 201, `scrolled ${total} px for two turns of 200 px, one over the canvas in use`);
    const changed = await page.evaluate(() => window.stateChanges.at(-1));
    assert.notEqual(changed.q1, '0.6');
    assert.deepEqual((await call(page, 'ik', 'getState')).result, changed);

    // A dozen malformed messages, two of another namespace, then one good request: the API
    // answers in order, so once the good one is answered every other reply is in.
    const replies = await page.evaluate(() => new Promise((resolve) => {
      const got = [];
      const ik = window.bsvDemo.ik.iframe.contentWindow;
      window.addEventListener('message', (e) => {
        if (e.source !== ik || e.data?.event) return;
        const data = typeof e.data === 'string' ? JSON.parse(e.data) : e.data;
        got.push(data);
        if (data.id === 'last') resolve(got);
      });
      const messages = [
        '{',
        '{"namespace":"bsv","id":"s1","method":"reset"}',
        { namespace: 'bsv' },
        { namespace: 'bsv', id: 1 },
        { namespace: 'bsv', id: 2, method: 'fly' },
        { namespace: 'bsv', id: 3, method: 42 },
        { namespace: 'bsv', id: { no: 1 }, method: 'getState' },
        { namespace: 'bsv', id: 4, method: 'getState', args: 'x' },
        { namespace: 'bsv', id: 5, method: 'getReadouts', args: [1] },
        { namespace: 'bsv', id: 6, method: 'setState' },
        { namespace: 'bsv', id: 7, method: 'setState', args: [[1, 2]] },
        { namespace: 'bsv', id: 8, method: 'step', args: [1.5] },
        { namespace: 'bsv', id: 9, method: 'step', args: ['3'] },
        { namespace: 'bsv', id: 10, method: 'setState', args: [{ q1: { deg: 30 } }] },
        { namespace: 'reveal', id: 11, method: 'slide' },
        'hello',
        { namespace: 'bsv', id: 'last', method: 'getState' },
      ];
      for (const m of messages) ik.postMessage(m, '*');
    }));
    const last = replies.pop();
    assert.deepEqual(last.result, changed);
    assert.equal(replies.length, 14, JSON.stringify(replies));
    for (const reply of replies) {
      assert.equal(reply.namespace, 'bsv');
      assert.equal(typeof reply.error, 'string', JSON.stringify(reply));
      assert.equal('result' in reply, false);
    }
    assert.deepEqual(replies.map((r) => r.id), [null, 's1', null, 1, 2, 3, null, 4, 5, 6, 7, 8, 9, 10]);
    assert.deepEqual(replies[13].ignored, [{ key: 'q1', reason: 'invalid' }]);
    // The state the drag left is kept.
    assert.deepEqual((await call(page, 'ik', 'getState')).result, changed);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

/** The embedded page's chrome and main view, seen from inside its frame. */
function frameLayout(frame) {
  return frame.evaluate(() => {
    const shown = (selector) => [...document.querySelectorAll(selector)].some((e) => e.getClientRects().length > 0);
    const view = document.querySelector('[data-embed-view]');
    const r = view?.getBoundingClientRect();
    const link = document.querySelector('[data-testid="embed-open"]');
    return {
      chrome: ['.site-header', '.site-footer', '.drill-chain', '.lesson-bar'].filter(shown),
      view: r && { left: r.left, top: r.top, right: r.right, bottom: r.bottom },
      width: innerWidth,
      height: innerHeight,
      scrollY,
      link: link && { href: link.href, target: link.target, text: link.textContent, shown: link.getClientRects().length > 0 },
    };
  });
}

/** A page holding one frame of the app at `hash`, `width`×`height`. */
async function framed(hash, width, height) {
  const opened = await newPage({ width: width + 40, height: height + 40 });
  await opened.page.setContent(`<iframe src="${app.url}/${hash}" width="${width}" height="${height}" style="border:0;display:block"></iframe>`);
  const frame = opened.page.frames().find((f) => f !== opened.page.mainFrame());
  await frame.waitForFunction(() => document.documentElement.dataset.appReady === '1' && document.querySelector('[data-embed-view]'), null, { timeout: 20000 });
  return { ...opened, frame };
}

test('embedded layout: no chrome, the main view in the frame at 800×500, usable at 320×240', async () => {
  for (const [hash, page] of [['#/ik-2r?q1=0.5&embed=1', 'ik-2r'], ['#/pendulum-energy?embed=1&lang=ja', 'pendulum-energy']]) {
    for (const [width, height] of [[800, 500], [320, 240]]) {
      const { page: host, frame, errors, close } = await framed(hash, width, height);
      try {
        const layout = await frameLayout(frame);
        const where = `${page} at ${width}×${height}`;
        assert.deepEqual(layout.chrome, [], where);
        assert.equal(layout.scrollY, 0, where);
        const v = layout.view;
        assert.ok(v.left >= 0 && v.right <= layout.width, `${where}: main view ${JSON.stringify(v)}`);
        assert.ok(layout.link.shown, where);
        assert.equal(layout.link.target, '_blank');
        const open = new URL(layout.link.href);
        assert.equal(open.origin, app.url);
        assert.ok(!open.hash.includes('embed'), open.hash);
        assert.ok(open.hash.startsWith(`#/${page}`), open.hash);
        if (width >= 800) {
          assert.ok(v.left >= 0 && v.top >= 0 && v.right <= layout.width && v.bottom <= layout.height,
            `${where}: main view ${JSON.stringify(v)}`);
          assert.ok(v.bottom - v.top >= 0.6 * height, `${where}: main view only ${v.bottom - v.top} px high`);
        }
        if (page === 'ik-2r') assert.match(open.hash, /[?&]q1=0\.5(&|$)/);
        if (width === 800) {
          await host.screenshot({ path: join(OUT, `embed-${page}-${width}x${height}.png`) });
        }
        assert.deepEqual(errors, []);
      } finally {
        await close();
      }
    }
  }
});

test('screenshot: the course page with both drills (English)', async () => {
  const { page, errors, close } = await openCoursePage({ width: 900, height: 2150 });
  try {
    await page.locator('#ik [data-pose="0.6,1.1"]').click();
    await page.locator('#pendulum [data-start="90"]').click();
    await page.locator('#pendulum [data-step="10"]').click();
    await page.waitForFunction(() => document.querySelectorAll('#pendulum .log').length
      && document.querySelector('#pendulum .log').textContent.includes('→ 10'), null, { timeout: 5000 });
    // The readouts event after the tenth step has come.
    const t = String((await readouts(page, 'pendulum')).values.t);
    await page.waitForFunction((t) => [...document.querySelectorAll('#pendulum .readouts tr')]
      .some((row) => row.cells[0].textContent === 't' && row.cells[1].textContent === t), t, { timeout: 5000 });
    // The viewport, not `fullPage`: a full-page capture leaves the first frame blank.
    await page.screenshot({ path: join(OUT, 'embed-course-page-en.png') });
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});
