//! Exports: `rrt_nodes.csv` and `rrt_path.csv` of the run at its end (the kernel's own output
//! for the page's arguments, so byte for byte what `bsv rrt-2d` writes), a PNG of the world
//! view, and the command lines: `bsv` always, `python rrt_2d_grid.py` only when the world
//! and the planner's constants are the recipe's (the Python recipe has no options).
//!
//! A big tree's `rrt_nodes.csv` (up to 1,000,001 rows) is written in slices between tasks,
//! each slice's rows made into a `Blob` of bytes and the file a `Blob` of those (no copy), with a
//! progress line: no task near 100 ms whatever the tree.

use std::cell::{Cell, RefCell};

use wasm_bindgen::JsValue;
use web_sys::{Blob, BlobPropertyBag, Element};

use crate::recipes::rrt_2d::{nodes_csv_part, path_csv, INFO};
use crate::ui::dom;
use crate::ui::kit::exports::Exports as Commands;
use crate::ui::schedule::now_ms;
use crate::view::rrt::PageState;

use super::run::Run;

/// Nodes whose CSV is written at once on a click; a bigger tree's is written in slices.
const NODES_AT_ONCE: usize = 50_000;
/// Rows of one piece of a sliced `rrt_nodes.csv`.
const ROWS_PER_PIECE: usize = 1_024;
/// Time spent writing pieces per task, ms.
const CSV_MS_PER_TASK: f64 = 20.0;

/// A `rrt_nodes.csv` being written in slices: the next row, a `Blob` per slice so far.
struct NodesJob {
    next: usize,
    slices: js_sys::Array,
}

/// A CSV `Blob` of `parts`: bytes, or blobs when `of_blobs`.
fn csv_blob(parts: &js_sys::Array, of_blobs: bool) -> Result<Blob, JsValue> {
    let options = BlobPropertyBag::new();
    options.set_type("text/csv");
    if of_blobs {
        Blob::new_with_blob_sequence_and_options(parts, &options)
    } else {
        Blob::new_with_u8_array_sequence_and_options(parts, &options)
    }
}

/// The exports component.
pub struct Exports {
    pub commands: Commands,
    pub nodes: Element,
    pub path: Element,
    pub png: Element,
    python_row: Option<Element>,
    python_note: Element,
    python_none: Element,
    recipe_world: Cell<bool>,
    /// "Writing rrt_nodes.csv: 12,288 of 864,001 rows…", while a sliced file is written.
    progress: Element,
    job: RefCell<Option<NodesJob>>,
}

impl Exports {
    /// Finds the elements under `root`.
    pub fn find(root: &Element) -> Result<Exports, JsValue> {
        let f = |sel: &str| -> Result<Element, JsValue> { dom::find(root, sel, "rrt") };
        let python = f("[data-cmd=\"python\"]")?;
        Ok(Exports {
            commands: Commands::find(root, "rrt")?,
            nodes: f("[data-download=\"rrt_nodes.csv\"]")?,
            path: f("[data-download=\"rrt_path.csv\"]")?,
            png: f("[data-download=\"rrt_2d.png\"]")?,
            python_row: python.parent_element(),
            python_note: f("[data-rrt=\"python-note\"]")?,
            python_none: f("[data-rrt=\"python-none\"]")?,
            recipe_world: Cell::new(true),
            progress: f("[data-rrt=\"csv-progress\"]")?,
            job: RefCell::new(None),
        })
    }

    /// Shows the command lines of `state`.
    pub fn update(&self, state: &PageState) {
        self.commands.show_run(&state.run_args(), INFO.python, None);
        self.recipe_world.set(state.is_recipe_world());
        self.python_visibility();
    }

    fn python_visibility(&self) {
        let recipe = self.recipe_world.get();
        if let Some(row) = &self.python_row {
            dom::show(row, recipe);
        }
        if !recipe {
            dom::show(&self.python_note, false);
        }
        dom::show(&self.python_none, !recipe);
    }

    /// Re-renders in the current language.
    pub fn relocalize(&self) {
        self.commands.relocalize();
        self.python_visibility();
    }

    /// Downloads `file` of the finished run; `true` when a big `rrt_nodes.csv` is being
    /// written in slices (call [`Exports::write_slice`] in the next tasks).
    pub fn download(&self, run: &Run, file: &str) -> bool {
        let rrt = &run.finished;
        if file == "rrt_path.csv" {
            self.commands.download(file, &path_csv(&rrt.path()));
            return false;
        }
        let rows = rrt.nodes().len();
        if rows <= NODES_AT_ONCE {
            self.commands.download(file, &nodes_csv_part(rrt, 0..rows));
            return false;
        }
        if self.job.borrow().is_none() {
            *self.job.borrow_mut() = Some(NodesJob {
                next: 0,
                slices: js_sys::Array::new(),
            });
        }
        self.write_slice(run)
    }

    /// The CSV downloads enabled once the run to its end is `done` (`rrt_nodes.csv` not while
    /// a sliced one is being written).
    pub fn enable_csv(&self, done: bool) {
        let writing = self.writing();
        for el in [&self.nodes, &self.path] {
            let busy = writing && *el == self.nodes;
            let _ = if done && !busy {
                el.remove_attribute("disabled")
            } else {
                el.set_attribute("disabled", "")
            };
        }
    }

    /// Whether a sliced `rrt_nodes.csv` is being written.
    fn writing(&self) -> bool {
        self.job.borrow().is_some()
    }

    /// Drops a file being written (the run changed).
    pub fn cancel(&self) {
        self.job.borrow_mut().take();
        self.show_progress(None);
    }

    /// Writes pieces of the sliced `rrt_nodes.csv` for about [`CSV_MS_PER_TASK`]; at its end
    /// offers the file. `true` while more is left.
    pub fn write_slice(&self, run: &Run) -> bool {
        let rrt = &run.finished;
        let rows = rrt.nodes().len();
        let started = now_ms();
        let mut job = self.job.borrow_mut();
        let Some(j) = job.as_mut() else {
            return false;
        };
        // The slice's rows as bytes (no JS strings for the garbage collector).
        let mut text = String::new();
        while j.next < rows {
            let end = (j.next + ROWS_PER_PIECE).min(rows);
            text.push_str(&nodes_csv_part(rrt, j.next..end));
            j.next = end;
            if now_ms() - started >= CSV_MS_PER_TASK {
                break;
            }
        }
        let pieces = js_sys::Array::of1(&js_sys::Uint8Array::from(text.as_bytes()));
        let file = "rrt_nodes.csv";
        let slice = match csv_blob(&pieces, false) {
            Ok(blob) => blob,
            Err(e) => {
                job.take();
                drop(job);
                self.show_progress(None);
                self.commands.download_failed(file, &e);
                return false;
            }
        };
        j.slices.push(&slice);
        if j.next < rows {
            let done = j.next;
            drop(job);
            self.show_progress(Some((done, rows)));
            return true;
        }
        let slices = j.slices.clone();
        job.take();
        drop(job);
        self.show_progress(None);
        // A Blob of Blobs refers to their bytes: nothing is copied here.
        let saved = csv_blob(&slices, true)
            .and_then(|blob| crate::ui::download::download_blob(&blob, file));
        if let Err(e) = saved {
            self.commands.download_failed(file, &e);
        }
        false
    }

    /// The progress line of a sliced file (`None`: hidden), and the button disabled meanwhile.
    fn show_progress(&self, rows: Option<(usize, usize)>) {
        let shown = rows.map(|rows| ("rrt_nodes.csv", rows));
        crate::ui::kit::progress::show_writing_line(&self.progress, "rrt-csv-writing", shown);
    }
}
