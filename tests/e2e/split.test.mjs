// The app split by route: each page's code arrives when the page is first opened (or in the
// background after the first page). A page whose code cannot be fetched shows its frame, a
// localized message and Retry, and recovers once the file is reachable; a slow network shows
// the page's frame and its loading line, then the page; switching language fetches the other
// language's strings without losing what the page holds.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { serveApp, openApp, readouts, throttle, DIST, OUT } from './harness.mjs';

const server = serveApp();
const table = JSON.parse(readFileSync(join(DIST, 'pkg', 'routes.json'), 'utf8'));

/** Saves a screenshot of `page` at `viewport` into the e2e output folder. */
async function shoot(page, file, viewport) {
  await page.setViewportSize(viewport);
  await page.waitForTimeout(200);
  await page.screenshot({ path: join(OUT, `${file}.png`) });
}

/** Console errors that are the app's (the browser's own line for a refused file is not). */
const appErrors = (errors) => errors.filter((e) => !/Failed to load resource/.test(e));

/** Blocks (404) every file of the split point of `route`: its pack and its own module. */
async function block(context, route) {
  const split = table.splits[route];
  const pattern = new RegExp(`/pkg/(pack_${split}(-after-\\w+)?\\.bin|chunks/split_${split}\\.wasm)$`);
  await context.route(pattern, (r) => r.fulfill({ status: 404, body: 'not found' }));
  return pattern;
}

test('every page of the page table has a pack, and the build lists what each route loads first', async () => {
  const { page, close } = await openApp(server.url, '#/');
  try {
    const ids = await page.evaluate(async () =>
      (await import(new URL('pkg/bsv_playground.js', document.baseURI).href)).pageTable().map((p) => p.id));
    assert.deepEqual(Object.keys(table.routes).sort(), [...ids].sort());
    assert.deepEqual(Object.keys(table.strings.routes).sort(), [...ids].sort());
    assert.ok(table.strings.first.includes('shell.ftl') && table.strings.first.includes('pages.ftl'));
    assert.deepEqual(table.strings.routes['ik-2r'], ['ik2r.ftl', 'recipes.ftl']);
    // The strings are the files of locales/, byte for byte, in both languages.
    for (const lang of ['en', 'ja']) {
      for (const file of new Set([...table.strings.first, ...Object.values(table.strings.routes).flat()])) {
        assert.deepEqual(readFileSync(join(DIST, 'locales', lang, file)), readFileSync(join(DIST, '..', 'locales', lang, file)), `${lang}/${file}`);
      }
      // A route's strings pack holds the files it needs first, each whole.
      for (const [route, own] of Object.entries(table.strings.routes)) {
        const pack = JSON.parse(readFileSync(join(DIST, 'locales', lang, `pack_${route}.json`), 'utf8'));
        assert.deepEqual(Object.keys(pack), [...table.strings.first, ...own], `${lang} ${route}`);
        for (const [file, text] of Object.entries(pack)) {
          assert.equal(text, readFileSync(join(DIST, '..', 'locales', lang, file), 'utf8'), `${lang} ${route} ${file}`);
        }
      }
    }
  } finally {
    await close();
  }
});

test('a first visit fetches the strings its page needs in its language only, in one request', async () => {
  const { page, close } = await openApp(server.url, '#/ik-2r?lang=ja');
  try {
    const fetched = await page.evaluate(() =>
      performance.getEntriesByType('resource').map((e) => new URL(e.name).pathname).filter((p) => p.includes('/locales/')));
    assert.equal(fetched[0], '/locales/ja/pack_ik-2r.json');
    // What the pack holds is not fetched again (the other language's files come later).
    const own = table.strings.routes['ik-2r'];
    for (const file of [...table.strings.first, ...own]) {
      assert.ok(!fetched.includes(`/locales/ja/${file}`), `${file} fetched besides the pack`);
    }
    assert.match(await page.locator('h1').first().textContent(), /IK/);
  } finally {
    await close();
  }
});

for (const lang of ['en', 'ja']) {
  test(`a page whose code cannot be fetched says so with Retry, and Retry works once it can (${lang})`, async () => {
    const { page, context, errors, close } = await openApp(server.url, `#/?lang=${lang}`);
    try {
      const pattern = await block(context, 'dh-fk');
      // The background loading of the rest may have fetched it already: start a new tab's
      // worth of state by reloading with the block in place.
      await page.reload();
      await page.waitForFunction(() => document.documentElement.dataset.appReady === '1');
      await page.evaluate(() => { location.hash = '#/dh-fk'; });
      const failed = page.locator('[data-testid="page-load-failed"]');
      await failed.waitFor({ state: 'visible', timeout: 15000 });
      const text = await failed.innerText();
      assert.match(text, lang === 'en' ? /could not be loaded/ : /読み込めませんでした/);
      // The page's frame stays: its title, in the page's language.
      assert.equal(
        await page.locator('[data-testid="page-frame"] h1').innerText(),
        lang === 'en' ? 'DH forward kinematics in 3D' : 'DH 順運動学を 3D で',
      );
      const retry = page.locator('[data-action="retry"]');
      assert.equal(await retry.innerText(), lang === 'en' ? 'Retry' : '再試行');
      await shoot(page, `split-load-failed-${lang}-390`, { width: 390, height: 844 });
      // Still unreachable: Retry fails again, visibly.
      await retry.click();
      await failed.waitFor({ state: 'visible' });
      // Reachable again: Retry shows the page.
      await context.unroute(pattern);
      await page.locator('[data-action="retry"]').click();
      await page.locator('[data-testid="page-load-failed"]').waitFor({ state: 'detached', timeout: 15000 });
      await page.locator('[data-readout]').first().waitFor({ timeout: 15000 });
      assert.ok(Object.keys(await readouts(page)).length > 0, 'the DH page is mounted');
      assert.deepEqual(appErrors(errors), []);
    } finally {
      await close();
    }
  });
}

for (const lang of ['en', 'ja']) {
  test(`the home page's arm is live before its tiles and cards; if their code cannot be fetched, a line says so with Retry (${lang})`, async () => {
    const { page, context, errors, close } = await openApp(server.url, `#/lesson?lang=${lang}`);
    try {
      const pattern = /\/pkg\/(pack_home_cards(-after-\w+)?\.bin|chunks\/split_home_cards\.wasm)$/;
      await context.route(pattern, (r) => r.fulfill({ status: 404, body: 'not found' }));
      await page.evaluate((l) => { location.hash = `#/?lang=${l}`; }, lang);
      await page.reload();
      await page.waitForFunction(() => document.documentElement.dataset.appReady === '1');
      const line = page.locator('[data-testid="home-more"]');
      await line.and(page.locator('[data-state="failed"]')).waitFor({ timeout: 15000 });
      assert.match(await line.innerText(), lang === 'en' ? /could not be loaded/ : /読み込めませんでした/);
      assert.equal(await line.getAttribute('role'), 'alert');
      // The arm is live meanwhile: an arrow key moves it.
      const q1 = await page.locator('[data-testid="home-arm-q1"]').innerText();
      await page.locator('[data-testid="home-arm-canvas"]').focus();
      await page.keyboard.press('ArrowUp');
      await page.waitForFunction((before) => document.querySelector('[data-testid="home-arm-q1"]').textContent !== before, q1);
      await page.setViewportSize({ width: 390, height: 844 });
      await line.scrollIntoViewIfNeeded();
      await shoot(page, `home-more-failed-${lang}-390`, { width: 390, height: 844 });
      await context.unroute(pattern);
      await line.locator('[data-action="retry"]').click();
      await line.waitFor({ state: 'detached', timeout: 15000 });
      assert.equal(await page.locator('.recipe-card').count(), 12);
      assert.ok(await page.locator('[data-testid="featured-ik-2r"]').isVisible());
      assert.deepEqual(appErrors(errors), []);
    } finally {
      await close();
    }
  });
}

for (const lang of ['en', 'ja']) {
  test(`the IK page's arm is live before its heatmap, plot and downloads; if their code cannot be fetched, a line says so with Retry (${lang})`, async () => {
    const { page, context, errors, close } = await openApp(server.url, `#/lesson?lang=${lang}`, { viewport: { width: 1280, height: 900 } });
    try {
      const pattern = /\/pkg\/(pack_ik2r_more(-after-\w+)?\.bin|chunks\/split_ik2r_more\.wasm)$/;
      await context.route(pattern, (r) => r.fulfill({ status: 404, body: 'not found' }));
      await page.evaluate((l) => { location.hash = `#/ik-2r?lang=${l}`; }, lang);
      await page.reload();
      await page.waitForFunction(() => document.documentElement.dataset.appReady === '1');
      const line = page.locator('[data-testid="ik-2r-more"]');
      await line.and(page.locator('[data-state="failed"]')).waitFor({ timeout: 15000 });
      assert.match(await line.innerText(), lang === 'en' ? /could not be loaded/ : /読み込めませんでした/);
      assert.equal(await line.getAttribute('role'), 'alert');
      assert.equal(await page.locator('[data-testid="ik-2r-heatmap"]').isVisible(), false);
      assert.equal(await page.locator('[data-testid="ik-2r-plot"]').isVisible(), false);
      assert.equal(await page.locator('[data-download="ik_workspace.csv"]').count(), 0);
      // The arm is live meanwhile: dragging the tip moves the readouts.
      const canvas = page.locator('[data-testid="ik-2r-canvas"][data-tip-x]');
      await canvas.waitFor();
      const q1 = await page.locator('[data-readout="q1"]').innerText();
      const g = await canvas.evaluate((c) => {
        const r = c.getBoundingClientRect();
        return { x: r.left + +c.dataset.tipX, y: r.top + +c.dataset.tipY };
      });
      await page.mouse.move(g.x, g.y);
      await page.mouse.down();
      await page.mouse.move(g.x - 40, g.y + 30, { steps: 5 });
      await page.mouse.up();
      await page.waitForFunction((before) => document.querySelector('[data-readout="q1"]').textContent !== before, q1);
      // Keys too.
      const q2 = await page.locator('[data-readout="q2"]').innerText();
      await page.locator('[data-testid="ik-2r-canvas"]').focus();
      await page.keyboard.press('=');
      await page.waitForFunction((before) => document.querySelector('[data-readout="q2"]').textContent !== before, q2);
      await page.setViewportSize({ width: 390, height: 844 });
      await line.scrollIntoViewIfNeeded();
      await shoot(page, `ik2r-more-failed-${lang}-390`, { width: 390, height: 844 });
      // Still unreachable: Retry fails again, visibly.
      await line.locator('[data-action="retry"]').click();
      await line.and(page.locator('[data-state="failed"]')).waitFor({ timeout: 15000 });
      // A click by the tip moves it there by IK with the platform's functions meanwhile.
      await page.setViewportSize({ width: 1280, height: 900 });
      await canvas.scrollIntoViewIfNeeded();
      const spot = await canvas.evaluate((c) => ({
        x: +c.dataset.tipX + 6, y: +c.dataset.tipY + 4, origin: c.dataset.originX, ppm: c.dataset.pxPerM,
      }));
      const click = async () => {
        const r = await canvas.evaluate((c) => { const b = c.getBoundingClientRect(); return { x: b.left, y: b.top }; });
        await page.mouse.click(r.x + spot.x, r.y + spot.y);
      };
      const pose = () => page.evaluate(() => {
        const q = new URLSearchParams(location.hash.split('?')[1]);
        return `${q.get('q1')} ${q.get('q2')}`;
      });
      const before = await pose();
      await click();
      await page.waitForFunction((b) => {
        const q = new URLSearchParams(location.hash.split('?')[1]);
        return `${q.get('q1')} ${q.get('q2')}` !== b;
      }, before);
      // Reachable again: Retry brings the heatmap, the plot, the form and the downloads,
      // drawn from the pose as it is now.
      await context.unroute(pattern);
      await line.locator('[data-action="retry"]').click();
      await line.waitFor({ state: 'detached', timeout: 15000 });
      const heatmap = page.locator('[data-testid="ik-2r-heatmap"][data-marker-q1]');
      await heatmap.waitFor({ timeout: 15000 });
      // The pose is solved again with the correctly rounded functions: the same click now
      // gives the same pose, to the last digit of the link.
      await page.waitForTimeout(400);
      const resolved = await pose();
      assert.deepEqual(
        await canvas.evaluate((c) => [c.dataset.originX, c.dataset.pxPerM]), [spot.origin, spot.ppm],
        'the arm view kept its scale',
      );
      await click();
      await page.waitForTimeout(400);
      assert.equal(await pose(), resolved);
      const shown = Number(await page.locator('[data-readout="q1"]').innerText());
      assert.ok(Math.abs(Number(await heatmap.getAttribute('data-marker-q1')) - shown) < 1e-5, 'the marker is at the pose');
      assert.ok(await page.locator('[data-testid="ik-2r-plot"]').isVisible());
      assert.ok(await page.locator('[data-ik2r="form"] input').first().isVisible());
      for (const file of ['ik_workspace.csv', 'jacobian_2r.csv', 'manip_ellipse.csv']) {
        assert.ok(await page.locator(`[data-download="${file}"]`).isVisible(), file);
      }
      assert.deepEqual(appErrors(errors), []);
    } finally {
      await close();
    }
  });
}

for (const lang of ['en', 'ja']) {
  test(`the Umeyama page's points, fit and steps are live before its exports; if their code cannot be fetched, a line says so with Retry (${lang})`, async () => {
    const { page, context, errors, close } = await openApp(server.url, `#/lesson?lang=${lang}`, { viewport: { width: 1280, height: 900 } });
    try {
      const pattern = /\/pkg\/(pack_umeyama_more(-after-\w+)?\.bin|chunks\/split_umeyama_more\.wasm)$/;
      await context.route(pattern, (r) => r.fulfill({ status: 404, body: 'not found' }));
      await page.evaluate((l) => { location.hash = `#/umeyama-2d?lang=${l}`; }, lang);
      await page.reload();
      await page.waitForFunction(() => document.documentElement.dataset.appReady === '1');
      const line = page.locator('[data-testid="umeyama-2d-more"]');
      await line.and(page.locator('[data-state="failed"]')).waitFor({ timeout: 15000 });
      assert.match(await line.innerText(), lang === 'en' ? /could not be loaded/ : /読み込めませんでした/);
      assert.equal(await line.getAttribute('role'), 'alert');
      assert.equal(await page.locator('[data-download="umeyama_2d.csv"]').isVisible(), false);
      assert.equal(await page.locator('[data-cmd="bsv"]').isVisible(), false);
      // The page is live meanwhile: dragging a point moves the readouts and the URL.
      const canvas = page.locator('[data-testid="umeyama-2d-canvas"][data-points-px]');
      await canvas.waitFor();
      await canvas.scrollIntoViewIfNeeded();
      const rmse = await page.locator('[data-readout="rmse"]').innerText();
      const g = await canvas.evaluate((c) => {
        const r = c.getBoundingClientRect();
        const [x, y] = c.dataset.pointsPx.split(';')[0].split(',').map(Number);
        return { x: r.left + x, y: r.top + y };
      });
      await page.mouse.move(g.x, g.y);
      await page.mouse.down();
      await page.mouse.move(g.x + 40, g.y - 30, { steps: 5 });
      await page.mouse.up();
      await page.waitForFunction((before) => document.querySelector('[data-readout="rmse"]').textContent !== before, rmse);
      await page.waitForFunction(() => /[?&]x=/.test(location.hash), null, { timeout: 3000 });
      // Keys too: the truth's translation, selected with n, moved with Shift + an arrow.
      const tx = await page.locator('[data-readout="tx-true"]').innerText();
      await page.locator('[data-testid="umeyama-2d-canvas"]').focus();
      for (let k = 0; k < 20; k++) {
        if ((await canvas.getAttribute('data-selected')) === 't') break;
        await page.keyboard.press('n');
      }
      assert.equal(await canvas.getAttribute('data-selected'), 't');
      await page.keyboard.press('Shift+ArrowRight');
      await page.waitForFunction((before) => document.querySelector('[data-readout="tx-true"]').textContent !== before, tx);
      // And the stepper.
      const title = await page.locator('[data-testid="umeyama-2d-step"] h3').innerText();
      await page.keyboard.press('ArrowRight');
      await page.waitForFunction((before) => document.querySelector('[data-testid="umeyama-2d-step"] h3').textContent !== before, title);
      await page.setViewportSize({ width: 390, height: 844 });
      await line.scrollIntoViewIfNeeded();
      await shoot(page, `umeyama-more-failed-${lang}-390`, { width: 390, height: 844 });
      // Still unreachable: Retry fails again, visibly.
      await line.locator('[data-action="retry"]').click();
      await line.and(page.locator('[data-state="failed"]')).waitFor({ timeout: 15000 });
      // Reachable again: Retry brings the downloads and the command lines, of the run as it is now.
      await context.unroute(pattern);
      await line.locator('[data-action="retry"]').click();
      await line.waitFor({ state: 'detached', timeout: 15000 });
      await page.locator('[data-download="umeyama_2d.csv"]').waitFor({ timeout: 15000 });
      for (const file of ['umeyama_2d.csv', 'umeyama_points.csv', 'umeyama_2d.png']) {
        assert.ok(await page.locator(`[data-download="${file}"]`).isVisible(), file);
      }
      const bsv = await page.locator('[data-cmd="bsv"]').innerText();
      assert.match(bsv, /^bsv umeyama-2d 0\.02 3 12 /);
      assert.match(bsv, / --tx /);
      assert.match(bsv, / --x '/);
      assert.ok(await page.locator('[data-cmd="python"]').isVisible());
      assert.deepEqual(appErrors(errors), []);
    } finally {
      await close();
    }
  });
}

for (const lang of ['en', 'ja']) {
  test(`the SO-101 arm flies before the session files' code is here; a download says so if it cannot be fetched, and works once it can (${lang})`, async () => {
    const { page, context, errors, close } = await openApp(server.url, `#/lesson?lang=${lang}`, { viewport: { width: 1280, height: 900 } });
    try {
      const pattern = /\/pkg\/(pack_so101_files(-after-\w+)?\.bin|chunks\/split_so101_files\.wasm)$/;
      await context.route(pattern, (r) => r.fulfill({ status: 404, body: 'not found' }));
      await page.evaluate((l) => { location.hash = `#/so101?lang=${l}`; }, lang);
      await page.reload();
      await page.waitForFunction(() => document.documentElement.dataset.appReady === '1');
      const canvas = page.locator('[data-testid="so101-canvas"]');
      await canvas.waitFor();
      const error = page.locator('[data-so101="open-error"]');
      // Nothing is said before the pilot asks for a file.
      await page.waitForTimeout(500);
      assert.equal(await error.isVisible(), false);
      // The arm flies meanwhile.
      const x = await page.locator('[data-readout="x"]').getAttribute('data-value');
      await canvas.focus();
      await page.keyboard.down('w');
      await page.waitForFunction((before) => document.querySelector('[data-readout="x"]').dataset.value !== before, x);
      await page.keyboard.up('w');
      const button = page.locator('[data-download="so101_episodes.csv"]');
      await button.click();
      await error.waitFor({ state: 'visible', timeout: 15000 });
      assert.match(await error.innerText(), lang === 'en' ? /could not be loaded/ : /読み込めませんでした/);
      assert.equal(await error.getAttribute('role'), 'alert');
      // Reachable again: the same button downloads the file and the line goes.
      await context.unroute(pattern);
      const [file] = await Promise.all([page.waitForEvent('download'), button.click()]);
      assert.equal(file.suggestedFilename(), 'so101_episodes.csv');
      await error.waitFor({ state: 'hidden', timeout: 15000 });
      assert.deepEqual(appErrors(errors), []);
    } finally {
      await close();
    }
  });
}

test('#/teleop: a download says so if the session files\' code cannot be fetched, and works once it can', async () => {
  const { page, context, errors, close } = await openApp(server.url, '#/lesson?lang=ja', { viewport: { width: 1280, height: 900 } });
  try {
    const pattern = /\/pkg\/(pack_teleop_files(-after-\w+)?\.bin|chunks\/split_teleop_files\.wasm)$/;
    await context.route(pattern, (r) => r.fulfill({ status: 404, body: 'not found' }));
    await page.evaluate(() => { location.hash = '#/teleop?lang=ja'; });
    await page.reload();
    await page.waitForFunction(() => document.documentElement.dataset.appReady === '1');
    await page.locator('[data-testid="teleop-canvas"]').waitFor();
    const button = page.locator('[data-download="teleop_episodes.csv"]').first();
    await button.click();
    const error = page.locator('[data-tele="open-error"]');
    await error.waitFor({ state: 'visible', timeout: 15000 });
    assert.match(await error.innerText(), /読み込めませんでした/);
    await context.unroute(pattern);
    const [file] = await Promise.all([page.waitForEvent('download'), button.click()]);
    assert.equal(file.suggestedFilename(), 'teleop_episodes.csv');
    await error.waitFor({ state: 'hidden', timeout: 15000 });
    assert.deepEqual(appErrors(errors), []);
  } finally {
    await close();
  }
});

for (const lang of ['en', 'ja']) {
  test(`"+ Lesson" says so when its code cannot be fetched, and adds the view once it can (${lang})`, async () => {
    const { page, context, errors, close } = await openApp(server.url, `#/pid-step?Kp=2&lang=${lang}`);
    try {
      const pattern = /\/pkg\/(pack_lesson_add(-after-\w+)?\.bin|chunks\/split_lesson_add\.wasm)$/;
      await context.route(pattern, (r) => r.fulfill({ status: 404, body: 'not found' }));
      await page.reload();
      await page.waitForFunction(() => document.documentElement.dataset.appReady === '1');
      const status = page.locator('[data-testid="lesson-add-status"]');
      await page.click('[data-testid="lesson-add"]');
      await page.waitForFunction(() => document.querySelector('[data-testid="lesson-add-status"]').textContent !== '');
      assert.match(await status.innerText(), lang === 'en' ? /Could not load what adds a view to the lesson/ : /読み込めませんでした/);
      assert.equal(await status.getAttribute('role'), 'alert');
      assert.ok(await status.isVisible());
      assert.equal(await page.evaluate(() => localStorage.getItem('bsv.lesson')), null);
      await shoot(page, `lesson-add-failed-${lang}-390`, { width: 390, height: 844 });
      await shoot(page, `lesson-add-failed-${lang}-1366`, { width: 1366, height: 800 });
      await context.unroute(pattern);
      await page.click('[data-testid="lesson-add"]');
      await page.waitForFunction(() => document.querySelector('[data-testid="lesson-add-status"]').getAttribute('role') === 'status');
      assert.match(await status.textContent(), lang === 'en' ? /step 1 / : /ステップ 1 /);
      const stored = JSON.parse(await page.evaluate(() => localStorage.getItem('bsv.lesson')));
      assert.match(stored.steps[0].route, /^#\/pid-step\?/);
      assert.deepEqual(appErrors(errors), []);
    } finally {
      await close();
    }
  });
}

for (const lang of ['en', 'ja']) {
  test(`"?" says so when the shortcuts' code cannot be fetched, and opens them once it can (${lang})`, async () => {
    const { page, context, errors, close } = await openApp(server.url, `#/rrt-2d?lang=${lang}`);
    try {
      const pattern = /\/pkg\/(pack_shortcuts_overlay(-after-\w+)?\.bin|chunks\/split_shortcuts_overlay\.wasm)$/;
      await context.route(pattern, (r) => r.fulfill({ status: 404, body: 'not found' }));
      await page.reload();
      await page.waitForFunction(() => document.documentElement.dataset.appReady === '1');
      const status = page.locator('[data-testid="help-status"]');
      await page.click('[data-testid="help-button"]');
      await page.waitForFunction(() => document.querySelector('[data-testid="help-status"]').textContent !== '');
      assert.match(await status.innerText(), lang === 'en' ? /Could not load the list of keyboard shortcuts/ : /読み込めませんでした/);
      assert.equal(await status.getAttribute('role'), 'alert');
      assert.ok(await status.isVisible());
      await shoot(page, `help-failed-${lang}-390`, { width: 390, height: 844 });
      await context.unroute(pattern);
      await page.keyboard.press('?');
      await page.locator('[data-testid="shortcut-overlay"]').waitFor({ state: 'visible' });
      assert.equal(await status.textContent(), '');
      assert.equal(await status.getAttribute('role'), 'status');
      assert.deepEqual(appErrors(errors), []);
    } finally {
      await close();
    }
  });
}

for (const lang of ['en', 'ja']) {
  test(`the drills page says so when its kernels cannot be fetched, and Run works once they can (${lang})`, async () => {
    const { page, context, errors, close } = await openApp(server.url, `#/lesson?lang=${lang}`);
    try {
      const pattern = /\/pkg\/(pack_worker(-after-\w+)?\.bin|chunks\/split_worker\.wasm)$/;
      await context.route(pattern, (r) => r.fulfill({ status: 404, body: 'not found' }));
      await page.evaluate(() => { location.hash = '#/drills?recipe=pid-step'; });
      const error = page.locator('[data-testid="drills-error"]');
      await error.waitFor({ state: 'visible', timeout: 15000 });
      assert.match(await error.innerText(), lang === 'en' ? /The code that runs the drills could not be loaded/ : /ドリルを実行するコードを読み込めませんでした/);
      assert.equal(await page.evaluate(() => Number(document.querySelector('[data-testid="drills-output"]').dataset.run ?? 0)), 0);
      await page.setViewportSize({ width: 390, height: 844 });
      await error.scrollIntoViewIfNeeded();
      await shoot(page, `drills-code-failed-${lang}-390`, { width: 390, height: 844 });
      await context.unroute(pattern);
      await page.locator('[data-testid="drills-run"]').click();
      await page.waitForFunction(() => Number(document.querySelector('[data-testid="drills-output"]').dataset.run) > 0, null, { timeout: 20000 });
      assert.match(await page.locator('[data-testid="drills-summary"]').innerText(), /PID samples/);
      assert.equal(await error.isVisible(), false);
      assert.deepEqual(appErrors(errors), []);
    } finally {
      await close();
    }
  });
}

for (const lang of ['en', 'ja']) {
  test(`on a slow network, going ik-2r → teleop → pendulum shows each page's frame and loading line, then the page (${lang})`, async () => {
    const { page, context, errors, close } = await openApp(server.url, `#/ik-2r?lang=${lang}`);
    try {
      await throttle(context, page);
      for (const [route, canvas] of [['teleop', 'teleop-canvas'], ['pendulum-energy', 'pendulum-energy-canvas']]) {
        await page.evaluate((r) => { location.hash = `#/${r}`; }, route);
        const loading = page.locator('[data-testid="page-loading"]');
        await loading.waitFor({ state: 'visible', timeout: 5000 });
        assert.equal(await page.locator('[data-testid="page-frame"]').getAttribute('data-page'), route);
        assert.match(await loading.innerText(), lang === 'ja' ? /読み込んで/ : /Loading this drill/);
        if (route === 'teleop') await shoot(page, `split-loading-${lang}-390`, { width: 390, height: 844 });
        await page.locator(`[data-testid="${canvas}"]`).waitFor({ timeout: 60000 });
        assert.equal(await loading.count(), 0, 'the loading line is gone once the page is in');
      }
      assert.deepEqual(appErrors(errors), []);
    } finally {
      await close();
    }
  });
}

test('switching to Japanese on #/teleop mid-session keeps the session', async () => {
  const { page, errors, close } = await openApp(server.url, '#/teleop');
  try {
    const canvas = page.locator('[data-testid="teleop-canvas"]');
    await canvas.focus();
    await page.keyboard.down('w');
    await page.waitForTimeout(300);
    await page.keyboard.up('w');
    await page.keyboard.press('k');
    const before = await readouts(page);
    await page.click('[data-testid="lang-switch"]');
    await page.waitForFunction(() => document.documentElement.lang === 'ja');
    await page.locator('[data-testid="lang-switch"][lang="en"]').waitFor();
    const after = await readouts(page);
    assert.deepEqual(after, before, 'the arm, the gripper and the session counters are the same');
    assert.equal(await page.locator('[data-readout="gripper"]').getAttribute('data-value'), 'closed');
    await shoot(page, 'split-teleop-ja-1366', { width: 1366, height: 768 });
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});
