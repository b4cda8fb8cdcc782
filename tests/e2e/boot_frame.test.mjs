// What a phone paints first is the route's own head, where the page will have it: before the
// app's code is in (its main wasm held back here), www/boot.js paints the route's frame from the
// strings it fetched (a bar as tall as the header, the page's heading and lede in the page's
// classes, the loading line). Every route, in English and in Japanese, at a phone's width and
// at the widths where the header has one, two or three rows: the frame's heading and lede stand
// exactly where the page's do once it is mounted, with the same text. Projector mode and an
// embedded page keep the "Loading…" lines (their header is not the frame's bar), and the app
// still starts when boot.js could not fetch the frame's strings (it fetches them again).
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { test } from 'node:test';
import { browser, DIST, serveApp } from './harness.mjs';

const app = serveApp();
const table = JSON.parse(readFileSync(join(DIST, 'pkg', 'routes.json'), 'utf8'));
const ROUTES = Object.keys(table.routes);
// A phone, and the widths of the header's three, two and one rows (English and Japanese wrap
// at different widths: app.css).
const WIDTHS = [412, 700, 1100, 1440];

/** The heading's and the lede's box and text, and the bar's or header's height. */
function head() {
  const box = (el) => {
    if (!el) return null;
    const r = el.getBoundingClientRect();
    return { x: r.x, y: r.y, w: r.width, h: r.height, text: el.textContent.trim() };
  };
  const h1 = document.querySelector('h1');
  const next = h1?.nextElementSibling;
  const lede = next?.tagName === 'P' && !next.hidden && !next.classList.contains('page-loading-line') ? next : null;
  const bar = document.querySelector('.boot-bar') ?? document.querySelector('.site-header');
  return { h1: box(h1), lede: box(lede), bar: bar?.getBoundingClientRect().height ?? null };
}

/** The route's head as the boot frame shows it (main wasm held back) and as the page does. */
async function heads(hash, width) {
  const viewport = { width, height: 823 };
  const held = await (await browser()).newContext({ viewport, serviceWorkers: 'block' });
  const shown = await (await browser()).newContext({ viewport, serviceWorkers: 'block' });
  try {
    const boot = await held.newPage();
    await boot.route('**/bsv_playground_bg.wasm', () => {});
    await boot.goto(`${app.url}/${hash}`);
    await boot.waitForSelector('[data-testid="boot-frame"] h1');
    const page = await shown.newPage();
    await page.goto(`${app.url}/${hash}`);
    await page.waitForSelector('html[data-app-ready]');
    await page.waitForFunction(() => !document.querySelector('[data-testid="page-frame"]'));
    return { boot: await boot.evaluate(head), page: await page.evaluate(head) };
  } finally {
    await held.close();
    await shown.close();
  }
}

const near = (a, b, what) => assert.ok(Math.abs(a - b) <= 0.5, `${what}: ${a} in the frame, ${b} on the page`);

function sameHead(hash, width, { boot, page }) {
  const where = `${hash} at ${width} px`;
  near(boot.bar, page.bar, `${where}: the bar's height`);
  for (const part of ['h1', 'lede']) {
    assert.equal(Boolean(boot[part]), Boolean(page[part]), `${where}: ${part} in one of them only`);
    if (!page[part]) continue;
    assert.equal(boot[part].text, page[part].text, `${where}: the ${part}'s text`);
    for (const key of ['x', 'y', 'w', 'h']) near(boot[part][key], page[part][key], `${where}: the ${part}'s ${key}`);
  }
}

for (const lang of ['en', 'ja']) {
  test(`every route's boot frame is its page's head, at a phone's width (${lang})`, async () => {
    const hashes = ROUTES.map((route) => `${route === 'home' ? '#/' : `#/${route}`}?lang=${lang}`);
    for (let i = 0; i < hashes.length; i += 5) {
      const batch = hashes.slice(i, i + 5);
      const results = await Promise.all(batch.map((hash) => heads(hash, 412)));
      batch.forEach((hash, j) => sameHead(hash, 412, results[j]));
    }
  });

  test(`the boot frame's bar is the header's height at every header's row count (${lang})`, async () => {
    const hash = `#/pid-step?lang=${lang}`;
    const results = await Promise.all(WIDTHS.slice(1).map((width) => heads(hash, width)));
    WIDTHS.slice(1).forEach((width, j) => sameHead(hash, width, results[j]));
  });
}

test('projector mode and an embedded page keep the loading lines; the app starts without the frame', async () => {
  const context = await (await browser()).newContext({ viewport: { width: 412, height: 823 }, serviceWorkers: 'block' });
  try {
    const projector = await context.newPage();
    await projector.addInitScript(() => localStorage.setItem('bsv.projector', '1'));
    await projector.route('**/bsv_playground_bg.wasm', () => {});
    await projector.goto(`${app.url}/#/pid-step`);
    await projector.waitForFunction(() => performance.getEntriesByName('first-contentful-paint').length > 0);
    await projector.waitForTimeout(300);
    assert.equal(await projector.locator('[data-testid="boot-frame"]').count(), 0, 'projector mode: no frame');
    assert.equal(await projector.locator('#boot-status p').count(), 2, 'projector mode: the loading lines');

    const embedded = await context.newPage();
    await embedded.route('**/bsv_playground_bg.wasm', () => {});
    await embedded.goto(`${app.url}/#/pid-step?embed=1`);
    await embedded.waitForFunction(() => performance.getEntriesByName('first-contentful-paint').length > 0);
    await embedded.waitForTimeout(300);
    assert.equal(await embedded.locator('[data-testid="boot-frame"]').count(), 0, 'embedded: no frame');

    // The route's strings pack refused: boot.js fetches each file by itself; the page's own file
    // refused once too: it is fetched again, and the page comes whole.
    const refused = await context.newPage();
    let packRefusals = 0;
    let refusals = 0;
    await refused.route('**/locales/en/pack_pid-step.json', (route) => {
      packRefusals++;
      return route.fulfill({ status: 503, body: '' });
    });
    await refused.route('**/locales/en/signals.ftl', (route) => (refusals++ === 0 ? route.fulfill({ status: 503, body: '' }) : route.continue()));
    await refused.goto(`${app.url}/#/pid-step?lang=en`);
    await refused.waitForSelector('html[data-app-ready]');
    await refused.waitForFunction(() => !document.querySelector('[data-testid="page-frame"]'));
    assert.equal(await refused.locator('[data-testid="boot-frame"]').count(), 0, 'the frame replaced');
    assert.equal(await refused.locator('h1').first().textContent(), 'PID step response');
    assert.equal(packRefusals, 1, 'the strings pack asked once');
    assert.equal(refusals, 2, 'the refused file fetched again');
  } finally {
    await context.close();
  }
});
