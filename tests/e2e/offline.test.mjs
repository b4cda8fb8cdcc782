// Offline install: the app's service worker caches exactly the files of one build, the app
// then opens every route with the server stopped (each page's code in one request, a pack the
// worker makes from its cached modules), and a new build is offered ("reload to update") and
// applied only when accepted.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { cpSync, appendFileSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { DIST, OUT, closeBrowser, openApp } from './harness.mjs';
import { startStaticServer } from '../../scripts/serve.mjs';
import { writeServiceWorker } from '../../scripts/sw-build.mjs';

/** The build id and file list dist/sw.js was written with. */
function swFacts(dir) {
  const text = readFileSync(join(dir, 'sw.js'), 'utf8');
  return {
    build: JSON.parse(text.match(/^const BUILD = (.*);$/m)[1]),
    files: JSON.parse(text.match(/^const FILES = (.*);$/m)[1]),
  };
}

/** Waits until the page is controlled by an activated service worker. */
async function controlled(page) {
  await page.waitForFunction(async () => {
    await navigator.serviceWorker.ready;
    return navigator.serviceWorker.controller !== null;
  }, null, { timeout: 30000 });
}

/** Cache names and, for the app's cache, the cached paths (sorted). */
async function cacheContents(page) {
  return page.evaluate(async () => {
    const names = await caches.keys();
    const out = { names, paths: [] };
    const mine = names.find((n) => n.startsWith('bsv-'));
    if (mine) {
      const cache = await caches.open(mine);
      out.paths = (await cache.keys()).map((r) => new URL(r.url).pathname).sort();
    }
    return out;
  });
}

let temp;
before(() => {
  temp = mkdtempSync(join(tmpdir(), 'bsv-offline-'));
});

after(async () => {
  await closeBrowser();
  rmSync(temp, { recursive: true, force: true });
});

test('after one visit the app opens every route with the server stopped, from a cache of exactly one build', async () => {
  const server = await startStaticServer(DIST, 0);
  const { page, context, errors, close } = await openApp(server.url, '#/', { serviceWorkers: 'allow' });
  try {
    await controlled(page);
    const { build, files } = swFacts(DIST);
    const cached = await cacheContents(page);
    assert.deepEqual(cached.names, [`bsv-${build}`]);
    assert.deepEqual(cached.paths, files.map((f) => new URL(f, 'http://x/').pathname).sort());
    assert.ok(files.includes('pkg/bsv_playground_bg.wasm') && files.includes('index.html'));
    const routes = await page.locator('[data-testid="site-nav"] a').evaluateAll((as) => as.map((a) => a.dataset.page));
    assert.ok(routes.length >= 9, routes.join());

    await server.close();
    await context.setOffline(true);
    // The server is really gone.
    assert.equal(await fetch(`${server.url}/index.html`).then(() => 'up', () => 'down'), 'down');
    for (const route of routes) {
      const tab = await context.newPage();
      await tab.goto(`${server.url}/#/${route}`);
      await tab.waitForFunction(() => document.documentElement.dataset.appReady === '1', null, { timeout: 20000 });
      assert.equal(await tab.locator('[data-testid="boot-error"]').count(), 0, route);
      assert.equal(await tab.locator('.page-error, [data-testid="notfound"]').count(), 0, route);
      assert.ok((await tab.locator('#app-main').innerText()).length > 40, `${route}: the page has content`);
      // The page's code came in one request, its pack, which the worker made from its cached
      // modules (packs are not cached, and the server is gone).
      const packs = await tab.evaluate(() => performance.getEntriesByType('resource')
        .filter((e) => /\/pkg\/pack_\w+\.bin$/.test(e.name) && e.responseStatus === 200).length);
      assert.ok(packs >= 1, `${route}: its pack`);
      if (route === 'rrt-2d') await tab.screenshot({ path: join(OUT, 'offline-rrt.png') });
      await tab.close();
    }
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('a new build is offered ("reload to update") and applied only when accepted; the old cache goes', async () => {
  const v1 = join(temp, 'v1');
  const v2 = join(temp, 'v2');
  cpSync(DIST, v1, { recursive: true });
  cpSync(DIST, v2, { recursive: true });
  appendFileSync(join(v2, 'www', 'app.css'), '\n/* build two */\n');
  const two = writeServiceWorker(v2);
  const one = swFacts(v1);
  assert.notEqual(one.build, two.build);

  let server = await startStaticServer(v1, 0);
  const port = new URL(server.url).port;
  const { page, errors, close } = await openApp(server.url, '#/pid-step', { serviceWorkers: 'allow' });
  try {
    await controlled(page);
    const banner = page.locator('[data-testid="update-banner"]');
    assert.equal(await banner.isVisible(), false);

    // The same origin now serves build two.
    await server.close();
    server = await startStaticServer(v2, Number(port));
    await page.evaluate(() => window.bsvCheckForUpdate());
    await banner.waitFor({ state: 'visible', timeout: 30000 });
    assert.match(await banner.innerText(), /new version/);
    // Not applied yet: the page still runs build one, and its files still come from cache one.
    assert.equal(await page.evaluate(() => fetch('www/app.css').then((r) => r.text()).then((t) => t.includes('build two'))), false);
    await page.screenshot({ path: join(OUT, 'offline-update-offer.png') });

    await Promise.all([page.waitForEvent('load'), banner.locator('[data-action="apply-update"]').click()]);
    await page.waitForFunction(() => document.documentElement.dataset.appReady === '1');
    assert.ok(page.url().endsWith('#/pid-step'));
    assert.equal(await page.evaluate(() => fetch('www/app.css').then((r) => r.text()).then((t) => t.includes('build two'))), true);
    const cached = await cacheContents(page);
    assert.deepEqual(cached.names, [`bsv-${two.build}`]);
    assert.equal(await banner.isVisible(), false);
    assert.deepEqual(errors, []);
  } finally {
    await close();
    await server.close();
  }
});
