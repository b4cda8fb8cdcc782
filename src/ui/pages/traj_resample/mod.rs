//! Trajectory resampling (`#/traj-resample?csv_path=walk.csv&dt=0.05`): open a trajectory CSV
//! (the button, or drop it on the page) or use the recipe's labeled sample, set dt, and see
//! each joint's samples (dots) and the resampled series (line), the row and joint counts and
//! the time span; download `traj_resampled.csv`, byte for byte what `bsv traj-resample`
//! writes for the same file and dt.
//!
//! A small input runs on the page as soon as it is valid, a big one in the kit's Web Worker
//! ([`Inner::run`]). Every problem (a bad cell, a file that is not UTF-8, a dt too small) is
//! the kernel's error, shown beside its field with its row and column; the last good plot
//! and download stay.
//!
//! Components, one file each: `joints` (the plot of every joint), `markup` (with the
//! explanation); the form, exports, readouts, URL, progress panel and input files are the
//! kit's. This file holds the run and wires them.

mod joints;
mod markup;

use std::cell::RefCell;
use std::rc::{Rc, Weak};

use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;
use web_sys::{Blob, Element, Event, KeyboardEvent};

use crate::args::Args;
use crate::error::RecipeError;
use crate::recipes::run_raw_of;
use crate::recipes::traj_resample::{self, RESAMPLED_NAME, SAMPLE, SAMPLE_NAME};
use crate::recipes::{CsvFile, Plan};
use crate::ui::ctx::{self, t_strings};
use crate::ui::dom;
use crate::ui::kit::canvas::Ink;
use crate::ui::kit::exercise_slot::ExerciseSlot;
use crate::ui::kit::exports::Exports;
use crate::ui::kit::form::{recipe_messages, Form, Message, RECIPE_GROUPS};
use crate::ui::kit::input_file::{self, Picked, ReadProblem};
use crate::ui::kit::keymap;
use crate::ui::kit::page_root::PageRoot;
use crate::ui::kit::progress::ProgressPanel;
use crate::ui::kit::readouts::Readouts;
use crate::ui::kit::scope::Scope;
use crate::ui::kit::url_state::{UrlNotice, UrlState, UrlWriter};
use crate::ui::kit::worker::{self, Job, RunOptions, WorkerError, WorkerFile, WorkerInput};
use crate::ui::page::{MountCtx, Page, Shortcut};
use crate::ui::schedule::{after_paint, now_ms, Timer};
use crate::view::command_line::RunArgs;
use crate::view::envelope::{csv_envelope, Envelope, BUCKETS};
use crate::view::exercises::traj_resample::EXERCISES;
use crate::view::exercises::PageModel;
use crate::view::form::{recipe_fields, runs_while_typing, validate};
use crate::view::traj_resample::{file_too_large, readings, PageQuery};
use markup::PREFIX;

/// The recipe the page runs.
const RECIPE: &str = traj_resample::INFO.id;
/// Input files up to this size are read on the page (their errors show at once, their
/// small runs happen while typing); bigger ones go to the worker unread.
pub const PRECHECK_MAX_BYTES: u64 = 4 * 1024 * 1024;
/// Milliseconds between the last keystroke and the run.
const RUN_DELAY_MS: i32 = 250;
/// The PNG of the plot.
const PNG_NAME: &str = "traj_resample_plot.png";

/// Where the input comes from.
enum Source {
    /// The recipe's labeled sample.
    Sample,
    /// A file read on the page.
    Text { name: String, text: Rc<String> },
    /// A big file, handed to the worker unread.
    File { name: String, blob: Blob },
    /// A file the link named, not open.
    Missing(String),
}

impl Source {
    fn name(&self) -> Option<&str> {
        match self {
            Source::Sample => None,
            Source::Text { name, .. } | Source::File { name, .. } | Source::Missing(name) => {
                Some(name)
            }
        }
    }
}

/// One file of the shown result.
enum ResultFile {
    Text(CsvFile),
    Worker(WorkerFile),
}

impl ResultFile {
    fn name(&self) -> &str {
        match self {
            ResultFile::Text(f) => &f.name,
            ResultFile::Worker(f) => &f.name,
        }
    }
}

/// The result on screen.
struct Shown {
    args: RunArgs,
    input_name: Option<String>,
    files: Vec<ResultFile>,
    input: Envelope,
    output: Envelope,
    ms: f64,
    /// Where it ran.
    in_worker: bool,
}

/// What the status line says.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Status {
    Idle,
    Reading,
    Running,
    Done,
    Failed,
}

/// The mounted page.
pub struct TrajResample {
    inner: Rc<Inner>,
    _exercises: ExerciseSlot,
}

struct Inner {
    me: Weak<Inner>,
    root: PageRoot,
    page: Element,
    status_line: Element,
    form: RefCell<Form>,
    joints: RefCell<joints::Joints>,
    exports: Exports,
    readouts: Readouts,
    progress: ProgressPanel,
    url_notice: UrlNotice,
    url: UrlWriter,
    run_timer: Rc<Timer>,
    source: RefCell<Source>,
    /// A problem with the chosen file (too large, unreadable, not UTF-8).
    file_problem: RefCell<Option<Message>>,
    /// Counts file choices, so a stale read is dropped.
    generation: RefCell<u32>,
    /// A failed run and its arguments (its message stays while they do not change).
    failed: RefCell<Option<(RunArgs, usize, Message)>>,
    /// The plan of the valid form now (`None`: invalid).
    plan: RefCell<Option<Option<u64>>>,
    shown: RefCell<Option<Shown>>,
    job: RefCell<Option<Job>>,
    status: RefCell<Status>,
    scope: RefCell<Scope>,
}

fn target(event: &Event) -> Option<Element> {
    event.target().and_then(|t| t.dyn_into::<Element>().ok())
}

impl Page for TrajResample {
    fn mount(mount: MountCtx) -> Result<TrajResample, JsValue> {
        let exercises_root = mount.root.clone();
        let root = PageRoot::fill(&mount.root, &markup::page(), "traj", "traj-resample")?;
        let (query, ignored) = PageQuery::read(&mount.query);
        let url_notice = UrlNotice::new(root.role("url-notice")?, ignored)?;
        let form = Form::build(
            &root.role("form")?,
            PREFIX,
            &RECIPE_GROUPS,
            recipe_fields(&traj_resample::INFO),
            &[String::new(), query.dt.clone()],
        )?;
        // Cancel reaches the page once it exists.
        let cancel_target: Rc<RefCell<Weak<Inner>>> = Rc::default();
        let progress = {
            let target = cancel_target.clone();
            ProgressPanel::new(move || {
                if let Some(p) = target.borrow().upgrade() {
                    p.cancel();
                }
            })?
        };
        let page: Element = root.find("[data-testid=\"traj-resample-page\"]")?;
        let exports = Exports::find(&root, PREFIX)?;
        let readouts = Readouts::find(&root)?;
        let status_line: Element = root.role("status")?;
        status_line.after_with_node_1(progress.element())?;
        let joints = joints::Joints::new(&root.role("stage")?)?;
        let source = match query.csv_path {
            Some(name) => Source::Missing(name),
            None => Source::Sample,
        };
        let inner = Rc::new_cyclic(|me: &Weak<Inner>| {
            let mut scope = Scope::new();
            let url = UrlWriter::new(&mut scope, me, Inner::url_pairs);
            let run_timer = scope.timer(me, Inner::run);
            Inner {
                me: me.clone(),
                page,
                root: root.clone(),
                status_line,
                form: RefCell::new(form),
                joints: RefCell::new(joints),
                exports,
                readouts,
                progress,
                url_notice,
                url,
                run_timer,
                source: RefCell::new(source),
                file_problem: RefCell::new(None),
                generation: RefCell::new(0),
                failed: RefCell::new(None),
                plan: RefCell::new(None),
                shown: RefCell::new(None),
                job: RefCell::new(None),
                status: RefCell::new(Status::Idle),
                scope: RefCell::new(scope),
            }
        });
        *cancel_target.borrow_mut() = Rc::downgrade(&inner);
        inner.install()?;
        inner.validate();
        inner.run();
        inner.render_result();
        inner.render_status();
        let exercises = ExerciseSlot::lending(&exercises_root, &EXERCISES, &inner, lend_model)?;
        Ok(TrajResample {
            inner,
            _exercises: exercises,
        })
    }

    fn relocalize(&self) {
        self.inner.relocalize();
    }

    fn set_projector(&self, _on: bool) {
        self.inner.joints.borrow_mut().relayout();
        self.inner.draw();
    }

    fn shortcuts(&self) -> Vec<Shortcut> {
        vec![
            keymap::key("o", "traj-key-open"),
            keymap::key("s", "traj-key-sample"),
            keymap::key("d", "traj-key-download"),
        ]
    }

    fn on_key(&self, event: &KeyboardEvent) -> bool {
        if !keymap::page_may_take(event) {
            return false;
        }
        match event.key().as_str() {
            "o" => {
                if let Some(input) = self.inner.form.borrow().file_input() {
                    input.click();
                }
                true
            }
            "s" => {
                self.inner.use_sample();
                true
            }
            "d" => {
                self.inner.download(RESAMPLED_NAME);
                true
            }
            _ => false,
        }
    }
}

impl Inner {
    /// What the exercises check: the trajectory read (the sample or a file read on the page;
    /// none for a big file the worker reads, or one that does not read) and the step `dt`
    /// (the recipe's default while the field is empty).
    fn exercise_model(&self) -> Option<(traj_resample::Trajectory, f64)> {
        let trajectory = match &*self.source.borrow() {
            Source::Sample => traj_resample::parse_trajectory(SAMPLE),
            Source::Text { text, .. } => traj_resample::parse_trajectory(text),
            Source::File { .. } | Source::Missing(_) => return None,
        }
        .ok()?;
        let dt_text = self.dt_text();
        let dt = if dt_text.is_empty() {
            traj_resample::ResampleParams::default().dt
        } else {
            dt_text.parse().ok()?
        };
        Some((trajectory, dt))
    }

    /// The URL pairs now.
    fn url_pairs(&self) -> Vec<(String, String)> {
        let dt = self.dt_text();
        PageQuery {
            csv_path: self.source.borrow().name().map(str::to_string),
            dt,
        }
        .write()
    }

    fn dt_text(&self) -> String {
        self.form
            .borrow()
            .texts()
            .get(1)
            .cloned()
            .flatten()
            .unwrap_or_default()
            .trim()
            .to_string()
    }

    /// The field texts with the file field holding the source's name.
    fn texts(&self) -> Vec<Option<String>> {
        let name = self.source.borrow().name().map(str::to_string);
        let form = self.form.borrow();
        form.fields
            .iter()
            .zip(form.texts())
            .map(|(f, t)| if f.is_file() { name.clone() } else { t })
            .collect()
    }

    fn args(&self) -> RunArgs {
        let texts = self.texts();
        RunArgs::new(RECIPE, &self.form.borrow().fields, &texts)
    }

    fn install(&self) -> Result<(), JsValue> {
        let mut scope = self.scope.borrow_mut();
        let me = &self.me;
        let form_el: Element = self.root.role("form")?;
        scope.listen_for(&form_el, "input", me, |p, e| {
            if let Some(el) = target(e).filter(|el| el.has_attribute("data-field")) {
                p.form.borrow().note_edit(&el);
                p.edited();
            }
        })?;
        scope.listen_for(&form_el, "change", me, |p, e| {
            if target(e).is_some_and(|el| el.has_attribute("data-file-input")) {
                let picked = p.form.borrow().file_input().and_then(input_file::chosen);
                if let Some(picked) = picked {
                    p.open(picked);
                }
            }
        })?;
        scope.listen_for(&form_el, "submit", me, |_, e| e.prevent_default())?;
        scope.listen_for(&form_el, "click", me, |p, e| {
            if target(e).is_some_and(|el| el.closest("[data-use-sample]").ok().flatten().is_some())
            {
                p.use_sample();
            }
        })?;
        // Drop a file anywhere on the page.
        scope.listen_for(&self.page, "dragover", me, |p, e| {
            if input_file::drags_files(e) {
                e.prevent_default();
                let _ = p.page.class_list().add_1("traj-dropping");
            }
        })?;
        scope.listen_for(&self.page, "dragleave", me, |p, _| {
            let _ = p.page.class_list().remove_1("traj-dropping");
        })?;
        scope.listen_for(&self.page, "drop", me, |p, e| {
            let _ = p.page.class_list().remove_1("traj-dropping");
            if let Some(picked) = input_file::dropped(e) {
                e.prevent_default();
                p.open(picked);
            }
        })?;
        let output: Element = self.root.role("output")?;
        scope.listen_for(&output, "click", me, |p, e| {
            let Some(el) = target(e) else {
                return;
            };
            if let Some(button) = el.closest("[data-download]").ok().flatten() {
                p.download(&button.get_attribute("data-download").unwrap_or_default());
            } else if let Some(button) = el.closest("[data-copy]").ok().flatten() {
                p.exports
                    .copy(&button.get_attribute("data-copy").unwrap_or_default());
            } else if el.closest("[data-png]").ok().flatten().is_some() {
                p.download_png();
            }
        })?;
        let stage: Element = self.root.role("stage")?;
        scope.observe_resize(&[&stage], me, |p| {
            p.joints.borrow_mut().relayout();
            p.draw();
        })?;
        Ok(())
    }

    /// A field changed: validate, and run soon if valid.
    fn edited(&self) {
        self.exports.clear_status();
        self.validate();
        self.url.schedule();
        if self.plan.borrow().is_some() {
            self.run_timer.schedule(RUN_DELAY_MS);
        } else {
            self.run_timer.cancel();
        }
    }

    /// The input changed: validate, write the URL, run.
    fn input_changed(&self) {
        *self.failed.borrow_mut() = None;
        self.validate();
        self.url.write_now();
        self.render_file_status();
        self.run_timer.cancel();
        self.run();
    }

    /// A file was chosen or dropped: refused above the recipe's limit; read on the page if
    /// small, else handed to the worker unread.
    fn open(&self, picked: Picked) {
        let Picked { name, bytes, blob } = picked;
        let generation = {
            let mut g = self.generation.borrow_mut();
            *g += 1;
            *g
        };
        self.forget_file_choice();
        self.cancel_job();
        if let Some((id, args)) = file_too_large(&name, bytes) {
            *self.file_problem.borrow_mut() = Some(Message::Text { id, args });
            self.validate();
            return;
        }
        *self.file_problem.borrow_mut() = None;
        self.url_notice.set(Vec::new());
        if bytes > PRECHECK_MAX_BYTES {
            *self.source.borrow_mut() = Source::File { name, blob };
            self.input_changed();
            return;
        }
        *self.status.borrow_mut() = Status::Reading;
        self.render_status();
        let me = self.me.clone();
        let file_name = name.clone();
        input_file::read_text(&file_name, &blob, move |result| {
            let Some(p) = me.upgrade() else {
                return;
            };
            if *p.generation.borrow() != generation {
                return;
            }
            *p.status.borrow_mut() = Status::Idle;
            match result {
                Ok(text) => {
                    *p.source.borrow_mut() = Source::Text {
                        name,
                        text: Rc::new(text),
                    };
                }
                Err(ReadProblem::Decode(error)) => {
                    *p.file_problem.borrow_mut() = Some(Message::Recipe(error));
                }
                Err(ReadProblem::Browser(reason)) => {
                    *p.file_problem.borrow_mut() = Some(Message::Text {
                        id: "traj-file-unreadable",
                        args: vec![("name", name), ("reason", reason)],
                    });
                }
            }
            p.input_changed();
            p.render_status();
        });
    }

    /// Clears the file picker (so choosing the same file again fires `change`).
    fn forget_file_choice(&self) {
        if let Some(input) = self.form.borrow().file_input() {
            input.set_value("");
        }
    }

    /// "Use the labeled sample" / `s`.
    fn use_sample(&self) {
        *self.generation.borrow_mut() += 1;
        *self.source.borrow_mut() = Source::Sample;
        *self.file_problem.borrow_mut() = None;
        self.url_notice.set(Vec::new());
        self.forget_file_choice();
        self.cancel_job();
        self.input_changed();
    }

    /// Checks the form with the recipe's parse + plan (the input attached when it is on the
    /// page) and shows the messages beside their fields.
    fn validate(&self) {
        let texts = self.texts();
        let form = self.form.borrow();
        let source = self.source.borrow();
        let check = |texts: &[Option<String>]| -> Result<Option<u64>, RecipeError> {
            let args = RunArgs::new(RECIPE, &form.fields, texts);
            let parsed = Args::parse(&args.raw(), traj_resample::INFO.args, &[])?;
            let parsed = match &*source {
                Source::Text { name, text } => {
                    parsed.with_inputs(vec![(name.clone(), text.as_str().to_string())])
                }
                _ => parsed,
            };
            match (traj_resample::INFO.plan)(&parsed) {
                // A big file is sized by its run, in the worker.
                Err(RecipeError::InputMissing { .. })
                    if matches!(&*source, Source::File { .. }) =>
                {
                    Ok(None)
                }
                other => other.map(|p: Plan| Some(p.rows)),
            }
        };
        let file_index = form.file_index();
        let checked = validate(&form.fields, &texts, form.changed(), check, |_| file_index);
        let mut messages = recipe_messages(&checked);
        let mut marked = checked.marked.clone();
        if let (Some(problem), Some(i)) = (self.file_problem.borrow().clone(), file_index) {
            messages.retain(|(k, _)| *k != i);
            messages.push((i, problem));
            marked.push(i);
        }
        let args = RunArgs::new(RECIPE, &form.fields, &texts);
        if let Some((failed_args, slot, message)) = &*self.failed.borrow() {
            if *failed_args == args && !messages.iter().any(|(k, _)| k == slot) {
                messages.push((*slot, message.clone()));
                marked.push(*slot);
            }
        }
        let plan = if messages.is_empty() {
            checked.value
        } else {
            None
        };
        drop(source);
        drop(form);
        self.form.borrow_mut().show(&messages, &marked);
        *self.plan.borrow_mut() = plan;
    }

    /// Runs the valid form: on the page when small, else in the worker. The same arguments
    /// as the result shown do not run again.
    ///
    /// A small input (at most [`PRECHECK_MAX_BYTES`], read and decoded at once, as the CLI
    /// decodes a file) whose run is small runs on the page; anything bigger (up to the
    /// recipe's 128 MiB; a bigger file is refused unread, with the page's own message in MiB)
    /// runs in the kit's Web Worker with progress and Cancel: the page hands the worker the
    /// file itself (never reading a big file's text on its main thread), and the worker sends
    /// back the files and their plot envelopes (min/max per bucket, [`crate::view::envelope`]),
    /// so a million rows draw in one frame.
    fn run(&self) {
        let Some(rows) = *self.plan.borrow() else {
            return;
        };
        let args = self.args();
        if self.shown.borrow().as_ref().is_some_and(|s| s.args == args)
            && self.job.borrow().is_none()
        {
            return;
        }
        let small = matches!(&*self.source.borrow(), Source::Sample | Source::Text { .. })
            && runs_while_typing(rows);
        if small {
            self.cancel_job();
            self.run_here(args);
        } else {
            self.run_in_worker(args);
        }
    }

    fn input_text(&self) -> (Option<String>, Rc<String>) {
        match &*self.source.borrow() {
            Source::Text { name, text } => (Some(name.clone()), text.clone()),
            _ => (None, Rc::new(SAMPLE.to_string())),
        }
    }

    /// A small run, on the page.
    fn run_here(&self, args: RunArgs) {
        let t0 = now_ms();
        let (name, text) = self.input_text();
        let inputs = name
            .iter()
            .map(|n| (n.clone(), text.as_str().to_string()))
            .collect();
        match run_raw_of::<traj_resample::Entry>(&args.raw(), inputs) {
            Ok(out) => {
                let output = out
                    .files
                    .iter()
                    .find(|f| f.name == RESAMPLED_NAME)
                    .map(|f| csv_envelope(&f.text, BUCKETS))
                    .unwrap_or_default();
                let shown = Shown {
                    input: csv_envelope(&text, BUCKETS),
                    output,
                    input_name: name,
                    files: out.files.into_iter().map(ResultFile::Text).collect(),
                    args,
                    ms: now_ms() - t0,
                    in_worker: false,
                };
                self.show(shown);
            }
            Err(error) => self.failed_with(args, error),
        }
    }

    /// A big run, in the worker, with progress and Cancel.
    fn run_in_worker(&self, args: RunArgs) {
        let input = match &*self.source.borrow() {
            Source::Text { name, text } => {
                Some((name.clone(), WorkerInput::Text(text.as_str().to_string())))
            }
            Source::File { name, blob } => Some((name.clone(), WorkerInput::Blob(blob.clone()))),
            _ => None,
        };
        let input_name = input.as_ref().map(|(n, _)| n.clone());
        self.progress.start();
        *self.status.borrow_mut() = Status::Running;
        self.render_status();
        let t0 = now_ms();
        let (on_progress, on_done) = (self.me.clone(), self.me.clone());
        let run_args = args.clone();
        let job = worker::run_recipe_with(
            RECIPE,
            args.raw(),
            input.into_iter().collect(),
            RunOptions {
                envelope: BUCKETS as u32,
            },
            move |done, total| {
                if let Some(p) = on_progress.upgrade() {
                    p.progress.set(done, total);
                }
            },
            move |result| {
                let Some(p) = on_done.upgrade() else {
                    return;
                };
                p.job.borrow_mut().take();
                p.progress.hide();
                match result {
                    Ok(out) => {
                        let input = match out.inputs.first() {
                            Some((_, Some(env))) => env.clone(),
                            _ => csv_envelope(SAMPLE, BUCKETS),
                        };
                        let output = out
                            .file(RESAMPLED_NAME)
                            .and_then(|f| f.envelope.clone())
                            .unwrap_or_default();
                        let mut files: Vec<ResultFile> =
                            out.files.into_iter().map(ResultFile::Worker).collect();
                        files.sort_by_key(|f| f.name() != RESAMPLED_NAME);
                        p.show(Shown {
                            args: run_args,
                            input_name,
                            files,
                            input,
                            output,
                            ms: now_ms() - t0,
                            in_worker: true,
                        });
                    }
                    Err(error) => match error.recipe_error().cloned() {
                        Some(e) => p.failed_with(run_args, e),
                        None => p.failed_worker(&error),
                    },
                }
            },
        );
        match job {
            Ok(job) => *self.job.borrow_mut() = Some(job),
            Err(e) => {
                self.progress.hide();
                self.failed_worker(&WorkerError::Failed(
                    e.as_string().unwrap_or_else(|| format!("{e:?}")),
                ));
            }
        }
    }

    fn cancel_job(&self) {
        if let Some(job) = self.job.borrow_mut().take() {
            job.cancel();
        }
        self.progress.hide();
        if *self.status.borrow() == Status::Running {
            *self.status.borrow_mut() = Status::Idle;
            self.render_status();
        }
    }

    /// Cancel: the run stops, the last result stays.
    fn cancel(&self) {
        self.cancel_job();
        *self.status.borrow_mut() = Status::Idle;
        self.render_status();
    }

    fn show(&self, shown: Shown) {
        *self.shown.borrow_mut() = Some(shown);
        *self.failed.borrow_mut() = None;
        *self.status.borrow_mut() = Status::Done;
        self.exports.clear_status();
        self.validate();
        self.render_result();
        self.render_status();
        // The URL in a task of its own (after a big result, `replaceState` can take tens of ms).
        self.url.schedule_in(0);
        let summary = self.readouts_summary();
        self.readouts.announce(&summary);
    }

    /// A run the recipe refused: its message beside the field it names (an input's beside
    /// the file picker), as the form's own checks show theirs.
    fn failed_with(&self, args: RunArgs, error: RecipeError) {
        let slot = {
            let form = self.form.borrow();
            error
                .param()
                .and_then(|p| form.index_of(p))
                .or_else(|| form.file_index())
                .unwrap_or(0)
        };
        *self.failed.borrow_mut() = Some((args, slot, Message::Recipe(error)));
        *self.status.borrow_mut() = Status::Failed;
        self.validate();
        self.render_status();
    }

    /// The worker could not run at all: said in the status line.
    fn failed_worker(&self, error: &WorkerError) {
        *self.status.borrow_mut() = Status::Failed;
        self.status_line.set_text_content(Some(&error.text()));
        let _ = self.page.set_attribute("data-state", "ready");
    }

    fn render_status(&self) {
        let status = *self.status.borrow();
        let text = match status {
            Status::Idle => String::new(),
            Status::Reading => ctx::t("traj-reading"),
            Status::Running => ctx::t("traj-running"),
            Status::Failed => ctx::t("traj-failed"),
            Status::Done => match self.shown.borrow().as_ref() {
                Some(s) => t_strings(
                    if s.in_worker {
                        "traj-done-worker"
                    } else {
                        "traj-done"
                    },
                    &[("ms", format!("{}", s.ms.max(0.0).round()))],
                ),
                None => String::new(),
            },
        };
        self.status_line.set_text_content(Some(&text));
        let busy = matches!(status, Status::Running | Status::Reading);
        let _ = self
            .page
            .set_attribute("data-state", if busy { "running" } else { "ready" });
    }

    /// The line under the file picker: which input the plot shows.
    fn render_file_status(&self) {
        let Some(line) = self.form.borrow().file_status.clone() else {
            return;
        };
        let text = match &*self.source.borrow() {
            Source::Sample => t_strings("traj-input-sample", &[("name", SAMPLE_NAME.into())]),
            Source::Text { name, .. } | Source::File { name, .. } => {
                t_strings("traj-input-file", &[("name", name.clone())])
            }
            Source::Missing(name) => t_strings("traj-input-missing", &[("name", name.clone())]),
        };
        line.set_text_content(Some(&text));
    }

    /// The readouts as one sentence for screen readers.
    fn readouts_summary(&self) -> String {
        let shown = self.shown.borrow();
        let Some(s) = shown.as_ref() else {
            return String::new();
        };
        let r = readings(&s.input, &s.output);
        t_strings(
            "traj-live",
            &[
                ("rows_in", r.rows_in),
                ("rows_out", r.rows_out),
                ("joints", r.joints),
                ("duration", r.duration),
            ],
        )
    }

    /// Readouts, plot, downloads and command lines of the shown result.
    fn render_result(&self) {
        self.render_file_status();
        let shown = self.shown.borrow();
        let Some(s) = shown.as_ref() else {
            return;
        };
        let r = readings(&s.input, &s.output);
        self.readouts.set("rows_in", &r.rows_in);
        self.readouts.set("rows_out", &r.rows_out);
        self.readouts.set("joints", &r.joints);
        self.readouts.set(
            "span",
            &t_strings(
                "traj-span-value",
                &[("first", r.t_first), ("last", r.t_last)],
            ),
        );
        self.readouts
            .set("duration", &t_strings("traj-seconds", &[("s", r.duration)]));
        self.readouts.set(
            "dt",
            &t_strings(
                "traj-seconds",
                &[("s", s.args.positional.get(1).cloned().unwrap_or_default())],
            ),
        );
        if let Ok(files) = self.root.role::<Element>("files") {
            let mut html = String::new();
            for f in &s.files {
                html.push_str(&crate::ui::kit::exports::download_button(PREFIX, f.name()));
            }
            html.push_str(&format!(
                "<button type=\"button\" class=\"button kit-download\" data-png data-testid=\"traj-png\">{}</button>",
                crate::ui::kit::form::escape(&ctx::t("traj-download-png"))
            ));
            files.set_inner_html(&html);
        }
        self.exports
            .show_run(&s.args, traj_resample::INFO.python, s.input_name.as_deref());
        drop(shown);
        // The plot in a task of its own, after the browser has laid out the new text: a
        // million-row result's texts and plot together made one task over 100 ms.
        let me = self.me.clone();
        let plotted = after_paint(move || {
            if let Some(p) = me.upgrade() {
                p.plot_result();
            }
        });
        if plotted.is_err() {
            self.plot_result();
        }
    }

    /// The shown result's joints into the plot: the axes drawn now, the data in the next
    /// task (together they made one long task after a million-row result on a busy machine).
    fn plot_result(&self) {
        if let Some(s) = self.shown.borrow().as_ref() {
            self.joints.borrow_mut().set(&s.input, &s.output);
        }
        self.draw();
        let me = self.me.clone();
        let fill = move || {
            if let Some(p) = me.upgrade() {
                p.joints.borrow_mut().fill();
                p.draw();
            }
        };
        if let Err(e) = after_paint(fill) {
            web_sys::console::warn_1(&e);
        }
    }

    fn draw(&self) {
        if let Err(e) = self.joints.borrow_mut().draw(Ink::current()) {
            web_sys::console::warn_1(&e.into());
        }
    }

    fn download(&self, name: &str) {
        let shown = self.shown.borrow();
        let Some(file) = shown
            .as_ref()
            .and_then(|s| s.files.iter().find(|f| f.name() == name))
        else {
            return;
        };
        match file {
            ResultFile::Text(f) => self.exports.download(&f.name, &f.text),
            ResultFile::Worker(f) => {
                if let Err(e) = worker::download(f) {
                    web_sys::console::warn_1(&e);
                }
            }
        }
    }

    fn download_png(&self) {
        let joints = self.joints.borrow();
        let layers: Vec<&web_sys::HtmlCanvasElement> = joints
            .plot
            .canvas
            .layers
            .iter()
            .map(|l| &l.canvas)
            .collect();
        if let Err(e) = crate::ui::kit::png::download_layers(&layers, "#ffffff", PNG_NAME) {
            web_sys::console::warn_1(&e);
        }
    }

    fn relocalize(&self) {
        let _ = dom::relocalize(&self.root);
        self.form.borrow().relocalize();
        self.validate();
        self.exports.relocalize();
        self.url_notice.relocalize();
        self.progress.relocalize();
        self.render_status();
        self.render_result();
    }
}

impl Drop for Inner {
    fn drop(&mut self) {
        if let Some(job) = self.job.get_mut().take() {
            job.cancel();
        }
    }
}

/// The page's model for its exercises (none while its state holds none).
fn lend_model(inner: &Inner, lend: &mut dyn FnMut(&PageModel)) {
    if let Some((trajectory, dt)) = inner.exercise_model() {
        lend(&PageModel::TrajResample(&trajectory, dt));
    }
}
