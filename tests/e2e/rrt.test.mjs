// The RRT stepper (#/rrt-2d) in headless Chromium: step / back / keys move the counters to the
// tree `bsv rrt-2d 7 <k>` writes; End on the default shows 91 nodes, 33 path points, length
// 1.604; downloads equal the CLI byte for byte (defaults, and a URL with two boxes, a moved
// start and goal and another step, which also restores the tree at its `it`); dragging the
// obstacle rewrites the URL and grows another tree; an invalid goal is refused with a message;
// Japanese leaves no English UI text. Screenshots (EN/JA 1920×1080, projector, phone 390 px) go
// to tests/e2e/out/. A 1,000,000-iteration walled-goal run grows to its end in slices while the
// stepper steps; End and the CSVs equal `bsv`. Opened from another page or as a fresh load (the
// default and a 20,000-iteration run), the page grows its run and is ready to step. By
// keyboard, `c` chooses a corner of the chosen box and Shift + arrows resize the box as a corner
// drag does (URL, CLI downloads, refusals). The main-thread tasks of these runs and the frame
// work while playing are figures of tests/bench/rrt.bench.mjs.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { openApp, readouts, screenshots } from './harness.mjs';
import { serveAppWithCli, cli, download, assertSameBytes } from './cli.mjs';
import { englishStrings } from './locales.mjs';

// The CLI is built and dist/ served before the tests; all is closed after them.
const server = serveAppWithCli();

const open = (hash = '#/rrt-2d', opts = {}) => openApp(server.url, hash, opts);

/** The counters as numbers (`length` as shown, a string). */
async function counters(page) {
  const shown = Object.entries(await readouts(page, { text: true }));
  return Object.fromEntries(shown.map(([k, v]) => [k, k === 'length' ? v : Number(v.replace(/,/g, ''))]));
}

/** Nodes `bsv rrt-2d <args>` writes. */
function cliNodes(args) {
  return cli(['rrt-2d', ...args]).files.get('rrt_nodes.csv').toString('utf8').trim().split('\n').length - 1;
}

/** Where world point (x, y) is on the canvas, page px (the square fits the canvas, 14 px margin). */
async function toPage(page, [x, y]) {
  const box = await page.locator('[data-testid="rrt-2d-canvas"]').boundingBox();
  const side = Math.min(box.width, box.height) - 28;
  const left = box.x + (box.width - side) / 2;
  const top = box.y + (box.height - side) / 2;
  return { x: left + x * side, y: top + (1 - y) * side };
}

/** Drags from world point `from` to `to` in `steps` pointer moves. */
async function dragWorld(page, from, to, steps = 8) {
  await page.evaluate(() => document.querySelector('[data-testid="rrt-2d-canvas"]').scrollIntoView({ block: 'center' }));
  const a = await toPage(page, from);
  const b = await toPage(page, to);
  await page.mouse.move(a.x, a.y);
  await page.mouse.down();
  for (let k = 1; k <= steps; k++) {
    await page.mouse.move(a.x + ((b.x - a.x) * k) / steps, a.y + ((b.y - a.y) * k) / steps);
  }
  await page.mouse.up();
}

const query = async (page) => new URLSearchParams(await page.evaluate(() => location.hash.split('?')[1] ?? ''));

test('step, back and the keys move the counters to the CLI tree; End shows 91 / 33 / 1.604', async () => {
  const { page, errors, close } = await open('#/rrt-2d?it=0');
  try {
    let c = await counters(page);
    assert.deepEqual([c.iteration, c.nodes, c.path_points, c.length], [0, 1, 0, '—']);
    await page.locator('[data-action="step"]').click();
    assert.equal((await counters(page)).iteration, 1);
    const canvas = page.locator('[data-testid="rrt-2d-canvas"]');
    await canvas.focus();
    for (const key of ['ArrowRight', 'PageDown', 'ArrowRight', 'ArrowRight']) await page.keyboard.press(key);
    c = await counters(page);
    assert.equal(c.iteration, 5);
    assert.equal(c.nodes, cliNodes(['7', '5']));
    for (const key of ['ArrowLeft', 'PageUp']) await page.keyboard.press(key);
    await page.locator('[data-action="back"]').click();
    c = await counters(page);
    assert.equal(c.iteration, 2);
    assert.equal(c.nodes, cliNodes(['7', '2']));
    // The sub-step panel writes the iteration out and the pseudocode marks a line.
    assert.match(await page.locator('[data-testid="rrt-2d-substeps"]').innerText(), /Iteration 2:.*sample q/s);
    assert.equal(await page.locator('[data-code-line][data-current="true"]').count(), 1);
    await canvas.focus();
    await page.keyboard.press('End');
    c = await counters(page);
    assert.deepEqual([c.nodes, c.path_points, c.length], [91, 33, '1.604']);
    assert.equal(await page.locator('[data-code-line="8"]').getAttribute('data-current'), 'true');
    // Exactly the CLI's tree at every iteration on the way back.
    const end = c.iteration;
    await page.keyboard.press('ArrowLeft');
    c = await counters(page);
    assert.equal(c.iteration, end - 1);
    assert.equal(c.nodes, cliNodes(['7', String(end - 1)]));
    assert.equal(c.path_points, 0);
    await page.keyboard.press('Home');
    assert.equal((await counters(page)).iteration, 0);
    // Space plays (10 iterations / s) and pauses; r starts over.
    await page.keyboard.press(' ');
    await page.waitForFunction(() => Number(document.querySelector('[data-readout="iteration"]').textContent) >= 2, null, { timeout: 3000 });
    await page.keyboard.press(' ');
    assert.equal(await page.locator('[data-action="run"]').getAttribute('aria-pressed'), 'false');
    await page.keyboard.press('r');
    assert.equal((await counters(page)).iteration, 0);
    // Sub-step mode: the arrows walk sample → nearest → … within one iteration.
    await page.locator('[data-rrt="substep-mode"]').check();
    await canvas.focus();
    await page.keyboard.press('ArrowRight');
    assert.equal((await counters(page)).iteration, 1);
    assert.equal(await page.locator('[data-testid="rrt-2d-substeps"] li').count(), 1);
    await page.keyboard.press('ArrowRight');
    assert.equal(await page.locator('[data-testid="rrt-2d-substeps"] li').count(), 2);
    assert.equal(await page.locator('[data-code-line="2"]').getAttribute('data-current'), 'true');
    assert.equal((await counters(page)).iteration, 1);
    // The step and back buttons walk the sub-steps too.
    const subs = page.locator('[data-testid="rrt-2d-substeps"] li');
    await page.locator('[data-action="step"]').click();
    assert.equal(await subs.count(), 3);
    assert.equal((await counters(page)).iteration, 1);
    await page.locator('[data-action="back"]').click();
    await page.locator('[data-action="back"]').click();
    assert.equal(await subs.count(), 1);
    assert.equal((await counters(page)).iteration, 1);
    // Past the iteration's last sub-step, the step button goes to the next iteration's first.
    for (let k = 0; k < 6 && (await counters(page)).iteration === 1; k++) {
      await page.locator('[data-action="step"]').click();
    }
    assert.equal((await counters(page)).iteration, 2);
    assert.equal(await subs.count(), 1);
    assert.match(await page.locator('[data-testid="rrt-2d-substeps"]').innerText(), /Iteration 2:/);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('downloads equal bsv: the default, and a URL with two boxes, moved start and goal, another step', async () => {
  const two = ['3', '800', '--obstacle', '0.2,0.3,0.4,0.5', '--obstacle', '0.6,0.1,0.7,0.9', '--start', '0.05,0.9', '--goal', '0.95,0.1', '--step', '0.04'];
  const cases = [
    ['#/rrt-2d', ['7', '800'], 'bsv rrt-2d 7 800', 'python rrt_2d_grid.py 7 800'],
    [
      '#/rrt-2d?seed=3&obstacle=0.2,0.3,0.4,0.5&obstacle=0.6,0.1,0.7,0.9&start=0.05,0.9&goal=0.95,0.1&step=0.04&it=12',
      two,
      `bsv rrt-2d ${two.join(' ')}`,
      null,
    ],
  ];
  for (const [hash, args, bsv, python] of cases) {
    const want = cli(['rrt-2d', ...args]).files;
    const { page, errors, close } = await open(hash);
    try {
      if (hash.includes('it=12')) {
        // The URL restores the tree at iteration 12: the CLI's tree after 12 iterations.
        const c = await counters(page);
        assert.equal(c.iteration, 12);
        assert.equal(c.nodes, cliNodes([...args.slice(0, 1), '12', ...args.slice(2)]));
      }
      for (const file of ['rrt_nodes.csv', 'rrt_path.csv']) {
        assertSameBytes(await download(page, file), want.get(file), `${hash} ${file}`);
      }
      const png = await download(page, 'rrt_2d.png');
      assert.deepEqual([...png.subarray(0, 4)], [0x89, 0x50, 0x4e, 0x47], 'a PNG');
      assert.equal(await page.locator('[data-cmd="bsv"]').innerText(), bsv);
      if (python) {
        assert.equal(await page.locator('[data-cmd="python"]').innerText(), python);
      } else {
        assert.equal(await page.locator('[data-cmd="python"]').isVisible(), false);
        assert.equal(await page.locator('[data-rrt="python-none"]').isVisible(), true);
      }
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
});

test('dragging the obstacle changes the URL and the tree; an invalid goal is refused with a message', async () => {
  const { page, errors, close } = await open();
  try {
    await page.locator('[data-action="end"]').click();
    assert.equal((await counters(page)).nodes, 91);
    await dragWorld(page, [0.5, 0.5], [0.6, 0.45]);
    await page.waitForFunction(() => /obstacle=/.test(location.hash), null, { timeout: 3000 });
    const box = (await query(page)).get('obstacle');
    const [x0, y0, x1, y1] = box.split(',').map(Number);
    assert.ok(Math.abs(x0 - 0.45) < 0.01 && Math.abs(y0 - 0.2) < 0.01, box);
    assert.ok(Math.abs(x1 - x0 - 0.3) < 1e-9 && Math.abs(y1 - y0 - 0.5) < 1e-9, box);
    // The edit restarted the run at iteration 0; its end is the CLI's tree in the new world.
    assert.equal((await counters(page)).iteration, 0);
    await page.locator('[data-action="end"]').click();
    const c = await counters(page);
    const nodes = cliNodes(['7', '800', '--obstacle', box]);
    assert.equal(c.nodes, nodes);
    assert.notEqual(nodes, 91);
    // Resize by the top-right corner.
    await dragWorld(page, [x1, y1], [x1 + 0.05, y1 + 0.05]);
    await page.waitForFunction((b) => !location.hash.includes(`obstacle=${b}`), box, { timeout: 3000 });
    // The goal into the box: refused, with the message; the goal stays.
    const message = page.locator('[data-testid="rrt-2d-world-message"]');
    assert.equal(await message.isVisible(), false);
    await dragWorld(page, [0.9, 0.9], [0.6, 0.5], 1);
    assert.equal(await message.isVisible(), true);
    assert.match(await message.innerText(), /the goal would lie inside box 1/);
    assert.equal((await query(page)).get('goal'), null);
    // Out of the square: refused too.
    await dragWorld(page, [0.1, 0.1], [0.1, -0.03], 1);
    assert.match(await message.innerText(), /the start must stay inside the unit square/);
    assert.equal((await query(page)).get('start'), null);
    // A valid move clears the message.
    await dragWorld(page, [0.9, 0.9], [0.85, 0.95]);
    assert.equal(await message.isVisible(), false);
    assert.ok((await query(page)).get('goal'));
    // Add two boxes, delete one.
    await page.locator('[data-action="add-box"]').click();
    await page.locator('[data-action="add-box"]').click();
    assert.equal((await query(page)).getAll('obstacle').length, 3);
    await page.locator('[data-action="delete-box"]').click();
    assert.equal((await query(page)).getAll('obstacle').length, 2);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('by keyboard, c chooses a corner of the chosen box and Shift + arrows resize the box through the corner drag (URL, CLI downloads, refusals); the ? overlay lists c', async () => {
  const { page, errors, close } = await open();
  try {
    const canvas = page.locator('[data-testid="rrt-2d-canvas"]');
    const target = page.locator('[data-testid="rrt-2d-key-target"]');
    const waitObstacle = (box) => page.waitForFunction(
      (b) => new URLSearchParams(location.hash.split('?')[1] ?? '').get('obstacle') === b, box, { timeout: 3000 });
    await canvas.focus();
    for (const key of ['n', 'n', 'n']) await page.keyboard.press(key);
    assert.equal(await target.innerText(), 'Shift + arrows move box 1.');
    await page.keyboard.press('c');
    assert.equal(await target.innerText(), 'Shift + arrows move the top-right corner of box 1.');
    // The recipe's box 0.35,0.25,0.65,0.75: its top-right corner 0.02 right and 0.01 up.
    await page.keyboard.press('Shift+ArrowRight');
    await page.keyboard.press('Shift+ArrowRight');
    await page.keyboard.press('Shift+ArrowUp');
    await waitObstacle('0.35,0.25,0.67,0.76');
    assert.equal((await counters(page)).iteration, 0, 'the run starts again');
    // The next corner anticlockwise: the top-left one, 0.01 left.
    await page.keyboard.press('c');
    assert.equal(await target.innerText(), 'Shift + arrows move the top-left corner of box 1.');
    await page.keyboard.press('Shift+ArrowLeft');
    const box = '0.34,0.25,0.67,0.76';
    await waitObstacle(box);
    // The run and the downloads are the CLI's in the resized world.
    const args = ['7', '800', '--obstacle', box];
    assert.equal(await page.locator('[data-cmd="bsv"]').innerText(), `bsv rrt-2d ${args.join(' ')}`);
    await page.locator('[data-action="end"]').click();
    assert.equal((await counters(page)).nodes, cliNodes(args));
    const want = cli(['rrt-2d', ...args]).files;
    for (const file of ['rrt_nodes.csv', 'rrt_path.csv']) {
      assertSameBytes(await download(page, file), want.get(file), `resized by keys: ${file}`);
    }
    // After the four corners, c comes back to the whole box.
    await canvas.focus();
    for (const key of ['c', 'c', 'c']) await page.keyboard.press(key);
    assert.equal(await target.innerText(), 'Shift + arrows move box 1.');
    // A corner cannot cross the opposite one: the box keeps its smallest side (0.02).
    await page.keyboard.press('c');
    for (let k = 0; k < 60; k++) await page.keyboard.press('Shift+ArrowDown');
    await waitObstacle('0.34,0.25,0.67,0.27');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
  // c with the start chosen (or nothing): the top-right corner of the selected box, else box 1.
  // A corner that would make the box cover the goal is refused with the drag's message.
  const near = await open('#/rrt-2d?obstacle=0.5,0.5,0.9,0.89');
  try {
    const { page } = near;
    const target = page.locator('[data-testid="rrt-2d-key-target"]');
    const message = page.locator('[data-testid="rrt-2d-world-message"]');
    await page.locator('[data-testid="rrt-2d-canvas"]').focus();
    await page.keyboard.press('c');
    assert.equal(await target.innerText(), 'Shift + arrows move the top-right corner of box 1.');
    await page.keyboard.press('Shift+ArrowUp');
    assert.equal(await message.isVisible(), true);
    assert.match(await message.innerText(), /box 1 would cover the goal/);
    assert.equal((await query(page)).get('obstacle'), '0.5,0.5,0.9,0.89');
    await page.keyboard.press('Shift+ArrowDown');
    await page.waitForFunction(() => /obstacle=0\.5(%2C|,)0\.5(%2C|,)0\.9(%2C|,)0\.88/.test(location.hash), null, { timeout: 3000 });
    assert.equal(await message.isVisible(), false);
    // The ? overlay lists the key, in English and in Japanese.
    await page.keyboard.press('?');
    assert.match(await page.locator('[data-testid="page-keys"]').innerText(), /c\s+Choose a corner of the chosen box/);
    await page.keyboard.press('Escape');
    await page.keyboard.press('l');
    await page.keyboard.press('?');
    assert.match(await page.locator('[data-testid="page-keys"]').innerText(), /c\s+選んだ箱の角を選ぶ/);
    await page.keyboard.press('Escape');
    await page.locator('[data-testid="rrt-2d-canvas"]').focus();
    await page.keyboard.press('c');
    assert.equal(await target.innerText(), 'Shift + 矢印キーで箱 1 の左上の角を動かします。');
    assert.deepEqual(near.errors, []);
  } finally {
    await near.close();
  }
});

test('a bad field shows its message and keeps the last run', async () => {
  const { page, errors, close } = await open();
  try {
    const field = page.locator('[data-field="step"]');
    const message = page.locator('[data-field-error="step"]');
    await field.fill('5');
    assert.equal(await message.isVisible(), true);
    await page.locator('[data-action="end"]').click();
    assert.equal((await counters(page)).nodes, 91);
    await field.fill('0.04');
    assert.equal(await message.isVisible(), false);
    await page.waitForFunction(() => /step=0\.04/.test(location.hash), null, { timeout: 3000 });
    await page.locator('[data-action="end"]').click();
    assert.equal((await counters(page)).nodes, cliNodes(['7', '800', '--step', '0.04']));
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('Japanese leaves no English UI text', async () => {
  const english = englishStrings();
  const { page, errors, close } = await open('#/rrt-2d?lang=ja&obstacle=0.35,0.25,0.65,0.75&obstacle=0.1,0.6,0.3,0.7&it=0');
  try {
    for (let k = 0; k < 6; k++) await page.locator('[data-action="step"]').click();
    await dragWorld(page, [0.9, 0.9], [0.5, 0.5], 1);
    assert.ok(await page.locator('[data-testid="rrt-2d-world-message"]').isVisible());
    await page.locator('[data-field="seed"]').fill('abc');
    const text = await page.evaluate(() => document.body.innerText);
    const left = english.filter((s) => text.includes(s));
    assert.deepEqual(left, [], `English left on the Japanese page: ${left.join(' | ')}`);
    assert.match(text, /RRT ステッパー/);
    assert.match(text, /反復 6：/);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('screenshots: EN and JA 1920×1080, projector, phone 390 px', async () => {
  const shots = [
    ['rrt-en-1920.png', '#/rrt-2d?it=60', { viewport: { width: 1920, height: 1080 } }],
    ['rrt-ja-1920.png', '#/rrt-2d?lang=ja&obstacle=0.35,0.25,0.65,0.75&obstacle=0.7,0.5,0.85,0.6&it=300', { viewport: { width: 1920, height: 1080 } }],
    ['rrt-projector-1920.png', '#/rrt-2d?it=120', { viewport: { width: 1920, height: 1080 }, storage: { 'bsv.projector': '1' } }],
    ['rrt-phone-390.png', '#/rrt-2d?lang=ja&it=40', { viewport: { width: 390, height: 844 } }],
  ];
  await screenshots(server.url, shots, { prepare: (page) => page.waitForTimeout(500) });
});

test('opening the page (the default, and 20,000 iterations with the goal walled in), from another page or as a fresh load: it grows the run to its end and opens ready to step', { timeout: 300_000 }, async () => {
  const walls = ['0.7,0.7,0.9,0.72', '0.7,0.88,0.9,0.9', '0.7,0.7,0.72,0.9', '0.88,0.7,0.9,0.9'];
  const cases = ['#/rrt-2d', `#/rrt-2d?max_iter=20000&${walls.map((w) => `obstacle=${w}`).join('&')}&goal=0.8,0.8`];
  const { page, errors, close } = await open('#/');
  /** Navigates to `url` (a new document) and waits for the shell. */
  const load = async (url) => {
    await page.goto('about:blank');
    await page.goto(url);
    await page.waitForFunction(() => document.documentElement.dataset.appReady === '1', null, { timeout: 20_000 });
  };
  /** The run grown to its end (in slices after the first frame), the stepper at its start. */
  const settled = async (label, nodes) => {
    await page.waitForSelector('[data-testid="rrt-2d-finishing"][data-state="done"]', { state: 'attached', timeout: 60_000 });
    const c = await counters(page);
    assert.deepEqual([c.iteration, c.nodes, c.path_points], [5, nodes, 0], `${label}: ready to step, five iterations in`);
  };
  try {
    const nodesAt5 = [cliNodes(['7', '5']), cliNodes(['7', '5', ...walls.flatMap((w) => ['--obstacle', w]), '--goal', '0.8,0.8'])];
    for (const [k, hash] of cases.entries()) {
      await load(`${server.url}/#/ik-2r`);
      await page.evaluate((h) => { location.hash = h; }, hash);
      await settled(`opened from the IK page: ${hash}`, nodesAt5[k]);
      await load(`${server.url}/${hash}`);
      await settled(`a fresh load: ${hash}`, nodesAt5[k]);
    }
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('a 1,000,000-iteration walled-goal run grows in slices while the stepper steps; End and the CSVs equal bsv', { timeout: 600_000 }, async () => {
  const walls = ['0.7,0.7,0.9,0.72', '0.7,0.88,0.9,0.9', '0.7,0.7,0.72,0.9', '0.88,0.7,0.9,0.9'];
  const args = ['7', '1000000', ...walls.flatMap((w) => ['--obstacle', w]), '--goal', '0.8,0.8'];
  const want = cli(['rrt-2d', ...args]).files;
  const wantNodes = want.get('rrt_nodes.csv').toString('utf8').trim().split('\n').length - 1;
  const { page, errors, close } = await open(`#/rrt-2d?max_iter=1000000&${walls.map((w) => `obstacle=${w}`).join('&')}&goal=0.8,0.8&it=0`);
  try {
    const finishing = page.locator('[data-testid="rrt-2d-finishing"]');
    await page.waitForSelector('[data-testid="rrt-2d-finishing"][data-state="running"]', { timeout: 20_000 });
    // While the run grows to its end: the progress shows, the CSVs wait, the stepper steps.
    assert.ok(await finishing.isVisible());
    assert.ok(await page.locator('[data-download="rrt_nodes.csv"]').isDisabled());
    await page.locator('[data-action="step"]').click();
    assert.equal((await counters(page)).iteration, 1);
    await page.waitForSelector('[data-testid="rrt-2d-finishing"][data-state="done"]', { state: 'attached', timeout: 300_000 });
    assert.ok(!(await finishing.isVisible()));
    // End (the tree shown is a prefix of the finished run's), back and End again.
    await page.locator('[data-action="end"]').click();
    const c = await counters(page);
    assert.equal(c.iteration, 1_000_000);
    assert.equal(c.nodes, wantNodes);
    assert.equal(c.path_points, 0);
    await page.locator('[data-action="back"]').click();
    assert.equal((await counters(page)).iteration, 999_999);
    assert.equal((await counters(page)).nodes, cliNodes(['7', '999999', ...args.slice(2)]));
    await page.locator('[data-action="end"]').click();
    // The CSVs: the nodes file (864k rows) is written in slices.
    for (const file of ['rrt_nodes.csv', 'rrt_path.csv']) {
      assertSameBytes(await download(page, file), want.get(file), `1,000,000 walled ${file}`);
    }
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('without `it` the page opens five iterations in, the panel saying what ▶ and ▶| do (EN, JA); it=0 opens at 0', async () => {
  for (const [hash, help] of [['#/rrt-2d', /▶ plays.*▶\| takes one iteration/s], ['#/rrt-2d?lang=ja', /▶ は再生.*▶\| は 1 反復だけ進め/s]]) {
    const { page, errors, close } = await open(hash, { viewport: { width: 1366, height: 768 } });
    try {
      await page.waitForFunction(() => document.querySelector('[data-readout="iteration"]')?.textContent.trim() === '5', null, { timeout: 5000 });
      const c = await counters(page);
      assert.deepEqual([c.iteration, c.nodes], [5, cliNodes(['7', '5'])]);
      assert.match(await page.locator('[data-testid="rrt-2d-substeps"]').innerText(), /5/);
      const line = page.locator('[data-testid="rrt-2d-sub-help"]');
      assert.ok(await line.isVisible());
      assert.match(await line.innerText(), help);
      await page.waitForFunction(() => /(\?|&)it=5(&|$)/.test(location.hash), null, { timeout: 3000 });
      // The CSVs are the whole run, whatever the iteration shown.
      if (!hash.includes('ja')) {
        const want = cli(['rrt-2d', '7', '800']).files;
        assertSameBytes(await download(page, 'rrt_nodes.csv'), want.get('rrt_nodes.csv'), 'opened at 5: rrt_nodes.csv');
      }
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
  const { page, errors, close } = await open('#/rrt-2d?it=0');
  try {
    await page.waitForSelector('[data-testid="rrt-2d-finishing"][data-state="done"]', { state: 'attached', timeout: 20_000 });
    await page.waitForTimeout(300);
    assert.equal((await counters(page)).iteration, 0);
    assert.ok(await page.locator('[data-rrt="sub-none"]').isVisible());
    assert.ok(await page.locator('[data-testid="rrt-2d-sub-help"]').isVisible());
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
  await screenshots(server.url, [
    ['rrt-open-en-1366.png', '#/rrt-2d', { viewport: { width: 1366, height: 768 } }],
    ['rrt-open-ja-390.png', '#/rrt-2d?lang=ja', { viewport: { width: 390, height: 844 } }],
  ], { prepare: (page) => page.waitForTimeout(500) });
});
