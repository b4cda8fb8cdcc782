//! Running a drill and the status line beside Run: an edit validates at once and (debounced)
//! rewrites the URL and runs a small drill; Run / Enter / `r` paints "Running…" first, then
//! runs and brings the result (or the first error) into view, clear of the phone's sticky Run
//! bar. A run computes the recipe's output (with the opened input file attached) and shows it,
//! or puts its error where it belongs.

use super::shown::Shown;
use super::state::{Page, Slot, Status};
use crate::ui::ctx::{self, t_strings};
use crate::ui::kit::form::{reveal, Message, Reveal};
use crate::ui::kit::worker::{self, WorkerError};
use crate::ui::schedule::{after_paint, now_ms};

/// Milliseconds between the last keystroke and a small drill's run.
const AUTO_RUN_DELAY_MS: i32 = 250;

impl Page {
    /// A field changed: validate, rewrite the URL soon, run soon if small.
    pub(super) fn on_edit(&self) {
        self.validate();
        let (valid, small) = {
            let st = self.st.borrow();
            (st.errors.is_empty(), st.plan.is_some_and(|p| p.is_small()))
        };
        {
            let mut st = self.st.borrow_mut();
            if st.status != Status::Running {
                st.status = if valid && !small {
                    Status::Large
                } else {
                    Status::Idle
                };
            }
        }
        self.exports.clear_status();
        self.render_status();
        self.url.schedule();
        if valid && small {
            self.auto_timer.schedule(AUTO_RUN_DELAY_MS);
        } else {
            self.auto_timer.cancel();
        }
    }

    /// Runs now if the form is valid, small and not already shown; otherwise says what is
    /// needed.
    pub(super) fn auto_run(&self) {
        let (valid, plan, busy) = {
            let st = self.st.borrow();
            (
                st.errors.is_empty(),
                st.plan,
                st.status == Status::Running || st.reading.is_some(),
            )
        };
        if busy || !valid {
            return;
        }
        match plan {
            Some(plan) if plan.is_small() => {
                let args = self.current_args();
                let already = self
                    .st
                    .borrow()
                    .shown
                    .as_ref()
                    .is_some_and(|s| s.args == args);
                if !already {
                    self.run_now(false);
                }
            }
            Some(_) => {
                self.st.borrow_mut().status = Status::Large;
                self.render_status();
            }
            None => {}
        }
    }

    /// Run / Enter / `r`: shows "Running…", lets the browser paint it, then runs and brings
    /// the result into view.
    pub(super) fn request_run(&self) {
        self.auto_timer.cancel();
        {
            let st = self.st.borrow();
            if st.status == Status::Running || st.reading.is_some() {
                return;
            }
        }
        self.validate();
        if !self.st.borrow().errors.is_empty() {
            self.st.borrow_mut().status = Status::Invalid;
            self.render_status();
            self.reveal_first_error();
            return;
        }
        self.st.borrow_mut().status = Status::Running;
        self.render_status();
        // Bigger than the auto-run size: in the Web Worker, with progress (background.rs).
        if !self.st.borrow().plan.is_some_and(|p| p.is_small()) {
            self.run_in_background();
            return;
        }
        let weak = self.weak.borrow().clone();
        let started = after_paint(move || {
            if let Some(page) = weak.upgrade() {
                page.run_now(true);
            }
        });
        if started.is_err() {
            self.run_now(true);
        }
    }

    /// Focuses the first field with a message (or shows the message under the form).
    pub(super) fn reveal_first_error(&self) {
        let has_field_error = self
            .st
            .borrow()
            .errors
            .iter()
            .any(|(s, _)| matches!(s, Slot::Field(_)));
        if has_field_error {
            self.form.borrow().focus_first_error();
        } else {
            reveal(&self.els.error, Reveal::Nearest);
        }
    }

    /// Runs the form's arguments as soon as the kernels are here (at once after the first
    /// run) and shows the result (or the error); `asked`: the user asked for it (Run, Enter,
    /// `r`), so the outcome is brought into view.
    fn run_now(&self, asked: bool) {
        let weak = self.weak.borrow().clone();
        wasm_bindgen_futures::spawn_local(async move {
            let loaded = worker::kernels().await;
            // The kernels' code is set up in a task of its own, the run in the next one.
            crate::ui::schedule::next_task().await;
            let Some(page) = weak.upgrade() else {
                return;
            };
            let run = match loaded {
                Ok(kernels) => page.run_with(kernels.on_page),
                Err(_) => return page.runner_failed(asked),
            };
            drop(page);
            // The run in one task, what it shows in the next.
            crate::ui::schedule::next_task().await;
            if let Some(page) = weak.upgrade() {
                page.show_run(run, asked);
            }
        });
    }

    /// The kernels could not be fetched: says so under the form, where a worker's failure
    /// shows (Run tries again; the arguments are not at fault, so they stay valid).
    fn runner_failed(&self, asked: bool) {
        self.st.borrow_mut().status = Status::Failed;
        self.validate();
        self.render_status();
        self.els
            .error
            .set_text_content(Some(&ctx::t("drills-code-failed")));
        crate::ui::dom::show(&self.els.error, true);
        if asked {
            reveal(&self.els.error, Reveal::Nearest);
        }
    }

    /// Runs the form's arguments with `run`.
    fn run_with(&self, run: worker::OnPage) -> PageRun {
        let args = self.current_args();
        let t0 = now_ms();
        let (result, input_name) = {
            let st = self.st.borrow();
            let file = st
                .input
                .as_ref()
                .filter(|f| args.positional.contains(&f.name));
            let inputs = file
                .map(|f| vec![(f.name.clone(), f.text.clone())])
                .unwrap_or_default();
            (
                run(args.recipe, &args.raw(), inputs),
                file.map(|f| f.name.clone()),
            )
        };
        PageRun {
            args,
            input_name,
            result,
            ms: now_ms() - t0,
        }
    }

    /// Shows a run's result (or its error).
    fn show_run(&self, run: PageRun, asked: bool) {
        let PageRun {
            args,
            input_name,
            result,
            ms,
        } = run;
        let ok = result.is_ok();
        match result {
            Ok(out) => {
                let shown = Shown::new(args, input_name, out);
                self.st.borrow_mut().succeeded(shown, ms);
            }
            Err(error) => {
                let slot = self.slot_for(&error);
                let mut st = self.st.borrow_mut();
                st.failed = Some((args, slot, Message::Recipe(error)));
                st.status = Status::Failed;
            }
        }
        self.exports.clear_status();
        self.validate();
        if let Err(e) = self.render_output() {
            web_sys::console::error_2(&"drills: result".into(), &e);
        }
        self.render_status();
        self.write_url();
        if ok {
            self.announce_result();
        }
        if asked {
            if ok {
                reveal(&self.els.output, Reveal::Start);
            } else {
                self.reveal_first_error();
            }
        }
    }

    /// The status line beside Run, the page's `data-state` and Run's `aria-busy`.
    pub(super) fn render_status(&self) {
        let st = self.st.borrow();
        let (text, bad) = match &st.status {
            Status::Idle => (String::new(), false),
            Status::Running => (ctx::t("drills-running"), false),
            Status::Large => (ctx::t("drills-large"), false),
            Status::Invalid => (ctx::t("drills-invalid"), true),
            Status::Reading(name) => (
                t_strings("drills-reading", &[("name", name.clone())]),
                false,
            ),
            Status::Done(ms) => (
                t_strings("drills-done", &[("ms", format!("{}", ms.max(0.0).round()))]),
                false,
            ),
            Status::Failed => (ctx::t("drills-failed"), true),
        };
        self.els.status.set_text_content(Some(&text));
        let _ = self
            .els
            .status
            .class_list()
            .toggle_with_force("drills-status-bad", bad);
        let running = st.status == Status::Running;
        let _ = self
            .els
            .page
            .set_attribute("data-state", if running { "running" } else { "ready" });
        let _ = self
            .els
            .run
            .set_attribute("aria-busy", if running { "true" } else { "false" });
        drop(st);
        self.render_stale();
    }

    /// The "values changed since this result" note.
    pub(super) fn render_stale(&self) {
        let st = self.st.borrow();
        let stale = match (&st.shown, self.form.try_borrow()) {
            (Some(shown), Ok(form)) => {
                shown.args
                    != crate::view::command_line::RunArgs::new(
                        st.recipe.id,
                        &form.fields,
                        &st.texts,
                    )
            }
            _ => false,
        };
        crate::ui::dom::show(&self.els.stale, stale && st.status != Status::Running);
    }
}

/// Runs in the Web Worker ([`Background`](super::background::Background)).
impl Page {
    /// Runs the form's arguments in the worker; `Running` until it ends or is cancelled.
    pub(super) fn run_in_background(&self) {
        let args = self.current_args();
        let (inputs, input_name) = {
            let st = self.st.borrow();
            match st
                .input
                .as_ref()
                .filter(|f| args.positional.contains(&f.name))
            {
                Some(f) => (vec![(f.name.clone(), f.text.clone())], Some(f.name.clone())),
                None => (Vec::new(), None),
            }
        };
        let Some(bg) = self.background.borrow().clone() else {
            return;
        };
        bg.error.borrow_mut().take();
        bg.panel.start();
        let t0 = now_ms();
        let weak_progress = self.weak.borrow().clone();
        let weak_done = self.weak.borrow().clone();
        let run_args = args.clone();
        let job = worker::run_recipe(
            args.recipe,
            args.raw(),
            inputs,
            move |done, total| {
                if let Some(page) = weak_progress.upgrade() {
                    if let Some(bg) = page.background.borrow().as_ref() {
                        bg.panel.set(done, total);
                    }
                }
            },
            move |result| {
                let Some(page) = weak_done.upgrade() else {
                    return;
                };
                let ms = now_ms() - t0;
                if let Some(bg) = page.background.borrow().clone() {
                    bg.job.borrow_mut().take();
                    bg.panel.hide();
                }
                match result {
                    Ok(out) => {
                        page.exports.clear_status();
                        let shown = Shown::from_worker(run_args, input_name, out);
                        page.st.borrow_mut().succeeded(shown, ms);
                    }
                    Err(error) => {
                        if let Some(recipe_error) = error.recipe_error().cloned() {
                            // As a run on the page: beside the field it names, same words.
                            let slot = page.slot_for(&recipe_error);
                            page.st.borrow_mut().failed =
                                Some((run_args, slot, Message::Recipe(recipe_error)));
                        } else if let Some(bg) = page.background.borrow().as_ref() {
                            *bg.error.borrow_mut() = Some(error);
                        }
                        page.st.borrow_mut().status = Status::Failed;
                    }
                }
                page.after_background_run();
            },
        );
        match job {
            Ok(job) => *bg.job.borrow_mut() = Some(job),
            Err(e) => {
                bg.panel.hide();
                *bg.error.borrow_mut() = Some(WorkerError::Failed(
                    e.as_string().unwrap_or_else(|| format!("{e:?}")),
                ));
                self.st.borrow_mut().status = Status::Failed;
                self.after_background_run();
            }
        }
    }

    /// Cancel: stops the worker; the last result stays.
    pub(super) fn cancel_background(&self) {
        if let Some(bg) = self.background.borrow().as_ref() {
            bg.stop();
        }
        self.st.borrow_mut().status = Status::Idle;
        self.render_status();
        self.validate();
    }

    fn after_background_run(&self) {
        self.validate();
        if let Err(e) = self.render_output() {
            web_sys::console::error_2(&"drills: result".into(), &e);
        }
        self.render_background_error();
        self.render_status();
        // The URL in a task of its own: `history.replaceState` alone can take tens of ms
        // (measured ~75 ms in headless Chromium right after a 60 MB result), and together with
        // the rendering it made one task over 100 ms.
        self.url.schedule_in(0);
        // Bring the outcome into view, as a run on the page does (Run asked for it), after the
        // browser has laid out and painted the new result (one long task otherwise).
        let weak = self.weak.borrow().clone();
        let _ = after_paint(move || {
            let Some(page) = weak.upgrade() else {
                return;
            };
            let has_background_error = page
                .background
                .borrow()
                .as_ref()
                .is_some_and(|bg| bg.error.borrow().is_some());
            if page.st.borrow().status == Status::Failed {
                if has_background_error {
                    reveal(&page.els.error, Reveal::Nearest);
                } else {
                    page.reveal_first_error();
                }
            } else {
                page.announce_result();
                reveal(&page.els.output, Reveal::Start);
            }
        });
    }

    /// The last worker run's error under the form (after `render_errors`, which owns that
    /// element otherwise).
    pub(super) fn render_background_error(&self) {
        let Some(bg) = self.background.borrow().clone() else {
            return;
        };
        let text = bg.error.borrow().as_ref().map(WorkerError::text);
        if let Some(text) = text {
            if self.st.borrow().status == Status::Failed {
                self.els.error.set_text_content(Some(&text));
                crate::ui::dom::show(&self.els.error, true);
            }
        }
    }
}

/// A run on the page, made and not yet shown.
struct PageRun {
    args: crate::view::command_line::RunArgs,
    /// The input file the run was given, if any.
    input_name: Option<String>,
    result: Result<crate::recipes::RecipeOutput, crate::error::RecipeError>,
    /// How long the run took.
    ms: f64,
}
