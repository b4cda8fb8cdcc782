//! Running a drill and the status line beside Run: an edit validates at once and (debounced)
//! rewrites the URL and runs a small drill; Run / Enter / `r` paints "Running…" first, then
//! runs and brings the result (or the first error) into view, clear of the phone's sticky Run
//! bar. A run computes the recipe's output (with the opened input file attached) and shows it,
//! or puts its error where it belongs.

use super::result::Shown;
use super::{Page, Status};
use crate::recipes;
use crate::ui::ctx::{self, t_strings};
use crate::ui::kit::form::{reveal, Message, Reveal};
use crate::ui::schedule::{after_paint, now_ms};

/// Milliseconds between the last keystroke and a small drill's run.
const AUTO_RUN_DELAY_MS: i32 = 250;

/// What a valid form will cost.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Plan {
    /// Rows of work (the recipe's `plan`); `None` when only the run can size it (a large
    /// input file).
    pub rows: Option<u64>,
}

impl Plan {
    /// Whether the page may run it while the user types.
    pub fn is_small(&self) -> bool {
        crate::view::form::runs_while_typing(self.rows)
    }
}

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
            .any(|(s, _)| matches!(s, super::Slot::Field(_)));
        if has_field_error {
            self.form.borrow().focus_first_error();
        } else {
            reveal(&self.els.error, Reveal::Nearest);
        }
    }

    /// Runs the form's arguments now and shows the result (or the error); `asked`: the user
    /// asked for it (Run, Enter, `r`), so the outcome is brought into view.
    fn run_now(&self, asked: bool) {
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
                recipes::run_with_inputs(args.recipe, &args.raw(), inputs),
                file.map(|f| f.name.clone()),
            )
        };
        let ms = now_ms() - t0;
        let ok = result.is_ok();
        match result {
            Ok(out) => {
                let mut st = self.st.borrow_mut();
                st.shown = Some(Shown::new(args, input_name, out));
                st.runs += 1;
                st.status = Status::Done(ms);
                st.failed = None;
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
                        st.recipe.info.id,
                        &form.fields,
                        &st.texts,
                    )
            }
            _ => false,
        };
        crate::ui::dom::show(&self.els.stale, stale && st.status != Status::Running);
    }
}
