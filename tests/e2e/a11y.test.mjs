// Accessibility: axe-core (npm, test only) finds no serious or critical violation on any route,
// in English and Japanese, with the `?` overlay, the share dialog and the drills menu open too.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { serveApp, openApp } from './harness.mjs';
import { violations } from './axe.mjs';

const server = serveApp();

test('no serious or critical axe violation on any route, in English and Japanese, with overlays open', async () => {
  const { page, errors, close } = await openApp(server.url, '#/');
  try {
    const routes = await page.locator('[data-testid="site-nav"] a').evaluateAll((as) => as.map((a) => a.dataset.page));
    const problems = [];
    for (const lang of ['en', 'ja']) {
      for (const route of routes) {
        await page.goto(`${server.url}/#/${route}?lang=${lang}`);
        await page.waitForFunction((l) => document.documentElement.lang === l && document.documentElement.dataset.appReady === '1', lang);
        await page.waitForTimeout(300);
        problems.push(...(await violations(page, `${lang} ${route}`)));
      }
      await page.click('[data-testid="help-button"]');
      await page.locator('[role="dialog"]').waitFor();
      problems.push(...(await violations(page, `${lang} ? overlay`)));
      await page.keyboard.press('Escape');
      await page.click('[data-action="share"]');
      await page.locator('[data-testid="share-dialog"]').waitFor();
      problems.push(...(await violations(page, `${lang} share dialog`)));
      await page.keyboard.press('Escape');
      await page.click('[data-testid="nav-menu-button"]');
      problems.push(...(await violations(page, `${lang} drills menu`)));
      await page.keyboard.press('Escape');
    }
    assert.deepEqual(problems, []);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});
