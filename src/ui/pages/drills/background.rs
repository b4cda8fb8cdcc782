//! Runs too big to auto-run go to the Web Worker (`crate::ui::kit::worker`), with the kit's
//! progress panel under Run: the page stays interactive, Cancel (the panel's button) stops the
//! run and keeps the last result, and the result's files stay Blobs made in the worker (the
//! preview reads their first lines; downloads hand the Blob to the browser). A recipe error
//! from the worker is the kernel's `RecipeError` itself, so it goes where a run on the page
//! puts it (beside its field, marked) with the same words; only a worker that could not run
//! at all is reported under the form.
//!
//! The worker integration of this page is this file plus: `Page::background` (mod.rs), its
//! construction and the panel's place (mount.rs), `request_run` sending big runs here
//! (run.rs), `Shown::from_worker`, the file size from the Blob and downloads of worker files
//! (result.rs).

use std::cell::RefCell;
use std::rc::Weak;

use wasm_bindgen::prelude::*;

use super::result::Shown;
use super::{Page, Status};
use crate::ui::kit::form::{reveal, Message, Reveal};
use crate::ui::kit::progress::ProgressPanel;
use crate::ui::kit::worker::{self, Job, WorkerError};
use crate::ui::schedule::{after_paint, now_ms};

/// The page's worker run (at most one) and its progress panel.
pub(super) struct Background {
    pub panel: ProgressPanel,
    job: RefCell<Option<Job>>,
    /// The last worker run's failure that is not a recipe error (shown under the form until
    /// the next run).
    pub error: RefCell<Option<WorkerError>>,
}

impl Background {
    /// The panel (hidden), whose Cancel button cancels the page's run.
    pub fn new(page: Weak<Page>) -> Result<Background, JsValue> {
        let panel = ProgressPanel::new(move || {
            if let Some(page) = page.upgrade() {
                page.cancel_background();
            }
        })?;
        Ok(Background {
            panel,
            job: RefCell::new(None),
            error: RefCell::new(None),
        })
    }

    /// Stops the run, if any (unmount).
    pub fn stop(&self) {
        if let Some(job) = self.job.borrow_mut().take() {
            job.cancel();
        }
        self.panel.hide();
    }
}

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
                        let mut st = page.st.borrow_mut();
                        st.shown = Some(Shown::from_worker(run_args, input_name, out));
                        st.runs += 1;
                        st.status = Status::Done(ms);
                        st.failed = None;
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
