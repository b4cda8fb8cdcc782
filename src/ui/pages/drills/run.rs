//! When and how a drill runs: an edit validates at once and (debounced) rewrites the URL and
//! runs a small drill; Run / Enter / `r` paints "Running…" first and then runs; a run computes
//! the recipe's output (traj-resample on the opened file's text in place) and shows it, or puts
//! its error where it belongs.

use super::command::RunArgs;
use super::fields::Message;
use super::file::InputFile;
use super::output::Shown;
use super::validate::slot_for;
use super::{Page, Status};
use crate::args::Args;
use crate::error::RecipeError;
use crate::recipes::{self, traj_resample, RecipeOutput};
use crate::ui::schedule::{after_paint, now_ms};

/// Milliseconds between the last keystroke and a small drill's run.
const AUTO_RUN_DELAY_MS: i32 = 250;
/// Milliseconds between the last keystroke and the URL update.
const URL_DELAY_MS: i32 = 300;

/// Runs `args`; traj-resample with an opened file reads the file's text in place (the same
/// kernel path as `run_with_inputs`, without copying a large input).
fn compute(args: &RunArgs, input: Option<&InputFile>) -> Result<RecipeOutput, RecipeError> {
    let raw = args.raw();
    if args.recipe == traj_resample::INFO.id {
        if let Some(file) = input.filter(|f| args.positional.first() == Some(&f.name)) {
            let info = &traj_resample::INFO;
            let parsed = Args::parse(&raw, info.args, info.flags)?;
            let params = traj_resample::ResampleParams::from_args(&parsed)?;
            return traj_resample::run_text(&params, &file.text);
        }
    }
    recipes::run(args.recipe, &raw)
}

impl Page {
    /// A field changed: validate, rewrite the URL soon, run soon if small.
    pub(super) fn on_edit(&self) {
        self.validate();
        let (valid, small, large) = {
            let st = self.st.borrow();
            let valid = st.errors.is_empty();
            let small = st.plan.is_some_and(|p| p.is_small());
            (valid, small, valid && !small)
        };
        {
            let mut st = self.st.borrow_mut();
            if st.status != Status::Running {
                st.status = if large { Status::Large } else { Status::Idle };
            }
            st.copy_status = None;
        }
        self.els.copy_status.set_text_content(None);
        self.render_status();
        self.url_timer.schedule(URL_DELAY_MS);
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
                    self.run_now();
                }
            }
            Some(_) => {
                self.st.borrow_mut().status = Status::Large;
                self.render_status();
            }
            None => {}
        }
    }

    /// Run / Enter / `r`: shows "Running…", lets the browser paint it, then runs.
    pub(super) fn request_run(&self) {
        self.auto_timer.cancel();
        if self.st.borrow().status == Status::Running {
            return;
        }
        if self.st.borrow().reading.is_some() {
            return;
        }
        self.validate();
        if !self.st.borrow().errors.is_empty() {
            self.st.borrow_mut().status = Status::Invalid;
            self.render_status();
            self.form.borrow().focus_first_error();
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
                page.run_now();
            }
        });
        if started.is_err() {
            self.run_now();
        }
    }

    /// Runs the form's arguments now and shows the result (or the error).
    fn run_now(&self) {
        let args = self.current_args();
        let t0 = now_ms();
        let result = {
            let st = self.st.borrow();
            compute(&args, st.input.as_ref())
        };
        let ms = now_ms() - t0;
        match result {
            Ok(out) => {
                let input_name = {
                    let st = self.st.borrow();
                    st.input
                        .as_ref()
                        .filter(|f| args.positional.first() == Some(&f.name))
                        .map(|f| f.name.clone())
                };
                let mut st = self.st.borrow_mut();
                st.shown = Some(Shown::new(args, input_name, out));
                st.runs += 1;
                st.status = Status::Done(ms);
                st.failed = None;
                st.copy_status = None;
            }
            Err(error) => {
                let slot = slot_for(&self.form.borrow(), &error);
                let mut st = self.st.borrow_mut();
                st.failed = Some((args, slot, Message::Recipe(error)));
                st.status = Status::Failed;
            }
        }
        self.validate();
        if let Err(e) = self.render_output() {
            web_sys::console::error_2(&"drills: result".into(), &e);
        }
        self.render_status();
        self.write_url();
    }
}
