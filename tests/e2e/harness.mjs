// End-to-end test harness: serves dist/ on loopback and drives Debian's Chromium headless
// through playwright-core. One browser per test file; one fresh context per openApp.
import { chromium } from 'playwright-core';
import { mkdirSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { startStaticServer } from '../../scripts/serve.mjs';

export const ROOT = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
export const OUT = join(ROOT, 'tests', 'e2e', 'out');
mkdirSync(OUT, { recursive: true });

const CHROMIUM_ARGS = [
  '--no-sandbox',
  '--disable-gpu',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
  '--no-first-run',
  '--disable-quic',
];

/** Serves dist/ on 127.0.0.1 at a free port: { url, close }. */
export function startServer() {
  return startStaticServer(join(ROOT, 'dist'), 0);
}

let browserPromise = null;

/** The shared headless Chromium of this test file. */
export function browser() {
  browserPromise ??= chromium.launch({
    executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
    headless: true,
    args: CHROMIUM_ARGS,
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
 */
export async function openApp(url, hash = '#/', { viewport = { width: 1280, height: 800 }, locale = 'en-US', storage = {} } = {}) {
  const context = await (await browser()).newContext({ viewport, locale, acceptDownloads: true, deviceScaleFactor: 1 });
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
  return { page, context, errors, close: () => context.close() };
}
