// The `bsv` CLI as the reference the pages' downloads are checked against: building it, running
// it into a fresh folder, saving what a page downloads, and comparing the two byte for byte.
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, readdirSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { ROOT, serveApp } from './harness.mjs';

export const BSV = join(ROOT, 'target', 'debug', 'bsv');

/** Builds the CLI from the same sources as the wasm under test (a no-op when it is up to date). */
export function buildCli() {
  execFileSync('cargo', ['build', '--quiet', '--bin', 'bsv'], { cwd: ROOT, stdio: 'inherit' });
}

/**
 * Registers the hooks of a test file that checks pages against the CLI: before its tests the
 * CLI is built and dist/ served; after them `onClose()` runs, then the browser and the server
 * close. Returns `{ url }` (the server's, once it is up).
 */
export function serveAppWithCli(onClose = () => {}) {
  return serveApp({ setup: buildCli, teardown: onClose, timeout: 600_000 });
}

/** Runs `bsv <args> --out DIR`: its stdout (trailing newline removed) and every file written.
 * The folder is removed again, whatever happens. */
export function cli(args) {
  const dir = mkdtempSync(join(tmpdir(), 'bsv-cli-'));
  try {
    const stdout = execFileSync(BSV, [...args, '--out', dir], { encoding: 'utf8', stdio: ['ignore', 'pipe', 'inherit'] });
    const files = new Map(readdirSync(dir).map((f) => [f, readFileSync(join(dir, f))]));
    return { stdout: stdout.replace(/\n$/, ''), files };
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
}

/**
 * The CSV `file` of `bsv <args>`: its bytes, its column names and its data rows as cell texts
 * (with the run's other files and stdout).
 */
export function cliCsv(args, file) {
  const { files, stdout } = cli(args);
  const bytes = files.get(file);
  const [head, ...rows] = bytes.toString('utf8').trim().split(/\r?\n/).map((l) => l.split(','));
  return { bytes, head, rows, files, stdout };
}

/** Clicks the page's `[data-download="<file>"]` button and returns the bytes it saved. */
export async function download(page, file) {
  const [dl] = await Promise.all([
    page.waitForEvent('download'),
    page.locator(`[data-download="${file}"]`).click(),
  ]);
  assert.equal(dl.suggestedFilename(), file);
  const dir = mkdtempSync(join(tmpdir(), 'bsv-dl-'));
  try {
    const path = join(dir, file);
    await dl.saveAs(path);
    return readFileSync(path);
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
}

/** Asserts identical bytes; on failure names the first differing line of both. */
export function assertSameBytes(got, want, label) {
  if (got.equals(want)) return;
  const a = got.toString('utf8').split('\n');
  const b = want.toString('utf8').split('\n');
  const i = a.findIndex((line, k) => line !== b[k]);
  assert.fail(`${label}: ${got.length} vs ${want.length} bytes; first difference on line ${i + 1}:\n  page: ${a[i]}\n  cli:  ${b[i]}`);
}
