//! Runs too big to auto-run go to the Web Worker (`crate::ui::kit::worker`), with the kit's
//! progress panel under Run: the page stays interactive, Cancel (the panel's button) stops the
//! run and keeps the last result, and the result's files stay Blobs made in the worker (the
//! preview reads their first lines; downloads hand the Blob to the browser). A recipe error
//! from the worker is the kernel's `RecipeError` itself, so it goes where a run on the page
//! puts it (beside its field, marked) with the same words; only a worker that could not run
//! at all is reported under the form.
//!
//! The worker integration of this page is this file (the run and its panel) plus:
//! `Page::background` (state.rs), its construction and the panel's place (mount.rs), the
//! worker run and `request_run` sending big runs to it (run.rs), `Shown::from_worker`
//! (shown.rs), the file size from the Blob and downloads of worker files (result.rs).

use std::cell::RefCell;

use wasm_bindgen::prelude::*;

use crate::ui::kit::progress::ProgressPanel;
use crate::ui::kit::worker::{Job, WorkerError};

/// The page's worker run (at most one) and its progress panel.
pub(super) struct Background {
    pub panel: ProgressPanel,
    pub job: RefCell<Option<Job>>,
    /// The last worker run's failure that is not a recipe error (shown under the form until
    /// the next run).
    pub error: RefCell<Option<WorkerError>>,
}

impl Background {
    /// The panel (hidden), whose Cancel button calls `on_cancel`.
    pub fn new(on_cancel: impl Fn() + 'static) -> Result<Background, JsValue> {
        let panel = ProgressPanel::new(on_cancel)?;
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
