// End-to-end test harness: serves dist/ on loopback and drives Debian's Chromium headless
// through playwright-core. One browser per test file; one fresh context per openApp.
//
// Strict: every context of the shared browser reports each Content-Security-Policy violation
// (`securitypolicyviolation`, listened for in the page before any page script runs) and each
// `console.warn` of the app's i18n (a missing or broken Fluent message); any such problem
// fails the test during which it happened (an `afterEach` hook of every file that imports this
// harness). A test that provokes one on purpose takes it with `takeProblems()`.
//
// Also what the test files share: the server hooks of a file, a page's readouts and URL query,
// and the screenshots of a page.
import assert from 'node:assert/strict';
import { afterEach, before, after } from 'node:test';
import { chromium } from 'playwright-core';
import { mkdirSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { startStaticServer } from '../../scripts/serve.mjs';
import { CHROMIUM_ARGS } from './chromium-args.mjs';

export const ROOT = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
export const OUT = join(ROOT, 'tests', 'e2e', 'out');
mkdirSync(OUT, { recursive: true });


/** The folder the tests serve: BSV_DIST (relative to the repo, or absolute), default dist/. */
export const DIST = resolve(ROOT, process.env.BSV_DIST || 'dist');

/** Serves DIST (dist/ unless BSV_DIST names another) on 127.0.0.1 at a free port: { url, close }. */
export function startServer(options = {}) {
  return startStaticServer(DIST, 0, '127.0.0.1', options);
}

/**
 * Registers the hooks of a test file: before its tests `setup()` runs and DIST is served; after
 * them `teardown()` runs, then the browser and the server close. Returns `{ url }` (the
 * server's, once it is up).
 */
export function serveApp({ setup = () => {}, teardown = () => {}, timeout = Infinity } = {}) {
  let server;
  before(async () => {
    await setup();
    server = await startServer();
  }, { timeout });
  after(async () => {
    await teardown();
    await closeBrowser();
    await server?.close();
  });
  return { get url() { return server.url; } };
}

/** What the app's i18n logs with console.warn (src/ui/ctx.rs: `i18n: <note>`). */
const I18N_WARNING = /^i18n: /;

/** CSP violations and i18n warnings seen since the last `takeProblems()`: { kind, text, url }. */
const problems = [];

/** The problems seen so far (a copy; they stay). */
export function seenProblems() {
  return [...problems];
}

/** Takes (and clears) the problems seen so far. */
export function takeProblems() {
  return problems.splice(0, problems.length);
}

/** Throws when a CSP violation or an i18n warning was seen (and clears them). */
export function assertNoProblems() {
  const seen = takeProblems();
  if (seen.length) {
    const lines = seen.map((p) => `  ${p.kind}: ${p.text}${p.url ? ` (${p.url})` : ''}`);
    throw new Error(`the page reported ${seen.length} problem(s):\n${lines.join('\n')}`);
  }
}

afterEach(() => assertNoProblems());

/** Reports violations of the page's CSP to the test (runs in the page before its scripts). */
function watchCsp() {
  document.addEventListener(
    'securitypolicyviolation',
    (e) => {
      const where = e.sourceFile ? ` at ${e.sourceFile}:${e.lineNumber}:${e.columnNumber}` : '';
      const sample = e.sample ? ` "${e.sample}"` : '';
      // eslint-disable-next-line no-undef
      globalThis.__bsvCspViolation(`${e.effectiveDirective} blocked ${e.blockedURI || '(inline)'}${sample}${where}`);
    },
    true,
  );
}

/** Makes a context of the shared browser strict (see the top of this file). */
async function watch(context) {
  await context.exposeBinding('__bsvCspViolation', ({ page }, text) => {
    problems.push({ kind: 'csp', text, url: page?.url() ?? '' });
  });
  await context.addInitScript(watchCsp);
  context.on('console', (m) => {
    if (m.type() === 'warning' && I18N_WARNING.test(m.text())) {
      problems.push({ kind: 'i18n', text: m.text(), url: m.page()?.url() ?? '' });
    }
  });
}

let browserPromise = null;

/** The shared headless Chromium of this test file; each of its new contexts is strict. */
export function browser() {
  browserPromise ??= chromium
    .launch({
      executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
      headless: true,
      args: CHROMIUM_ARGS,
    })
    .then((b) => {
      const newContext = b.newContext.bind(b);
      b.newContext = async (options) => {
        const context = await newContext(options);
        await watch(context);
        return context;
      };
      return b;
    });
  return browserPromise;
}

/** Closes the shared browser (call in `after`). */
export async function closeBrowser() {
  if (browserPromise) {
    const b = await browserPromise;
    browserPromise = null;
    await b.close();
  }
}

/**
 * Opens the app at `url` + `/` + `hash` in a fresh context and waits until the shell has
 * mounted (html[data-app-ready="1"]). `errors` collects console errors and page errors.
 * `serviceWorkers: 'allow'` lets the app install its offline service worker.
 */
export async function openApp(url, hash = '#/', { viewport = { width: 1280, height: 800 }, locale = 'en-US', storage = {}, serviceWorkers = 'block', touch = false } = {}) {
  // The offline service worker is blocked unless a test asks for it (offline.test.mjs), so
  // every other test sees the files of dist/ exactly as served. `touch`: a phone's touch
  // screen (hasTouch, isMobile).
  const context = await (await browser()).newContext({ viewport, locale, acceptDownloads: true, deviceScaleFactor: 1, serviceWorkers, hasTouch: touch, isMobile: touch });
  if (Object.keys(storage).length) {
    await context.addInitScript((entries) => {
      for (const [k, v] of Object.entries(entries)) localStorage.setItem(k, v);
    }, storage);
  }
  const page = await context.newPage();
  const errors = [];
  page.on('console', (m) => {
    if (m.type() === 'error') errors.push(m.text());
  });
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.goto(`${url}/${hash}`);
  await page.waitForFunction(() => document.documentElement.dataset.appReady === '1', null, { timeout: 20000 });
  // The home page's tiles and cards come in a chunk of their own once the arm is live.
  await page.waitForFunction(() => !document.querySelector('[data-testid="home-more"][data-state="loading"]'), null, { timeout: 20000 });
  return { page, context, errors, close: () => context.close() };
}

/**
 * An init script (`context.addInitScript(watchFirstFrame)`): the first animation frame after
 * the shell sets html[data-app-ready] (the route settled, its page answering input) is
 * recorded as `window.__firstFrameMs`.
 */
export function watchFirstFrame() {
  // The init script runs before <html> exists: watch the whole document.
  new MutationObserver((_, observer) => {
    if (document.documentElement?.dataset.appReady === '1') {
      observer.disconnect();
      requestAnimationFrame(() => {
        window.__firstFrameMs = performance.now();
      });
    }
  }).observe(document, { subtree: true, attributes: true, attributeFilter: ['data-app-ready'] });
}

/**
 * Lighthouse's mobile network (150 ms round trip, 1.6 Mbps down, 750 kbps up) on `page`,
 * and with `cpu` its CPU slowed 4×, through the DevTools protocol. Returns `bytes()`: the
 * bytes received on the wire so far.
 */
export async function throttle(context, page, { cpu = false } = {}) {
  const cdp = await context.newCDPSession(page);
  await cdp.send('Network.enable');
  await cdp.send('Network.emulateNetworkConditions', {
    offline: false,
    latency: 150,
    downloadThroughput: (1.6 * 1000 * 1000) / 8,
    uploadThroughput: (750 * 1000) / 8,
  });
  if (cpu) await cdp.send('Emulation.setCPUThrottlingRate', { rate: 4 });
  let bytes = 0;
  cdp.on('Network.loadingFinished', (e) => {
    bytes += e.encodedDataLength;
  });
  return { bytes: () => bytes };
}

/**
 * `data-readout` → what each readout of the page holds: its exact value (`data-value`); with
 * `text: true` its shown text (trimmed), with `text: 'fallback'` the shown text of a readout
 * that has no value. With `numbers`, a number wherever the string is one and null for an empty
 * or absent one. `root` (a selector) limits the readouts to those inside it, `except` leaves
 * out those inside an element it matches.
 */
export function readouts(page, { text = false, numbers = false, root = 'body', except = null } = {}) {
  return page.evaluate(({ text, numbers, root, except }) => {
    const out = {};
    for (const el of document.querySelector(root).querySelectorAll('[data-readout]')) {
      if (except && el.closest(except)) continue;
      const shown = el.textContent.trim();
      let v = text === true ? shown : text === 'fallback' ? (el.dataset.value ?? shown) : el.dataset.value;
      if (numbers) v = v === undefined || v === '' ? null : Number.isNaN(Number(v)) ? v : Number(v);
      out[el.dataset.readout] = v;
    }
    return out;
  }, { text, numbers, root, except });
}

/** The URL query of the page (after the `?` of its hash) as an object. */
export const query = (page) => page.evaluate(() => Object.fromEntries(new URLSearchParams(location.hash.split('?')[1] ?? '')));

/**
 * Saves the screenshot of each `[file, hash, options]` of `shots` (options as openApp's) to
 * OUT: opens the app there, runs `prepare(page)` (by default it waits 300 ms), asserts that the
 * page is no wider than its viewport, saves the page (`shot`: options of page.screenshot), runs
 * `then(page, file)` and asserts that no console error came.
 */
export async function screenshots(url, shots, { prepare = (page) => page.waitForTimeout(300), shot = {}, then = async () => {} } = {}) {
  // Three pages at a time, each in its own context: a screenshot is layout, which the others
  // do not change.
  const one = async ([file, hash, options]) => {
    const { page, errors, close } = await openApp(url, hash, options);
    try {
      await prepare(page);
      const width = await page.evaluate(() => document.documentElement.scrollWidth);
      assert.ok(width <= options.viewport.width, `${file}: page ${width} px wide`);
      await page.screenshot({ path: join(OUT, file), ...shot });
      await then(page, file);
      assert.deepEqual(errors, [], file);
    } finally {
      await close();
    }
  };
  for (let i = 0; i < shots.length; i += 3) await Promise.all(shots.slice(i, i + 3).map(one));
}
