// Accessibility: axe-core (npm, test only) finds no serious or critical violation on any route,
// in English and Japanese, with the `?` overlay, the share dialog and the drills menu open too.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { serveApp, openApp } from './harness.mjs';

const AXE = readFileSync(createRequire(import.meta.url).resolve('axe-core/axe.min.js'), 'utf8');

const server = serveApp();

/** Serious and critical violations on the page as it stands, one line each. */
async function violations(page, what) {
  // Evaluated through the DevTools protocol, so the page's CSP (no inline scripts) is kept.
  if (!(await page.evaluate(() => typeof window.axe === 'object'))) await page.evaluate(AXE);
  const found = await page.evaluate(async () => {
    const result = await window.axe.run(document, {
      runOnly: { type: 'tag', values: ['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa', 'wcag22aa', 'best-practice'] },
      resultTypes: ['violations'],
    });
    return result.violations
      .filter((v) => v.impact === 'serious' || v.impact === 'critical')
      .map((v) => `${v.id} (${v.impact}): ${v.nodes.slice(0, 4).map((n) => n.target.join(' ')).join(' | ')}`);
  });
  return found.map((line) => `${what}: ${line}`);
}

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
