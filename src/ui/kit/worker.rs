//! Long recipe runs off the main thread: a module Web Worker (`www/worker.js`) that loads the
//! same `pkg/bsv_playground.js` + wasm as the page (no second build, no bundler) and runs the
//! recipe with the same kernel code, so its files are byte for byte those of a run on the page.
//!
//! Two halves live here:
//! - [`worker_run_recipe`] (`workerRunRecipe`), the export the worker script calls; it runs in
//!   the worker and never touches the DOM. It returns each file's bytes (the worker makes a
//!   `Blob` of them: a 50 MB CSV is never decoded or copied on the main thread), a preview of
//!   [`HEAD_LINES`] lines, the summary, the warnings and the messages in English and Japanese.
//! - [`run_recipe`] / [`Job`], used by pages on the main thread: one worker, started lazily
//!   and kept, serves one job at a time; a new job or [`Job::cancel`] terminates a running one
//!   at once (the next starts a fresh worker), and a late message of a cancelled job is
//!   ignored (each carries its job number). A file the page never read goes as the `Blob`
//!   itself ([`WorkerInput::Blob`]); with [`RunOptions::envelope`] the worker also sends each
//!   file's plot envelope. The messages between page and worker: [`run_recipe_with`].

use std::cell::{Cell, RefCell};
use std::rc::Rc;

use js_sys::{Array, Reflect, Uint8Array};
use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
#[cfg(feature = "split")]
use wasm_split_helpers::{wasm_split, SplitLoaderError};
use web_sys::{Blob, ErrorEvent, MessageEvent, Worker, WorkerOptions, WorkerType};

use crate::error::RecipeError;
use crate::i18n::{FluentArg, I18n, Lang};
use crate::recipes;
use crate::ui::ctx;
use crate::view::envelope::{csv_envelope, Envelope};
use crate::view::worker::{data_rows, head};

/// The worker script, relative to `index.html`.
const WORKER_URL: &str = "www/worker.js";

/// Lines of each file (header included) that come back as text for previews.
pub const HEAD_LINES: usize = 200;

// ---------------------------------------------------------------------------------------------
// In the worker.

thread_local! {
    /// The worker's own Fluent bundles: the kernels' errors and warnings, in both languages
    /// (built on its first message that needs them).
    static WORKER_I18N: I18n = I18n::from_sources(crate::i18n::ERROR_SOURCES);
}

fn set(target: &JsValue, key: &str, value: &JsValue) -> Result<(), JsValue> {
    Reflect::set(target, &JsValue::from_str(key), value).map(|_| ())
}

fn get(target: &JsValue, key: &str) -> JsValue {
    Reflect::get(target, &JsValue::from_str(key)).unwrap_or(JsValue::UNDEFINED)
}

fn get_string(target: &JsValue, key: &str) -> String {
    get(target, key).as_string().unwrap_or_default()
}

/// `{ en, ja }` of one message, formatted by `format` in each language, and the bundles'
/// notes (missing messages) made meanwhile.
fn both(format: impl Fn(&I18n, Lang) -> String) -> Result<(JsValue, Array), JsValue> {
    WORKER_I18N.with(|i18n| {
        let texts = js_sys::Object::new();
        set(&texts, "en", &format(i18n, Lang::En).into())?;
        set(&texts, "ja", &format(i18n, Lang::Ja).into())?;
        let notes: Array = i18n
            .take_warnings()
            .into_iter()
            .map(|n| JsValue::from_str(&n))
            .collect();
        Ok((texts.into(), notes))
    })
}

/// An envelope as a plain object: `{ header: [..], rows, span: [x0, x1] | null, series:
/// [Float64Array (x, y interleaved)] }`.
fn envelope_to_js(envelope: &Envelope) -> Result<JsValue, JsValue> {
    let out = js_sys::Object::new();
    set(&out, "header", &strings(envelope.header.iter().cloned()))?;
    set(&out, "rows", &JsValue::from_f64(envelope.rows as f64))?;
    let span = match envelope.x_span {
        Some((a, b)) => Array::of2(&JsValue::from_f64(a), &JsValue::from_f64(b)).into(),
        None => JsValue::NULL,
    };
    set(&out, "span", &span)?;
    let series = Array::new();
    for column in &envelope.series {
        let flat: Vec<f64> = column.iter().flat_map(|&(x, y)| [x, y]).collect();
        series.push(&js_sys::Float64Array::from(flat.as_slice()));
    }
    set(&out, "series", &series)?;
    Ok(out.into())
}

fn envelope_from_js(value: &JsValue) -> Option<Envelope> {
    if value.is_null() || value.is_undefined() {
        return None;
    }
    let header = Array::from(&get(value, "header"))
        .iter()
        .map(|h| h.as_string().unwrap_or_default())
        .collect();
    let span = get(value, "span");
    let x_span = if span.is_null() || span.is_undefined() {
        None
    } else {
        let span = Array::from(&span);
        Some((
            span.get(0).as_f64().unwrap_or(0.0),
            span.get(1).as_f64().unwrap_or(0.0),
        ))
    };
    let series = Array::from(&get(value, "series"))
        .iter()
        .map(|s| {
            js_sys::Float64Array::new(&s)
                .to_vec()
                .chunks_exact(2)
                .map(|p| (p[0], p[1]))
                .collect()
        })
        .collect();
    Some(Envelope {
        header,
        rows: get(value, "rows").as_f64().unwrap_or(0.0) as u64,
        x_span,
        series,
    })
}

/// The refusal `{ ok: false, error, param, en, ja, english, i18n }` of `error`.
fn refusal(error: &crate::error::RecipeError) -> Result<JsValue, JsValue> {
    let out = js_sys::Object::new();
    let (texts, notes) = both(|i18n, lang| i18n.recipe_error(lang, error))?;
    set(&out, "ok", &JsValue::FALSE)?;
    set(
        &out,
        "error",
        &serde_wasm_bindgen::to_value(error).unwrap_or(JsValue::NULL),
    )?;
    set(
        &out,
        "param",
        &error.param().map_or(JsValue::NULL, JsValue::from_str),
    )?;
    set(&out, "en", &get(&texts, "en"))?;
    set(&out, "ja", &get(&texts, "ja"))?;
    set(&out, "english", &error.to_string().into())?;
    set(&out, "i18n", &notes)?;
    Ok(out.into())
}

/// `workerRunRecipe(id, args, names, inputs, progress, envelope)`: runs recipe `id` with
/// command-line style `args` and input files (`names[i]` holds `inputs[i]`: its text, or its
/// bytes as a `Uint8Array`, decoded here as the CLI decodes a file), calling
/// `progress(done, total)` as rows are done. Called by `www/worker.js` only. Returns `{ ok:
/// true, summary, warnings, i18n, files: [{ name, data: Uint8Array, rows, head, envelope }],
/// inputs: [{ name, envelope }] }` (envelopes of `envelope` buckets when it is not 0, else
/// null) or `{ ok: false, error, param, en, ja, english, i18n }`.
/// Its code (the kernels) is a wasm chunk of its own, loaded on the worker's first job.
#[wasm_bindgen(js_name = workerRunRecipe)]
pub async fn worker_run_recipe(
    id: String,
    args: Vec<String>,
    names: Vec<String>,
    inputs: Array,
    progress: js_sys::Function,
    envelope: u32,
) -> Result<JsValue, JsValue> {
    let kernels = kernels()
        .await
        .map_err(|error| JsValue::from_str(&format!("the worker's code: {error}")))?;
    (kernels.in_worker)(&id, args, names, inputs, &progress, envelope)
}

/// A worker job ([`run_in_worker`]).
type InWorker =
    fn(&str, Vec<String>, Vec<String>, Array, &js_sys::Function, u32) -> Result<JsValue, JsValue>;

/// A run on the page ([`recipes::run_with_inputs`]).
pub type OnPage =
    fn(&str, &[String], Vec<(String, String)>) -> Result<recipes::RecipeOutput, RecipeError>;

/// Every kernel, as the worker's jobs and the drills page's small runs reach them.
#[derive(Clone, Copy)]
pub struct Kernels {
    in_worker: InWorker,
    /// Runs a recipe on the page and returns its output.
    pub on_page: OnPage,
}

const KERNELS: Kernels = Kernels {
    in_worker: run_in_worker,
    on_page: recipes::run_with_inputs,
};

/// The kernels: a wasm chunk of their own (the worker's), loaded by the worker's first job,
/// or on the page by the first run of the drills page.
#[cfg(feature = "split")]
#[wasm_split(worker, fallible)]
pub fn kernels() -> Result<Kernels, SplitLoaderError> {
    Ok(KERNELS)
}

/// Without the `split` feature the kernels are in the one wasm.
#[cfg(not(feature = "split"))]
pub async fn kernels() -> Result<Kernels, wasm_split_helpers::SplitLoaderError> {
    Ok(KERNELS)
}

fn run_in_worker(
    id: &str,
    args: Vec<String>,
    names: Vec<String>,
    inputs: Array,
    progress: &js_sys::Function,
    envelope: u32,
) -> Result<JsValue, JsValue> {
    let mut texts = Vec::new();
    for (name, value) in names.iter().zip(inputs.iter()) {
        let text = match value.as_string() {
            Some(text) => text,
            None => match recipes::decode_input(name, &Uint8Array::new(&value).to_vec()) {
                Ok(text) => text,
                Err(error) => return refusal(&error),
            },
        };
        texts.push(text);
    }
    let buckets = envelope as usize;
    let envelope_of = |text: &str| -> Result<JsValue, JsValue> {
        if buckets == 0 {
            Ok(JsValue::NULL)
        } else {
            envelope_to_js(&csv_envelope(text, buckets))
        }
    };
    let input_envelopes = Array::new();
    for (name, text) in names.iter().zip(&texts) {
        let entry = js_sys::Object::new();
        set(&entry, "name", &name.as_str().into())?;
        set(&entry, "envelope", &envelope_of(text)?)?;
        input_envelopes.push(&entry);
    }
    let inputs: Vec<(String, String)> = names.into_iter().zip(texts).collect();
    let report = |done: u64, total: u64| {
        // Numbers, not BigInts: row counts stay far below 2^53.
        let _ = progress.call2(
            &JsValue::NULL,
            &JsValue::from_f64(done as f64),
            &JsValue::from_f64(total as f64),
        );
    };
    let mut report = report;
    let result = recipes::run_with_progress(id, &args, inputs, &mut report);
    let out = js_sys::Object::new();
    match result {
        Ok(output) => {
            set(&out, "ok", &JsValue::TRUE)?;
            set(&out, "summary", &output.summary.as_str().into())?;
            let files = Array::new();
            for file in output.files {
                let entry = js_sys::Object::new();
                set(&entry, "name", &file.name.as_str().into())?;
                set(&entry, "head", &head(&file.text, HEAD_LINES).into())?;
                set(
                    &entry,
                    "rows",
                    &JsValue::from_f64(data_rows(&file.text) as f64),
                )?;
                set(
                    &entry,
                    "data",
                    &Uint8Array::from(file.text.as_bytes()).into(),
                )?;
                set(&entry, "envelope", &envelope_of(&file.text)?)?;
                files.push(&entry);
            }
            set(&out, "files", &files)?;
            set(&out, "inputs", &input_envelopes)?;
            let warnings = Array::new();
            let notes = Array::new();
            for warning in &output.warnings {
                let args: Vec<(&str, FluentArg)> = warning
                    .message_args()
                    .into_iter()
                    .map(|(name, value)| (name, FluentArg::Text(value)))
                    .collect();
                let (texts, more) =
                    both(|i18n, lang| i18n.t_args(lang, warning.message_id(), &args))?;
                warnings.push(&texts);
                for note in more.iter() {
                    notes.push(&note);
                }
            }
            set(&out, "warnings", &warnings)?;
            set(&out, "i18n", &notes)?;
        }
        Err(error) => return refusal(&error),
    }
    Ok(out.into())
}

// ---------------------------------------------------------------------------------------------
// On the page.

/// A message in both languages (the worker formats it, so the page can switch language while
/// it is shown).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Localized {
    pub en: String,
    pub ja: String,
}

impl Localized {
    /// The text in the current language.
    pub fn text(&self) -> &str {
        match ctx::lang() {
            Lang::Ja => &self.ja,
            Lang::En => &self.en,
        }
    }

    fn from_js(value: &JsValue) -> Localized {
        Localized {
            en: get_string(value, "en"),
            ja: get_string(value, "ja"),
        }
    }
}

/// A finished worker run.
#[derive(Debug, Clone)]
pub struct WorkerOutput {
    /// Exactly what the recipe prints.
    pub summary: String,
    pub files: Vec<WorkerFile>,
    /// What the recipe warns about (diverged, goal not reached...), localized.
    pub warnings: Vec<Localized>,
    /// The input files' plot envelopes, by name (with [`RunOptions::envelope`]).
    pub inputs: Vec<(String, Option<Envelope>)>,
}

impl WorkerOutput {
    /// The file called `name`.
    pub fn file(&self, name: &str) -> Option<&WorkerFile> {
        self.files.iter().find(|f| f.name == name)
    }
}

/// One file of a worker run: its bytes as a `Blob` (offer it with [`download`]; never read it
/// whole on the main thread) and its first [`HEAD_LINES`] lines for a preview.
#[derive(Debug, Clone)]
pub struct WorkerFile {
    pub name: String,
    pub blob: Blob,
    /// Size in bytes.
    pub bytes: u64,
    /// Data rows (non-empty lines after the header).
    pub rows: u64,
    /// The first [`HEAD_LINES`] lines (all of a shorter file), line ends included.
    pub head: String,
    /// Its plot envelope (with [`RunOptions::envelope`]).
    pub envelope: Option<Envelope>,
}

/// An input file handed to the worker: its text, or the file itself, read and decoded in the
/// worker (by [`crate::recipes::decode_input`]) so the page never holds a big file's text.
#[derive(Debug, Clone)]
pub enum WorkerInput {
    Text(String),
    Blob(Blob),
}

/// What a run sends back besides the recipe's output.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct RunOptions {
    /// Buckets of the plot envelopes of every input and output file (0: none).
    pub envelope: u32,
}

/// Why a worker run gave no output.
#[derive(Debug, Clone, PartialEq)]
pub enum WorkerError {
    /// The recipe refused its arguments or input: the error itself (for a page to place and
    /// word it as it does its own runs' errors; `None` only if it could not be decoded), the
    /// kernel's message in both languages, the parameter it is about (if any) and its English
    /// one-liner (the CLI's).
    Recipe {
        error: Option<RecipeError>,
        message: Localized,
        param: Option<String>,
        english: String,
    },
    /// The worker could not start or stopped (the browser's message).
    Failed(String),
}

impl WorkerError {
    /// The message in the current language.
    pub fn text(&self) -> String {
        match self {
            WorkerError::Recipe { message, .. } => message.text().to_string(),
            WorkerError::Failed(detail) => {
                ctx::t_strings("kit-worker-failed", &[("detail", detail.clone())])
            }
        }
    }

    /// The recipe's error, when the recipe refused (decoded from the worker's message).
    pub fn recipe_error(&self) -> Option<&RecipeError> {
        match self {
            WorkerError::Recipe { error, .. } => error.as_ref(),
            WorkerError::Failed(_) => None,
        }
    }

    /// The parameter the error is about.
    pub fn param(&self) -> Option<&str> {
        match self {
            WorkerError::Recipe { param, .. } => param.as_deref(),
            WorkerError::Failed(_) => None,
        }
    }
}

type OnProgress = Rc<dyn Fn(u64, u64)>;
type OnDone = Box<dyn FnOnce(Result<WorkerOutput, WorkerError>)>;

/// The worker and its handlers (dropped only after a timer once retired: a handler may be the
/// one retiring it).
struct Host {
    worker: Worker,
    _on_message: Closure<dyn FnMut(MessageEvent)>,
    _on_error: Closure<dyn FnMut(ErrorEvent)>,
}

struct Active {
    job: u32,
    on_progress: OnProgress,
    on_done: Option<OnDone>,
}

thread_local! {
    static HOST: RefCell<Option<Host>> = const { RefCell::new(None) };
    static RETIRED: RefCell<Vec<Host>> = const { RefCell::new(Vec::new()) };
    static ACTIVE: RefCell<Option<Active>> = const { RefCell::new(None) };
    static NEXT_JOB: Cell<u32> = const { Cell::new(1) };
}

/// A running worker job. [`cancel`](Job::cancel) or dropping it stops the run (its `on_done`
/// is then never called); after it finished both do nothing.
#[derive(Debug)]
pub struct Job {
    id: u32,
}

impl Job {
    /// Stops the run now: terminates the worker (a fresh one serves the next job).
    pub fn cancel(&self) {
        let mine = ACTIVE.with(|a| {
            let mut active = a.borrow_mut();
            if active.as_ref().is_some_and(|x| x.job == self.id) {
                *active = None;
                true
            } else {
                false
            }
        });
        if mine {
            retire_host();
        }
    }

    /// Whether the run has neither finished nor been cancelled.
    pub fn is_running(&self) -> bool {
        ACTIVE.with(|a| a.borrow().as_ref().is_some_and(|x| x.job == self.id))
    }
}

impl Drop for Job {
    fn drop(&mut self) {
        self.cancel();
    }
}

/// Terminates the current worker and drops its handlers soon (not now: this may run inside one
/// of them).
fn retire_host() {
    let Some(host) = HOST.with(|h| h.borrow_mut().take()) else {
        return;
    };
    host.worker.terminate();
    host.worker.set_onmessage(None);
    host.worker.set_onerror(None);
    RETIRED.with(|r| r.borrow_mut().push(host));
    let clear = Closure::once_into_js(|| RETIRED.with(|r| r.borrow_mut().clear()));
    if let Some(window) = web_sys::window() {
        let _ =
            window.set_timeout_with_callback_and_timeout_and_arguments_0(clear.unchecked_ref(), 0);
    }
}

/// Ends the active job `job` (if it still is) and hands `result` to its `on_done`.
fn finish(job: u32, result: Result<WorkerOutput, WorkerError>) {
    let done = ACTIVE.with(|a| {
        let mut active = a.borrow_mut();
        if active.as_ref().is_some_and(|x| x.job == job) {
            active.take().and_then(|x| x.on_done)
        } else {
            None
        }
    });
    if let Some(on_done) = done {
        on_done(result);
    }
}

/// Logs the worker's i18n notes as the page's own are logged (`i18n: ...`).
fn log_notes(data: &JsValue) {
    for note in Array::from(&get(data, "i18n")).iter() {
        if let Some(note) = note.as_string() {
            web_sys::console::warn_1(&format!("i18n: {note}").into());
        }
    }
}

fn output_of(data: &JsValue) -> Result<WorkerOutput, JsValue> {
    let mut files = Vec::new();
    for entry in Array::from(&get(data, "files")).iter() {
        files.push(WorkerFile {
            name: get_string(&entry, "name"),
            blob: get(&entry, "blob").dyn_into::<Blob>()?,
            bytes: get(&entry, "bytes").as_f64().unwrap_or(0.0) as u64,
            rows: get(&entry, "rows").as_f64().unwrap_or(0.0) as u64,
            head: get_string(&entry, "head"),
            envelope: envelope_from_js(&get(&entry, "envelope")),
        });
    }
    let inputs = Array::from(&get(data, "inputs"))
        .iter()
        .map(|i| {
            (
                get_string(&i, "name"),
                envelope_from_js(&get(&i, "envelope")),
            )
        })
        .collect();
    let warnings = Array::from(&get(data, "warnings"))
        .iter()
        .map(|w| Localized::from_js(&w))
        .collect();
    Ok(WorkerOutput {
        summary: get_string(data, "summary"),
        files,
        warnings,
        inputs,
    })
}

fn on_message(event: MessageEvent) {
    let data = event.data();
    let Some(job) = get(&data, "job").as_f64().map(|j| j as u32) else {
        return;
    };
    let kind = get_string(&data, "type");
    match kind.as_str() {
        "progress" => {
            let callback = ACTIVE.with(|a| {
                a.borrow()
                    .as_ref()
                    .filter(|x| x.job == job)
                    .map(|x| x.on_progress.clone())
            });
            if let Some(callback) = callback {
                let number = |k| get(&data, k).as_f64().unwrap_or(0.0).max(0.0) as u64;
                callback(number("done"), number("total"));
            }
        }
        "done" => {
            log_notes(&data);
            let result = output_of(&data).map_err(|e| {
                WorkerError::Failed(e.as_string().unwrap_or_else(|| format!("{e:?}")))
            });
            finish(job, result);
        }
        "error" => {
            log_notes(&data);
            let param = get(&data, "param").as_string();
            let error = serde_wasm_bindgen::from_value(get(&data, "error")).ok();
            finish(
                job,
                Err(WorkerError::Recipe {
                    error,
                    message: Localized::from_js(&data),
                    param,
                    english: get_string(&data, "english"),
                }),
            );
        }
        "crash" => {
            // The wasm instance in the worker may be unusable now: the next job gets a fresh one.
            let is_active = ACTIVE.with(|a| a.borrow().as_ref().is_some_and(|x| x.job == job));
            if is_active {
                retire_host();
            }
            finish(job, Err(WorkerError::Failed(get_string(&data, "message"))));
        }
        _ => {}
    }
}

fn on_error(event: ErrorEvent) {
    // The script or its imports failed to load, or an error escaped the worker's handler.
    event.prevent_default();
    let job = ACTIVE.with(|a| a.borrow().as_ref().map(|x| x.job));
    retire_host();
    if let Some(job) = job {
        let message = event.message();
        let detail = if message.is_empty() {
            WORKER_URL.to_string()
        } else {
            message
        };
        finish(job, Err(WorkerError::Failed(detail)));
    }
}

fn host_worker() -> Result<Worker, JsValue> {
    if let Some(worker) = HOST.with(|h| h.borrow().as_ref().map(|h| h.worker.clone())) {
        return Ok(worker);
    }
    let options = WorkerOptions::new();
    options.set_type(WorkerType::Module);
    let worker = Worker::new_with_options(WORKER_URL, &options)?;
    let on_message = Closure::<dyn FnMut(MessageEvent)>::new(on_message);
    let on_error = Closure::<dyn FnMut(ErrorEvent)>::new(on_error);
    worker.set_onmessage(Some(on_message.as_ref().unchecked_ref()));
    worker.set_onerror(Some(on_error.as_ref().unchecked_ref()));
    HOST.with(|h| {
        *h.borrow_mut() = Some(Host {
            worker: worker.clone(),
            _on_message: on_message,
            _on_error: on_error,
        })
    });
    Ok(worker)
}

fn strings(items: impl IntoIterator<Item = String>) -> Array {
    items.into_iter().map(|s| JsValue::from_str(&s)).collect()
}

/// Runs recipe `id` with command-line style `args` and input files `(name, text)` in the
/// worker. `on_progress(done, total)` is called as rows are done (about 10 times a second at
/// most); `on_done` once with the output or the error, unless the job is cancelled first.
/// A job already running is cancelled.
pub fn run_recipe(
    id: &str,
    args: Vec<String>,
    inputs: Vec<(String, String)>,
    on_progress: impl Fn(u64, u64) + 'static,
    on_done: impl FnOnce(Result<WorkerOutput, WorkerError>) + 'static,
) -> Result<Job, JsValue> {
    let inputs = inputs
        .into_iter()
        .map(|(name, text)| (name, WorkerInput::Text(text)))
        .collect();
    run_recipe_with(
        id,
        args,
        inputs,
        RunOptions::default(),
        on_progress,
        on_done,
    )
}

/// [`run_recipe`] with inputs as text or files and [`RunOptions`].
///
/// Messages, page → worker: `{ job, id, args: [..], names: [..], texts: [string | Blob],
/// envelope }`; worker → page: `{ job, type: "progress", done, total }` (at most ~10 a second),
/// `{ job, type: "done", summary, warnings: [{en, ja}], i18n: [..], files: [{ name, blob, bytes,
/// rows, head, envelope }], inputs: [{ name, envelope }] }`,
/// `{ job, type: "error", error, param, en, ja, english, i18n }` (the recipe refused: `error`
/// is the [`RecipeError`] itself, serialized, so the page can put it beside its field and word it
/// exactly as its own run's error) or
/// `{ job, type: "crash", message }` (the worker could not load or stopped).
pub fn run_recipe_with(
    id: &str,
    args: Vec<String>,
    inputs: Vec<(String, WorkerInput)>,
    options: RunOptions,
    on_progress: impl Fn(u64, u64) + 'static,
    on_done: impl FnOnce(Result<WorkerOutput, WorkerError>) + 'static,
) -> Result<Job, JsValue> {
    let running = ACTIVE.with(|a| a.borrow_mut().take()).is_some();
    if running {
        retire_host();
    }
    let worker = host_worker()?;
    let job = NEXT_JOB.with(|n| {
        let job = n.get();
        n.set(job.wrapping_add(1).max(1));
        job
    });
    let (names, texts): (Vec<String>, Vec<WorkerInput>) = inputs.into_iter().unzip();
    let texts: Array = texts
        .into_iter()
        .map(|input| match input {
            WorkerInput::Text(text) => JsValue::from_str(&text),
            WorkerInput::Blob(blob) => blob.into(),
        })
        .collect();
    let message = js_sys::Object::new();
    set(&message, "job", &JsValue::from_f64(f64::from(job)))?;
    set(&message, "id", &id.into())?;
    set(&message, "args", &strings(args))?;
    set(&message, "names", &strings(names))?;
    set(&message, "texts", &texts)?;
    set(
        &message,
        "envelope",
        &JsValue::from_f64(f64::from(options.envelope)),
    )?;
    ACTIVE.with(|a| {
        *a.borrow_mut() = Some(Active {
            job,
            on_progress: Rc::new(on_progress),
            on_done: Some(Box::new(on_done)),
        })
    });
    if let Err(e) = worker.post_message(&message) {
        ACTIVE.with(|a| a.borrow_mut().take());
        retire_host();
        return Err(e);
    }
    Ok(Job { id: job })
}

/// Offers a worker file for download ([`crate::ui::download::download_blob`]: an object URL
/// of its `Blob`, so nothing is read or copied on the main thread, whatever the size).
pub fn download(file: &WorkerFile) -> Result<(), JsValue> {
    crate::ui::download::download_blob(&file.blob, &file.name)
}
