// The Web Worker of long recipe runs (src/ui/kit/worker.rs starts it as a module worker).
// It loads the page's own wasm module (../pkg/bsv_playground.js + its .wasm: no second build)
// and runs one recipe per message with `workerRunRecipe`, the same kernel code as a run on the
// page (its first job fetches the kernels' chunk). Progress goes back at most ~10 times a
// second; the files go back as Blobs built here, so that the page never decodes or copies a
// large CSV on its main thread, with a text head
// for previews. Nothing here touches a DOM (there is none).
import init, { workerRunRecipe } from '../pkg/bsv_playground.js';

/** Milliseconds between two progress messages. */
const PROGRESS_EVERY_MS = 100;

const ready = init();

self.onmessage = async ({ data }) => {
  const { job } = data;
  try {
    await ready;
  } catch (error) {
    self.postMessage({ job, type: 'crash', message: `could not load the wasm: ${error?.message ?? error}` });
    return;
  }
  let last = -Infinity;
  const progress = (done, total) => {
    const now = performance.now();
    if (now - last < PROGRESS_EVERY_MS && done < total) return;
    last = now;
    self.postMessage({ job, type: 'progress', done, total });
  };
  let out;
  try {
    // Input files sent as Blobs are read here; the wasm decodes their bytes as the CLI does.
    const inputs = await Promise.all(data.texts.map(async (t) => (typeof t === 'string' ? t : new Uint8Array(await t.arrayBuffer()))));
    out = await workerRunRecipe(data.id, data.args, data.names, inputs, progress, data.envelope ?? 0);
  } catch (error) {
    // A panic (or an exception) in the kernel: the instance may be unusable; the page starts
    // a fresh worker for its next run.
    self.postMessage({ job, type: 'crash', message: String(error?.message ?? error) });
    return;
  }
  if (!out.ok) {
    self.postMessage({ job, type: 'error', error: out.error, param: out.param, en: out.en, ja: out.ja, english: out.english, i18n: out.i18n });
    return;
  }
  const files = out.files.map((f) => ({
    name: f.name,
    bytes: f.data.byteLength,
    rows: f.rows,
    head: f.head,
    blob: new Blob([f.data], { type: 'text/csv' }),
    envelope: f.envelope,
  }));
  const transfer = [...files, ...out.inputs].flatMap((f) => (f.envelope ? f.envelope.series.map((s) => s.buffer) : []));
  self.postMessage({ job, type: 'done', summary: out.summary, warnings: out.warnings, i18n: out.i18n, files, inputs: out.inputs }, transfer);
};
