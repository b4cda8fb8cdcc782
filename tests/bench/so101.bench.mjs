// Speed of the SO-101 page (#/so101) in headless Chromium at 1920×1080, on a dist whose wasm
// has the bench hooks (`make bench`: window.__so101FrameMs, every frame's work: poll the
// devices, step the 100 Hz simulation, write the readouts, draw the world view and the wrist
// camera; window.__so101LoadMs, every slice of a stored session simulated again).
//
// Cases: the first second of flying (listed, no budget: V8 is still tiering the wasm up), then
// the pilot flying the arm with the wrist view on (x, then y and yaw, then z and pitch held for
// 1.5 s each), with and without the wall; then a reload of a stored session of ten
// 60 s episodes (60,000 steps) whose main-thread tasks after the app is ready are counted (the
// boot's, with the first slice, are listed without a budget); then the LeRobot dataset of those
// ten episodes written in slices.
// Budgets: frame work p95 < 4 ms; load slices and main-thread tasks under 50 ms.
// With SO101_BENCH_STRICT=1 the exit code is 1 when one is missed.
import { BenchTable, openWatched, runBench, takeLongTasks } from './bench-table.mjs';

const VIEWPORT = { width: 1920, height: 1080 };
const table = new BenchTable();
const KEY = 'bsv.so101.session';

/** Holds each group of keys for `ms` in turn. */
async function fly(page, groups, ms) {
  for (const keys of groups) {
    for (const k of keys) await page.keyboard.down(k);
    await page.waitForTimeout(ms);
    for (const k of keys) await page.keyboard.up(k);
  }
}

await runBench({ table, strict: 'SO101_BENCH_STRICT' }, async (url) => {
  const { page, context, close } = await openWatched(url, '#/so101', { viewport: VIEWPORT });
  try {
    if (!(await page.evaluate(() => Array.isArray(window.__so101FrameMs)))) {
      throw new Error('no window.__so101FrameMs: serve a dist built with --features bench (make bench)');
    }
    const canvas = page.locator('[data-testid="so101-canvas"]');
    // The first second of flying after the page opens, while V8 compiles the wasm's hot code
    // with its optimizing tier: listed, without a budget; then the steady flight is measured.
    await canvas.focus();
    await page.evaluate(() => { window.__so101FrameMs.length = 0; });
    await fly(page, [['w'], ['s']], 500);
    await page.keyboard.press('r');
    table.report('frame work, the first second of flying (V8 tiering up)', await page.evaluate(() => window.__so101FrameMs.splice(0)));
    for (const wall of [false, true]) {
      if (wall) {
        await page.locator('details.so101-settings summary').click();
        await page.locator('[data-field="obstacle"]').check();
        await canvas.focus();
        await page.keyboard.press('r');
      }
      await canvas.focus();
      await page.evaluate(() => { window.__so101FrameMs.length = 0; });
      await fly(page, [['w'], ['a', 'c'], ['q', 't'], ['s', 'd', 'e']], 1500);
      const work = await page.evaluate(() => window.__so101FrameMs.splice(0));
      table.report(`frame work, flying with the wrist view${wall ? ', wall' : ''}`, work.slice(1), 4);
    }

    // Ten stored 60 s episodes: the first recorded here, its commands stretched to 6,000.
    await page.locator('[data-module="record-ten"]').click();
    await canvas.focus();
    await fly(page, [['w']], 200);
    await page.locator('[data-action="end-episode"]').click();
    await page.locator('[data-action="confirm-label"]').click();
    const stored = JSON.parse(await page.evaluate((k) => localStorage.getItem(k), KEY));
    const [entry] = stored.episodes;
    const cmd = (dx, dy, dz, dyaw) => ({ dx, dy, dz, droll: 0, dpitch: 0, dyaw, gripper_closed: false });
    entry.episode.runs = [[1500, cmd(1, 0, 0, 0)], [1500, cmd(0, 1, 0.5, 0.5)], [1500, cmd(-1, -0.5, 0, 0)], [1500, cmd(0.3, -0.2, -1, -1)]];
    stored.episodes = Array.from({ length: 10 }, () => structuredClone(entry));
    stored.in_progress = null;
    // Written before the app starts (the leaving page saves its own session on pagehide).
    await context.addInitScript(([k, text]) => {
      if (sessionStorage.getItem('bench-session') === null) {
        sessionStorage.setItem('bench-session', '1');
        localStorage.setItem(k, text);
      }
    }, [KEY, JSON.stringify(stored)]);
    await page.reload();
    await page.waitForFunction(() => document.documentElement.dataset.appReady === '1', null, { timeout: 60_000 });
    // The boot's own tasks (the wasm's compile) are the first-frame bench's; from here on,
    // the load's slices.
    const boot = await takeLongTasks(page);
    await page.locator('[data-so101="restored"]').waitFor({ state: 'visible', timeout: 120_000 });
    const rows = await page.locator('[data-so101="episodes"] tr').count();
    if (rows !== 10) throw new Error(`the reload gave ${rows} episodes, not 10`);
    table.report('load of ten stored 60 s episodes: slices', await page.evaluate(() => window.__so101LoadMs ?? []), { max: 50 });
    table.longTasks('load of ten stored 60 s episodes: main-thread tasks', await takeLongTasks(page), 50);
    table.longTasks('the reload until the app is ready (boot, first slice)', boot);

    // The LeRobot dataset of the ten (15,000 frames): its chunk fetched on the click, the
    // episodes replayed and the files written in slices, with a progress line.
    await takeLongTasks(page);
    const [zip] = await Promise.all([
      page.waitForEvent('download', { timeout: 120_000 }),
      page.locator('[data-download="so101_lerobot_v3.zip"]').click(),
    ]);
    const state = await page.locator('[data-so101="dataset-progress"]').getAttribute('data-state');
    if (zip.suggestedFilename() !== 'so101_lerobot_v3.zip' || state !== 'done') {
      throw new Error(`the dataset export ended ${state} with ${zip.suggestedFilename()}`);
    }
    table.report('LeRobot dataset of ten 60 s episodes: slices', await page.evaluate(() => window.__so101DatasetMs ?? []), { max: 50 });
    table.longTasks('LeRobot dataset of ten 60 s episodes: main-thread tasks', await takeLongTasks(page), 50);
  } finally {
    await close();
  }
});
