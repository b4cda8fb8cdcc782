// "Share": the header button (and S while presenting a lesson) opens a dialog with the page's
// full address as a QR code at least 60 % of a 1920×1080 screen's height, and as text; the QR
// code, screenshot and decoded with jsQR, reads back the address (the one of the press: the
// pendulum rewrites its time in the address while it plays). Esc closes the dialog and
// gives focus back; the code's chunk is fetched on first use only.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { join } from 'node:path';
import { serveApp, openApp, OUT } from './harness.mjs';

const JSQR = readFileSync(createRequire(import.meta.url).resolve('jsqr/dist/jsQR.js'), 'utf8');
const FULL_HD = { width: 1920, height: 1080 };
const SHARE = '[data-action="share"]';
const DIALOG = '[data-testid="share-dialog"]';
const QR = '[data-testid="share-qr"]';

const server = serveApp();

/** The text jsQR reads from a PNG screenshot, decoded in a blank page of the same browser
 * (the app's CSP lets no added script run on the app's own page). */
async function decodeQr(context, png) {
  const blank = await context.newPage();
  try {
    await blank.setContent('<!doctype html><title>decode</title>');
    await blank.addScriptTag({ content: JSQR });
    return await blank.evaluate(async (dataUrl) => {
      const image = new Image();
      image.src = dataUrl;
      await image.decode();
      const canvas = document.createElement('canvas');
      canvas.width = image.naturalWidth;
      canvas.height = image.naturalHeight;
      const g = canvas.getContext('2d');
      g.drawImage(image, 0, 0);
      const pixels = g.getImageData(0, 0, canvas.width, canvas.height);
      return window.jsQR(pixels.data, pixels.width, pixels.height)?.data ?? null;
    }, `data:image/png;base64,${png.toString('base64')}`);
  } finally {
    await blank.close();
  }
}

/** Notes the page's address at the next `event` (click or keydown), before the app sees it. */
async function noteAddressAt(page, event) {
  await page.evaluate((type) => {
    window.__addressAtPress = null;
    addEventListener(type, () => { window.__addressAtPress = location.href; }, { capture: true, once: true });
  }, event);
}

/** The address noted by `noteAddressAt`, checked against the link the dialog shows. */
async function shownLink(page) {
  const noted = await page.evaluate(() => window.__addressAtPress);
  assert.match(noted, /^http:\/\/127\.0\.0\.1:\d+\/#\//);
  assert.equal(await page.locator('[data-testid="share-link"]').innerText(), noted);
  return noted;
}

/** Opens the dialog from the header and checks the code, the link and closing with Esc. */
async function shareChecks(context, page, shot) {
  const chunk = /\/pkg\/(pack_share_dialog\.bin|chunks\/split_share_dialog\.wasm)$/;
  const fetched = [];
  page.on('request', (r) => chunk.test(new URL(r.url()).pathname) && fetched.push(r.url()));
  assert.equal(await page.locator(DIALOG).count(), 0);
  await noteAddressAt(page, 'click');
  await page.click(SHARE);
  const dialog = page.locator(DIALOG);
  await dialog.waitFor();
  assert.ok(fetched.length >= 1, 'the QR code comes in a chunk fetched on first use');
  assert.equal(await dialog.getAttribute('role'), 'dialog');
  assert.equal(await dialog.getAttribute('aria-modal'), 'true');
  assert.ok(await page.evaluate(() => document.querySelector('[data-testid="share-dialog"]').contains(document.activeElement)),
    'focus moves into the dialog');
  assert.ok(await page.evaluate(() => document.getElementById('app').inert), 'the app behind is inert');

  const url = await shownLink(page);
  const box = await page.locator(QR).boundingBox();
  assert.ok(box.height >= 0.6 * FULL_HD.height, `the QR code is ${box.height} px tall`);
  assert.ok(Math.abs(box.width - box.height) < 1, 'the QR code is square');
  assert.ok(box.x >= 0 && box.y >= 0 && box.x + box.width <= FULL_HD.width && box.y + box.height <= FULL_HD.height,
    'the QR code is on screen');
  assert.equal(await decodeQr(context, await page.locator(QR).screenshot()), url);
  await page.screenshot({ path: join(OUT, shot) });

  await page.keyboard.press('Escape');
  await dialog.waitFor({ state: 'detached' });
  assert.equal(await page.evaluate(() => document.activeElement?.dataset.action), 'share');
  assert.equal(await page.evaluate(() => document.getElementById('app').inert), false);
  return url;
}

test('Share shows the page link as a QR code that reads back the link, in English and Japanese', async () => {
  for (const [hash, shot] of [
    ['#/ik-2r?L1=0.12&L2=0.1&q1=0.3&q2=0.8&elbow=down', 'share-ik2r-en-1920.png'],
    ['#/pendulum-energy', 'share-pendulum-en-1920.png'],
    ['#/pid-step?Kp=2&Ki=3&lang=ja', 'share-pid-ja-1920.png'],
  ]) {
    const { page, context, errors, close } = await openApp(server.url, hash, { viewport: FULL_HD });
    try {
      const url = await shareChecks(context, page, shot);
      assert.ok(url.includes(hash.split('?')[0]), `${url} is the page's address`);
      if (hash.includes('lang=ja')) {
        assert.equal(await page.locator(SHARE).getAttribute('aria-label'), '共有');
      }
      // The state in the hash is carried: opened again after a change, the code follows it.
      await page.click(SHARE);
      await page.locator(DIALOG).waitFor();
      await page.click('[data-testid="share-close"]');
      await page.locator(DIALOG).waitFor({ state: 'detached' });
      assert.equal(await page.evaluate(() => document.activeElement?.dataset.action), 'share');
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
});

test('S while presenting a lesson opens Share; Esc closes it and the lesson goes on', async () => {
  const { page, errors, close } = await openApp(server.url, '#/lesson', { viewport: FULL_HD });
  try {
    await page.click('[data-action="lesson-present"]');
    const bar = page.locator('[data-testid="lesson-bar"]');
    await bar.waitFor({ state: 'visible' });
    await page.waitForFunction(() => location.hash.startsWith('#/ik-2r'));
    await page.waitForFunction(() => document.documentElement.dataset.appReady === '1');
    await noteAddressAt(page, 'keydown');
    await page.keyboard.press('s');
    await page.locator(DIALOG).waitFor();
    assert.match(await shownLink(page), /#\/ik-2r(\?|$)/);
    const box = await page.locator(QR).boundingBox();
    assert.ok(box.height >= 0.6 * FULL_HD.height, `the QR code is ${box.height} px tall`);
    await page.keyboard.press('Escape');
    await page.locator(DIALOG).waitFor({ state: 'detached' });
    assert.ok(await bar.isVisible(), 'Esc closed the dialog, not the lesson');
    await page.keyboard.press('Escape');
    await bar.waitFor({ state: 'hidden' });
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('the dialog on a tablet in Japanese and in projector mode: the code fits, dark on white; no Share on a phone', async () => {
  // A phone keeps its header on one row of tools: no Share there (its browser shares links).
  {
    const { page, errors, close } = await openApp(server.url, '#/pendulum-energy?lang=ja', { viewport: { width: 390, height: 844 } });
    try {
      assert.ok(!(await page.locator(SHARE).isVisible()), 'Share shows on a 390 px phone');
      const header = await page.locator('[data-testid="site-header"]').boundingBox();
      assert.ok(header.height <= 110, `the header takes ${header.height} px`);
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
  for (const [hash, viewport, storage, shot] of [
    ['#/pendulum-energy?lang=ja', { width: 768, height: 1024 }, {}, 'share-pendulum-ja-768.png'],
    ['#/ik-2r?q1=0.5&q2=1.2', FULL_HD, { 'bsv.projector': '1' }, 'share-ik2r-projector-1920.png'],
  ]) {
    const { page, context, errors, close } = await openApp(server.url, hash, { viewport, storage });
    try {
      // The header keeps every tool on screen.
      const right = await page.locator(SHARE).evaluate((b) => b.getBoundingClientRect().right);
      assert.ok(right <= viewport.width, `the Share button ends at ${right} px`);
      assert.ok(await page.evaluate(() => document.documentElement.scrollWidth <= innerWidth));
      await noteAddressAt(page, 'click');
      await page.click(SHARE);
      await page.locator(DIALOG).waitFor();
      const box = await page.locator(QR).boundingBox();
      assert.ok(box.x >= 0 && box.x + box.width <= viewport.width, 'the QR code fits the width');
      assert.ok(box.height >= Math.min(0.6 * viewport.height, 0.75 * viewport.width), `the QR code is ${box.height} px tall`);
      const colours = await page.locator(QR).evaluate((svg) =>
        [...svg.children].map((c) => getComputedStyle(c).fill));
      assert.deepEqual(colours, ['rgb(255, 255, 255)', 'rgb(0, 0, 0)']);
      const url = await shownLink(page);
      assert.equal(await decodeQr(context, await page.locator(QR).screenshot()), url);
      await page.screenshot({ path: join(OUT, shot) });
      await page.keyboard.press('Escape');
      await page.locator(DIALOG).waitFor({ state: 'detached' });
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
});

test('the Share button sits in the header row within the height of "?", at 1366 and 1920 px', async () => {
  for (const [width, height] of [[1366, 768], [1920, 1080]]) {
    for (const lang of ['en', 'ja']) {
      for (const projector of ['0', '1']) {
        const { page, errors, close } = await openApp(server.url, `#/pendulum-energy?lang=${lang}`,
          { viewport: { width, height }, storage: { 'bsv.projector': projector } });
        try {
          const [share, help] = await Promise.all([SHARE, '[data-testid="help-button"]'].map((s) =>
            page.locator(s).evaluate((b) => { const r = b.getBoundingClientRect(); return [r.top, r.bottom]; })));
          assert.ok(share[0] >= help[0] - 0.5 && share[1] <= help[1] + 0.5,
            `${width} px, ${lang}, projector ${projector}: Share ${share}, ? ${help}`);
          assert.equal(await page.locator(SHARE).getAttribute('aria-label'), lang === 'ja' ? '共有' : 'Share');
          assert.deepEqual(errors, []);
        } finally {
          await close();
        }
      }
    }
  }
});
