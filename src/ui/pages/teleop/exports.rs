//! The session's downloads: `teleop_episodes.csv` at once (one short row per episode), and
//! `teleop_episode_<n>.csv` and `teleop_session_evidence.json` written in slices between
//! tasks (the files' chunk's jobs, `super::files`: a 60 s episode is 6,000 rows, and the
//! evidence hashes every episode's CSV), each slice's bytes a `Blob` and the file a `Blob` of
//! them (no copy), with a progress line (`data-tele="export-progress"`, `data-state`
//! `writing|idle`). A click on another file while one is written queues it; each file is the
//! session as it was at its click. Each slice runs in its own task (a timer at 0 ms).

use std::cell::RefCell;
use std::collections::VecDeque;
use std::rc::{Rc, Weak};

use wasm_bindgen::JsValue;
use web_sys::{Blob, BlobPropertyBag, Element};

use crate::teleop::session::{Session, EPISODES_NAME};
use crate::ui::kit::scope::Scope;
use crate::ui::schedule::{now_ms, Timer};

use super::bench;
use super::files::{FileJob, Files};
use super::markup::role;
use super::sessions::iso_now;

/// Rows written (or hashed) between two clock reads.
const ROWS_PER_PIECE: usize = 200;
/// Time spent writing per task, ms (a frame at 60 Hz: the page stays responsive while a long
/// file is written, with room for a busy machine under the 100 ms of a long task).
const MS_PER_TASK: f64 = 16.0;

/// A file being written: the job and the `Blob` of each slice so far.
struct Writing {
    job: Box<dyn FileJob>,
    slices: js_sys::Array,
}

/// The exports component.
pub struct Exports {
    progress: Element,
    writing: RefCell<Option<Writing>>,
    /// Files asked for while another was written.
    queue: RefCell<VecDeque<Box<dyn FileJob>>>,
    /// The next slice.
    timer: Rc<Timer>,
    _scope: Scope,
}

impl Exports {
    /// Finds the progress line under `root`.
    pub fn find(root: &Element) -> Result<Rc<Exports>, JsValue> {
        let progress = role(root, "export-progress")?;
        Ok(Rc::new_cyclic(|me: &Weak<Exports>| {
            let mut scope = Scope::new();
            let timer = scope.timer(me, Exports::slice);
            Exports {
                progress,
                writing: RefCell::new(None),
                queue: RefCell::new(VecDeque::new()),
                timer,
                _scope: scope,
            }
        }))
    }

    /// Downloads `file` of `session` (ended now if it has no end time) with `files`: the
    /// episodes table at once, an episode's CSV or the evidence in slices, in the next tasks.
    pub fn download(&self, files: Files, file: &str, session: &Session) {
        let started_ms = now_ms();
        let more = self.start_download(files, file, session, &iso_now());
        bench::record_export(now_ms() - started_ms);
        if more {
            self.timer.schedule(0);
        }
    }

    /// One slice of the file being written (the file offered at its end).
    fn slice(&self) {
        let started_ms = now_ms();
        let more = self.write_slice();
        bench::record_export(now_ms() - started_ms);
        if more {
            self.timer.schedule(0);
        }
    }

    /// Starts `file` (`ended_at`: the session's end time if it has none); `true` when more
    /// slices are due.
    fn start_download(&self, files: Files, file: &str, session: &Session, ended_at: &str) -> bool {
        if file == EPISODES_NAME {
            let text = (files.episodes_csv)(session);
            if let Err(e) = crate::ui::download::download_text(file, &text, "text/csv") {
                web_sys::console::warn_1(&e);
            }
            return self.is_writing();
        }
        let busy = self
            .writing
            .borrow()
            .as_ref()
            .map(|w| w.job.file().to_string());
        if let Some(current) = busy {
            let queued = self.queue.borrow().iter().any(|j| j.file() == file);
            if current != file && !queued {
                if let Some(job) = (files.job)(file, session, ended_at) {
                    self.queue.borrow_mut().push_back(job);
                }
            }
            return true;
        }
        let Some(job) = (files.job)(file, session, ended_at) else {
            return false;
        };
        self.start(job);
        self.write_slice()
    }

    fn start(&self, job: Box<dyn FileJob>) {
        *self.writing.borrow_mut() = Some(Writing {
            job,
            slices: js_sys::Array::new(),
        });
    }

    /// Whether a file is being written.
    fn is_writing(&self) -> bool {
        self.writing.borrow().is_some()
    }

    /// Writes the file for about [`MS_PER_TASK`]; at its end offers it and starts the next
    /// file asked for. `true` while more is left.
    fn write_slice(&self) -> bool {
        let started = now_ms();
        let mut writing = self.writing.borrow_mut();
        let Some(w) = writing.as_mut() else {
            return false;
        };
        let mut text = String::new();
        while !w.job.is_done() {
            text.push_str(&w.job.step(ROWS_PER_PIECE));
            if now_ms() - started >= MS_PER_TASK {
                break;
            }
        }
        let file = w.job.file().to_string();
        let mime = w.job.mime();
        if !text.is_empty() {
            // The slice's bytes (no JS string for the garbage collector).
            let bytes = js_sys::Array::of1(&js_sys::Uint8Array::from(text.as_bytes()));
            match blob(&bytes, mime, false) {
                Ok(b) => {
                    w.slices.push(&b);
                }
                Err(e) => {
                    writing.take();
                    drop(writing);
                    web_sys::console::warn_1(&e);
                    return self.next();
                }
            }
        }
        if !w.job.is_done() {
            let progress = w.job.progress();
            drop(writing);
            self.show_progress(Some((&file, progress)));
            return true;
        }
        let slices = w.slices.clone();
        writing.take();
        drop(writing);
        // A Blob of Blobs refers to their bytes: nothing is copied here.
        let saved =
            blob(&slices, mime, true).and_then(|b| crate::ui::download::download_blob(&b, &file));
        if let Err(e) = saved {
            web_sys::console::warn_1(&e);
        }
        self.next()
    }

    /// Starts the next queued file, if any; `true` when a slice is due.
    fn next(&self) -> bool {
        let next = self.queue.borrow_mut().pop_front();
        match next {
            Some(job) => {
                let progress = job.progress();
                let file = job.file().to_string();
                self.start(job);
                self.show_progress(Some((&file, progress)));
                true
            }
            None => {
                self.show_progress(None);
                false
            }
        }
    }

    /// Re-renders the progress line in the current language.
    pub fn relocalize(&self) {
        let shown = self
            .writing
            .borrow()
            .as_ref()
            .map(|w| (w.job.file().to_string(), w.job.progress()));
        match shown {
            Some((file, progress)) => self.show_progress(Some((&file, progress))),
            None => self.show_progress(None),
        }
    }

    /// The progress line (`None`: hidden).
    fn show_progress(&self, shown: Option<(&str, (usize, usize))>) {
        crate::ui::kit::progress::show_writing_line(&self.progress, "teleop-export-writing", shown);
    }
}

/// A `Blob` of `parts` (bytes, or blobs when `of_blobs`) of type `mime`.
fn blob(parts: &js_sys::Array, mime: &str, of_blobs: bool) -> Result<Blob, JsValue> {
    let options = BlobPropertyBag::new();
    options.set_type(mime);
    if of_blobs {
        Blob::new_with_blob_sequence_and_options(parts, &options)
    } else {
        Blob::new_with_u8_array_sequence_and_options(parts, &options)
    }
}
